# vtkradiosity solve on the committed room scene: documented files, probe
# values, and exit status 2 with nothing written for bad input.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")

# Error bounds, each beside the figure it measured (the project's metric:
# |value - reference| / peak reference irradiance over every probe, at
# 49ee462 on the 2-core development machine; the solvers are deterministic,
# the path tracer seeded).
set(ROOM_RMS 0.00257)            # progressive room against the path tracer
set(ROOM_RMS_BOUND 0.006)
set(ROOM_MAX 0.00419)
set(ROOM_MAX_BOUND 0.01)
set(AGAIN_RMS 0.00135)           # the written room.vtp solved again, against the path tracer
set(AGAIN_RMS_BOUND 0.0035)
set(SHADOW_RMS 0.0356)           # progressive shadow scene against the closed form
set(SHADOW_RMS_BOUND 0.06)
set(SHADOW_PT_RMS 0.0344)        # the same against the path tracer, 4,096 paths
set(SHADOW_PT_DIFFERENCE_BOUND 0.0035) # measured difference 0.0012
set(CONTACT_RMS 0.00237)         # progressive contact scene, three probes
set(CONTACT_RMS_BOUND 0.005)
set(H_RMS 0.00041)               # hierarchical + discontinuity mesh, shadow scene
set(H_RMS_BOUND 0.001)
set(H_LEAF_RMS 0.109)            # its constant leaves
set(H_LEAF_RMS_BOUND 0.2)
# Leaves (and --no-discontinuity-meshing) / interpolants: measured 267. A
# lower bound for the README's claim that the interpolants resolve what the
# constant leaves cannot, the leaves' own figure bounded above.
set(H_LEAF_RMS_FACTOR 20)
set(HL_RMS 0.109)                # --no-discontinuity-meshing
set(HL_RMS_BOUND 0.2)
set(HROOM_RMS 0.0051)            # hierarchical room against the path tracer
set(HROOM_RMS_BOUND 0.012)
set(HCROOM_RMS 0.0061)           # the same, --clustering on
set(ML_RMS 0.00176)              # meshless contact scene
set(ML_RMS_BOUND 0.004)
set(FC_RMS 9.5e-7)               # face cluster closed room of reflectance 0.99
set(FC_RMS_BOUND 2.5e-6)
set(FC_ABS_BOUND 2.5e-4)         # |E - 100|: measured 9.5e-5
set(EDGE4_RMS 0.00085)           # face cluster by a contact edge, 4 halvings
set(EDGE4_RMS_BOUND 0.0025)
set(EDGE0_RMS 0.047)             # the paper's leaves
set(EDGE0_RMS_BOUND 0.1)
set(EDGE_GAIN 20)                # no halving / 4 halvings: measured 55 (a lower bound, as above)

expect_exit(0 "${PROGRAM}" solve "${DATA}/room.obj" --method progressive --tolerance 1e-2
  --probes "${DATA}/room_probes.csv" --probe-output "${WORK}/values.csv"
  --output "${WORK}/room.vtp" --image "${WORK}/room.png" --exr "${WORK}/room.exr"
  --report "${WORK}/report.json" --size 128 --reference pathtraced --reference-samples 16384)
foreach (f room.vtp room.png room.exr report.json values.csv)
  if (NOT EXISTS "${WORK}/${f}")
    message(FATAL_ERROR "missing output ${f}")
  endif ()
endforeach ()
file(STRINGS "${WORK}/values.csv" rows)
list(LENGTH rows n)
if (NOT n EQUAL 5)
  message(FATAL_ERROR "values.csv: expected a header and 4 rows, got ${n} lines")
endif ()
list(GET rows 0 header)
if (NOT header STREQUAL "x,y,z,E_r,E_g,E_b")
  message(FATAL_ERROR "values.csv header: ${header}")
