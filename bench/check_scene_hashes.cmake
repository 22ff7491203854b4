# Runs scene_hashes twice on a few steps of every bundled scene and fails unless the two
# outputs agree line for line: the same scene and settings give bit-identical states.
# With SETTING (key=value), the second run overrides that scene field (`--set`) and only the
# state hashes (the first three columns: name, steps, state bits) must agree: the evidence
# that a setting meant to change only the time, such as the candidate lists' reach, changes
# nothing else.
#   cmake -DPROGRAM=<scene_hashes> -DSTEPS=<n> -DOUT=<dir> [-DSETTING=<key=value>] -P check_scene_hashes.cmake
set(outputs "")
foreach(run 1 2)
  set(extra "")
  if(run EQUAL 2 AND DEFINED SETTING)
    set(extra --set "${SETTING}")
  endif()
  execute_process(COMMAND "${PROGRAM}" --steps "${STEPS}" --full-steps "${STEPS}" ${extra}
                  OUTPUT_VARIABLE text
                  ERROR_VARIABLE err
                  RESULT_VARIABLE rc)
  file(WRITE "${OUT}/scene_hashes${SUFFIX}_${run}.txt" "${text}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "scene_hashes run ${run} failed (${rc}):\n${text}\n${err}")
  endif()
  if(DEFINED SETTING)  # the state columns only
    string(REGEX REPLACE "([^ \n]+ [^ \n]+ [^ \n]+)[^\n]*" "\\1" text "${text}")
  endif()
  list(APPEND outputs "${text}")
endforeach()
list(GET outputs 0 first)
list(GET outputs 1 second)
if(DEFINED SETTING)
  set(what "the same state bits with ${SETTING}")
else()
  set(what "identical in both runs")
endif()
if(NOT first STREQUAL second)
  message(FATAL_ERROR "not ${what}:\n${first}\n---\n${second}")
endif()
string(REGEX MATCHALL "\n" lines "${first}")
list(LENGTH lines count)
if(count LESS 10)
  message(FATAL_ERROR "scene_hashes printed only ${count} lines:\n${first}")
endif()
message(STATUS "${count} scenes, ${what}:\n${first}")
