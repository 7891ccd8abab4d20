# vtkradiosity solve on what real files bring (issue 53):
# - a glTF file with a degenerate light (a sun on a node scaled to zero: its
#   direction collapses, as a .3ds light whose position is its target) is
#   solved with the warning naming that light, which is left out and counted
#   in the report (scene.import.file_lights_left_out); the good light lights
#   the floor as before;
# - --view: a bad camera refused before the solve, a good one draws;
# - a floor modelled upside down under a lamp draws the facing-away warning
#   and receives nothing; --two-sided solves its other side, which the lamp
#   lights to the closed form I h / d^3;
# cmake -DPROGRAM=vtkradiosity -DDATA=Testing/Data -DWORK=dir -DSUPPORT=Testing/CliTestSupport.cmake -P TestCommandLineTruth.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${SUPPORT}")

# --- A degenerate light in a file: warned about, left out, the rest solved.
file(READ "${DATA}/gltf_point_floor.gltf" gltf)
string(JSON gltf SET "${gltf}" extensions KHR_lights_punctual lights 1
  "{\"type\": \"directional\", \"name\": \"flat sun\", \"intensity\": 5}")
string(JSON gltf SET "${gltf}" nodes 4
  "{\"name\": \"sun\", \"scale\": [0, 0, 0], \"extensions\": {\"KHR_lights_punctual\": {\"light\": 1}}}")
string(JSON gltf SET "${gltf}" scenes 0 nodes 3 4)
file(WRITE "${WORK}/degenerate.gltf" "${gltf}")
file(WRITE "${WORK}/floor_probe.csv" "x,y,z,nx,ny,nz\n0,0,0,0,1,0\n")
expect_exit(0 "${PROGRAM}" solve "${WORK}/degenerate.gltf" --method progressive --probes "${WORK}/floor_probe.csv"
  --probe-output "${WORK}/degenerate.csv" --report "${WORK}/degenerate.json")
if (NOT last_stderr MATCHES "warning: [^\n]*degenerate\\.gltf: light 1 \\('flat sun'\\) \\(directional\\): field 'direction' is a zero vector[^\n]*that light is left out")
  message(FATAL_ERROR "no warning naming the degenerate light:\n${last_stderr}")
endif ()
file(READ "${WORK}/degenerate.json" report)
string(JSON left GET "${report}" scene import file_lights_left_out)
string(JSON lights GET "${report}" scene import file_lights)
if (NOT left EQUAL 1 OR NOT lights EQUAL 2)
  message(FATAL_ERROR "file_lights ${lights}, file_lights_left_out ${left}: expected 2 and 1")
endif ()
# The bulb (2 W/sr x colour (1, 0.5, 0.25), 1 m above the floor's centre):
# E_r = I / h^2 = 2 W/m^2 at the sensor under it.
read_probe_values("${WORK}/degenerate.csv" e)
list(GET e_0 3 red)
expect_within("floor irradiance under the bulb" "${red}" 1.999 2.001)

# --- A floor upside down under a lamp, then solved on both sides.
file(WRITE "${WORK}/flipped.obj" "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nf 1 3 2\nf 1 4 3\n")
file(WRITE "${WORK}/lamp.json" "{ \"lights\": [ { \"type\": \"point\", \"position\": [0, 0, 1], \"intensity\": 3 } ] }\n")
file(WRITE "${WORK}/up.csv" "x,y,z,nx,ny,nz\n0.5,0,0,0,0,1\n")
expect_exit(0 "${PROGRAM}" solve "${WORK}/flipped.obj" --lights "${WORK}/lamp.json" --method progressive
  --probes "${WORK}/up.csv" --probe-output "${WORK}/one.csv")
if (NOT last_stderr MATCHES "warning: 2 triangles \\(100\\.0% of the surface area[^\n]*face away from every light[^\n]*--two-sided")
  message(FATAL_ERROR "no facing-away warning:\n${last_stderr}")
endif ()
expect_exit(0 "${PROGRAM}" solve "${WORK}/flipped.obj" --lights "${WORK}/lamp.json" --method progressive
  --two-sided --probes "${WORK}/up.csv" --probe-output "${WORK}/two.csv")
if (last_stderr MATCHES "face away from every light")
  message(FATAL_ERROR "the facing-away warning with --two-sided:\n${last_stderr}")
endif ()
# I h / d^3 at (0.5, 0, 0) under the lamp at (0, 0, 1): 3 / 1.25^1.5.
read_probe_values("${WORK}/two.csv" e)
list(GET e_0 3 lit)
float_eval(exact "3 / (1.25 ^ 1.5)")
float_eval(lo "${exact} * 0.9999")
float_eval(hi "${exact} * 1.0001")
expect_within("two-sided floor under the lamp" "${lit}" "${lo}" "${hi}")

# --- --view: a camera of the user's, checked before the solve.
foreach (bad "1,2,3,4,5" "0,0,0,0,0,0" "0,0,0,1,0,0,1,0,0" "0,0,0,1,0,0,0,0,1,200" "0,0,x,1,0,0")
  expect_exit(2 "${PROGRAM}" solve cornell --view "${bad}" --image "${WORK}/bad.png" --report "${WORK}/bad.json")
  expect_one_error("error: bad input: --view '${bad}'")
  if (EXISTS "${WORK}/bad.json")
    message(FATAL_ERROR "--view '${bad}' was refused after the solve")
  endif ()
endforeach ()
# Inside the Cornell box (0.556 m wide), from its open side towards the back wall.
expect_exit(0 "${PROGRAM}" solve cornell --method progressive --max-iterations 100
  --view "0.278,0.273,-0.5,0.278,0.273,0.5,0,1,0,40" --image "${WORK}/view.png" --size 64)
if (NOT EXISTS "${WORK}/view.png")
  message(FATAL_ERROR "--view: no picture")
endif ()
