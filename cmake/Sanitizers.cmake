# AddressSanitizer + UndefinedBehaviorSanitizer for every target of the build when asked for.
if(CGAL_POLICIES_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# ThreadSanitizer, for the partitioned runs' threads (.ci/run builds only the tests of them).
option(CGAL_POLICIES_TSAN "Build with ThreadSanitizer" OFF)
if(CGAL_POLICIES_TSAN)
  if(CGAL_POLICIES_SANITIZE)
    message(FATAL_ERROR "CGAL_POLICIES_TSAN and CGAL_POLICIES_SANITIZE do not go together")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()

# The fuzz targets (fuzz/) live in the sanitized build, made by clang.
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
endif()

# What the fuzz targets run (the apps' library and the targets themselves) is built with
# libFuzzer's coverage instrumentation, and at -O1: CGAL code at -O0 runs too slowly to fuzz. The
# rest of the sanitized build (the tests, the apps' mains) has neither, which keeps it fast to
# build and to run. A Debug build defines no NDEBUG either way: CGAL's assertions stay on.
function(cgal_policies_instrument_for_fuzzing target)
  if(CGAL_POLICIES_FUZZ)
    target_compile_options(${target} PRIVATE -O1 -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# Tests that run heavy geometry in their own process (not through the apps' -O1 layers) run much
# faster at -O1 under the sanitizers, which pays for their longer compile (the figures:
# docs/compatibility.md, "CI time"). CGAL's assertions stay on: no NDEBUG.
function(cgal_policies_optimize_under_sanitizers target)
  if(CGAL_POLICIES_SANITIZE)
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()
