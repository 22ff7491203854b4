# stackbook_add_chapter(chNN SOURCES <test files> [EXERCISES <names>] [LIBRARIES <targets>])
# called from tests/chNN/CMakeLists.txt; SOURCES are relative to that folder.
#
# Builds test_chNN from the chapter's test files and registers every test case with
# CTest under the prefix "chNN/" and the label of its doctest suite.
#
# Each exercise name exNN_M_topic has three files:
#   src/stackbook/exercises/exNN_M_topic.hpp   the API the exercise asks for
#   src/stackbook/exercises/exNN_M_topic.cpp   a stub that compiles (the reader's starting point)
#   chapters/solutions/exNN_M_topic.cpp        the reference solution
# and their tests live in tests/chNN/exercises.cpp (suite chNN_exercises, skipped by default).
# They build into their own binary, test_chNN_exercises, always (so the stubs are known to
# compile); STACKBOOK_EXERCISE_SOLUTIONS=ON links the solutions instead of the stubs, and
# STACKBOOK_EXERCISES=ON registers one entry per exercise, "exNN.M" (labels: exercise, chNN),
# which says in one line that the exercise is not solved yet while its stub keeps a
# "// TODO(reader)" comment and runs its test cases after (cmake/run_exercise.cmake), and
# "exercises/solved", which runs last and prints "N of M exercises solved" (M: every exercise).
# The target stackbook_exercises builds every chapter's exercise binary (and nothing else).
# STACKBOOK_SOLUTIONS=ON (the main preset) also builds test_chNN_solutions from the same
# compiled exercises.cpp with the solutions linked, registered as "chNN/solutions" (labels
# solutions, chNN); the target stackbook_solutions builds them all. CI's solutions check
# then reuses the main build instead of compiling the library a second time.
# STACKBOOK_EXERCISE_BINARIES=OFF (the sanitize preset) builds no exercise binary at all:
# the main build has already shown that the stubs and the solutions compile.
if(NOT TARGET stackbook_exercises)
  add_custom_target(stackbook_exercises)
  add_custom_target(stackbook_solutions)
endif()

