# Runs PROGRAM with the list ARGS in WORK_DIR (default: the current folder) and fails unless
# it exits with EXPECT_CODE, its stdout and stderr together match the regular expression
# EXPECT_OUTPUT (when given), and every path of EXPECT_FILES (relative to WORK_DIR) exists
# after the run. Used by tests/simulator (cmake -DPROGRAM=... -P run_program_check.cmake).
if(NOT DEFINED WORK_DIR)
  set(WORK_DIR ".")
endif()
foreach(f IN LISTS EXPECT_FILES)
  file(REMOVE "${WORK_DIR}/${f}")
endforeach()
execute_process(COMMAND "${PROGRAM}" ${ARGS} WORKING_DIRECTORY "${WORK_DIR}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(APPEND out "${err}")
if(NOT code STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: exit code ${code}, expected ${EXPECT_CODE}; output:\n${out}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT out MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: the output does not match '${EXPECT_OUTPUT}':\n${out}")
endif()
foreach(f IN LISTS EXPECT_FILES)
  if(NOT EXISTS "${WORK_DIR}/${f}")
    message(FATAL_ERROR "${PROGRAM} ${ARGS}: wrote no ${f} (in ${WORK_DIR})")
  endif()
endforeach()
message(STATUS "${PROGRAM} ${ARGS}: exit code ${code} as expected")
