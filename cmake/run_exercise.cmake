# One exercise's CTest entry (registered by cmake/StackbookChapterTests.cmake as "exNN.M"):
#
#   cmake -DEXERCISE=3.2 -DSTUB=src/.../ex03_2_cone_projection.cpp -DBINARY=test_ch03_exercises
#         -DSUITE=ch03_exercises -DSTATUS_DIR=<dir> -P run_exercise.cmake
#
# While the stub still has a "// TODO(reader)" comment the exercise is not solved yet: the
# entry prints one line that says what to implement and where (the stub's "Implement:"
# comment), and does not run the tests. Once the comments are gone it runs the exercise's
# test cases ("Exercise N.M: ...") and passes when they all pass. Either way it records
# solved or unsolved in STATUS_DIR for the count that exercises/solved prints.
cmake_minimum_required(VERSION 3.25)
foreach(var EXERCISE STUB BINARY SUITE STATUS_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_exercise.cmake needs -D${var}=...")
  endif()
endforeach()
file(MAKE_DIRECTORY "${STATUS_DIR}")
file(READ "${STUB}" stub)
file(RELATIVE_PATH stub_shown "${CMAKE_CURRENT_LIST_DIR}/.." "${STUB}")
if(stub MATCHES "//[ \t]*TODO\\(reader\\)")
  set(task "the exercise")
  if(stub MATCHES "// Implement: ([^.]*)\\.")
    set(task "${CMAKE_MATCH_1}")
  endif()
  file(WRITE "${STATUS_DIR}/${EXERCISE}" "unsolved")
  message(NOTICE "exercise ${EXERCISE} is not solved yet: implement ${task} in ${stub_shown}")
  return()
endif()
execute_process(COMMAND "${BINARY}" --no-skip "--test-suite=${SUITE}" "--test-case=Exercise ${EXERCISE}:*"
                RESULT_VARIABLE result)
if(result EQUAL 0)
  file(WRITE "${STATUS_DIR}/${EXERCISE}" "solved")
  message(NOTICE "exercise ${EXERCISE} is solved")
else()
  file(WRITE "${STATUS_DIR}/${EXERCISE}" "unsolved")
  message(NOTICE "exercise ${EXERCISE} fails its tests (see above): keep working in ${stub_shown}")
endif()