endif ()
# Floor centre below the light (0.6 m square of exitance 30 at height 1.99):
# at least the direct light, 30 F with the closed form of a point below the
# centre of a parallel rectangle, 4 corner rectangles of X = Y = 0.3 / 1.99
# (Howell's catalogue: a differential element on the normal through a
# corner of a parallel rectangle): 0.8426; the rest is light from the walls.
read_probe_values("${WORK}/values.csv" room)
list(GET room_0 3 er)
set(X "0.3 / 1.99")
float_eval(direct "30 * 4 / (2 * 3.14159265358979) * 2 * (${X}) / sqrt(1 + (${X})^2) * atan((${X}) / sqrt(1 + (${X})^2))")
expect_within("floor-centre irradiance (direct ${direct}, measured 1.3947)" "${er}" "${direct}" "2 * ${direct}")
# Every probe (the sensor in mid-air included) against the path tracer
# (16,384 paths, largest relative standard error 3.9e-3), all 4 counted.
file(READ "${WORK}/report.json" report)
string(JSON kind GET "${report}" error reference)
string(JSON rms GET "${report}" error probe_output_rms_relative_error)
string(JSON max GET "${report}" error probe_output_max_relative_error)
string(JSON counted GET "${report}" error probe_output_probes_counted)
if (NOT kind MATCHES "^path traced: 16384 paths per probe" OR NOT counted EQUAL 4)
  message(FATAL_ERROR "room reference: ${kind}, ${counted} probes counted")
endif ()
expect_within("room: RMS error against the path tracer (measured ${ROOM_RMS})" "${rms}" 0 ${ROOM_RMS_BOUND})
expect_within("room: max error against the path tracer (measured ${ROOM_MAX})" "${max}" 0 ${ROOM_MAX_BOUND})
# --max-memory 0 (the default) is 75% of physical memory (README).
file(STRINGS "/proc/meminfo" memTotal REGEX "^MemTotal:")
if (memTotal MATCHES "([0-9]+) kB")
  string(JSON budget GET "${report}" parameters memory_budget_bytes)
  float_eval(expected "0.75 * ${CMAKE_MATCH_1} * 1024")
  expect_within("default memory budget (75% of MemTotal: ${expected})" "${budget}"
    "0.999 * ${expected}" "1.001 * ${expected}")
endif ()
string(JSON method GET "${report}" method)
string(JSON stop GET "${report}" solution stop)
if (NOT method STREQUAL "progressive" OR NOT stop STREQUAL "converged")
  message(FATAL_ERROR "report: method ${method}, stop ${stop}")
endif ()

# The written solution is itself a valid scene (its cell arrays carry the
# materials): solving it again gives the room's light again, against the
# path tracer on the original room.obj (the materials survived).
expect_exit(0 "${PROGRAM}" solve "${WORK}/room.vtp" --method progressive --tolerance 1e-2 --output "${WORK}/again.vtp"
  --probes "${DATA}/room_probes.csv" --probe-output "${WORK}/again_values.csv"
  --reference pathtraced --reference-samples 16384 --report "${WORK}/again.json")
if (NOT EXISTS "${WORK}/again.vtp")
  message(FATAL_ERROR "missing again.vtp")
endif ()
file(READ "${WORK}/again.json" again)
string(JSON rms GET "${again}" error probe_output_rms_relative_error)
expect_within("the written room solved again: RMS error against the path tracer (measured ${AGAIN_RMS})"
  "${rms}" 0 ${AGAIN_RMS_BOUND})
# STL carries no materials: default reflectance and no emitter, both warned
# about; the zero solution is returned at once.
expect_exit(0 "${PROGRAM}" solve "${DATA}/triangle.stl" --report "${WORK}/stl.json")
if (NOT last_stderr MATCHES "Reflectance" OR NOT last_stderr MATCHES "no emitter")
  message(FATAL_ERROR "STL warnings missing: ${last_stderr}")
endif ()
expect_exit(0 "${PROGRAM}" solve "${DATA}/square.ply" --report "${WORK}/ply.json")
file(READ "${WORK}/ply.json" ply)
string(JSON plyTriangles GET "${ply}" scene triangles)
if (NOT plyTriangles EQUAL 2)
  message(FATAL_ERROR "PLY: ${plyTriangles} triangles")
endif ()
file(READ "${WORK}/stl.json" stl)
string(JSON stop GET "${stl}" solution stop)
if (NOT stop STREQUAL "no emitters")
  message(FATAL_ERROR "STL without emitters: stop ${stop}")
endif ()

# Error against run time: the exact penumbra scene against its analytic
# reference (backprojection of the convex blocker: exact).
expect_exit(0 "${PROGRAM}" solve shadow --method progressive --probes "${DATA}/shadow_probes.csv"
  --reference analytic --probe-output "${WORK}/shadow_values.csv" --report "${WORK}/shadow.json"
  --history "${WORK}/shadow_history.csv")
