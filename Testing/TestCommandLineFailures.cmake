# Command-line failures that used to crash, hang or leave files behind:
# memory budgets, scenes without emitters on every method, failed writes.
# cmake -DPROGRAM=vtkradiosity -DDATA=Testing/Data -DWORK=dir -P TestCommandLineFailures.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")

# A hierarchical solve whose initial links (1,280 triangles inside a sphere:
# 1.64 million links, about 180 MB) do not fit a budget of 10 MB is refused
# before it allocates them, as bad input, with nothing written.
expect_exit(2 "${PROGRAM}" solve sphere --method hierarchical --max-memory 0.01
  --output "${WORK}/sphere.vtp" --report "${WORK}/sphere.json")
expect_one_error("error: bad input: hierarchical radiosity: the initial links between every facing pair of the 1280 input triangles \\(1.64 million links[^\n]*memory budget of 10 MB \\(--max-memory")
if (EXISTS "${WORK}/sphere.vtp" OR EXISTS "${WORK}/sphere.json")
  message(FATAL_ERROR "a refused solve wrote its output")
endif ()
# Meshless points from a radius of 1e-6 of the diagonal: refused by name.
expect_exit(2 "${PROGRAM}" solve cornell --method meshless --point-radius 1e-6 --max-memory 8
  --output "${WORK}/fine.vtp")
expect_one_error("error: bad input: meshless radiosity: up to [^\n]* points need about [^\n]*raise --point-radius")

# No emitter: every method returns the documented zero solution with its
# warning (meshless used to segfault here).
foreach (method progressive hierarchical meshless facecluster)
  expect_exit(0 "${PROGRAM}" solve "${DATA}/square.ply" --method ${method}
    --output "${WORK}/dark-${method}.vtp" --report "${WORK}/dark-${method}.json")
  if (NOT last_stderr MATCHES "warning: the scene has no emitter: the solution is zero")
    message(FATAL_ERROR "${method}: no 'no emitter' warning:\n${last_stderr}")
  endif ()
  file(READ "${WORK}/dark-${method}.json" report)
  string(JSON stop GET "${report}" solution stop)
  if (NOT stop STREQUAL "no emitters")
    message(FATAL_ERROR "${method}: stop '${stop}' for a scene without emitters")
  endif ()
  if (NOT EXISTS "${WORK}/dark-${method}.vtp")
    message(FATAL_ERROR "${method}: the zero solution was not written")
  endif ()
endforeach ()

# A write that fails (the output path is a directory) is an internal failure
# (exit 1) and leaves no temporary file behind.
file(MAKE_DIRECTORY "${WORK}/taken.vtp")
expect_exit(1 "${PROGRAM}" solve "${DATA}/square.ply" --output "${WORK}/taken.vtp")
expect_one_error("internal error: cannot write [^\n]*taken.vtp")
file(GLOB leftovers "${WORK}/*.partial*")
if (leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif ()
