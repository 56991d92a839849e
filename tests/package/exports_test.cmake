# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# A shared build's libraries export brdfbake's own symbols only: every
# defined dynamic symbol, demangled, names the brdfbake namespace.
# Run as cmake -DNM=... -DLIBS="a.so;b.so" -P exports_test.cmake.

foreach(lib IN LISTS LIBS)
  execute_process(COMMAND ${NM} -D --defined-only -C ${lib} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} ${lib}: exit ${rc}")
  endif()
  string(REPLACE "\n" ";" lines "${out}")
  set(foreign "")
  set(own 0)
  foreach(line IN LISTS lines)
    if(line STREQUAL "")
      continue()
    endif()
    # "<address> <type> <name>"; the version node (type A) is not a symbol.
    string(REGEX REPLACE "^[0-9a-f]+ [A-Za-z] " "" name "${line}")
    if(line MATCHES "^[0-9a-f]+ A ")
      continue()
    endif()
    if(name MATCHES "brdfbake::")
      math(EXPR own "${own} + 1")
    else()
      string(APPEND foreign "  ${name}\n")
    endif()
  endforeach()
  if(NOT foreign STREQUAL "")
    message(FATAL_ERROR "${lib} exports symbols of other libraries:\n${foreign}")
  endif()
  if(own EQUAL 0)
    message(FATAL_ERROR "${lib} exports nothing of brdfbake")
  endif()
  message(STATUS "${lib}: ${own} brdfbake symbols, none foreign")
endforeach()