file(READ "${WORK}/shadow.json" shadow)
string(JSON kind GET "${shadow}" error reference)
string(JSON rms GET "${shadow}" error rms_relative_error)
string(JSON tracked GET "${shadow}" error probes_on_a_surface)
string(JSON probes GET "${shadow}" error probes)
string(JSON counted GET "${shadow}" error probe_output_probes_counted)
string(JSON notFinite GET "${shadow}" error probe_output_probes_not_finite)
if (NOT kind STREQUAL "analytic: direct with convex blocker" OR NOT tracked EQUAL 31 OR NOT probes EQUAL 31
    OR NOT counted EQUAL 31 OR NOT notFinite EQUAL 0)
  message(FATAL_ERROR "shadow reference: ${kind}, ${probes} probes, ${tracked} on a surface, "
    "${counted} counted, ${notFinite} not finite")
endif ()
# The progressive method's constant elements smear both penumbrae.
expect_within("shadow: progressive RMS error (measured ${SHADOW_RMS})" "${rms}" 0 ${SHADOW_RMS_BOUND})
string(JSON shadowRms GET "${shadow}" error probe_output_rms_relative_error)
file(STRINGS "${WORK}/shadow_history.csv" history LIMIT_COUNT 2)
list(GET history 1 first)
if (first MATCHES "nan")
  message(FATAL_ERROR "the history has no error figures: ${first}")
endif ()
# A reference file (--reference FILE, the --probe-output format): the contact
# scene's closed form written here, a floor point (d, 0.5, 0) below an
# emitting wall x = 0, 0 <= y, z <= 1 of exitance 10 (SceneGenerators.cxx):
# two rectangles 0.5 wide, 1 high, perpendicular to the floor with a corner
# at the foot of the point's normal plane (Howell's catalogue),
# F = (atan(W/d) - d/sqrt(d^2+H^2) atan(W/sqrt(d^2+H^2))) / (2 pi) each.
# The error against that file is the error against --reference analytic.
file(WRITE "${WORK}/contact_probes.csv" "x,y,z,nx,ny,nz\n0.05,0.5,0,0,0,1\n0.3,0.5,0,0,0,1\n1.0,0.5,0,0,0,1\n")
set(contactReference "x,y,z,E_r,E_g,E_b\n")
foreach (d 0.05 0.3 1.0)
  set(r "sqrt(${d}^2 + 1)")
  float_eval(e "10 * 2 * (atan(0.5 / ${d}) - ${d} / ${r} * atan(0.5 / ${r})) / (2 * 3.14159265358979)")
  string(APPEND contactReference "${d},0.5,0,${e},${e},${e}\n")
  list(APPEND contactClosedForm ${e})
endforeach ()
file(WRITE "${WORK}/contact_reference.csv" "${contactReference}")
foreach (reference analytic "${WORK}/contact_reference.csv")
  expect_exit(0 "${PROGRAM}" solve contact --method progressive --probes "${WORK}/contact_probes.csv"
    --reference "${reference}" --probe-output "${WORK}/contact_values.csv" --report "${WORK}/contact.json")
  file(READ "${WORK}/contact.json" contact)
  string(JSON rms GET "${contact}" error probe_output_rms_relative_error)
  list(APPEND contactRms ${rms})
endforeach ()
list(GET contactRms 0 analyticRms)
list(GET contactRms 1 fileRms)
expect_within("contact: RMS error against the analytic reference (measured ${CONTACT_RMS})" "${analyticRms}"
  0 ${CONTACT_RMS_BOUND})
expect_within("contact: RMS error against the closed form in a file (against analytic: ${analyticRms})"
  "${fileRms}" "${analyticRms} - 1e-9" "${analyticRms} + 1e-9")
# The path-traced reference: at the probes, and per pixel of the --exr view.
expect_exit(0 "${PROGRAM}" solve shadow --method progressive --probes "${DATA}/shadow_probes.csv"
  --reference pathtraced --reference-samples 4096 --exr "${WORK}/shadow.exr"
  --reference-exr "${WORK}/shadow_reference.exr" --size 32 --report "${WORK}/shadow_pt.json")
