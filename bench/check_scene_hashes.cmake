# Runs scene_hashes twice on a few steps of every bundled scene and fails unless the two
# outputs agree line for line: the same scene and settings give bit-identical states.
#   cmake -DPROGRAM=<scene_hashes> -DSTEPS=<n> -DOUT=<dir> -P check_scene_hashes.cmake
foreach(run 1 2)
  execute_process(COMMAND "${PROGRAM}" --steps "${STEPS}" --full-steps "${STEPS}"
                  OUTPUT_FILE "${OUT}/scene_hashes_${run}.txt"
                  ERROR_FILE "${OUT}/scene_hashes_${run}.err"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    file(READ "${OUT}/scene_hashes_${run}.txt" text)
    message(FATAL_ERROR "scene_hashes run ${run} failed (${rc}):\n${text}")
  endif()
endforeach()
file(READ "${OUT}/scene_hashes_1.txt" first)
file(READ "${OUT}/scene_hashes_2.txt" second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "two runs of the same scenes differ:\n${first}\n---\n${second}")
endif()
string(REGEX MATCHALL "\n" lines "${first}")
list(LENGTH lines count)
if(count LESS 10)
  message(FATAL_ERROR "scene_hashes printed only ${count} lines:\n${first}")
endif()
message(STATUS "${count} scenes, identical in both runs:\n${first}")
