# One case of osgglyphviewer's offscreen trajectory output (--frame-range, --interpolate, --movie)
# on the LAMMPS dump tests/data/trajectory/melt500.lammpstrj (11 frames of 500 atoms):
#   cmake -DCASE=<case> -DVIEWER=<osgglyphviewer> -DCHECK=<osgglyphviewer_image_check>
#         -DTRAJ_DIR=<tests/data/trajectory> -DWORK_DIR=<scratch> [-DMOVIE=<0|1>]
#         -P TrajectorySequenceTest.cmake
# Cases:
#   sequence     --frame-range 2:6:2 writes exactly seq000..seq002, each equal to a --frame render;
#                "8:" and "8:50" (past the end: clamped) write frames 8, 9 and 10
#   interpolate  --interpolate 1 --frame-range 0:2 writes 5 pictures, the one between its stored
#                neighbours differs from both, and the stored ones equal --frame renders
#   movie        --movie at --fps 5: 11 H.264 frames at 5/s (ffprobe; that part skipped without it),
#                its 5th decoded picture close to the 5th PNG; MOVIE=0 (no FFmpeg): one line saying so
#   errors       bad command lines: one line on stderr, exit code 1, no picture
#   compressed   .gz and .zst give the same picture as the plain file; opened again, each reads
#                its frame index without a warning
# The data is copied into WORK_DIR: opening a file writes its frame index beside it.
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
foreach(name melt500.lammpstrj melt500.lammpstrj.gz melt500.lammpstrj.zst)
    file(COPY "${TRAJ_DIR}/${name}" DESTINATION "${WORK_DIR}")
endforeach()
set(traj melt500.lammpstrj)
# One camera and one colour range for every picture, so that the pictures of a sequence and of
# single renders can be compared pixel for pixel (without --camera, a single render frames its
# own frame, a sequence its first one).
set(view --size 240 180 --camera 18 14 24 4.2 4.2 4.2 0 1 0 --range 0 3 --radius 0.4)

macro(run_viewer)
    execute_process(COMMAND "${VIEWER}" ${ARGN} WORKING_DIRECTORY "${WORK_DIR}"
        RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "osgglyphviewer ${ARGN}\n-> ${result}\n${out}${err}")
endmacro()

macro(expect_success)
    run_viewer(${ARGN})
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "expected success, got ${result}")
    endif()
endmacro()

# The viewer fails with exit code 1 (no crash), one line on stderr matching pattern, no picture.
function(expect_failure pattern)
    file(GLOB before "${WORK_DIR}/*.png" "${WORK_DIR}/*.mp4")
    run_viewer(${ARGN})
    if(NOT result EQUAL 1)
        message(FATAL_ERROR "expected exit code 1, got '${result}'")
    endif()
    string(STRIP "${err}" line)
    if(line MATCHES "\n" OR NOT line MATCHES "^osgglyphviewer: ${pattern}")
        message(FATAL_ERROR "expected one line on stderr matching 'osgglyphviewer: ${pattern}'")
    endif()
    file(GLOB after "${WORK_DIR}/*.png" "${WORK_DIR}/*.mp4")
    if(NOT before STREQUAL after)
        message(FATAL_ERROR "a failed run wrote files: ${after}")
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

# The PNG files matching glob in WORK_DIR, by name, must be exactly the expected names.
function(expect_files glob)
    file(GLOB found RELATIVE "${WORK_DIR}" "${WORK_DIR}/${glob}")
    list(SORT found)
    set(expected ${ARGN})
    if(NOT found STREQUAL expected)
        message(FATAL_ERROR "expected the files '${expected}', found '${found}'")
    endif()
endfunction()