file(READ "${WORK}/shadow_pt.json" pt)
string(JSON kind GET "${pt}" error reference)
string(JSON rms GET "${pt}" error probe_output_rms_relative_error)
if (NOT kind MATCHES "^path traced: 4096 paths per probe" OR NOT EXISTS "${WORK}/shadow_reference.exr")
  message(FATAL_ERROR "path-traced reference: ${kind}")
endif ()
# The same solution's error against the path tracer is its error against the
# closed form, up to the path tracer's noise (relative SE up to 4.7e-2 in the
# penumbrae).
expect_within("shadow: RMS error against the path tracer (measured ${SHADOW_PT_RMS}, against analytic ${shadowRms})"
  "${rms}" "${shadowRms} - ${SHADOW_PT_DIFFERENCE_BOUND}" "${shadowRms} + ${SHADOW_PT_DIFFERENCE_BOUND}")
expect_exit(2 "${PROGRAM}" solve shadow --reference-exr "${WORK}/bad.exr")

# Hierarchical radiosity (Hardt & Teller): discontinuity-meshed by default,
# the .vtp carries the quadratic interpolants, the probes come from them
# (exact penumbra scene, analytic reference), the report names the meshing.
expect_exit(0 "${PROGRAM}" solve shadow --method hierarchical --probes "${DATA}/shadow_probes.csv"
  --reference analytic --probe-output "${WORK}/h_values.csv" --output "${WORK}/h.vtp"
  --report "${WORK}/h.json" --history "${WORK}/h_history.csv" --image "${WORK}/h.png"
  --exr "${WORK}/h.exr" --size 64 --link-tolerance 0.1 --discontinuities-per-leaf 8)
foreach (f h.vtp h.png h.exr h.json h_values.csv h_history.csv)
  if (NOT EXISTS "${WORK}/${f}")
    message(FATAL_ERROR "hierarchical: missing output ${f}")
  endif ()
endforeach ()
file(STRINGS "${WORK}/h.vtp" interpolant REGEX "Name=\"QuadraticInterpolant\" [^>]*NumberOfComponents=\"18\"")
if (NOT interpolant)
  message(FATAL_ERROR "hierarchical: h.vtp has no 18-component QuadraticInterpolant cell array")
endif ()
file(STRINGS "${WORK}/h_values.csv" rows)
list(LENGTH rows n)
if (NOT n EQUAL 32 OR rows MATCHES "nan")
  message(FATAL_ERROR "hierarchical probe output: ${n} lines (expected a header and 31 rows)")
endif ()
file(READ "${WORK}/h.json" h)
string(JSON method GET "${h}" method)
string(JSON meshing GET "${h}" time meshing_s)
string(JSON linkTolerance GET "${h}" parameters link_tolerance)
string(JSON perLeaf GET "${h}" parameters discontinuities_per_leaf)
string(JSON links GET "${h}" solution links)
string(JSON partial GET "${h}" solution partial_links)
string(JSON triangles GET "${h}" discontinuity_mesh triangles)
string(JSON kept GET "${h}" discontinuity_mesh segments_kept)
string(JSON rms GET "${h}" error rms_relative_error)
string(JSON leafRms GET "${h}" error leaves_rms_relative_error)
if (NOT method STREQUAL "hierarchical" OR NOT meshing GREATER 0 OR NOT linkTolerance EQUAL 0.1
    OR NOT perLeaf EQUAL 8 OR NOT links GREATER 0 OR NOT partial GREATER 0
    OR NOT triangles GREATER 0 OR NOT kept GREATER 0)
  message(FATAL_ERROR "hierarchical report: method ${method}, meshing ${meshing} s, link "
    "tolerance ${linkTolerance}, k ${perLeaf}, links ${links} (${partial} partial), "
    "${triangles} triangles, ${kept} segments")
endif ()
# The interpolants resolve the penumbra that the constant leaves cannot.
expect_within("hierarchical: interpolants' RMS error (measured ${H_RMS})" "${rms}" 0 ${H_RMS_BOUND})
expect_within("hierarchical: leaves' RMS error (measured ${H_LEAF_RMS})" "${leafRms}"
  "${H_LEAF_RMS_FACTOR} * ${rms}" ${H_LEAF_RMS_BOUND})
set(meshedRms "${rms}")
file(STRINGS "${WORK}/h_history.csv" history LIMIT_COUNT 2)
list(GET history 1 first)
if (first MATCHES "nan")
  message(FATAL_ERROR "hierarchical history has no error figures: ${first}")
