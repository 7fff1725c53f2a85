# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors

# libq3.so neither imports nor exports an OpenGL, EGL or OSMesa symbol: its
# backends open their libraries with dlopen and resolve every GL entry point
# through their own loader (src/render/GlApi.h says why). Likewise Xlib,
# which src/render/X11Window.cpp opens for the X11 draw context. Run as
# cmake -DQ3_NM=nm -DQ3_LIBRARY=libq3.so -P CheckGlImports.cmake; fails
# (exit status 1) listing every such symbol, defined or undefined.

execute_process(COMMAND "${Q3_NM}" -D "${Q3_LIBRARY}"
  RESULT_VARIABLE status OUTPUT_VARIABLE nm_output ERROR_VARIABLE nm_error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${Q3_NM} -D ${Q3_LIBRARY} failed (${status}): ${nm_error}")
endif()
set(found)
set(count 0)
string(REPLACE "\n" ";" lines "${nm_output}")
foreach(line IN LISTS lines)
  # "[address] type name[@version]": the name is the last field.
  if(line MATCHES "([^ \t]+)[ \t]*$")
    math(EXPR count "${count} + 1")
    string(REGEX REPLACE "@.*$" "" name "${CMAKE_MATCH_1}")
    if(name MATCHES "^(gl[A-Z_]|egl[A-Z]|OSMesa|glX|_glapi|X[A-Z][a-z])")
      list(APPEND found "${line}")
    endif()
  endif()
endforeach()
if(count LESS 100)
  message(FATAL_ERROR "${Q3_NM} -D listed only ${count} symbols of ${Q3_LIBRARY}: the pattern no longer matches")
endif()
if(found)
  list(LENGTH found n)
  string(REPLACE ";" "\n  " names "${found}")
  message(FATAL_ERROR "${Q3_LIBRARY} binds ${n} GL/EGL/OSMesa/Xlib symbol(s) by name (call them through "
    "src/render/GlApi.h, adding the function to Q3_GL_FUNCTIONS):\n  ${names}")
endif()

# Nor does it need the libraries themselves: a system without one of them
# must still load libq3.so.
execute_process(COMMAND "${Q3_READELF}" -d "${Q3_LIBRARY}"
  RESULT_VARIABLE status OUTPUT_VARIABLE readelf_output ERROR_VARIABLE readelf_error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${Q3_READELF} -d ${Q3_LIBRARY} failed (${status}): ${readelf_error}")
endif()
string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[(lib(GL|EGL|OSMesa|glapi|GLX|OpenGL|X11)[^]]*)\\]" needed "${readelf_output}")
if(needed)
  string(REPLACE ";" "\n  " names "${needed}")
  message(FATAL_ERROR "${Q3_LIBRARY} links a GL library at load time:\n  ${names}")
endif()
message(STATUS "${Q3_LIBRARY}: no GL, EGL or OSMesa symbol among its ${count} dynamic symbols, no GL library needed")
