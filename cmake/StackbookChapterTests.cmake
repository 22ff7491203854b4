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
# STACKBOOK_EXERCISES=ON registers "chNN/exercises" (labels: exercise, chNN) that runs them.
# The target stackbook_exercises builds every chapter's exercise binary (and nothing else).
if(NOT TARGET stackbook_exercises)
  add_custom_target(stackbook_exercises)
endif()

function(stackbook_add_chapter chapter)
  cmake_parse_arguments(ARG "" "" "SOURCES;EXERCISES;LIBRARIES" ${ARGN})
  set(target test_${chapter})
  add_executable(${target} ${ARG_SOURCES} $<TARGET_OBJECTS:stackbook_test_main>)
  target_link_libraries(${target} PRIVATE stackbook ${ARG_LIBRARIES} stackbook_options doctest::doctest)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${target} PRIVATE STACKBOOK_CHAPTER="${chapter}")
  doctest_discover_tests(${target} TEST_PREFIX "${chapter}/" ADD_LABELS 1)

  if(ARG_EXERCISES)
    set(exercise_target test_${chapter}_exercises)
    add_executable(${exercise_target} ${CMAKE_CURRENT_SOURCE_DIR}/exercises.cpp
                   $<TARGET_OBJECTS:stackbook_test_main>)
    foreach(exercise IN LISTS ARG_EXERCISES)
      if(STACKBOOK_EXERCISE_SOLUTIONS)
        target_sources(${exercise_target} PRIVATE ${PROJECT_SOURCE_DIR}/chapters/solutions/${exercise}.cpp)
      else()
        target_sources(${exercise_target} PRIVATE ${PROJECT_SOURCE_DIR}/src/stackbook/exercises/${exercise}.cpp)
      endif()
    endforeach()
    target_link_libraries(${exercise_target} PRIVATE stackbook ${ARG_LIBRARIES} stackbook_options
                          doctest::doctest)
    target_include_directories(${exercise_target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
    target_compile_definitions(${exercise_target} PRIVATE STACKBOOK_CHAPTER="${chapter}")
    add_dependencies(stackbook_exercises ${exercise_target})
    add_dependencies(${target} ${exercise_target})
    if(STACKBOOK_EXERCISES)
      add_test(NAME ${chapter}/exercises
               COMMAND ${exercise_target} --no-skip --test-suite=${chapter}_exercises)
      set_tests_properties(${chapter}/exercises PROPERTIES LABELS "exercise;${chapter}")
    endif()
  endif()
endfunction()
