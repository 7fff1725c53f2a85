# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Run by ctest (a TEST_INCLUDE_FILES script, see q3_gtest in
# tests/CMakeLists.txt): lists the tests of one GoogleTest program and adds one
# ctest test per test suite, which runs the suite's tests in one process.
# Inputs: Q3_SUITE_EXE, Q3_SUITE_DIR (working directory), Q3_SUITE_PREFIX,
# Q3_SUITE_PROPERTIES (a list of property/value pairs).
#
# Used by the sanitizer stage of scripts/test.sh: there a process costs about
# half a second before its first test (the sanitizer runtimes start, and leak
# checking runs at exit), so one process per suite instead of one per test
# saves most of that stage's time. Each test still reports on its own in the
# suite's output, and a failure names the suite to run again.
if(NOT EXISTS "${Q3_SUITE_EXE}")
  add_test("${Q3_SUITE_PREFIX}NOT_BUILT" "${Q3_SUITE_EXE}")
  return()
endif()
execute_process(COMMAND "${Q3_SUITE_EXE}" --gtest_list_tests
                WORKING_DIRECTORY "${Q3_SUITE_DIR}"
                OUTPUT_VARIABLE listing ERROR_VARIABLE listing_errors
                RESULT_VARIABLE listing_result TIMEOUT 120)
if(NOT listing_result EQUAL 0)
  message(FATAL_ERROR "${Q3_SUITE_EXE} --gtest_list_tests failed (${listing_result}):\n${listing}${listing_errors}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  # A suite's line starts in the first column and ends with '.' (a typed or
  # parameterized suite adds a "  # TypeParam = ..." comment); its tests'
  # lines are indented.
  if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    set(suite "${CMAKE_MATCH_1}")
    set(name "${Q3_SUITE_PREFIX}${suite}")
    add_test("${name}" "${Q3_SUITE_EXE}" "--gtest_filter=${suite}.*")
    set_tests_properties("${name}" PROPERTIES WORKING_DIRECTORY "${Q3_SUITE_DIR}" ${Q3_SUITE_PROPERTIES})
  endif()
endforeach()
