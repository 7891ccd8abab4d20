# What the command-line test scripts share (include()d by them).
cmake_policy(VERSION 3.16) # cmake -P runs with the oldest policies otherwise

# Runs the command in ARGN and fails unless it exits with `code`; its
# standard error is left in `last_stderr` for the checks that follow.
function(expect_exit code)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc STREQUAL "${code}")
    message(FATAL_ERROR "expected exit ${code}, got ${rc}: ${ARGN}\n${out}\n${err}")
  endif ()
  set(last_stderr "${err}" PARENT_SCOPE)
endfunction()

# Fails unless `last_stderr` holds exactly one error line (SPEC: one line,
# "error: bad input: ..." or "internal error: ...") and matches `pattern`.
function(expect_one_error pattern)
  string(REPLACE ";" "," plain "${last_stderr}") # a list counts its ';' as separators
  string(REGEX MATCHALL "(^|\n)(error|internal error):[^\n]*" errors "${plain}")
  list(LENGTH errors n)
  if (NOT n EQUAL 1 OR NOT last_stderr MATCHES "${pattern}")
    message(FATAL_ERROR "expected one error line matching '${pattern}':\n${last_stderr}")
  endif ()
endfunction()

# CMake's math() is integer only: floating-point figures are computed and
# compared by awk (mawk, in every Debian system). `expr` is an awk
# expression (atan2, sqrt, exp, log; the names defined below included).
set(_cli_awk_functions "function abs(x) { return x < 0 ? -x : x }
function atan(x) { return atan2(x, 1) }")
function(float_eval out expr)
  execute_process(COMMAND awk "${_cli_awk_functions}
BEGIN { printf \"%.12g\", (${expr}) }"
    RESULT_VARIABLE rc OUTPUT_VARIABLE value ERROR_VARIABLE err)
  if (NOT rc EQUAL 0 OR NOT value MATCHES "^-?[0-9]")
    message(FATAL_ERROR "cannot evaluate '${expr}': ${value} ${err}")
  endif ()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

# Fails unless `value` is a finite number in [lo, hi] (a JSON null, "nan" or
# "inf" fail: if (x GREATER y) is false for them, so they would pass a plain
# CMake comparison). `what` names the figure in the message.
function(expect_within what value lo hi)
  if (NOT "${value}" MATCHES "^-?[0-9]+(\\.[0-9]*)?([eE][-+]?[0-9]+)?$")
    message(FATAL_ERROR "${what}: '${value}' is not a finite number (expected in [${lo}, ${hi}])")
  endif ()
  float_eval(inside "(${value}) >= (${lo}) && (${value}) <= (${hi})")
  if (NOT inside EQUAL 1)
    message(FATAL_ERROR "${what}: ${value} is outside [${lo}, ${hi}]")
  endif ()
endfunction()

# Reads a --probe-output CSV into `prefix`_COUNT and, per row i (from 0),
# `prefix`_<i> = "x;y;z;E_r;E_g;E_b".
function(read_probe_values file prefix)
  file(STRINGS "${file}" rows)
  list(POP_FRONT rows header)
  if (NOT header STREQUAL "x,y,z,E_r,E_g,E_b")
    message(FATAL_ERROR "${file}: header '${header}'")
  endif ()
  list(LENGTH rows n)
  set(${prefix}_COUNT ${n} PARENT_SCOPE)
  set(i 0)
  foreach (row IN LISTS rows)
    string(REPLACE "," ";" fields "${row}")
    set(${prefix}_${i} "${fields}" PARENT_SCOPE)
    math(EXPR i "${i} + 1")
  endforeach ()
endfunction()