function(stackbook_add_chapter chapter)
  cmake_parse_arguments(ARG "" "" "SOURCES;EXERCISES;LIBRARIES" ${ARGN})
  set(target test_${chapter})
  add_executable(${target} ${ARG_SOURCES} $<TARGET_OBJECTS:stackbook_test_main>)
  target_link_libraries(${target} PRIVATE stackbook ${ARG_LIBRARIES} stackbook_options doctest::doctest)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${target} PRIVATE STACKBOOK_CHAPTER="${chapter}")
  doctest_discover_tests(${target} TEST_PREFIX "${chapter}/" ADD_LABELS 1)
  # doctest.cmake asks each case for its suite with the name unescaped, and doctest reads a
  # comma in --test-case as "or": a case whose name holds a comma got no suite, so no label,
  # and `ctest -L chNN` (or the presets' "slow" filter) passed it over. This second script,
  # run after doctest's, asks again with the commas escaped and sets the labels.
  set(relabel_script "${CMAKE_CURRENT_BINARY_DIR}/${target}_comma_labels.cmake")
  file(GENERATE OUTPUT "${relabel_script}" CONTENT "
foreach(name IN LISTS ${target}_TESTS)
  if(NOT name MATCHES \",\")
    continue()
  endif()
  string(REGEX REPLACE \"^${chapter}/\" \"\" case \"\${name}\")
  string(REPLACE \",\" \"\\\\,\" filter \"\${case}\")
  execute_process(COMMAND \"$<TARGET_FILE:${target}>\" \"--test-case=\${filter}\" --list-test-suites
                  OUTPUT_VARIABLE listing RESULT_VARIABLE status)
  set(labels \"\")
  string(REPLACE \"\\n\" \";\" listing \"\${listing}\")
  foreach(line IN LISTS listing)
    if(line STREQUAL \"\" OR line MATCHES \"^===\" OR line MATCHES \"^\\\\[doctest\\\\] \")
      continue()
    endif()
    list(APPEND labels \"\${line}\")
  endforeach()
  if(status EQUAL 0 AND labels)
    set_tests_properties(\"\${name}\" PROPERTIES LABELS \"\${labels}\")
  endif()
endforeach()
")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${relabel_script}")

  if(ARG_EXERCISES AND STACKBOOK_EXERCISE_BINARIES)
    # exercises.cpp is compiled once and linked twice: with the stubs and the solutions.
    set(exercise_objects ${chapter}_exercise_tests)
    add_library(${exercise_objects} OBJECT ${CMAKE_CURRENT_SOURCE_DIR}/exercises.cpp)
    target_link_libraries(${exercise_objects} PRIVATE stackbook ${ARG_LIBRARIES} stackbook_options
                          doctest::doctest)
    target_include_directories(${exercise_objects} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
    target_compile_definitions(${exercise_objects} PRIVATE STACKBOOK_CHAPTER="${chapter}")
    set(stub_sources "")
    set(solution_sources "")
    foreach(exercise IN LISTS ARG_EXERCISES)
      list(APPEND stub_sources ${PROJECT_SOURCE_DIR}/src/stackbook/exercises/${exercise}.cpp)
      list(APPEND solution_sources ${PROJECT_SOURCE_DIR}/chapters/solutions/${exercise}.cpp)
    endforeach()

    set(exercise_target test_${chapter}_exercises)
    if(STACKBOOK_EXERCISE_SOLUTIONS)
      set(linked_sources ${solution_sources})
    else()
      set(linked_sources ${stub_sources})
    endif()
    add_executable(${exercise_target} ${linked_sources} $<TARGET_OBJECTS:${exercise_objects}>
                   $<TARGET_OBJECTS:stackbook_test_main>)
    target_link_libraries(${exercise_target} PRIVATE stackbook ${ARG_LIBRARIES} stackbook_options
                          doctest::doctest)
    target_include_directories(${exercise_target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
    target_compile_definitions(${exercise_target} PRIVATE STACKBOOK_CHAPTER="${chapter}")
    add_dependencies(stackbook_exercises ${exercise_target})
    add_dependencies(${target} ${exercise_target})
    if(STACKBOOK_EXERCISES)
      # One entry per exercise, "exNN.M" (ctest --preset exercises -R ex03.2), run through
      # cmake/run_exercise.cmake: one line while the stub is unsolved, its tests after.
      foreach(exercise IN LISTS ARG_EXERCISES)
        string(REGEX MATCH "^ex([0-9][0-9])_([0-9]+)_" _ "${exercise}")
        math(EXPR chapter_number "${CMAKE_MATCH_1}")
        set(number "${chapter_number}.${CMAKE_MATCH_2}")
        set(test_name "ex${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")
        add_test(NAME ${test_name}
                 COMMAND ${CMAKE_COMMAND} -DEXERCISE=${number}
                         -DSTUB=${PROJECT_SOURCE_DIR}/src/stackbook/exercises/${exercise}.cpp
                         -DBINARY=$<TARGET_FILE:${exercise_target}> -DSUITE=${chapter}_exercises
                         -DSTATUS_DIR=${PROJECT_BINARY_DIR}/exercise_status
                         -P ${PROJECT_SOURCE_DIR}/cmake/run_exercise.cmake)
        set_tests_properties(${test_name} PROPERTIES LABELS "exercise;${chapter}"
                             FAIL_REGULAR_EXPRESSION "is not solved yet|fails its tests")
        set_property(GLOBAL APPEND PROPERTY STACKBOOK_EXERCISE_TESTS ${test_name})
        set_property(GLOBAL APPEND PROPERTY STACKBOOK_EXERCISE_NUMBERS ${number})
      endforeach()
    endif()

    if(STACKBOOK_SOLUTIONS)
      set(solution_target test_${chapter}_solutions)
      add_executable(${solution_target} ${solution_sources} $<TARGET_OBJECTS:${exercise_objects}>
                     $<TARGET_OBJECTS:stackbook_test_main>)
      target_link_libraries(${solution_target} PRIVATE stackbook ${ARG_LIBRARIES} stackbook_options
                            doctest::doctest)
      target_include_directories(${solution_target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
      target_compile_definitions(${solution_target} PRIVATE STACKBOOK_CHAPTER="${chapter}")
      add_dependencies(stackbook_solutions ${solution_target})
      add_test(NAME ${chapter}/solutions
               COMMAND ${solution_target} --no-skip --test-suite=${chapter}_exercises)
      set_tests_properties(${chapter}/solutions PROPERTIES LABELS "solutions;${chapter}")
    endif()
  endif()
endfunction()