endif ()
# Without meshing: the leaves, no interpolants, probes from the constant leaves.
expect_exit(0 "${PROGRAM}" solve shadow --method hierarchical --no-discontinuity-meshing
  --probes "${DATA}/shadow_probes.csv" --reference analytic --probe-output "${WORK}/hl_values.csv"
  --output "${WORK}/hl.vtp" --report "${WORK}/hl.json")
file(STRINGS "${WORK}/hl.vtp" interpolant REGEX "QuadraticInterpolant")
if (interpolant)
  message(FATAL_ERROR "--no-discontinuity-meshing: the .vtp has interpolants")
endif ()
file(STRINGS "${WORK}/hl_values.csv" rows)
list(LENGTH rows n)
file(READ "${WORK}/hl.json" hl)
string(JSON meshing GET "${hl}" parameters discontinuity_meshing)
string(JSON rms GET "${hl}" error rms_relative_error)
if (NOT n EQUAL 32 OR meshing)
  message(FATAL_ERROR "--no-discontinuity-meshing: ${n} lines, meshing ${meshing}")
endif ()
expect_within("--no-discontinuity-meshing: RMS error (measured ${HL_RMS}, interpolants of the meshed run ${meshedRms})"
  "${rms}" "${H_LEAF_RMS_FACTOR} * ${meshedRms}" ${HL_RMS_BOUND})
# The README's defaults: link tolerance 0.05, minimum element 1/64 of the
# diagonal, 4 refinement rounds, k = 10, w_min = 0.05, gathering tolerance 1e-3.
foreach (pair "link_tolerance;0.05" "min_element_size;0.015625" "max_refinement_rounds;4"
    "discontinuities_per_leaf;10" "min_discontinuity_weight;0.05" "tolerance;0.001")
  list(GET pair 0 name)
  list(GET pair 1 documented)
  string(JSON value GET "${hl}" parameters ${name})
  expect_within("hierarchical default ${name}" "${value}" ${documented} ${documented})
endforeach ()
# A room from a file, the sensor in mid-air included (gathered from the
# leaves), against the path tracer.
expect_exit(0 "${PROGRAM}" solve "${DATA}/room.obj" --method hierarchical --max-time 20
  --probes "${DATA}/room_probes.csv" --probe-output "${WORK}/hroom_values.csv"
  --reference pathtraced --reference-samples 16384 --report "${WORK}/hroom.json")
file(STRINGS "${WORK}/hroom_values.csv" rows)
list(LENGTH rows n)
if (NOT n EQUAL 5 OR rows MATCHES "nan")
  message(FATAL_ERROR "hierarchical room probes: ${rows}")
endif ()
file(READ "${WORK}/hroom.json" hroom)
string(JSON rms GET "${hroom}" error probe_output_rms_relative_error)
expect_within("hierarchical room: RMS error against the path tracer (measured ${HROOM_RMS})" "${rms}"
  0 ${HROOM_RMS_BOUND})
expect_exit(2 "${PROGRAM}" solve shadow --method hierarchical --link-tolerance 0
  --output "${WORK}/bad.vtp")
# The same room with clustering forced on (links from the face cluster
# roots; Auto would leave 14 triangles unclustered): the report says so, the
# answer stays within the plain solve's bound.
expect_exit(0 "${PROGRAM}" solve "${DATA}/room.obj" --method hierarchical --max-time 20
  --clustering on --probes "${DATA}/room_probes.csv" --probe-output "${WORK}/hcroom_values.csv"
  --reference pathtraced --reference-samples 16384 --report "${WORK}/hcroom.json")
file(READ "${WORK}/hcroom.json" hcroom)
string(JSON clustering GET "${hcroom}" parameters clustering)
string(JSON clustered GET "${hcroom}" parameters clustered)
string(JSON rms GET "${hcroom}" error probe_output_rms_relative_error)
if (NOT clustering STREQUAL "on" OR NOT clustered)
  message(FATAL_ERROR "--clustering on: the report says clustering ${clustering}, clustered ${clustered}")
endif ()
expect_within("clustered hierarchical room: RMS error against the path tracer (measured ${HCROOM_RMS})"
  "${rms}" 0 ${HROOM_RMS_BOUND})
