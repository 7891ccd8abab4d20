# --method progressive-gpu (Rendering/GPU): under a display the Cornell box
# is solved on the GPU (llvmpipe in CI), the report names the method and the
# hemicube resolution, the output and the probes are written; without a
# display the solve is refused with one error line naming DISPLAY and
# xvfb-run, exit 2, and nothing is written.
include(${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
expect_exit(0 ${PROGRAM} solve cornell --method progressive-gpu --tolerance 0.01 --hemicube-resolution 128
  --output ${WORK}/c.vtp --report ${WORK}/r.json)
file(READ "${WORK}/r.json" report)
string(JSON method GET "${report}" method)
string(JSON resolution GET "${report}" parameters hemicube_resolution)
if (NOT method STREQUAL "progressive-gpu" OR NOT resolution EQUAL 128)
  message(FATAL_ERROR "report: method '${method}', hemicube_resolution '${resolution}'")
endif ()
if (NOT EXISTS "${WORK}/c.vtp")
  message(FATAL_ERROR "no ${WORK}/c.vtp")
endif ()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
expect_exit(2 ${CMAKE_COMMAND} -E env --unset=DISPLAY ${PROGRAM} solve cornell --method progressive-gpu
  --tolerance 0.01 --output ${WORK}/c.vtp --report ${WORK}/r.json)
expect_one_error("progressive-gpu needs an OpenGL context.*DISPLAY.*xvfb-run")
file(GLOB written "${WORK}/*")
if (written)
  message(FATAL_ERROR "the refused run wrote files: ${written}")
endif ()
expect_exit(2 ${PROGRAM} solve cornell --method progressive-gpu --hemicube-resolution 8)
if (NOT last_stderr MATCHES "--hemicube-resolution: Value 8 not in range 16 to 4096")
  message(FATAL_ERROR "--hemicube-resolution 8: ${last_stderr}")
endif ()
