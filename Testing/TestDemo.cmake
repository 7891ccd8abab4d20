# vtkradiosity demo (scripts/demo.sh): the README's six files, the Cornell
# box solved and converged, its error against the path tracer at the demo's
# probes within a bound beside the measured figure, and the convergence
# history's columns.
# cmake -DPROGRAM=vtkradiosity -DWORK=dir -P TestDemo.cmake
include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")
file(REMOVE_RECURSE "${WORK}")
set(out "${WORK}/new/out")
expect_exit(0 "${PROGRAM}" demo --output-dir "${out}")
foreach (f cornell.vtp cornell.png cornell.exr report.json convergence.csv convergence.png)
  if (NOT EXISTS "${out}/${f}")
    message(FATAL_ERROR "demo: missing ${f}")
  endif ()
endforeach ()
file(READ "${out}/report.json" report)
string(JSON stop GET "${report}" solution stop)
string(JSON triangles GET "${report}" scene triangles)
string(JSON kind GET "${report}" error reference)
string(JSON rms GET "${report}" error probe_output_rms_relative_error)
if (NOT stop STREQUAL "converged" OR NOT triangles EQUAL 32 OR NOT kind MATCHES "^path traced")
  message(FATAL_ERROR "demo report: stop ${stop}, ${triangles} triangles, reference ${kind}")
endif ()
# 30 lit probes, 16,384 paths each (largest relative SE 3.5e-2), every one
# counted; the error relative to the peak, then per probe.
string(JSON counted GET "${report}" error probe_output_probes_counted)
string(JSON perProbe GET "${report}" error probe_output_rms_per_probe_relative_error)
if (NOT counted EQUAL 30)
  message(FATAL_ERROR "demo: ${counted} probes counted, expected 30")
endif ()
expect_within("demo: RMS error / peak against the path tracer (measured 0.00719)" "${rms}" 0 0.015)
expect_within("demo: RMS per-probe relative error against the path tracer (measured 0.0709)" "${perProbe}" 0 0.15)
file(STRINGS "${out}/convergence.csv" history)
list(LENGTH history rows)
list(GET history 0 header)
if (NOT header STREQUAL "iteration,time_s,unshot_power_W,energy_balance,rms_error,max_rel_error,overshoot_power_W"
    OR rows LESS 3)
  message(FATAL_ERROR "demo: convergence.csv: ${rows} lines, header ${header}")
endif ()
# The last row: converged to the default tolerance (unshot power at most 1e-3
# of the emitted), the energy balance closed (measured -1.0e-4), its error the
# report's.
list(GET history -1 last)
string(REPLACE "," ";" last "${last}")
list(GET last 2 unshot)
list(GET last 3 balance)
list(GET last 4 lastRms)
string(JSON emitted GET "${report}" scene emitted_power_W)
expect_within("demo: relative unshot power (measured 9.7e-4)" "${unshot}" 0 "1e-3 * ${emitted}")
expect_within("demo: energy balance (measured -1.0e-4)" "${balance}" -3e-4 3e-4)
expect_within("demo: the history's last error is the report's" "${lastRms}" "${rms} - 1e-9" "${rms} + 1e-9")
