# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors

# The test q3_add_golden_test adds (Q3GoldenTest.cmake), run as
# cmake -DQ3_GOLDEN_...=... -P Q3GoldenTestDriver.cmake. Fails (exit status
# 1) with a message saying why; passes silently on a match, and with a
# message when Q3_UPDATE_GOLDENS=1 rewrote the golden.

set(name "${Q3_GOLDEN_NAME}")
set(output "${Q3_GOLDEN_OUTPUT}")
set(golden "${Q3_GOLDEN_GOLDEN}")
string(REGEX REPLACE "\\.[pP][nN][gG]$" "" stem "${output}")
set(diff "${stem}.diff.png")
set(update FALSE)
if("$ENV{Q3_UPDATE_GOLDENS}" STREQUAL "1")
  set(update TRUE)
endif()

# A picture left by an earlier run must not pass for this run's.
file(REMOVE "${output}" "${diff}")

set(command)
math(EXPR last "${Q3_GOLDEN_ARGC} - 1")
foreach(index RANGE ${last})
  list(APPEND command "${Q3_GOLDEN_ARG${index}}")
endforeach()
execute_process(COMMAND ${command} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${name}: the program failed (${status}): ${command}")
endif()
if(NOT EXISTS "${output}")
  message(FATAL_ERROR "${name}: the program did not write ${output}")
endif()

if(NOT EXISTS "${golden}")
  if(update)
    get_filename_component(folder "${golden}" DIRECTORY)
    file(MAKE_DIRECTORY "${folder}")
    file(COPY "${output}" DESTINATION "${folder}")
    get_filename_component(written "${output}" NAME)
    file(RENAME "${folder}/${written}" "${golden}")
    message("${name}: Q3_UPDATE_GOLDENS=1: created the golden ${golden} from ${output}")
    return()
  endif()
  message(FATAL_ERROR "${name}: the golden ${golden} is missing (the picture drawn is ${output}); "
                      "run the test with Q3_UPDATE_GOLDENS=1 to create it")
endif()

execute_process(
  COMMAND "${Q3_GOLDEN_COMPARE}" "${output}" "${golden}" --tolerance "${Q3_GOLDEN_TOLERANCE}"
          --max-pixels "${Q3_GOLDEN_MAX_PIXELS}" --diff "${diff}"
  RESULT_VARIABLE status OUTPUT_VARIABLE summary ERROR_VARIABLE errors
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_STRIP_TRAILING_WHITESPACE)
if(status EQUAL 0)
  file(REMOVE "${diff}")
  return()
endif()
if(update AND status EQUAL 1)
  # execute_process rather than file(COPY_FILE), which needs CMake 3.21.
  execute_process(COMMAND "${CMAKE_COMMAND}" -E copy "${output}" "${golden}" RESULT_VARIABLE copied)
  if(NOT copied EQUAL 0)
    message(FATAL_ERROR "${name}: Q3_UPDATE_GOLDENS=1: cannot copy ${output} over ${golden}")
  endif()
  file(REMOVE "${diff}")
  message("${name}: Q3_UPDATE_GOLDENS=1: re-blessed: copied ${output} over ${golden} (${summary})")
  return()
endif()
if(status EQUAL 1)
  message(FATAL_ERROR "${name}: the picture does not match its golden.\n"
                      "  ${summary}\n"
                      "  actual: ${output}\n"
                      "  diff:   ${diff}\n"
                      "  golden: ${golden}\n"
                      "If the change is meant, re-bless with Q3_UPDATE_GOLDENS=1 and commit the golden.")
endif()
message(FATAL_ERROR "${name}: q3compare could not compare ${output} with ${golden} (${status}): ${errors}")