string(JSON clustered GET "${hroom}" parameters clustered)
if (clustered)
  message(FATAL_ERROR "--clustering auto clustered a room of 14 triangles")
endif ()
expect_exit(2 "${PROGRAM}" solve shadow --method hierarchical --clustering sideways
  --output "${WORK}/bad.vtp")

# Meshless: the contact scene against its closed form, probes from the Shepard
# field, the Table 1 columns in the report.
expect_exit(0 "${PROGRAM}" solve contact --method meshless --point-levels 4
  --probes "${WORK}/contact_probes.csv" --reference analytic --probe-output "${WORK}/ml_values.csv"
  --output "${WORK}/ml.vtp" --report "${WORK}/ml.json" --image "${WORK}/ml.png")
if (NOT EXISTS "${WORK}/ml.png")
  message(FATAL_ERROR "meshless: no splatted image written")
endif ()
file(STRINGS "${WORK}/ml_values.csv" rows)
list(LENGTH rows n)
file(READ "${WORK}/ml.json" ml)
string(JSON method GET "${ml}" method)
string(JSON generated GET "${ml}" meshless samples_generated)
string(JSON gathered GET "${ml}" meshless samples_gathered_to)
string(JSON rms GET "${ml}" error probe_output_rms_relative_error)
if (NOT n EQUAL 4 OR rows MATCHES "nan" OR NOT method STREQUAL "meshless" OR NOT generated GREATER gathered
    OR NOT gathered GREATER 0)
  message(FATAL_ERROR "meshless: ${n} rows, method ${method}, samples ${generated}/${gathered}")
endif ()
expect_within("meshless: RMS error (measured ${ML_RMS})" "${rms}" 0 ${ML_RMS_BOUND})
expect_exit(2 "${PROGRAM}" solve contact --method meshless --point-levels 0 --output "${WORK}/bad.vtp")

# Face cluster radiosity: a closed room of reflectance 0.99 against its closed
# form, the irradiance vectors in the output, the solution statistics in the
# report; bad bases refused.
file(WRITE "${WORK}/cube_probes.csv" "x,y,z,nx,ny,nz\n0.3,0.6,0,0,0,1\n1,0.5,0.2,-1,0,0\n0.5,0.5,1,0,0,-1\n")
expect_exit(0 "${PROGRAM}" solve closed-room-0.99 --method facecluster --probes "${WORK}/cube_probes.csv"
  --reference analytic --probe-output "${WORK}/fc_values.csv" --output "${WORK}/fc.vtp"
  --report "${WORK}/fc.json" --image "${WORK}/fc.png" --size 64)
file(READ "${WORK}/fc.json" fc)
string(JSON method GET "${fc}" method)
string(JSON leaves GET "${fc}" facecluster leaf_elements)
string(JSON transfers GET "${fc}" facecluster transfers)
string(JSON rms GET "${fc}" error probe_output_rms_relative_error)
file(READ "${WORK}/fc.vtp" vtp)
if (NOT method STREQUAL "facecluster" OR NOT leaves GREATER 0 OR NOT transfers GREATER 0
    OR NOT vtp MATCHES "Name=\"IrradianceVector\" [^>]*NumberOfComponents=\"9\"" OR NOT EXISTS "${WORK}/fc.png")
  message(FATAL_ERROR "facecluster: method ${method}, ${leaves} leaves, ${transfers} transfers, "
    "no 9-component IrradianceVector or no image")
endif ()
expect_within("facecluster closed room: RMS error (measured ${FC_RMS})" "${rms}" 0 ${FC_RMS_BOUND})
# The closed form itself: every surface of a closed room of uniform
# reflectance 0.99 and exitance 1 has irradiance H = 1 + 0.99 H = 100.
read_probe_values("${WORK}/fc_values.csv" fcv)
foreach (i RANGE 2)
  foreach (channel 3 4 5)
    list(GET fcv_${i} ${channel} e)
    expect_within("facecluster closed room: probe ${i} (measured 100.000095)" "${e}"
      "100 - ${FC_ABS_BOUND}" "100 + ${FC_ABS_BOUND}")
  endforeach ()
endforeach ()
# The README's defaults.
foreach (pair "irradiance_basis;linear" "radiosity_basis;constant")
  list(GET pair 0 name)
  list(GET pair 1 documented)
  string(JSON value GET "${fc}" parameters ${name})
  if (NOT value STREQUAL documented)
    message(FATAL_ERROR "facecluster default ${name}: ${value}, documented ${documented}")
  endif ()
