# bench_render --quick (the CI run of the render benchmark): the Cornell box by
# every display at the three sizes, 3 frames each, into a directory that does
# not exist yet; then render.md checked: the machine and OpenGL renderer, one
# row per display and size with finite positive times (median and mean at
# most the worst, fps 1000 / mean), each frame lit (not a black window) and
# the pass solved once over all its frames. Without a display: skipped.
# cmake -DPROGRAM=bench_render -DWORK=dir -P TestBenchRenderQuick.cmake
include("${CMAKE_CURRENT_LIST_DIR}/CliTestSupport.cmake")

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${PROGRAM}" "${WORK}" --quick
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (rc EQUAL 77)
  message(STATUS "SKIPPED: ${err}")
  return()
endif ()
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "bench_render --quick exited ${rc}:\n${out}\n${err}")
endif ()
message(STATUS "${out}")

file(READ "${WORK}/render.md" md)
foreach (expected "Mode: quick" "OpenGL renderer: [^.]+[.]" "Load average" "The pass solved once")
  if (NOT md MATCHES "${expected}")
    message(FATAL_ERROR "render.md does not match '${expected}':\n${md}")
  endif ()
endforeach ()

set(displays "quadratic interpolants|hierarchical" "vector irradiance|facecluster"
  "Shepard splats|meshless" "element samples|progressive" "Gouraud|progressive" "vtkRadiosityPass|facecluster")
set(sizes "640 x 480" "1280 x 720" "1920 x 1080")
set(number "([0-9]+[.]?[0-9]*)")
foreach (entry IN LISTS displays)
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 display)
  list(GET entry 1 method)
  foreach (size IN LISTS sizes)
    set(what "cornell, ${display}, ${size}")
    if (NOT md MATCHES "\n\\| cornell \\| 32 \\| ${display} \\| ${method} \\| ${number} \\| ${number} \\| ${size} \\| 3 \\| ${number} \\| ${number} \\| ${number} \\| ${number} \\| ${number}% \\|")
      message(FATAL_ERROR "render.md: no row for ${what}:\n${md}")
    endif ()
    set(solve "${CMAKE_MATCH_1}")
    set(median "${CMAKE_MATCH_3}")
    set(mean "${CMAKE_MATCH_4}")
    set(worst "${CMAKE_MATCH_5}")
    set(fps "${CMAKE_MATCH_6}")
    set(lit "${CMAKE_MATCH_7}")
    expect_within("${what} solve (s)" "${solve}" 0 300)
    expect_within("${what} median (ms)" "${median}" 0.01 "${worst}")
    expect_within("${what} mean (ms)" "${mean}" 0.01 "${worst}")
    # fps is 1000 / mean, both rounded to 0.1 (fps below 10 to 0.01).
    float_eval(low "1000 / (${mean} + 0.05) - 0.05")
    float_eval(high "1000 / (${mean} - 0.05 > 0.001 ? ${mean} - 0.05 : 0.001) + 0.05")
    expect_within("${what} fps (mean ${mean} ms)" "${fps}" "${low}" "${high}")
    # The box fills about 70% of a 4:3 frame and 50% of a 16:9 one.
    expect_within("${what} lit pixels (%)" "${lit}" 30 100)
  endforeach ()
endforeach ()
message(STATUS "bench_render --quick: 6 displays x 3 sizes checked")
