# AddressSanitizer + UndefinedBehaviorSanitizer for every target of the build when asked for.
if(CGAL_POLICIES_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# The fuzz targets (fuzz/) live in the sanitized build: with clang, every target of that build is
# compiled with libFuzzer's coverage instrumentation, and only the fuzz targets link its driver.
if(CGAL_POLICIES_SANITIZE AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(CGAL_POLICIES_FUZZ_DEFAULT ON)
else()
  set(CGAL_POLICIES_FUZZ_DEFAULT OFF)
endif()
option(CGAL_POLICIES_FUZZ "Build the libFuzzer targets (clang, sanitized build)" ${CGAL_POLICIES_FUZZ_DEFAULT})
if(CGAL_POLICIES_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CGAL_POLICIES_SANITIZE)
    message(FATAL_ERROR "CGAL_POLICIES_FUZZ needs clang and CGAL_POLICIES_SANITIZE=ON")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

# -O1 for the code the fuzz targets run (the apps' library and the targets themselves): CGAL code
# built at -O0 runs too slowly to fuzz. The rest of the sanitized build stays at -O0, which
# compiles faster. Either way a Debug build defines no NDEBUG: CGAL's assertions stay on.
function(cgal_policies_optimize_when_fuzzing target)
  if(CGAL_POLICIES_FUZZ)
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()