endforeach ()
string(JSON value GET "${fc}" parameters transfer_tolerance)
expect_within("facecluster default transfer_tolerance" "${value}" 0.99999e-5 1.00001e-5)
string(JSON value GET "${fc}" parameters max_bisections)
expect_within("facecluster default max_bisections" "${value}" 5 5)
expect_exit(2 "${PROGRAM}" solve closed-room-0.99 --method facecluster --irradiance-basis septic
  --output "${WORK}/bad.vtp")
expect_exit(2 "${PROGRAM}" solve closed-room-0.99 --method facecluster --irradiance-basis linear
  --radiosity-basis quadratic --output "${WORK}/bad.vtp")
expect_exit(2 "${PROGRAM}" solve closed-room-0.99 --method facecluster --max-bisections 99
  --output "${WORK}/bad.vtp")
if (EXISTS "${WORK}/bad.vtp")
  message(FATAL_ERROR "bad input wrote an output")
endif ()
# Probes by a contact edge: halving the floor's triangles where the linear
# basis cannot follow the light, against the paper's leaves (the solution's
# fit of the wall's light, --no-exact-emitters; by default the output shows
# it exactly, below).
file(WRITE "${WORK}/edge_probes.csv" "x,y,z,nx,ny,nz\n0.001,0.5,0,0,0,1\n0.01,0.5,0,0,0,1\n0.3,0.4,0,0,0,1\n")
foreach (halvings 0 4)
  expect_exit(0 "${PROGRAM}" solve contact --method facecluster --max-bisections ${halvings} --no-exact-emitters
    --probes "${WORK}/edge_probes.csv" --reference analytic --probe-output "${WORK}/edge_values.csv"
    --report "${WORK}/edge_${halvings}.json")
  file(READ "${WORK}/edge_${halvings}.json" edge)
  string(JSON edge_rms_${halvings} GET "${edge}" error probe_output_rms_relative_error)
endforeach ()
expect_within("facecluster by a contact edge, 4 halvings: RMS error (measured ${EDGE4_RMS})" "${edge_rms_4}"
  0 ${EDGE4_RMS_BOUND})
expect_within("facecluster by a contact edge, no halving: RMS error (measured ${EDGE0_RMS}; halved ${edge_rms_4})"
  "${edge_rms_0}" "${EDGE_GAIN} * ${edge_rms_4}" ${EDGE0_RMS_BOUND})
# The wall's light shown exactly (the default): the closed form at the
# probes, measured 2.5e-16 RMS; the report says so.
expect_exit(0 "${PROGRAM}" solve contact --method facecluster --max-bisections 0
  --probes "${WORK}/edge_probes.csv" --reference analytic --probe-output "${WORK}/edge_values.csv"
  --report "${WORK}/edge_exact.json")
file(READ "${WORK}/edge_exact.json" edge)
string(JSON edge_rms_exact GET "${edge}" error probe_output_rms_relative_error)
string(JSON exact_emitters GET "${edge}" facecluster exact_emitter_triangles)
expect_within("facecluster by a contact edge, the wall shown exactly: RMS error (measured 2.5e-16)"
  "${edge_rms_exact}" 0 1e-12)
expect_within("facecluster by a contact edge: exact emitter triangles (the wall's 32)" "${exact_emitters}" 32 32)

expect_exit(2 "${PROGRAM}" solve shadow --probes "${DATA}/room_probes.csv"
  --reference "${WORK}/shadow_values.csv" --output "${WORK}/bad.vtp")
# --reference needs --probes (README).
expect_exit(2 "${PROGRAM}" solve shadow --reference analytic --output "${WORK}/bad.vtp")
expect_exit(2 "${PROGRAM}" solve cornell --probes "${DATA}/room_probes.csv"
  --reference analytic --output "${WORK}/bad.vtp")
if (NOT last_stderr MATCHES "no closed form")
  message(FATAL_ERROR "analytic reference for the Cornell box: ${last_stderr}")
endif ()

# Bad input: exit 2, the array and value named, nothing written.
expect_exit(2 "${PROGRAM}" solve "${DATA}/room_bad.obj" --output "${WORK}/bad.vtp"
  --report "${WORK}/bad.json")
