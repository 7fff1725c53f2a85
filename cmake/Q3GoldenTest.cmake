# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors

# q3_add_golden_test: a CTest test that runs a program drawing a PNG file and
# compares the file with a golden image through q3compare. Included by
# Q3Config.cmake, so find_package(Q3) provides it; docs/golden-testing.md
# and the README's "Golden testing in your project" explain its use.
#
#   q3_add_golden_test(NAME <test name>
#                      COMMAND <program> [<argument>...]
#                      OUTPUT <png the program writes>
#                      GOLDEN <golden png>
#                      [TOLERANCE <n>] [MAX_PIXELS <m>]
#                      [WORKING_DIRECTORY <dir>])
#
# COMMAND's first word may be an executable target of the project (its file
# is used). A relative OUTPUT is taken from the current binary directory, a
# relative GOLDEN from the current source directory. TOLERANCE and MAX_PIXELS
# are q3compare's --tolerance and --max-pixels (both 0 by default: one changed
# bit fails). The test is labelled q3-golden (ctest -L q3-golden).
#
# The test removes OUTPUT, runs the program (which must succeed and write
# OUTPUT), then compares. On a mismatch it fails and keeps OUTPUT and
# OUTPUT's name with .diff.png in place of .png (the golden dimmed, the
# differing pixels in red), naming both. With Q3_UPDATE_GOLDENS=1 in the
# environment it copies OUTPUT over GOLDEN instead when they differ (or the
# golden is missing) and passes, saying so.

set(_Q3_GOLDEN_TEST_DRIVER "${CMAKE_CURRENT_LIST_DIR}/Q3GoldenTestDriver.cmake")

function(q3_add_golden_test)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;OUTPUT;GOLDEN;TOLERANCE;MAX_PIXELS;WORKING_DIRECTORY" "COMMAND")
  foreach(required NAME COMMAND OUTPUT GOLDEN)
    if(NOT arg_${required})
      message(FATAL_ERROR "q3_add_golden_test: ${required} is required")
    endif()
  endforeach()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "q3_add_golden_test(${arg_NAME}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET Q3::q3compare)
    message(FATAL_ERROR "q3_add_golden_test: this Q3 was installed without its tools (q3compare)")
  endif()
  foreach(limit TOLERANCE MAX_PIXELS)
    if(NOT DEFINED arg_${limit})
      set(arg_${limit} 0)
    elseif(NOT arg_${limit} MATCHES "^[0-9]+$")
      message(FATAL_ERROR "q3_add_golden_test(${arg_NAME}): ${limit} must be a whole number, not '${arg_${limit}}'")
    endif()
  endforeach()
  if(arg_TOLERANCE GREATER 255)
    message(FATAL_ERROR "q3_add_golden_test(${arg_NAME}): TOLERANCE is at most 255")
  endif()
  get_filename_component(output "${arg_OUTPUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  get_filename_component(golden "${arg_GOLDEN}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT arg_WORKING_DIRECTORY)
    set(arg_WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  endif()

  # Each word of the command is its own -D definition, so that no character
  # of an argument (a semicolon included) needs escaping.
  set(words)
  set(index 0)
  foreach(word IN LISTS arg_COMMAND)
    if(index EQUAL 0 AND TARGET "${word}")
      set(word "$<TARGET_FILE:${word}>")
    endif()
    list(APPEND words "-DQ3_GOLDEN_ARG${index}=${word}")
    math(EXPR index "${index} + 1")
  endforeach()

  add_test(NAME "${arg_NAME}"
    COMMAND "${CMAKE_COMMAND}"
      "-DQ3_GOLDEN_NAME=${arg_NAME}"
      "-DQ3_GOLDEN_ARGC=${index}" ${words}
      "-DQ3_GOLDEN_OUTPUT=${output}"
      "-DQ3_GOLDEN_GOLDEN=${golden}"
      "-DQ3_GOLDEN_TOLERANCE=${arg_TOLERANCE}"
      "-DQ3_GOLDEN_MAX_PIXELS=${arg_MAX_PIXELS}"
      "-DQ3_GOLDEN_COMPARE=$<TARGET_FILE:Q3::q3compare>"
      -P "${_Q3_GOLDEN_TEST_DRIVER}"
    WORKING_DIRECTORY "${arg_WORKING_DIRECTORY}")
  set_property(TEST "${arg_NAME}" APPEND PROPERTY LABELS q3-golden)
endfunction()
