# Link cycles between the project's own targets. CMake links a cycle of static libraries without a
# word (it repeats them on the link line), so a library that links one above it back goes
# unnoticed: voxflame_check_link_cycles() stops the configure instead, naming the cycle.

# voxflame_find_link_cycle(<out-var> <node>...): the graph is read from variables
# VOXFLAME_LINKS_<node> (the nodes that <node> links). Sets <out-var> to the first cycle found,
# as "a -> b -> a", or to "" when there is none. It reads no targets, so a script (cmake -P) can
# try it on a made-up graph.
function(voxflame_find_link_cycle out)
  foreach(node IN LISTS ARGN)
    set_property(GLOBAL PROPERTY VOXFLAME_LINK_STATE_${node} "")
  endforeach()
  set_property(GLOBAL PROPERTY VOXFLAME_LINK_CYCLE "")
  foreach(node IN LISTS ARGN)
    get_property(state GLOBAL PROPERTY VOXFLAME_LINK_STATE_${node})
    if(NOT state)
      _voxflame_link_visit("${node}" "")
      get_property(cycle GLOBAL PROPERTY VOXFLAME_LINK_CYCLE)
      if(cycle)
        break()  # the search stopped halfway: nodes on its path are still marked active
      endif()
    endif()
  endforeach()
  get_property(cycle GLOBAL PROPERTY VOXFLAME_LINK_CYCLE)
  set(${out} "${cycle}" PARENT_SCOPE)
endfunction()

# Depth first from `node`; `path` is the chain of nodes that led here. A node still on the chain
# ("active") reached again closes a cycle.
function(_voxflame_link_visit node path)
  list(APPEND path "${node}")
  set_property(GLOBAL PROPERTY VOXFLAME_LINK_STATE_${node} active)
  foreach(next IN LISTS VOXFLAME_LINKS_${node})
    get_property(state GLOBAL PROPERTY VOXFLAME_LINK_STATE_${next})
    if(state STREQUAL "active")
      list(FIND path "${next}" start)
      list(SUBLIST path ${start} -1 cycle)
      list(APPEND cycle "${next}")
      list(JOIN cycle " -> " text)
      set_property(GLOBAL PROPERTY VOXFLAME_LINK_CYCLE "${text}")
      return()
    elseif(NOT state)
      _voxflame_link_visit("${next}" "${path}")
      get_property(cycle GLOBAL PROPERTY VOXFLAME_LINK_CYCLE)
      if(cycle)
        return()
      endif()
    endif()
  endforeach()
  set_property(GLOBAL PROPERTY VOXFLAME_LINK_STATE_${node} done)
endfunction()

# The targets defined in `dir` and the folders below it.
function(_voxflame_targets_below dir out)
  get_property(found DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirectories DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    _voxflame_targets_below("${subdirectory}" below)
    list(APPEND found ${below})
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# What `target` links, directly: LINK_LIBRARIES holds the PRIVATE and PUBLIC links,
# INTERFACE_LINK_LIBRARIES the PUBLIC and INTERFACE ones (and a static library's PRIVATE ones again,
# as $<LINK_ONLY:name>, unwrapped here: they are linked too). Other generator expressions are not
# evaluated: a target named only inside one is missed.
function(_voxflame_links_of target out)
  set(links "")
  foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
    get_target_property(items ${target} ${property})
    if(NOT items)
      continue()
    endif()
    foreach(item IN LISTS items)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
      list(APPEND links "${item}")
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES links)
  set(${out} "${links}" PARENT_SCOPE)
endfunction()

# voxflame_check_link_cycles(): call at the end of the top-level CMakeLists.txt, once every target
# is defined. Walks LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES of every library and executable
# the project defines (imported ones cannot link ours back) and stops with FATAL_ERROR on a cycle.
function(voxflame_check_link_cycles)
  _voxflame_targets_below("${CMAKE_SOURCE_DIR}" all)
  set(targets "")
  foreach(target IN LISTS all)
    get_target_property(type ${target} TYPE)
    if(type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY|INTERFACE_LIBRARY|EXECUTABLE)$")
      list(APPEND targets ${target})
    endif()
  endforeach()
  foreach(target IN LISTS targets)
    _voxflame_links_of(${target} items)
    set(VOXFLAME_LINKS_${target} "")
    foreach(item IN LISTS items)
      if(item IN_LIST targets)
        list(APPEND VOXFLAME_LINKS_${target} "${item}")
      endif()
    endforeach()
  endforeach()
  voxflame_find_link_cycle(cycle ${targets})
  if(cycle)
    message(FATAL_ERROR "link cycle between targets: ${cycle}\n"
                        "A library must not link one that links it back: move what both need below them "
                        "(or what uses both above them).")
  endif()
endfunction()

# voxflame_find_forbidden_link(<out-var> <start> <forbidden>...): follows VOXFLAME_LINKS_<node>
# from <start> (breadth first) and sets <out-var> to the first chain that reaches one of the
# forbidden names, as "a -> b -> imgui", or to "" when none is reached. Like
# voxflame_find_link_cycle it reads only variables, so a script can try it on a made-up graph.
function(voxflame_find_forbidden_link out start)
  set(forbidden ${ARGN})
  set(queue "${start}")
  set(seen "${start}")
  set(chain_${start} "${start}")
  while(queue)
    list(POP_FRONT queue node)
    foreach(next IN LISTS VOXFLAME_LINKS_${node})
      # list(FIND), not IN_LIST: a script (cmake -P) runs this under the old policies.
      list(FIND seen "${next}" seenAt)
      if(seenAt GREATER -1)
        continue()
      endif()
      list(APPEND seen "${next}")
      set(chain_${next} "${chain_${node}} -> ${next}")
      list(FIND forbidden "${next}" forbiddenAt)
      if(forbiddenAt GREATER -1)
        set(${out} "${chain_${next}}" PARENT_SCOPE)
        return()
      endif()
      list(APPEND queue "${next}")
    endforeach()
  endwhile()
  set(${out} "" PARENT_SCOPE)
endfunction()

# voxflame_check_links_avoid(<target> <forbidden>...): call once every target is defined. Stops the
# configure when <target> links, directly or through any of the project's libraries, one of the
# forbidden libraries (imported targets or plain names), naming the chain. The headless commands
# use it to stay without a window: `voxflame render` on a server must not need GLFW or ImGui.
function(voxflame_check_links_avoid target)
  _voxflame_targets_below("${CMAKE_SOURCE_DIR}" ours)
  foreach(node IN LISTS ours)
    _voxflame_links_of(${node} VOXFLAME_LINKS_${node})
  endforeach()
  voxflame_find_forbidden_link(chain ${target} ${ARGN})
  if(chain)
    message(FATAL_ERROR "${target} must not link ${ARGN}, but links: ${chain}")
  endif()
endfunction()
