# vtkradiosity solve on the committed room scene: documented files, probe
# values, and exit status 2 with nothing written for bad input.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")

expect_exit(0 "${PROGRAM}" solve "${DATA}/room.obj" --tolerance 1e-2
  --probes "${DATA}/room_probes.csv" --probe-output "${WORK}/values.csv"
  --output "${WORK}/room.vtp" --image "${WORK}/room.png" --exr "${WORK}/room.exr"
  --report "${WORK}/report.json" --size 128)
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
# Floor centre below the light: irradiance well above zero and below the
# light's exitance; the sensor in mid-air facing up sees the ceiling only.
list(GET rows 1 centre)
string(REPLACE "," ";" centre "${centre}")
list(GET centre 3 er)
if (er LESS 1 OR er GREATER 30)
  message(FATAL_ERROR "floor-centre irradiance out of range: ${er}")
endif ()
file(READ "${WORK}/report.json" report)
string(JSON method GET "${report}" method)
string(JSON stop GET "${report}" solution stop)
if (NOT method STREQUAL "progressive" OR NOT stop STREQUAL "converged")
  message(FATAL_ERROR "report: method ${method}, stop ${stop}")
endif ()

# The written solution is itself a valid scene (its cell arrays carry the
# materials): solving it again works.
expect_exit(0 "${PROGRAM}" solve "${WORK}/room.vtp" --tolerance 1e-2 --output "${WORK}/again.vtp")
if (NOT EXISTS "${WORK}/again.vtp")
  message(FATAL_ERROR "missing again.vtp")
endif ()
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
# reference; then the values written by that run, read back as a reference
# file, give zero error (the same deterministic solution).
expect_exit(0 "${PROGRAM}" solve shadow --probes "${DATA}/shadow_probes.csv"
  --reference analytic --probe-output "${WORK}/shadow_values.csv" --report "${WORK}/shadow.json"
  --history "${WORK}/shadow_history.csv")
file(READ "${WORK}/shadow.json" shadow)
string(JSON kind GET "${shadow}" error reference)
string(JSON rms GET "${shadow}" error rms_relative_error)
string(JSON tracked GET "${shadow}" error probes_on_a_surface)
if (NOT kind STREQUAL "analytic: direct with convex blocker" OR NOT tracked EQUAL 31 OR rms GREATER 0.3)
  message(FATAL_ERROR "shadow reference: ${kind}, rms ${rms}, tracked ${tracked}")
endif ()
file(STRINGS "${WORK}/shadow_history.csv" history LIMIT_COUNT 2)
list(GET history 1 first)
if (first MATCHES "nan")
  message(FATAL_ERROR "the history has no error figures: ${first}")
endif ()
expect_exit(0 "${PROGRAM}" solve shadow --probes "${DATA}/shadow_probes.csv"
  --reference "${WORK}/shadow_values.csv" --report "${WORK}/shadow_again.json")
file(READ "${WORK}/shadow_again.json" again)
string(JSON rms GET "${again}" error probe_output_rms_relative_error)
if (rms GREATER 1e-12)
  message(FATAL_ERROR "the run's own values as reference: rms ${rms}")
endif ()
# The path-traced reference: at the probes, and per pixel of the --exr view.
expect_exit(0 "${PROGRAM}" solve shadow --probes "${DATA}/shadow_probes.csv"
  --reference pathtraced --reference-samples 4096 --exr "${WORK}/shadow.exr"
  --reference-exr "${WORK}/shadow_reference.exr" --size 32 --report "${WORK}/shadow_pt.json")
file(READ "${WORK}/shadow_pt.json" pt)
string(JSON kind GET "${pt}" error reference)
if (NOT kind MATCHES "^path traced: 4096 paths per probe" OR NOT EXISTS "${WORK}/shadow_reference.exr")
  message(FATAL_ERROR "path-traced reference: ${kind}")
endif ()
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
if (rms GREATER 0.05 OR NOT rms LESS leafRms)
  message(FATAL_ERROR "hierarchical error: interpolants ${rms}, leaves ${leafRms}")
endif ()
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
if (NOT n EQUAL 32 OR meshing OR NOT rms GREATER meshedRms)
  message(FATAL_ERROR "--no-discontinuity-meshing: ${n} lines, meshing ${meshing}, rms ${rms} "
    "(interpolants of the meshed run: ${meshedRms})")
endif ()
# A room from a file, the sensor in mid-air included (gathered from the leaves).
expect_exit(0 "${PROGRAM}" solve "${DATA}/room.obj" --method hierarchical --max-time 20
  --probes "${DATA}/room_probes.csv" --probe-output "${WORK}/hroom_values.csv")
file(STRINGS "${WORK}/hroom_values.csv" rows)
list(LENGTH rows n)
list(GET rows 1 centre)
string(REPLACE "," ";" centre "${centre}")
list(GET centre 3 er)
if (NOT n EQUAL 5 OR rows MATCHES "nan" OR er LESS 1 OR er GREATER 30)
  message(FATAL_ERROR "hierarchical room probes: ${rows}")
endif ()
expect_exit(2 "${PROGRAM}" solve shadow --method hierarchical --link-tolerance 0
  --output "${WORK}/bad.vtp")

# Meshless: the contact scene against its closed form, probes from the Shepard
# field, the Table 1 columns in the report.
file(WRITE "${WORK}/contact_probes.csv" "x,y,z,nx,ny,nz\n0.05,0.5,0,0,0,1\n0.3,0.5,0,0,0,1\n1.0,0.5,0,0,0,1\n")
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
string(JSON rms GET "${ml}" error rms_relative_error)
if (NOT n EQUAL 4 OR rows MATCHES "nan" OR NOT method STREQUAL "meshless" OR NOT generated GREATER gathered
    OR NOT gathered GREATER 0 OR NOT rms LESS 0.02)
  message(FATAL_ERROR "meshless: ${n} rows, method ${method}, samples ${generated}/${gathered}, rms ${rms}")
endif ()
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
    OR NOT rms LESS 0.01 OR NOT vtp MATCHES "IrradianceVector" OR NOT EXISTS "${WORK}/fc.png")
  message(FATAL_ERROR "facecluster: method ${method}, ${leaves} leaves, ${transfers} transfers, rms ${rms}")
endif ()
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
# basis cannot follow the light, against the paper's leaves.
file(WRITE "${WORK}/edge_probes.csv" "x,y,z,nx,ny,nz\n0.001,0.5,0,0,0,1\n0.01,0.5,0,0,0,1\n0.3,0.4,0,0,0,1\n")
foreach (halvings 0 4)
  expect_exit(0 "${PROGRAM}" solve contact --method facecluster --max-bisections ${halvings}
    --probes "${WORK}/edge_probes.csv" --reference analytic --probe-output "${WORK}/edge_values.csv"
    --report "${WORK}/edge_${halvings}.json")
  file(READ "${WORK}/edge_${halvings}.json" edge)
  string(JSON edge_rms_${halvings} GET "${edge}" error probe_output_rms_relative_error)
endforeach ()
if (NOT edge_rms_4 LESS 0.02 OR NOT edge_rms_4 LESS edge_rms_0)
  message(FATAL_ERROR "facecluster by a contact edge: rms ${edge_rms_4} halved, ${edge_rms_0} not")
endif ()

expect_exit(2 "${PROGRAM}" solve shadow --probes "${DATA}/room_probes.csv"
  --reference "${WORK}/shadow_values.csv" --output "${WORK}/bad.vtp")
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
expect_refusal("${WORK}/scene.gltf" "unknown scene file type '.gltf'")
