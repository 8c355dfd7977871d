# Warnings as errors on the project's own targets (CGAL, Eigen and Boost are system headers).
# GCC 12 at -O2/-O3 reports false "may be used uninitialized" warnings inside Eigen's fixed-size
# matrices once they are inlined into our code, where system-header suppression no longer reaches;
# that one diagnostic stays a warning instead of an error.
function(cgal_policies_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Werror)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized)
  endif()
endfunction()
