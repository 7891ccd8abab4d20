# Without an X display (DISPLAY unset, as on a headless server) every output
# that needs a window is refused before the solve with one error line naming
# the option, DISPLAY and xvfb-run, exit 2, and nothing is written; a solve
# without images still runs. (VTK's X window aborts or crashes otherwise:
# exit 134 for --image, 139 for --history-plot and bench, measured.)
include(${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach (case "--image;${WORK}/c.png" "--exr;${WORK}/c.exr" "--history-plot;${WORK}/h.png")
  list(GET case 0 option)
  expect_exit(2 ${CMAKE_COMMAND} -E env --unset=DISPLAY ${PROGRAM} solve cornell ${case}
    --history ${WORK}/h.csv --tolerance 0.01)
  expect_one_error("${option}: cannot render: no X display could be opened.*xvfb-run")
endforeach ()
expect_exit(2 ${CMAKE_COMMAND} -E env --unset=DISPLAY ${PROGRAM} bench --quick --output-dir ${WORK}/bench)
expect_one_error("bench .*no X display could be opened")
file(GLOB written "${WORK}/*" "${WORK}/bench/*")
if (written)
  message(FATAL_ERROR "refused runs wrote files: ${written}")
endif ()
expect_exit(0 ${CMAKE_COMMAND} -E env --unset=DISPLAY ${PROGRAM} solve cornell --tolerance 0.01
  --output ${WORK}/c.vtp)
if (NOT EXISTS "${WORK}/c.vtp")
  message(FATAL_ERROR "a solve without images wrote no ${WORK}/c.vtp")
endif ()
