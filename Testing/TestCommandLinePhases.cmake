# The report's time section (SPEC: time per phase): every phase of a run is
# named and timed, the phases listed in time.phases add up to time.total_s,
# each part of a phase (time.part_of) lies within its phase, and the output
# is evaluated only when asked for. Every method on the Cornell box.
# cmake -DPROGRAM=vtkradiosity -DWORK=dir -P TestCommandLinePhases.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")

# Bounds, each beside what it measured (2-core AMD EPYC, shared, load 3-6).
# total_s less the phases' sum, relative to total_s: measured at most 2.6e-5
# (the report's own bookkeeping after the last phase ended).
set(UNACCOUNTED_BOUND 1e-3)
# pipeline_s (the VTK pipeline's own work around the filter's phases),
# relative to total_s: measured at most 2.4e-3 (face cluster, a 0.19 s run).
set(PIPELINE_BOUND 0.01)
# Meshless with --output: output_evaluation_s / solve_s, measured 0.065
# (0.158 s of a 2.45 s solve), 0.016 when the solve took 9.7 s (a loaded
# machine): its support searches got faster (one k-d tree per group and
# radius class, MeshlessPoints.cxx), the evaluation's 0.16 s stayed (0.068
# before the output's tiled evaluation, ShepardField::EvaluateTile).
set(MESHLESS_OUTPUT_BOUND 0.15)
# Meshless with --report alone: nothing to evaluate, measured 3.6e-4 s
# (0.31 s before) of a 9.7 s solve.
set(REPORT_ONLY_OUTPUT_BOUND 0.01)

# The phases of `report` (a file): named, finite, adding up; the parts
# within their phases. `expected`: the phases that must be there.
function(check_phases report expected)
  file(READ "${report}" json)
  string(JSON total GET "${json}" time total_s)
  string(JSON unaccounted GET "${json}" time unaccounted_s)
  string(JSON count LENGTH "${json}" time phases)
  set(sum 0)
  set(names "")
  math(EXPR last "${count} - 1")
  foreach (i RANGE ${last})
    string(JSON name GET "${json}" time phases ${i})
    string(JSON seconds GET "${json}" time ${name})
    expect_within("${report}: ${name}" "${seconds}" 0 "${total}")
    float_eval(sum "${sum} + ${seconds}")
    list(APPEND names "${name}")
  endforeach ()
  foreach (name IN LISTS expected)
    if (NOT name IN_LIST names)
      message(FATAL_ERROR "${report}: no phase ${name} in ${names}")
    endif ()
  endforeach ()
  float_eval(gap "abs(${total} - ${sum})")
  expect_within("${report}: total_s less the phases (unaccounted_s ${unaccounted})" "${gap}"
    0 "${UNACCOUNTED_BOUND} * ${total}")
  string(JSON pipeline GET "${json}" time pipeline_s)
  expect_within("${report}: pipeline_s" "${pipeline}" 0 "${PIPELINE_BOUND} * ${total}")
  string(JSON parts LENGTH "${json}" time part_of)
  if (parts GREATER 0)
    math(EXPR last "${parts} - 1")
    foreach (i RANGE ${last})
      string(JSON part MEMBER "${json}" time part_of ${i})
      string(JSON phase GET "${json}" time part_of ${part})
      string(JSON seconds GET "${json}" time ${part})
      string(JSON whole GET "${json}" time ${phase})
      expect_within("${report}: ${part} within ${phase} (${whole} s)" "${seconds}" 0 "${whole} * 1.000001")
    endforeach ()
  endif ()
  set(json "${json}" PARENT_SCOPE)
endfunction()

set(common load_s preprocessing_s solve_s output_evaluation_s product_s pipeline_s write_s render_s
  probes_s report_s)
foreach (method progressive hierarchical meshless facecluster)
  expect_exit(0 "${PROGRAM}" solve cornell --method ${method} --output "${WORK}/${method}.vtp"
    --image "${WORK}/${method}.png" --size 64 --report "${WORK}/${method}.json")
  check_phases("${WORK}/${method}.json" "${common}")
  if (method STREQUAL "meshless")
    string(JSON output GET "${json}" time output_evaluation_s)
    string(JSON solve GET "${json}" time solve_s)
    expect_within("meshless: output_evaluation_s against solve_s (${solve} s)" "${output}"
      0 "${MESHLESS_OUTPUT_BOUND} * ${solve}")
    string(JSON bounces GET "${json}" time part_of bounces_s)
    if (NOT bounces STREQUAL "solve_s")
      message(FATAL_ERROR "meshless: bounces_s is part of '${bounces}', not solve_s")
    endif ()
  elseif (method STREQUAL "facecluster")
    string(JSON hierarchy GET "${json}" time hierarchy_s)
    expect_within("facecluster: hierarchy_s" "${hierarchy}" 1e-9 1e9)
  elseif (method STREQUAL "hierarchical")
    string(JSON of GET "${json}" time part_of meshing_s)
    if (NOT of STREQUAL "product_s")
      message(FATAL_ERROR "hierarchical: meshing_s is part of '${of}', not product_s")
    endif ()
  endif ()
endforeach ()

# Only what was asked for: a report alone evaluates no output.
expect_exit(0 "${PROGRAM}" solve cornell --method meshless --report "${WORK}/report-only.json")
check_phases("${WORK}/report-only.json" "load_s;preprocessing_s;solve_s;output_evaluation_s;report_s")
string(JSON output GET "${json}" time output_evaluation_s)
string(JSON product GET "${json}" time product_s)
string(JSON solve GET "${json}" time solve_s)
float_eval(evaluated "${output} + ${product}")
expect_within("report alone: output_evaluation_s + product_s against solve_s (${solve} s)"
  "${evaluated}" 0 "${REPORT_ONLY_OUTPUT_BOUND} * ${solve}")