if(CASE STREQUAL "sequence")
    expect_success(${traj} --frame-range 2:6:2 --output seq%03d.png ${view})
    expect_files("seq*" seq000.png seq001.png seq002.png)
    if(NOT out MATCHES "rendered 3 pictures \\(0 interpolated\\) in [0-9.]+ s")
        message(FATAL_ERROR "no line 'rendered 3 pictures (0 interpolated) in .. s'")
    endif()
    # Frames 2, 4 and 6, each as --frame renders it.
    foreach(picture frame IN ZIP_LISTS "0;1;2" "2;4;6")
        expect_success(${traj} --offscreen --frame ${frame} --output frame${frame}.png ${view})
        check(match seq00${picture}.png frame${frame}.png 0 0)
    endforeach()
    check(coverage seq001.png 0.1)
    check(differ seq000.png seq001.png 0.05)
    check(differ seq001.png seq002.png 0.05)
    # "a:" runs to the last frame; a last frame past the end is clamped to it.
    expect_success(${traj} --frame-range 8: --output tail%d.png ${view})
    expect_files("tail*" tail0.png tail1.png tail2.png)
    expect_success(${traj} --frame-range 8:50 --output past%d.png ${view})
    expect_files("past*" past0.png past1.png past2.png)
    expect_success(${traj} --offscreen --frame 10 --output frame10.png ${view})
    check(match tail2.png frame10.png 0 0)
    check(match past2.png frame10.png 0 0)
elseif(CASE STREQUAL "interpolate")
    expect_success(${traj} --interpolate 1 --frame-range 0:2 --output int%d.png ${view})
    set(sequence_out "${out}")
    expect_files("int*" int0.png int1.png int2.png int3.png int4.png)
    # Pictures 0, 2 and 4 are the stored frames 0, 1 and 2.
    foreach(picture frame IN ZIP_LISTS "0;2;4" "0;1;2")
        expect_success(${traj} --offscreen --frame ${frame} --output frame${frame}.png ${view})
        check(match int${picture}.png frame${frame}.png 0 0)
    endforeach()
    # The pictures between differ from both their neighbours.
    check(differ int0.png int1.png 0.05)
    check(differ int1.png int2.png 0.05)
    check(differ int2.png int3.png 0.05)
    check(differ int3.png int4.png 0.05)
    if(NOT sequence_out MATCHES "rendered 5 pictures \\(2 interpolated\\)")
        message(FATAL_ERROR "no line 'rendered 5 pictures (2 interpolated)'")
    endif()
elseif(CASE STREQUAL "movie")
    if(NOT MOVIE)
        expect_failure("m.mp4: this osgglyphviewer was built without FFmpeg's libraries"
            ${traj} --movie m.mp4 --frame-range 0:10 --fps 5 ${view})
        return()
    endif()
    expect_success(${traj} --movie m.mp4 --frame-range 0:10 --fps 5 --output m%02d.png ${view})
    if(NOT EXISTS "${WORK_DIR}/m.mp4")
        message(FATAL_ERROR "m.mp4 was not written")
    endif()
    if(NOT out MATCHES "wrote m.mp4 \\(11 pictures, libx264\\)")
        message(FATAL_ERROR "no line 'wrote m.mp4 (11 pictures, libx264)'")
    endif()
    expect_files("m*.png" m00.png m01.png m02.png m03.png m04.png m05.png m06.png m07.png m08.png m09.png
        m10.png)
    find_program(FFPROBE ffprobe)
    find_program(FFMPEG ffmpeg)
    if(NOT FFPROBE)
        message(STATUS "SKIPPED the movie's contents: ffprobe is not installed")
        return()
    endif()
    execute_process(COMMAND "${FFPROBE}" -v error -count_frames -select_streams v:0
        -show_entries stream=codec_name,nb_read_frames,r_frame_rate,width,height -of default=noprint_wrappers=1
        m.mp4 WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE result OUTPUT_VARIABLE probe ERROR_VARIABLE err)
    message(STATUS "ffprobe m.mp4 -> ${result}\n${probe}${err}")
    foreach(field codec_name=h264 nb_read_frames=11 r_frame_rate=5/1 width=240 height=180)
        if(NOT probe MATCHES "(^|\n)${field}\n")
            message(FATAL_ERROR "ffprobe: expected ${field}")
        endif()
    endforeach()
    if(FFMPEG)
        # The movie's picture 4 is the PNG of picture 4 (H.264 is lossy: within 64 levels at
        # 95 % of the pixels; pictures 3 and 5, or picture 4 upside down, miss by far).
        execute_process(COMMAND "${FFMPEG}" -v error -i m.mp4 -vf "select=eq(n\\,4)" -vsync 0 -frames:v 1
            decoded4.png WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE result)
        if(NOT result EQUAL 0)
            message(FATAL_ERROR "ffmpeg cannot decode picture 4 of m.mp4")
        endif()
        check(match decoded4.png m04.png 64 0.05)
    endif()
