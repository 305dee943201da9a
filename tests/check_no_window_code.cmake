# Fails when the binary BINARY, a test that links only the headless commands, holds any Dear
# ImGui or GLFW code: what `voxflame render` would drag onto a server without a display. (ImGui is
# a static library and the linker drops unused shared ones, so `ldd` alone would not see it.)
# The symbols are searched mangled (ImGui's namespace is "5ImGui", GLFW's functions are plain C).
execute_process(COMMAND nm --defined-only ${BINARY} COMMAND grep -c "8voxflame3app" OUTPUT_VARIABLE ours
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT ours GREATER 0)
  message(FATAL_ERROR "${BINARY} holds none of the commands' code: not the binary this check is for")
endif()
execute_process(COMMAND nm -C --defined-only ${BINARY} COMMAND grep -E "5ImGui|ImGui::|ImGui_Impl|glfw[A-Z]"
                OUTPUT_VARIABLE found)
if(found)
  string(SUBSTRING "${found}" 0 600 first)
  message(FATAL_ERROR "${BINARY} holds ImGui or GLFW symbols, such as:\n${first}")
endif()
execute_process(COMMAND ldd ${BINARY} OUTPUT_VARIABLE libraries)
if(libraries MATCHES "lib(glfw|imgui)")
  message(FATAL_ERROR "${BINARY} loads a window library:\n${libraries}")
endif()
