# Proves the link-cycle check of cmake/link_cycles.cmake can fail: on made-up graphs, and by
# configuring two small projects, one with a cycle (the configure must stop, naming it) and one
# without. Run by ctest: cmake -DROOT=<source> -DWORK=<scratch folder> -DGENERATOR=<gen> -P this.
include(${ROOT}/cmake/link_cycles.cmake)

function(expect_cycle expected)
  voxflame_find_link_cycle(cycle ${ARGN})
  if(NOT cycle STREQUAL expected)
    message(FATAL_ERROR "graph of ${ARGN}: expected the cycle '${expected}', found '${cycle}'")
  endif()
endfunction()

# The layers as they are now: the executable above the CLI, the CLI above app and bench, bench
# above app. A diamond is not a cycle.
set(VOXFLAME_LINKS_voxflame cli)
set(VOXFLAME_LINKS_cli app bench)
set(VOXFLAME_LINKS_bench app core)
set(VOXFLAME_LINKS_app core gl)
set(VOXFLAME_LINKS_gl core)
set(VOXFLAME_LINKS_core "")
expect_cycle("" voxflame cli bench app gl core)
# The cycle this check was written for: app linked bench, which links app.
set(VOXFLAME_LINKS_app core gl bench)
expect_cycle("app -> bench -> app" voxflame cli bench app gl core)
expect_cycle("bench -> app -> bench" bench app core gl)
# A longer one, entered from outside it, and a library linking itself.
set(VOXFLAME_LINKS_app core gl)
set(VOXFLAME_LINKS_core gl)
set(VOXFLAME_LINKS_gl cli)
expect_cycle("cli -> app -> core -> gl -> cli" voxflame cli bench app gl core)
set(VOXFLAME_LINKS_gl gl)
expect_cycle("gl -> gl" gl)

# The check on real targets stops the configure of a project that CMake itself would configure
# and generate without a word (it links a cycle of static libraries by repeating them).
# `body` goes in the top folder, `below` in a subdirectory (the check looks in every folder).
function(configure_project name body below expect_failure expected_output)
  set(source ${WORK}/${name})
  file(REMOVE_RECURSE ${source})
  file(WRITE ${source}/CMakeLists.txt
       "cmake_minimum_required(VERSION 3.25)\nproject(${name} LANGUAGES C)\n${body}\nadd_subdirectory(below)\n"
       "include(${ROOT}/cmake/link_cycles.cmake)\nvoxflame_check_link_cycles()\n")
  file(WRITE ${source}/below/CMakeLists.txt "${below}\n")
  file(WRITE ${source}/empty.c "int voxflame_empty;\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${source} -B ${source}/build -G "${GENERATOR}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(expect_failure AND status EQUAL 0)
    message(FATAL_ERROR "${name}: the configure passed despite the cycle:\n${output}")
  elseif(NOT expect_failure AND NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: the configure failed:\n${output}")
  endif()
  if(NOT output MATCHES "${expected_output}")
    message(FATAL_ERROR "${name}: expected output matching '${expected_output}':\n${output}")
  endif()
endfunction()

# A PRIVATE link (LINK_LIBRARIES) one way, an INTERFACE one back, across folders.
configure_project(cyclic [[
add_library(low STATIC empty.c)
target_link_libraries(low PRIVATE high)
]] [[
add_library(high INTERFACE)
target_link_libraries(high INTERFACE low)
]] TRUE "link cycle between targets: (low -> high -> low|high -> low -> high)")
configure_project(acyclic [[
add_library(low STATIC empty.c)
add_library(middle INTERFACE)
target_link_libraries(middle INTERFACE low)
]] [[
add_library(high INTERFACE)
target_link_libraries(high INTERFACE middle low)
]] FALSE "")

# The headless commands' check (voxflame_check_links_avoid): a forbidden library reached through
# any chain of links is found, with the chain; none reached, none reported.
function(expect_forbidden expected start)
  voxflame_find_forbidden_link(chain ${start} ${ARGN})
  if(NOT chain STREQUAL expected)
    message(FATAL_ERROR "from ${start}: expected the chain '${expected}', found '${chain}'")
  endif()
endfunction()
set(VOXFLAME_LINKS_commands core gl)
set(VOXFLAME_LINKS_explorer commands imgui PkgConfig::GLFW)
set(VOXFLAME_LINKS_core "")
set(VOXFLAME_LINKS_gl core EGL)
expect_forbidden("" commands imgui PkgConfig::GLFW)
expect_forbidden("explorer -> imgui" explorer imgui PkgConfig::GLFW)
set(VOXFLAME_LINKS_gl core EGL explorer)
expect_forbidden("commands -> gl -> explorer -> imgui" commands imgui PkgConfig::GLFW)

# On real targets: a PRIVATE link of a static library (kept as $<LINK_ONLY:...>) to a library that
# links a window library stops the configure, naming the chain.
function(configure_headless name links expect_failure)
  set(source ${WORK}/${name})
  file(REMOVE_RECURSE ${source})
  file(WRITE ${source}/CMakeLists.txt
       "cmake_minimum_required(VERSION 3.25)\nproject(${name} LANGUAGES C)\n"
       "add_library(window INTERFACE)\ntarget_link_libraries(window INTERFACE glfw)\n"
       "add_library(commands STATIC empty.c)\n${links}\n"
       "include(${ROOT}/cmake/link_cycles.cmake)\nvoxflame_check_links_avoid(commands glfw)\n")
  file(WRITE ${source}/empty.c "int voxflame_empty;\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${source} -B ${source}/build -G "${GENERATOR}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(expect_failure AND (status EQUAL 0 OR NOT output MATCHES "commands must not link glfw, but links: commands -> window -> glfw"))
    message(FATAL_ERROR "${name}: expected the configure to stop on commands -> window -> glfw:\n${output}")
  elseif(NOT expect_failure AND NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: the configure failed:\n${output}")
  endif()
endfunction()
configure_headless(links_a_window "target_link_libraries(commands PRIVATE window)" TRUE)
configure_headless(headless "" FALSE)