elseif(CASE STREQUAL "errors")
    expect_failure("--frame-range writes a picture per frame: give --output a pattern"
        ${traj} --frame-range 0:2 ${view})
    expect_failure("--frame-range writes a picture per frame: give --output a pattern"
        ${traj} --frame-range 0:2 --output single.png ${view})
    expect_failure("--frame-range '5:2': expected first:last" ${traj} --frame-range 5:2 --output b%d.png ${view})
    expect_failure("--frame-range '0:2:0': expected first:last" ${traj} --frame-range 0:2:0 --output b%d.png)
    expect_failure("--frame-range 'x:2': expected first:last" ${traj} --frame-range x:2 --output b%d.png)
    expect_failure("--frame-range: no frame 11 \\(the file has 11 frames, counted from 0\\)"
        ${traj} --frame-range 11:12 --output b%d.png ${view})
    expect_failure("--frame-range: no frame 20 \\(the file has 11 frames" ${traj} --movie b.mp4 --frame-range 20: ${view})
    expect_failure("--output 'b%d_%d.png': a pattern holds one integer conversion"
        ${traj} --frame-range 0:2 --output b%d_%d.png ${view})
    expect_failure("--output 'b%s.png': a pattern holds one integer conversion"
        ${traj} --frame-range 0:2 --output b%s.png ${view})
    expect_failure("--frame-range needs a file of frames" --frame-range 0:2 --output b%d.png ${view})
    expect_failure("--frame-range and --movie render the frames of the file; they do not combine with --frames"
        ${traj} --frame-range 0:2 --output b%d.png --frames 3 ${view})
    expect_failure("--interpolate needs a number of pictures from 0 to 1000"
        ${traj} --frame-range 0:2 --output b%d.png --interpolate -1)
    expect_failure("--fps needs a rate" ${traj} --movie b.mp4 --fps 0)
elseif(CASE STREQUAL "compressed")
    foreach(file ${traj} ${traj}.gz ${traj}.zst)
        expect_success(${file} --offscreen --frame 7 --output "${file}.png" ${view})
        if(NOT out MATCHES "${file}: 11\\+? frames \\(lammps")
            message(FATAL_ERROR "${file}: no line '11 frames (lammps...'")
        endif()
    endforeach()
    # Opened again, each file reads the frame index the first opening wrote beside it, silently.
    foreach(file ${traj} ${traj}.gz ${traj}.zst)
        if(NOT EXISTS "${WORK_DIR}/${file}.glyphindex")
            message(FATAL_ERROR "no frame index ${file}.glyphindex was written")
        endif()
        expect_success(${file} --offscreen --frame 7 --output "again.png" ${view})
        if(err MATCHES "warning")
            message(FATAL_ERROR "${file} opened again printed a warning: ${err}")
        endif()
        check(match again.png ${file}.png 0 0)
    endforeach()
    check(coverage ${traj}.png 0.1)
    check(match ${traj}.gz.png ${traj}.png 0 0)
    check(match ${traj}.zst.png ${traj}.png 0 0)
    # And a sequence from the compressed file, reading frames out of order.
    expect_success(${traj}.gz --frame-range 3:7:4 --output gz%d.png ${view})
    check(match gz1.png ${traj}.png 0 0)
else()
    message(FATAL_ERROR "unknown CASE '${CASE}'")
endif()
