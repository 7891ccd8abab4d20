# vtkradiosity bench --quick (the CI run of the error harness) into a
# directory that does not exist yet, then its figures checked: every standard
# scene written (CSV, plot, its section of README.md), the probe and triangle
# counts those of the scene definitions (Modules/Radiosity/Scenes/), every run
# converged with a finite error, every error within the committed full run's
# figure for the same method and setting (bench/results/error-vs-time/), and
# --method auto within 1.5x of the best error at equal time.
# cmake -DPROGRAM=vtkradiosity -DCOMMITTED=bench/results/error-vs-time -DWORK=dir -P TestBenchQuick.cmake
include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")

file(REMOVE_RECURSE "${WORK}")
set(out "${WORK}/new/tables")
string(TIMESTAMP start "%s")
expect_exit(0 "${PROGRAM}" bench --quick --output-dir "${out}")
string(TIMESTAMP end "%s")
math(EXPR seconds "${end} - ${start}")
message(STATUS "bench --quick: ${seconds} s")

# Probes and triangles from the scene definitions (StandardScenes.cxx,
# SceneGenerators.cxx): the Cornell box has 32 triangles, one probe per
# triangle centroid (stride 32 / 40 rounded down to 1); the shadow scene 31
# probes (x = -0.6 + 0.05 i, i = 0..30), a 4 x 4 floor (32 triangles) and
# three quads (6); the contact scene 6 probes, two 4 x 4 quads; the sphere
# 20 * 4^3 = 1280 triangles, every 32nd centroid (40 probes); the closed
# rooms 6 faces * 2 * 2 * 2 = 48 triangles, a probe at each centroid.
set(scenes cornell shadow contact sphere closed-room-0.99 closed-room-0.999)
set(probes_cornell 32)
set(triangles_cornell 32)
set(probes_shadow 31)
set(triangles_shadow 38)
set(probes_contact 6)
set(triangles_contact 64)
set(probes_sphere 40)
set(triangles_sphere 1280)
foreach (room closed-room-0.99 closed-room-0.999)
  set(probes_${room} 48)
  set(triangles_${room} 48)
endforeach ()
# --quick: the coarse and default progressive settings and link tolerance 0.2
# (constant leaves and discontinuity mesh), plain and clustered; no plain
# hierarchical sphere (its initial links are quadratic in the input: README).
# Then meshless radiosity with 3 point levels and what --method auto runs.
set(clustered_rows "hierarchical-clustered/link_0.2;hierarchical-clustered+DM/link_0.2;"
  "meshless/levels_3;auto/hierarchical")
string(REPLACE ";;" ";" clustered_rows "${clustered_rows}")
set(rows_sphere "progressive/coarse;progressive/default;${clustered_rows}")
set(rows_default "progressive/coarse;progressive/default;hierarchical/link_0.2;"
  "hierarchical+DM/link_0.2;${clustered_rows}")
string(REPLACE ";;" ";" rows_default "${rows_default}")

file(READ "${out}/README.md" readme)
if (NOT readme MATCHES "Mode: quick")
  message(FATAL_ERROR "bench README.md does not say quick mode")
endif ()

# Reads a bench CSV into <prefix>_KEYS (method/setting, spaces as _) and, per key,
# <prefix>_<key>_rms, _max and _stop.
function(read_bench_csv file prefix)
  file(STRINGS "${file}" lines)
  list(POP_FRONT lines header)
  if (NOT header MATCHES "^method,setting,element_size,tolerance,preprocess_s,solve_s,peak_memory_bytes,elements,rays,iterations,stop,relative_unshot,rms_error,max_rel_error,")
    message(FATAL_ERROR "${file}: unexpected columns: ${header}")
  endif ()
  set(keys)
  foreach (line IN LISTS lines)
    string(REPLACE "," ";" f "${line}")
    list(GET f 0 method)
    list(GET f 1 setting)
    list(GET f 10 stop)
    list(GET f 12 rms)
    list(GET f 13 max)
    string(REPLACE " " "_" key "${method}/${setting}")
    list(APPEND keys "${key}")
    set(${prefix}_${key}_rms "${rms}" PARENT_SCOPE)
    set(${prefix}_${key}_max "${max}" PARENT_SCOPE)
    set(${prefix}_${key}_stop "${stop}" PARENT_SCOPE)
  endforeach ()
  set(${prefix}_KEYS "${keys}" PARENT_SCOPE)
endfunction()

# The committed tables were written with the project's metric (error / peak
# reference irradiance, every probe) when their README says so: then each
# quick figure is within a factor 3 of the committed one both ways (the
# analytic scenes reproduce exactly). Tables from before that metric
# (per-probe relative errors, larger) bound the quick figures from above only.
file(READ "${COMMITTED}/README.md" committedReadme)
if (committedReadme MATCHES "relative to the peak reference")
  set(lowerFactor 3)
