# Installs the package into a scratch prefix, builds examples/ against it as a project of its own,
# and runs each program on a shipped mesh, checking what it promises with the suite's mesh_error.
# Expects BINARY_DIR (the project's build), SOURCE_DIR (examples/), DATA_DIR, BIN_DIR (where
# mesh_error is), WORK_DIR, CXX_COMPILER (the build's), CXX_FLAGS (the sanitizers', or empty) and
# EXAMPLES (the programs to build and run, separated by commas).
cmake_minimum_required(VERSION 3.19)  # string(JSON)
string(REPLACE "," ";" EXAMPLES "${EXAMPLES}")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/out")

function(run_step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "examples: failed (${result}): ${ARGN}\n${out}${err}")
  endif()
  message(STATUS "${ARGN}: ${out}")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# A field of mesh_error --json for INPUT and OUTPUT.
function(measured field input output variable)
  run_step("${BIN_DIR}/mesh_error" "${input}" "${output}" --json --attributes --samples 20000)
  string(JSON value GET "${step_output}" "${field}")
  set(${variable} "${value}" PARENT_SCOPE)
endfunction()

run_step("${CMAKE_COMMAND}" --install "${BINARY_DIR}" --prefix "${WORK_DIR}/prefix")
run_step("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Release
         "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
         "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CXX_FLAGS}")
run_step("${CMAKE_COMMAND}" --build "${WORK_DIR}/build" --parallel 2 --target ${EXAMPLES})

set(cow "${DATA_DIR}/cow.obj")
set(out "${WORK_DIR}/out")
foreach(example policy_with_filter lt_then_fit simplify_curvature simplify_fusion simplify_fast
                simplify_hausdorff)
  if(NOT example IN_LIST EXAMPLES)
    continue()
  endif()
  run_step("${WORK_DIR}/build/${example}" "${cow}" "${out}/${example}.off" 0.1)
  string(REGEX MATCH "^[0-9]+" faces "${step_output}")  # "N faces ..."
  measured(hausdorff_rel "${cow}" "${out}/${example}.off" hausdorff)  # read back and measured
  if(faces GREATER 700 OR faces LESS 100 OR hausdorff GREATER 0.05)
    message(FATAL_ERROR "examples: ${example} left ${faces} faces of the cow's 5,804 at 10%, "
                        "${hausdorff} of the diagonal away")
  endif()
endforeach()

# The certified bound holds by the evaluator: 0.5% of the diagonal.
if("certified_bound" IN_LIST EXAMPLES)
  run_step("${WORK_DIR}/build/certified_bound" "${cow}" "${out}/bounded.off" 0.05 0.005)
  measured(hausdorff_rel "${cow}" "${out}/bounded.off" hausdorff)
  if(hausdorff GREATER 0.005)
    message(FATAL_ERROR "examples: certified_bound is at ${hausdorff} of the diagonal, above 0.005")
  endif()
endif()

# The textured OBJ keeps its texture coordinates, its seams and the orientation of every texture
# triangle.
if(NOT "textured_obj" IN_LIST EXAMPLES)
  return()
endif()
set(spot "${DATA_DIR}/spot.obj")
run_step("${WORK_DIR}/build/textured_obj" "${spot}" "${out}/spot.obj")
if(NOT step_output MATCHES "corner attributes carried")
  message(FATAL_ERROR "examples: textured_obj did not carry spot's texture coordinates")
endif()
measured(flipped_uv_faces "${spot}" "${out}/spot.obj" flipped)
measured(seam_loops_a "${spot}" "${out}/spot.obj" loops_in)
measured(seam_loops_b "${spot}" "${out}/spot.obj" loops_out)
if(NOT flipped EQUAL 0 OR NOT loops_in EQUAL loops_out)
  message(FATAL_ERROR
          "examples: textured_obj turned ${flipped} texture triangles over; seam loops ${loops_in} "
          "in, ${loops_out} out")
endif()
