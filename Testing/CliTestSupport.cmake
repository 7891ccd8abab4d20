# What the command-line test scripts share (include()d by them).

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
