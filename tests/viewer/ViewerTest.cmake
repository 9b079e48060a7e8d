# One case of the osgglyphviewer tests (ctest -L viewer), on the data of WriteViewerTestData.cmake:
#   cmake -DCASE=<case> -DVIEWER=<osgglyphviewer> -DCHECK=<osgglyphviewer_image_check>
#         -DDATA_DIR=<data> -DWORK_DIR=<scratch> -P ViewerTest.cmake
# Cases: render, cone, frame, malformed, unknown_column, unknown_option, frames, default, help,
# stray_shaders, broken_shader, hidden_cones, hidden_radius, hidden_sub_pixel, hidden_bounds, far,
# vast.
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(spheres "${DATA_DIR}/spheres.lammpstrj")
# Camera at (0, 0, 5) looking at the origin, y up: ViewerImageCheck's depth check assumes it.
set(view --size 160 120 --camera 0 0 5 0 0 0 0 1 0 --fov 30 --radius 0.5)
# Frame 0 of spheres.lammpstrj.
set(centres 0 0 0 1 0.7 0.5 -1 0.7 -0.5 1 -0.7 -0.5 -1 -0.7 0.3)

# Runs the viewer in viewer_dir; sets result, out and err.
set(viewer_dir "${WORK_DIR}")
macro(run_viewer)
    execute_process(COMMAND "${VIEWER}" ${ARGN} WORKING_DIRECTORY "${viewer_dir}"
        RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "osgglyphviewer ${ARGN}\n-> ${result}\n${out}${err}")
endmacro()

macro(expect_success)
    run_viewer(${ARGN})
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "expected success, got ${result}")
    endif()
endmacro()

# The viewer fails with exit code 1 (no crash) and one line on stderr matching pattern.
function(expect_failure pattern)
    run_viewer(${ARGN})
    if(NOT result EQUAL 1)
        message(FATAL_ERROR "expected exit code 1, got '${result}'")
    endif()
    string(STRIP "${err}" line)
    if(line MATCHES "\n" OR NOT line MATCHES "^osgglyphviewer: ${pattern}")
        message(FATAL_ERROR "expected one line on stderr matching 'osgglyphviewer: ${pattern}'")
    endif()
endfunction()

# The viewer writes the picture (exit code 0) with one line on stderr: a warning matching pattern.
function(expect_warning pattern)
    file(REMOVE "${WORK_DIR}/hidden.png")
    run_viewer(${ARGN} --offscreen --output hidden.png)
    if(NOT result EQUAL 0 OR NOT EXISTS "${WORK_DIR}/hidden.png")
        message(FATAL_ERROR "expected exit code 0 and hidden.png, got '${result}'")
    endif()
    string(STRIP "${err}" line)
    if(line MATCHES "\n" OR NOT line MATCHES "^osgglyphviewer: warning: ${pattern}")
        message(FATAL_ERROR "expected one line on stderr matching 'osgglyphviewer: warning: ${pattern}'")
    endif()
endfunction()

function(check)
    execute_process(COMMAND "${CHECK}" ${ARGN} WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE result
        OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "check ${ARGN}\n-> ${result}\n${out}${err}")
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "check failed: ${ARGN}")
    endif()
endfunction()

if(CASE STREQUAL "render")
    expect_success(${spheres} --offscreen --output render.png --depth-output render.pfm ${view})
    if(NOT EXISTS "${WORK_DIR}/render.png")
        message(FATAL_ERROR "render.png was not written")
    endif()
    check(depth render.pfm 160 120 30 5 0.5 ${centres})
    check(coverage render.png 0.05)
elseif(CASE STREQUAL "cone")
    expect_success(${spheres} --output spheres.png ${view})
    expect_success(${spheres} --output cones.png --glyph cone ${view})
    check(coverage cones.png 0.01)
    check(differ spheres.png cones.png 0.01)
elseif(CASE STREQUAL "frame")
    expect_success(${spheres} --output frame0.png ${view})
    expect_success(${spheres} --output frame1.png --frame 1 ${view})
    check(differ frame0.png frame1.png 0.01)
    expect_failure("--frame 2: .*spheres.lammpstrj has 2 frames" ${spheres} --offscreen --frame 2)
elseif(CASE STREQUAL "malformed")
    expect_failure(".*malformed.lammpstrj:12: .*'zero'" "${DATA_DIR}/malformed.lammpstrj" --offscreen)
elseif(CASE STREQUAL "unknown_column")
    expect_failure("--color-by: no column 'nope' in .*; available columns: id type x y z vx vy vz"
        ${spheres} --offscreen --color-by nope)
elseif(CASE STREQUAL "unknown_option")
    expect_failure("unrecognized option --frobnicate" ${spheres} --offscreen --frobnicate)
