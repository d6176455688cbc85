# Guards that keep the layering honest: the algorithm library (and the other CPU-only
# targets) must never link Qt or OpenGL. Checked at configure time.
function(shadowlab_forbid_gpu_and_qt target)
  # Deferred so that links added later in the same directory are seen; EVAL binds the
  # target name now (deferred arguments are otherwise expanded at call time).
  cmake_language(EVAL CODE
    "cmake_language(DEFER DIRECTORY [[${CMAKE_SOURCE_DIR}]] CALL _shadowlab_check_links [[${target}]])")
endfunction()

function(_shadowlab_check_links target)
  get_target_property(libs ${target} LINK_LIBRARIES)
  get_target_property(ilibs ${target} INTERFACE_LINK_LIBRARIES)
  foreach(lib IN LISTS libs ilibs)
    if(lib MATCHES "Qt|OpenGL|epoxy|EPOXY|EGL|GL$|shadowlab_gl|shadowlab_renderer")
      message(FATAL_ERROR "${target} must not link Qt or OpenGL (found '${lib}'): "
                          "it is the CPU reference library.")
    endif()
  endforeach()
endfunction()
