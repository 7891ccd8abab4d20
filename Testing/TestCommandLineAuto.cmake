# vtkradiosity solve --method auto (the default): the method chosen per scene
# by MethodChoice.h's rules, said in the report's method_choice and on stderr,
# and the choice paying off where the scene has an exact answer.
# cmake -DPROGRAM=vtkradiosity -DDATA=Testing/Data -DWORK=dir -P TestCommandLineAuto.cmake
include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Reads the report's method and method_choice into m_method, m_requested,
# m_chosen and m_why.
function(read_choice file)
  file(READ "${file}" report)
  string(JSON method GET "${report}" method)
  string(JSON requested GET "${report}" method_choice requested)
  string(JSON chosen GET "${report}" method_choice chosen)
  string(JSON whyType TYPE "${report}" method_choice why)
  set(why "")
  if (whyType STREQUAL "STRING")
    string(JSON why GET "${report}" method_choice why)
  endif ()
  set(m_method "${method}" PARENT_SCOPE)
  set(m_requested "${requested}" PARENT_SCOPE)
  set(m_chosen "${chosen}" PARENT_SCOPE)
  set(m_why "${why}" PARENT_SCOPE)
endfunction()

# 1. The shadow scene (38 triangles, matte): clustered hierarchical radiosity
#    with discontinuity meshing, the penumbrae exact where progressive
#    refinement's constant elements smear them (its RMS 3.56e-2 at the
#    defaults, TestCommandLine.cmake). Measured: RMS 3.55e-4 of the peak.
expect_exit(0 "${PROGRAM}" solve shadow --probes "${DATA}/shadow_probes.csv" --reference analytic
  --report "${WORK}/shadow.json")
read_choice("${WORK}/shadow.json")
if (NOT m_method STREQUAL "hierarchical" OR NOT m_requested STREQUAL "auto" OR NOT m_chosen STREQUAL "hierarchical"
    OR NOT m_why MATCHES "^38 triangles, at most 2048")
  message(FATAL_ERROR "shadow: method ${m_method}, choice ${m_requested} -> ${m_chosen} (${m_why})")
endif ()
if (NOT last_stderr MATCHES "method auto: hierarchical \\(38 triangles")
  message(FATAL_ERROR "shadow: stderr does not say what auto chose:\n${last_stderr}")
endif ()
file(READ "${WORK}/shadow.json" shadow)
string(JSON clustered GET "${shadow}" parameters clustered)
string(JSON from GET "${shadow}" error evaluated_from)
string(JSON rms GET "${shadow}" error rms_relative_error)
if (NOT clustered OR NOT from STREQUAL "quadratic interpolants")
  message(FATAL_ERROR "shadow: clustered ${clustered}, evaluated from ${from}")
endif ()
expect_within("shadow: auto's RMS error against the closed form (measured 3.55e-4)" "${rms}" 0 1e-3)

# 2. A method by name is solved as asked, with no choice to explain.
expect_exit(0 "${PROGRAM}" solve shadow --method progressive --report "${WORK}/named.json")
read_choice("${WORK}/named.json")
if (NOT m_method STREQUAL "progressive" OR NOT m_requested STREQUAL "progressive" OR NOT m_why STREQUAL ""
    OR last_stderr MATCHES "method auto")
  message(FATAL_ERROR "by name: method ${m_method}, choice ${m_requested} -> ${m_chosen} (${m_why})")
endif ()

# 3. A glossy floor under a lamp (.obj with Ks): face cluster radiosity.
file(WRITE "${WORK}/glossy.mtl" "newmtl floor\nKd 0.5 0.5 0.5\nKs 0.3 0.3 0.3\nNs 20\n"
  "newmtl lamp\nKd 0 0 0\nKe 10 10 10\n")
file(WRITE "${WORK}/glossy.obj" "mtllib glossy.mtl\n"
  "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv -0.2 -0.2 1\nv 0.2 -0.2 1\nv 0.2 0.2 1\nv -0.2 0.2 1\n"
  "usemtl floor\nf 1 2 3\nf 1 3 4\nusemtl lamp\nf 5 7 6\nf 5 8 7\n")
expect_exit(0 "${PROGRAM}" solve "${WORK}/glossy.obj" --report "${WORK}/glossy.json")
read_choice("${WORK}/glossy.json")
if (NOT m_method STREQUAL "facecluster" OR NOT m_why MATCHES "^2 of the 4 triangles have a glossy part")
  message(FATAL_ERROR "glossy: method ${m_method} (${m_why})")
endif ()

# 4. A matte floor of 2,178 triangles (a 33 x 33 grid) under the lamp:
#    more than 2048, meshless radiosity.
set(obj "mtllib glossy.mtl\n")
foreach (j RANGE 33)
  foreach (i RANGE 33)
    string(APPEND obj "v ${i} ${j} 0\n") # a 33 m square floor
  endforeach ()
endforeach ()
string(APPEND obj "v 15 15 8\nv 18 15 8\nv 18 18 8\nv 15 18 8\nusemtl lamp\nf 1157 1159 1158\nf 1157 1160 1159\n")
file(WRITE "${WORK}/large.mtl" "newmtl floor\nKd 0.5 0.5 0.5\nnewmtl lamp\nKd 0 0 0\nKe 10 10 10\n")
string(REPLACE "glossy.mtl" "large.mtl" obj "${obj}")
string(APPEND obj "usemtl floor\n")
foreach (j RANGE 32)
  foreach (i RANGE 32)
    math(EXPR a "${j} * 34 + ${i} + 1")
    math(EXPR b "${a} + 1")
    math(EXPR c "${a} + 35")
    math(EXPR d "${a} + 34")
    string(APPEND obj "f ${a} ${b} ${c}\nf ${a} ${c} ${d}\n")
  endforeach ()
endforeach ()
file(WRITE "${WORK}/large.obj" "${obj}")
expect_exit(0 "${PROGRAM}" solve "${WORK}/large.obj" --report "${WORK}/large.json")
read_choice("${WORK}/large.json")
file(READ "${WORK}/large.json" large)
string(JSON triangles GET "${large}" scene triangles)
if (NOT m_method STREQUAL "meshless" OR NOT triangles EQUAL 2180 OR NOT m_why MATCHES "^2180 triangles, more than 2048")
  message(FATAL_ERROR "large: method ${m_method}, ${triangles} triangles (${m_why})")
endif ()
message(STATUS "auto: shadow hierarchical (RMS ${rms}), glossy facecluster, 2180 triangles meshless")
