# The ctest fuzz.scene-loading (Testing/CMakeLists.txt): replays every file in
# regressions/ and corpus/ once, then fuzzes for SECONDS from a working copy of
# the corpus in WORK (the committed corpus is never written). Any finding (a
# crash, a sanitizer report, an allocation over 2048 MB, a run over 10 s) fails
# the test; its input is left in WORK/artifacts/.
#
#   cmake -DFUZZER=.../FuzzSceneLoading -DFUZZ_DIR=Testing/Fuzz -DWORK=dir
#         [-DSECONDS=60] -P RunFuzz.cmake
foreach (var FUZZER FUZZ_DIR WORK)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "RunFuzz.cmake: -D${var}=... is required")
  endif ()
endforeach ()
if (NOT DEFINED SECONDS)
  set(SECONDS 60)
endif ()
if (NOT EXISTS "${FUZZER}")
  message(FATAL_ERROR "the fuzzer ${FUZZER} was not built")
endif ()

set(limits -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=10)
file(MAKE_DIRECTORY "${WORK}/artifacts")
set(ENV{TMPDIR} "${WORK}")

# 1. Every committed input once: libFuzzer runs the files given as arguments
# once each ("Running: FILE") and stops at the first finding.
file(GLOB regressions LIST_DIRECTORIES false "${FUZZ_DIR}/regressions/*")
list(FILTER regressions EXCLUDE REGEX "/README[^/]*$")
file(GLOB seeds LIST_DIRECTORIES false "${FUZZ_DIR}/corpus/*")
list(LENGTH regressions n_regressions)
list(LENGTH seeds n_seeds)
message(STATUS "replaying ${n_regressions} regressions and ${n_seeds} seeds")
execute_process(COMMAND "${FUZZER}" ${limits} ${regressions} ${seeds}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if (NOT rc EQUAL 0)
  string(REGEX MATCHALL "Running: [^\n]*" running "${out}")
  list(POP_BACK running last)
  string(REPLACE "Running: " "" last "${last}")
  message("${out}")
  message(FATAL_ERROR "FINDING: ${last} fails (exit ${rc}); stack above")
endif ()

# 2. Fuzz for SECONDS from a working corpus (seeds added to what earlier runs kept).
file(MAKE_DIRECTORY "${WORK}/corpus")
file(COPY ${seeds} DESTINATION "${WORK}/corpus")
message(STATUS "fuzzing for ${SECONDS} s")
# A fixed seed by default, so that CI explores the same inputs each run (a
# finding there is reproducible, not luck); -DSEED=0 draws one.
if (NOT DEFINED SEED)
  set(SEED 1)
endif ()
execute_process(COMMAND "${FUZZER}" ${limits}
    -max_total_time=${SECONDS} -print_final_stats=1 -seed=${SEED}
    -dict=${FUZZ_DIR}/scene.dict
    -artifact_prefix=${WORK}/artifacts/
    "${WORK}/corpus"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" runs "${out}")
string(REGEX MATCH "#[0-9]+[^\n]*DONE[^\n]*" done "${out}")
if (NOT rc EQUAL 0)
  string(LENGTH "${out}" len)
  if (len GREATER 20000)
    math(EXPR start "${len} - 20000")
    string(SUBSTRING "${out}" ${start} -1 out)
  endif ()
  message("${out}")
  message(FATAL_ERROR "FINDING: fuzzing failed (exit ${rc}); the input is in ${WORK}/artifacts/ "
    "(minimise it with ${FUZZER} -minimize_crash=1 -runs=10000 FILE, then add it to "
    "${FUZZ_DIR}/regressions/, README.md)")
endif ()
message(STATUS "no finding: ${done} ${runs}")