if (NOT last_stderr MATCHES "Reflectance" OR NOT last_stderr MATCHES "1.2")
  message(FATAL_ERROR "bad reflectance message: ${last_stderr}")
endif ()
expect_exit(2 "${PROGRAM}" solve "${DATA}/missing.vtp" --output "${WORK}/bad.vtp")
expect_exit(2 "${PROGRAM}" solve "${DATA}/room.obj" --method nonsense --output "${WORK}/bad.vtp")
expect_exit(2 "${PROGRAM}" solve "${DATA}/room.obj" --tolerance -1 --output "${WORK}/bad.vtp")
file(GLOB leftovers "${WORK}/bad*")
if (leftovers)
  message(FATAL_ERROR "bad input left files: ${leftovers}")
endif ()

# The scene loader (SceneLoader.h, SceneFileCheck.h): a legacy file's every
# array is read and named on stderr; bad files are refused with exactly one
# "error: bad input: FILE: ..." line and nothing written; white .mtl colours
# are clamped to --max-reflectance with one warning.
expect_exit(0 "${PROGRAM}" solve "${DATA}/two_arrays.vtk" --report "${WORK}/two_arrays.json")
if (NOT last_stderr MATCHES "read [^\n]*two_arrays.vtk: 8 points, 4 polygons; cell arrays: Reflectance \\(3\\), Emission \\(3\\)")
  message(FATAL_ERROR "two_arrays.vtk: no info line naming both arrays: ${last_stderr}")
endif ()
file(READ "${WORK}/two_arrays.json" two)
string(JSON emitters GET "${two}" scene emitters)
if (NOT emitters EQUAL 2)
  message(FATAL_ERROR "two_arrays.vtk: ${emitters} emitters (the Emission array lost?)")
endif ()
expect_exit(0 "${PROGRAM}" solve "${DATA}/white.obj" --report "${WORK}/white.json")
string(REGEX MATCHALL "clamped to 0.95" clamps "${last_stderr}")
list(LENGTH clamps nclamps)
if (NOT nclamps EQUAL 1 OR NOT last_stderr MATCHES "1 material\\(s\\) of '[^']*white.obj' have a Kd")
  message(FATAL_ERROR "white.obj: expected one clamping warning: ${last_stderr}")
endif ()
expect_exit(0 "${PROGRAM}" solve "${DATA}/white.obj" --max-reflectance 0.8 --report "${WORK}/white.json")
if (NOT last_stderr MATCHES "clamped to 0.8")
  message(FATAL_ERROR "--max-reflectance 0.8 not applied: ${last_stderr}")
endif ()
expect_exit(2 "${PROGRAM}" solve "${DATA}/white.obj" --max-reflectance 1 --output "${WORK}/bad_loader.vtp")
function(expect_refusal file pattern)
  expect_exit(2 "${PROGRAM}" solve "${file}" --output "${WORK}/bad_loader.vtp"
    --report "${WORK}/bad_loader.json")
  expect_one_error("error: bad input: [^\n]*${pattern}")
  if (EXISTS "${WORK}/bad_loader.vtp" OR EXISTS "${WORK}/bad_loader.json")
    message(FATAL_ERROR "${file}: refused but wrote an output")
  endif ()
endfunction()
expect_refusal("${DATA}/list_in_vertex.ply" "list_in_vertex.ply: line 13 \\(vertex 0 of 4\\) holds 6 values")
expect_refusal("${DATA}/box_utf16.obj" "box_utf16.obj: UTF-16 text")
file(WRITE "${WORK}/billion.vtk" "# vtk DataFile Version 3.0\nbig\nASCII\nDATASET POLYDATA\nPOINTS 1000000000 float\n0 0 0\n")
expect_refusal("${WORK}/billion.vtk" "billion.vtk: line 5 declares 1000000000 points")
file(WRITE "${WORK}/huge.ply" "ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\nproperty float x\nproperty float y\nproperty float z\nend_header\n0123456789")
expect_refusal("${WORK}/huge.ply" "huge.ply: header line 3 declares 4294967295 vertices of 12 bytes \\(51.5 GB\\) but the file holds 10 bytes after the header")
file(WRITE "${WORK}/scene.gltf" "{}")
expect_refusal("${WORK}/scene.gltf" "scene.gltf: no asset.version \\(a glTF 2.0 file has one\\)")
