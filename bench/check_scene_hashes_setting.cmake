# Runs scene_hashes on a few steps of every bundled scene with each scene's own settings and
# again with `--set SETTING`, and fails unless every scene's state hash (the first three
# columns: name, steps, state bits) is the same in both: the evidence that a setting that
# should change only the time, such as the candidate lists' reach, changes nothing else.
#   cmake -DPROGRAM=<scene_hashes> -DSTEPS=<n> -DSETTING=<key=value> -DOUT=<dir> -P check_scene_hashes_setting.cmake
set(states "")
foreach(run plain set)
  set(extra "")
  if(run STREQUAL "set")
    set(extra --set "${SETTING}")
  endif()
  execute_process(COMMAND "${PROGRAM}" --steps "${STEPS}" --full-steps "${STEPS}" ${extra}
                  OUTPUT_VARIABLE text
                  ERROR_VARIABLE err
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "scene_hashes (${run}) failed (${rc}):\n${text}\n${err}")
  endif()
  # Keep the first three columns of each line.
  string(REGEX REPLACE "([^ \n]+ [^ \n]+ [^ \n]+)[^\n]*" "\\1" state "${text}")
  list(APPEND states "${state}")
endforeach()
list(GET states 0 plain)
list(GET states 1 changed)
if(NOT plain STREQUAL changed)
  message(FATAL_ERROR "${SETTING} changed some scene's state:\n${plain}\n---\n${changed}")
endif()
string(REGEX MATCHALL "\n" lines "${plain}")
list(LENGTH lines count)
if(count LESS 10)
  message(FATAL_ERROR "scene_hashes printed only ${count} lines:\n${plain}")
endif()
message(STATUS "${count} scenes, the same state bits with ${SETTING}:\n${plain}")
