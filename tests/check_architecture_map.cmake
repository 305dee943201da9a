# Fails when a target the project defines (add_library / add_executable in a CMakeLists.txt) or a
# top-level folder of the repository is not named, in backquotes, in docs/ARCHITECTURE.md: the map
# must follow the tree. Run by ctest: cmake -DROOT=<source> -P this.
file(READ ${ROOT}/docs/ARCHITECTURE.md map)
set(missing "")

file(GLOB_RECURSE lists RELATIVE ${ROOT} ${ROOT}/*CMakeLists.txt)
foreach(list IN LISTS lists)
  if(list MATCHES "^build" OR list MATCHES "/build")
    continue()  # build folders configured inside the tree
  endif()
  file(READ ${ROOT}/${list} text)
  string(REGEX MATCHALL "add_(library|executable)\\([ \t\n]*[A-Za-z0-9_]+" calls "${text}")
  foreach(call IN LISTS calls)
    string(REGEX REPLACE "add_(library|executable)\\([ \t\n]*" "" target "${call}")
    string(FIND "${map}" "`${target}`" at)
    if(at EQUAL -1)
      list(APPEND missing "target ${target} (${list})")
    endif()
  endforeach()
endforeach()

file(GLOB entries RELATIVE ${ROOT} ${ROOT}/*)
foreach(entry IN LISTS entries)
  if(NOT IS_DIRECTORY ${ROOT}/${entry} OR entry MATCHES "^\\." OR entry MATCHES "^build")
    continue()  # files, hidden folders (.git, .ci), build folders
  endif()
  string(FIND "${map}" "`${entry}/`" at)
  if(at EQUAL -1)
    list(APPEND missing "folder ${entry}/")
  endif()
endforeach()

if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "docs/ARCHITECTURE.md does not name:\n  ${text}")
endif()
