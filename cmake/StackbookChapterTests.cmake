# stackbook_add_chapter(chNN SOURCES <test files> [EXERCISES <names>])
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
# STACKBOOK_EXERCISE_SOLUTIONS=ON links the solutions instead of the stubs, and
# STACKBOOK_EXERCISES=ON registers "chNN/exercises" (label: exercise) that runs them.
function(stackbook_add_chapter chapter)
  cmake_parse_arguments(ARG "" "" "SOURCES;EXERCISES" ${ARGN})
  set(target test_${chapter})
  add_executable(${target} ${ARG_SOURCES} $<TARGET_OBJECTS:stackbook_test_main>)
  if(ARG_EXERCISES)
    target_sources(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/exercises.cpp)
  endif()
  foreach(exercise IN LISTS ARG_EXERCISES)
    if(STACKBOOK_EXERCISE_SOLUTIONS)
      target_sources(${target} PRIVATE ${PROJECT_SOURCE_DIR}/chapters/solutions/${exercise}.cpp)
    else()
      target_sources(${target} PRIVATE ${PROJECT_SOURCE_DIR}/src/stackbook/exercises/${exercise}.cpp)
    endif()
  endforeach()
  target_link_libraries(${target} PRIVATE stackbook stackbook_options doctest::doctest)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${target} PRIVATE STACKBOOK_CHAPTER="${chapter}")
  doctest_discover_tests(${target} TEST_PREFIX "${chapter}/" ADD_LABELS 1)
  if(STACKBOOK_EXERCISES AND ARG_EXERCISES)
    add_test(NAME ${chapter}/exercises
             COMMAND ${target} --no-skip --test-suite=${chapter}_exercises)
    set_tests_properties(${chapter}/exercises PROPERTIES LABELS "exercise;${chapter}")
  endif()
endfunction()
