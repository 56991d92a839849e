# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# What the command-line scripts share: run the tool at ${BRDFBAKE} and
# assert its exit status and output.

# Runs the tool with ARGN; fails unless it exits 0 (expect_ok) or
# non-zero (not expect_ok); its stdout and stderr into out_var, err_var.
function(run_tool expect_ok out_var err_var)
  execute_process(COMMAND ${BRDFBAKE} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect_ok AND NOT rc EQUAL 0)
    message(FATAL_ERROR "brdfbake ${ARGN}: exit ${rc}, stderr: ${err}")
  endif()
  if(NOT expect_ok AND rc EQUAL 0)
    message(FATAL_ERROR "brdfbake ${ARGN}: expected a non-zero exit, got 0")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()

# A failure with one line on stderr and nothing on stdout; the line into
# err_var.
function(one_line_error err_var)
  run_tool(FALSE out err ${ARGN})
  string(STRIP "${err}" err)
  string(FIND "${err}" "\n" nl)
  if(NOT nl EQUAL -1 OR err STREQUAL "")
    message(FATAL_ERROR "brdfbake ${ARGN}: expected a one-line error, got: '${err}'")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "brdfbake ${ARGN}: expected no output on error, got: '${out}'")
  endif()
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()

function(expect_one_line_error)
  one_line_error(err ${ARGN})
endfunction()

# A one-line error whose text matches `pattern`.
function(expect_error_matching pattern)
  one_line_error(err ${ARGN})
  if(NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "brdfbake ${ARGN}: expected an error matching '${pattern}', got: '${err}'")
  endif()
endfunction()