elseif(CASE STREQUAL "frames")
    expect_success(${spheres} --offscreen --frames 3 --size 160 120)
    if(NOT out MATCHES "\nframe_ms median=[0-9.]+ min=[0-9.]+ max=[0-9.]+\n")
        message(FATAL_ERROR "no frame_ms line")
    endif()
elseif(CASE STREQUAL "default")
    # The README's run command: the built-in scene, its path and the time taken.
    expect_success(--offscreen --output default.png --size 320 240)
    if(NOT out MATCHES "wrote [^\n]*default.png \\(320x240, [a-z]+\\) in [0-9.]+ ms")
        message(FATAL_ERROR "no line naming the image and the time")
    endif()
    check(coverage default.png 0.2)
elseif(CASE STREQUAL "help")
    expect_success(--help)
    foreach(option --format --frame --random --seed --position --radius --radius-by --color-by --colormap --range
            --vector --length-scale --glyph --unlit --technique --size --camera --fov --background --offscreen
            --headless --output --depth-output --frames)
        if(NOT out MATCHES "\n  ${option} ")
            message(FATAL_ERROR "--help does not list ${option}")
        endif()
    endforeach()
    foreach(key l n p r)
        if(NOT out MATCHES "\n  ${key}  ")
            message(FATAL_ERROR "--help does not list key ${key}")
        endif()
    endforeach()
elseif(CASE STREQUAL "stray_shaders")
    # Shader files of the library's names where the viewer runs change nothing.
    expect_success(${spheres} --output "${WORK_DIR}/clean.png" ${view})
    set(viewer_dir "${WORK_DIR}/stray")
    foreach(name sphere.glsl impostor.frag osgGlyphs/sphere.glsl osgGlyphs/impostor.frag)
        file(WRITE "${viewer_dir}/${name}" "this is not GLSL;\n")
    endforeach()
    expect_success(${spheres} --output "${WORK_DIR}/stray.png" ${view})
    if(err MATCHES "osgGlyphs|FAILED")
        message(FATAL_ERROR "the stray shaders were read")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/clean.png" "${WORK_DIR}/stray.png"
        RESULT_VARIABLE differ)
    if(differ)
        message(FATAL_ERROR "the stray shaders changed the picture")
    endif()
elseif(CASE STREQUAL "broken_shader")
    # A shader on OSG's data path that does not compile: one line naming it, exit code 1, no picture.
    file(WRITE "${WORK_DIR}/shaders/osgGlyphs/sphere.glsl" "// broken\n\nthis is not GLSL;\n")
    set(ENV{OSG_FILE_PATH} "${WORK_DIR}/shaders")
    expect_failure("glyph program 'osgGlyphs geometry-shader' does not compile: [^\n]*/shaders/osgGlyphs/sphere.glsl:3: error: "
        ${spheres} --offscreen --output broken.png ${view})
    if(EXISTS "${WORK_DIR}/broken.png")
        message(FATAL_ERROR "broken.png was written")
    endif()
elseif(CASE STREQUAL "hidden_cones")
    expect_warning("no glyph is drawn: every glyph is skipped \\(3 of 3 have a zero vector"
        "${DATA_DIR}/still.csv" --glyph cone --size 160 120)
elseif(CASE STREQUAL "hidden_radius")
    # The projection is fitted to the view; what remains is the shaders' float range.
    expect_warning("no glyph is seen: the glyphs lie up to [^ ]+ from the eye; beyond [^ ]+ the shaders' float arithmetic overflows"
        ${spheres} --size 160 120 --radius 1e30)
elseif(CASE STREQUAL "hidden_sub_pixel")
    expect_warning("the glyphs hardly show: every glyph is under a pixel wide" ${spheres} --size 160 120
        --radius 1e-6)
elseif(CASE STREQUAL "hidden_bounds")
    expect_warning("no glyph is drawn: the glyphs' bounds are not finite" "${DATA_DIR}/huge.csv" --size 160 120
        --radius 1e38)
elseif(CASE STREQUAL "far")
    # 1e7 from the origin on each axis, seen from the same place relative to the data: the same
    # picture, and the analytic depth.
    set(common --offscreen --size 160 120 --fov 30 --radius 0.5)
    expect_success("${DATA_DIR}/near.csv" --output near.png ${common} --camera 0 0 5 0 0 0 0 1 0)
    expect_success("${DATA_DIR}/far.csv" --output far.png --depth-output far.pfm ${common}
        --camera 10000000 10000000 10000005 10000000 10000000 10000000 0 1 0)
    check(coverage far.png 0.05)
    check(match far.png near.png 2 0.002)
    check(depth far.pfm 160 120 30 5 0.5 ${centres})
elseif(CASE STREQUAL "vast")
    # Points 1e17 apart, framed automatically: drawn, without a warning.
    expect_success("${DATA_DIR}/vast.csv" --offscreen --output vast.png --size 160 120)
    if(err MATCHES "warning")
        message(FATAL_ERROR "unexpected warning")
    endif()
    check(coverage vast.png 0.005)
else()
    message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
