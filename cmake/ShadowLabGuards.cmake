# Guards that keep the layering honest: the algorithm library (and the other CPU-only
# targets) must never link Qt or OpenGL. Checked at configure time.
function(shadowlab_forbid_gpu_and_qt target)
  _shadowlab_forbid_links(${target} "Qt|OpenGL|epoxy|EPOXY|EGL|GL$|shadowlab_gl|shadowlab_renderer"
                          "Qt or OpenGL" "it is the CPU reference library.")
endfunction()

# The GL libraries below the GUI (shadowlab_measure) may link OpenGL but never Qt: the CLI and
# the GUI's render service run the same code.
function(shadowlab_forbid_qt target)
  _shadowlab_forbid_links(${target} "Qt|shadowlab_ui|shadowlab_figures" "Qt"
                          "the CLI and the GUI's render service share it.")
endfunction()

# Deferred so that links added later in the same directory are seen; EVAL binds the arguments
# now (deferred arguments are otherwise expanded at call time).
function(_shadowlab_forbid_links target pattern what why)
  cmake_language(EVAL CODE
    "cmake_language(DEFER DIRECTORY [[${CMAKE_SOURCE_DIR}]] CALL _shadowlab_check_links [[${target}]] [[${pattern}]] [[${what}]] [[${why}]])")
endfunction()

function(_shadowlab_check_links target pattern what why)
  get_target_property(libs ${target} LINK_LIBRARIES)
  get_target_property(ilibs ${target} INTERFACE_LINK_LIBRARIES)
  foreach(lib IN LISTS libs ilibs)
    if(lib MATCHES "${pattern}")
      message(FATAL_ERROR "${target} must not link ${what} (found '${lib}'): ${why}")
    endif()
  endforeach()
endfunction()
