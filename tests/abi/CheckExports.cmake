# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors

# Compares the dynamic symbols libq3.so defines with the functions
# include/Q3 declares, both ways: every Q3_EXTERN_API_C function is exported,
# and nothing else is, apart from the symbols the linker itself may add. Run
# as cmake -DQ3_NM=nm -DQ3_LIBRARY=libq3.so -DQ3_HEADERS=include/Q3 -P
# CheckExports.cmake; fails (exit status 1) listing every difference.

# Older linkers define these in every shared object's dynamic table.
set(toolchain_symbols _init _fini _edata _end __bss_start)

execute_process(COMMAND "${Q3_NM}" -D --defined-only "${Q3_LIBRARY}"
  RESULT_VARIABLE status OUTPUT_VARIABLE nm_output ERROR_VARIABLE nm_error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${Q3_NM} -D --defined-only ${Q3_LIBRARY} failed (${status}): ${nm_error}")
endif()
set(exported)
string(REPLACE "\n" ";" lines "${nm_output}")
foreach(line IN LISTS lines)
  # "address type name": the name is the last field.
  if(line MATCHES "([^ \t]+)[ \t]*$")
    list(APPEND exported "${CMAKE_MATCH_1}")
  endif()
endforeach()
list(REMOVE_DUPLICATES exported)

# Every public function is declared as Q3_EXTERN_API_C(type) Name(...).
set(declared)
file(GLOB headers "${Q3_HEADERS}/*.h")
foreach(header IN LISTS headers)
  file(READ "${header}" text)
  string(REGEX MATCHALL "Q3_EXTERN_API_C\\([^)]*\\)[ \t\r\n*]*[A-Za-z_][A-Za-z0-9_]*[ \t\r\n]*\\("
    declarations "${text}")
  foreach(declaration IN LISTS declarations)
    string(REGEX MATCH "([A-Za-z_][A-Za-z0-9_]*)[ \t\r\n]*\\($" name "${declaration}")
    list(APPEND declared "${CMAKE_MATCH_1}")
  endforeach()
endforeach()
list(REMOVE_DUPLICATES declared)
list(LENGTH declared declared_count)
if(declared_count LESS 500)
  message(FATAL_ERROR "found only ${declared_count} declarations in ${Q3_HEADERS}: the header pattern no longer matches")
endif()

set(missing ${declared})
list(REMOVE_ITEM missing ${exported})
set(extra ${exported})
list(REMOVE_ITEM extra ${declared} ${toolchain_symbols})

# Appends to `report` the names `names` holds, sorted and counted, as `what`.
function(report_names names what)
  if(${names})
    set(sorted ${${names}})
    list(SORT sorted)
    list(LENGTH sorted count)
    string(REPLACE ";" "\n  " lines "${sorted}")
    set(report "${report}${count} ${what}:\n  ${lines}\n" PARENT_SCOPE)
  endif()
endfunction()

set(report)
report_names(missing "function(s) declared in include/Q3 but not exported")
report_names(extra "symbol(s) exported but not declared in include/Q3")
if(report)
  message(FATAL_ERROR "${Q3_LIBRARY}:\n${report}")
endif()
list(LENGTH exported exported_count)
message(STATUS "${Q3_LIBRARY} exports exactly the ${declared_count} functions include/Q3 declares (${exported_count} dynamic symbols)")