else ()
  set(lowerFactor 0)
  message(WARNING "${COMMITTED} predates the peak-relative error metric: "
    "its figures bound the quick run's from above only; rerun vtkradiosity bench and commit it")
endif ()

foreach (scene IN LISTS scenes)
  foreach (f "${scene}.csv" "${scene}.png")
    if (NOT EXISTS "${out}/${f}")
      message(FATAL_ERROR "bench --quick did not write ${f}")
    endif ()
  endforeach ()
  if (NOT readme MATCHES "## ${scene} \\(([^\n]*), ([0-9]+) probes, ([0-9]+) triangles\\)")
    message(FATAL_ERROR "README.md: no section for ${scene}")
  endif ()
  set(kind "${CMAKE_MATCH_1}")
  if (NOT CMAKE_MATCH_2 EQUAL probes_${scene} OR NOT CMAKE_MATCH_3 EQUAL triangles_${scene})
    message(FATAL_ERROR "${scene}: ${CMAKE_MATCH_2} probes and ${CMAKE_MATCH_3} triangles, "
      "expected ${probes_${scene}} and ${triangles_${scene}}")
  endif ()
  read_bench_csv("${out}/${scene}.csv" quick)
  read_bench_csv("${COMMITTED}/${scene}.csv" committed)
  if (DEFINED rows_${scene})
    set(expected "${rows_${scene}}")
  else ()
    set(expected "${rows_default}")
  endif ()
  if (NOT quick_KEYS STREQUAL expected)
    message(FATAL_ERROR "${scene}: rows ${quick_KEYS}, expected ${expected}")
  endif ()
  foreach (key IN LISTS quick_KEYS)
    if (NOT quick_${key}_stop STREQUAL "converged")
      message(FATAL_ERROR "${scene} ${key}: stop '${quick_${key}_stop}'")
    endif ()
    if (NOT DEFINED committed_${key}_rms)
      message(FATAL_ERROR "${scene} ${key}: no such row in ${COMMITTED}/${scene}.csv")
    endif ()
    # The committed full run ran the same settings against the same reference
    # (the path-traced Cornell box with 65,536 paths per probe, the quick run
    # with 16,384: its reference's own error is twice as large), so the quick
    # figure is the committed one up to the reference's noise: at most 3x,
    # and at least 1e-10 (the hierarchical closed rooms are exact to 4e-13,
    # rounding that another summation order can change).
    foreach (figure rms max)
      set(c "${committed_${key}_${figure}}")
      float_eval(bound "3 * ${c} > 1e-10 ? 3 * ${c} : 1e-10")
      float_eval(lower "${lowerFactor} > 0 && ${c} > 1e-10 ? ${c} / ${lowerFactor} : 0")
      expect_within("${scene} ${key} ${figure} error (committed ${c})"
        "${quick_${key}_${figure}}" "${lower}" "${bound}")
    endforeach ()
    message(STATUS "${scene} ${key}: rms ${quick_${key}_rms} (committed ${committed_${key}_rms}), "
      "max ${quick_${key}_max} (committed ${committed_${key}_max})")
  endforeach ()
endforeach ()

# --method auto against the best at equal time (auto.csv: the lowest RMS
# error any other run of the scene reached in at most auto's time; errors
# below 1e-10 count as exact). The issue's target: at most 1.5x. Measured
# in the quick run at this commit: Cornell box 1.06, shadow 0.28, contact
# 1.00, sphere 1.27, closed rooms 1.00.
file(STRINGS "${out}/auto.csv" autoLines)
list(POP_FRONT autoLines autoHeader)
if (NOT autoHeader STREQUAL "scene,chosen,rule,seconds,rms_error,best_method,best_setting,best_seconds,best_rms_error,ratio")
  message(FATAL_ERROR "auto.csv: unexpected columns: ${autoHeader}")
endif ()
set(autoScenes)
foreach (line IN LISTS autoLines)
  string(REPLACE "," ";" f "${line}")
  list(GET f 0 scene)
  list(GET f 1 chosen)
  list(GET f 9 ratio)
  list(APPEND autoScenes "${scene}")
  # Every standard scene of the quick run is small and matte: rule 2.
  if (NOT chosen STREQUAL "hierarchical")
    message(FATAL_ERROR "auto chose ${chosen} for ${scene}, expected hierarchical (at most 2048 triangles)")
  endif ()
  expect_within("${scene}: auto's RMS error over the best at equal time" "${ratio}" 0 1.5)
  message(STATUS "${scene}: auto ${chosen}, ${ratio}x the best at equal time")
endforeach ()
if (NOT autoScenes STREQUAL scenes)
  message(FATAL_ERROR "auto.csv: scenes ${autoScenes}, expected ${scenes}")
endif ()
message(STATUS "bench --quick: every scene checked")
