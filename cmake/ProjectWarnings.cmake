# Warnings as errors on the project's own targets (CGAL, Eigen and Boost are system headers).
function(cgal_policies_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Werror)
endfunction()
