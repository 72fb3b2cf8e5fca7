# The physical robot's side builds without the simulator: the platform interface, the recording
# formats, the controller and the ROS client must not link ambf_like or Bullet, directly or
# through another target. Checked on the link graph at configure time; a link that brings the
# simulator back stops the configure and names the path it came by.

# Fails if `forbidden` is reachable from `target` through LINK_LIBRARIES or
# INTERFACE_LINK_LIBRARIES; `path` is the chain walked so far (for the message).
function(raven_forbid_link target forbidden path)
  if(NOT TARGET ${target})
    return()
  endif()
  get_target_property(aliased ${target} ALIASED_TARGET)
  if(aliased)
    set(target ${aliased})
  endif()
  if(target STREQUAL forbidden)
    message(FATAL_ERROR "${path} links ${forbidden}: the simulator has reached a room that must "
                        "build without it (cmake/SimulatorFreeTargets.cmake)")
  endif()
  get_target_property(type ${target} TYPE)
  set(links)
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(direct ${target} LINK_LIBRARIES)
    if(direct)
      list(APPEND links ${direct})
    endif()
  endif()
  get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
  if(interface)
    list(APPEND links ${interface})
  endif()
  list(REMOVE_DUPLICATES links)
  foreach(link ${links})
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
    raven_forbid_link(${link} ${forbidden} "${path} -> ${link}")
  endforeach()
endfunction()

function(raven_check_simulator_free)
  foreach(target ${ARGN})
    if(NOT TARGET ${target})
      message(FATAL_ERROR "raven_check_simulator_free: no target ${target}")
    endif()
    foreach(forbidden ambf_like PkgConfig::BULLET)
      raven_forbid_link(${target} ${forbidden} ${target})
    endforeach()
  endforeach()
endfunction()
