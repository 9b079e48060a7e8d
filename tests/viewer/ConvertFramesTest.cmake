# osgglyphconvert --frame-range (ctest -L viewer): the frames of a LAMMPS trajectory (melt500: 11
# frames of 500 atoms, timesteps 0, 20, .., 200), plain, gzip and zstd, each into a tile archive
# that osgglyphviewer renders; a frame that fails is reported and skipped; bad ranges fail with
# one line.
#   cmake -DCONVERT=<osgglyphconvert> -DVIEWER=<osgglyphviewer> -DCHECK=<osgglyphviewer_image_check>
#         -DTRAJECTORY_DIR=<tests/data/trajectory> -DWORK_DIR=<scratch> -P ConvertFramesTest.cmake
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK_DIR}")

# Copies of the dump, so that the frame indices are written here, beside them. The archives' clouds
# are named after the file: gz/ and zst/ also hold the compressed dumps under the plain name
# (recognised by their first bytes), whose archives are byte for byte those of plain/.
set(DUMP melt500.lammpstrj)
foreach(dir plain gz zst)
    file(MAKE_DIRECTORY "${WORK_DIR}/${dir}")
endforeach()
file(COPY_FILE "${TRAJECTORY_DIR}/${DUMP}" "${WORK_DIR}/plain/${DUMP}")
file(COPY_FILE "${TRAJECTORY_DIR}/${DUMP}.gz" "${WORK_DIR}/gz/${DUMP}.gz")
file(COPY_FILE "${TRAJECTORY_DIR}/${DUMP}.gz" "${WORK_DIR}/gz/${DUMP}")
file(COPY_FILE "${TRAJECTORY_DIR}/${DUMP}.zst" "${WORK_DIR}/zst/${DUMP}")

# One colour range and radius in every run, so that the archives of a range and of a single
# frame compare (a range's are otherwise those of 8 frames spread over the file).
set(MAPPING --range 0 6 --radius 0.4)

# Runs a command in the folder dir of the work folder.
macro(run_in dir)
    execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK_DIR}/${dir}"
        RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "[${dir}] ${ARGN}\n-> ${result}\n${out}${err}")
endmacro()

# The program fails with the exit code and one line on stderr matching "<program>: <pattern>".
function(expect_failure dir code pattern)
    run_in(${dir} ${ARGN})
    string(STRIP "${err}" line)
    if(NOT result EQUAL code OR line MATCHES "\n" OR NOT line MATCHES "^osgglyphconvert: ${pattern}")
        message(FATAL_ERROR "expected exit code ${code} and one line matching 'osgglyphconvert: ${pattern}'")
    endif()
endfunction()

# Fails unless the work folder's files a and b (relative paths) hold the same bytes.
function(expect_same_file a b)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/${a}" "${WORK_DIR}/${b}"
        RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "${a} is not ${b}")
    endif()
endfunction()

function(expect_files dir)
    foreach(file ${ARGN})
        if(NOT EXISTS "${WORK_DIR}/${dir}/${file}")
            message(FATAL_ERROR "${dir}/${file} was not written")
        endif()
    endforeach()
endfunction()

# Every third frame of the gzip file, its archives named by the frame's number; each holds its
# frame (its clouds are named after the frame's timestep).
run_in(gz "${CONVERT}" ${DUMP}.gz --frame-range 0:10:5 ${MAPPING} out%04d.osga)
if(NOT result EQUAL 0 OR NOT err MATCHES "wrote 3 frames to out%04d.osga: 1500 glyph-frames, [0-9.]+ MB \\([0-9.]+ bytes per glyph-frame\\) in [0-9.]+ s \\([0-9.e+-]+ M glyph-frames/s\\)")
    message(FATAL_ERROR "the conversion of frames 0, 5 and 10 failed")
endif()
expect_files(gz out0000.osga out0005.osga out0010.osga)
if(EXISTS "${WORK_DIR}/gz/out0001.osga")
    message(FATAL_ERROR "frame 1 is not in --frame-range 0:10:5")
endif()
foreach(frame 0 5 10)
    math(EXPR timestep "${frame} * 20")
    math(EXPR padded "10000 + ${frame}")
    string(SUBSTRING "${padded}" 1 4 number)
    file(STRINGS "${WORK_DIR}/gz/out${number}.osga" names REGEX "timestep")
    if(NOT names MATCHES "^${DUMP}.gz timestep ${timestep}$")
        message(FATAL_ERROR "out${number}.osga holds '${names}', not timestep ${timestep}")
    endif()
endforeach()

# The same frames, one at a time from the plain file (read whole, the path before frame ranges);
# the compressed files give them byte for byte, through --frame-range and --frame.
foreach(frame 0 5 10)
    run_in(plain "${CONVERT}" ${DUMP} --frame ${frame} ${MAPPING} frame${frame}.osga)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "the conversion of frame ${frame} failed")
    endif()
endforeach()
foreach(dir gz zst)
    run_in(${dir} "${CONVERT}" ${DUMP} --frame-range 0:10:5 ${MAPPING} same%d.osga)
    run_in(${dir} "${CONVERT}" ${DUMP} --frame 5 ${MAPPING} single5.osga)
    foreach(pair "same0;frame0" "same5;frame5" "same10;frame10" "single5;frame5")
        list(GET pair 0 archive)
        list(GET pair 1 expected)
        expect_same_file(${dir}/${archive}.osga plain/${expected}.osga)
    endforeach()
endforeach()

# Bad command lines and ranges.
expect_failure(gz 2 "--frame-range 0:10:5 writes an archive per frame: name the output with a pattern"
    "${CONVERT}" ${DUMP}.gz --frame-range 0:10:5 out.osga)
expect_failure(gz 2 "--frame-range 0: writes an archive per frame" "${CONVERT}" ${DUMP}.gz --frame-range 0: out.osga)
expect_failure(gz 1 "--frame-range 0:11 is past the last frame of ${DUMP}.gz \\(11 frames, 0 to 10\\)"
    "${CONVERT}" ${DUMP}.gz --frame-range 0:11 out%d.osga)
expect_failure(gz 1 "--frame-range 11: is past the last frame" "${CONVERT}" ${DUMP}.gz --frame-range 11: out%d.osga)
expect_failure(gz 1 "--frame 11 is past the last frame" "${CONVERT}" ${DUMP}.gz --frame 11 out.osga)
expect_failure(gz 2 "--frame-range '3:x': expected first:last" "${CONVERT}" ${DUMP}.gz --frame-range 3:x out%d.osga)
expect_failure(gz 2 "--frame-range '5:3': expected first:last" "${CONVERT}" ${DUMP}.gz --frame-range 5:3 out%d.osga)
expect_failure(gz 2 "--frame and --frame-range do not combine" "${CONVERT}" ${DUMP}.gz --frame 1 --frame-range 0:2
    out%d.osga)
expect_failure(gz 2 "out%s.osga: the output's pattern takes one integer conversion" "${CONVERT}" ${DUMP}.gz
    --frame-range 0:2 out%s.osga)

# Frames larger than --memory-glyphs are sorted through temporary files: the same archives, byte for
# byte.
run_in(gz "${CONVERT}" ${DUMP}.gz --frame-range 0:10:5 ${MAPPING} --memory-glyphs 100 small%04d.osga)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the conversion 100 glyphs at a time failed")
endif()
foreach(number 0000 0005 0010)
    expect_same_file(gz/small${number}.osga gz/out${number}.osga)
endforeach()

# A row of frame 3 (lines 1528 to 2036) damaged: that frame fails with a line naming it, the file
# and the line; the others are converted; the exit code is 1.
file(STRINGS "${WORK_DIR}/plain/${DUMP}" lines)
list(GET lines 1599 row)
string(REGEX REPLACE "^([^ ]+ [^ ]+ [^ ]+) [^ ]+" "\\1 abc" row "${row}")
list(REMOVE_AT lines 1599)
list(INSERT lines 1599 "${row}")
list(JOIN lines "\n" text)
file(WRITE "${WORK_DIR}/plain/broken.lammpstrj" "${text}\n")
run_in(plain "${CONVERT}" broken.lammpstrj --frame-range 0: broken%02d.osga)
string(REGEX MATCHALL "osgglyphconvert: frame [0-9]+[^\n]*" failures "${err}")
if(NOT result EQUAL 1 OR NOT failures MATCHES
        "^osgglyphconvert: frame 3 \\(timestep 60\\): broken.lammpstrj:1600: column 'y': 'abc' is not a number$"
        OR NOT err MATCHES "wrote 10 frames to broken%02d.osga" OR NOT err MATCHES "\nosgglyphconvert: 1 of 11 frames failed\n$")
    message(FATAL_ERROR "frame 3 did not fail alone, in one line naming it")
endif()
expect_files(plain broken00.osga broken02.osga broken04.osga broken10.osga)
if(EXISTS "${WORK_DIR}/plain/broken03.osga")
    message(FATAL_ERROR "broken03.osga was written")
endif()
# Into a series: the index lists the 10 frames converted, not frame 3.
run_in(plain "${CONVERT}" broken.lammpstrj --frame-range 0: brokenseries.osgt)
file(READ "${WORK_DIR}/plain/brokenseries.osgt" index)
if(NOT result EQUAL 1 OR NOT index MATCHES "Frames 10 {" OR index MATCHES "brokenseries_000003"
        OR NOT index MATCHES "\"brokenseries_000004.osga\" 80")
    message(FATAL_ERROR "the series' index does not list the frames converted, without frame 3:\n${index}")
endif()

# Frames that 8 of would pass --memory-glyphs: the colour range over fewer, said in a line.
run_in(gz "${CONVERT}" ${DUMP}.gz --frame-range 0:10:5 --memory-glyphs 1200 --radius 0.4 few%04d.osga)
if(NOT result EQUAL 0 OR NOT err MATCHES "osgglyphconvert: the colour range is taken over 2 frames, all that --memory-glyphs 1200 holds of frames of 500 points; --range fixes it\n")
    message(FATAL_ERROR "the colour range's frames were not fewer, or not said")
endif()

# A series: the frames' archives (those of the pattern, byte for byte) and their index, which the
# viewer plays: its frame 10 is out0010.osga's picture, pixel for pixel.
run_in(gz "${CONVERT}" ${DUMP}.gz --frame-range 0:10:5 ${MAPPING} series.osgt)
if(NOT result EQUAL 0 OR NOT err MATCHES "wrote 3 frames to series.osgt: 1500 glyph-frames")
    message(FATAL_ERROR "the series was not written")
endif()
foreach(number 0000 0005 0010)
    expect_same_file(gz/series_00${number}.osga gz/out${number}.osga)
endforeach()
file(READ "${WORK_DIR}/gz/series.osgt" index)
if(NOT index MATCHES "osgGlyphsTiles::TileSeries" OR NOT index MATCHES "Frames 3 {[ \n]*\"series_000000.osga\" 0[ \n]*\"series_000005.osga\" 100[ \n]*\"series_000010.osga\" 200")
    message(FATAL_ERROR "series.osgt does not list the frames:\n${index}")
endif()
expect_failure(gz 2 "out%d.osgt: a series' index is one file" "${CONVERT}" ${DUMP}.gz --frame-range 0:2 out%d.osgt)
run_in(gz "${VIEWER}" series.osgt --frame 2 --offscreen --size 320 240 --output series.osgt.png)
if(NOT result EQUAL 0 OR NOT out MATCHES "paged in")
    message(FATAL_ERROR "the viewer did not page the series' frame 2 in")
endif()
run_in(gz "${VIEWER}" out0010.osga --offscreen --size 320 240 --output out0010.osga.png)
run_in(gz "${CHECK}" match series.osgt.png out0010.osga.png 0 0)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the series' frame 2 is not out0010.osga")
endif()
# Pictures of every frame of the series, and a frame past its end.
run_in(gz "${VIEWER}" series.osgt --frame-range 0: --offscreen --size 160 120 --output series%d.png)
if(NOT result EQUAL 0 OR NOT EXISTS "${WORK_DIR}/gz/series2.png" OR EXISTS "${WORK_DIR}/gz/series3.png")
    message(FATAL_ERROR "the series' pictures were not written")
endif()
run_in(gz "${VIEWER}" series.osgt --frame 3 --offscreen --size 160 120 --output none.png)
if(NOT result EQUAL 1 OR NOT err MATCHES "--frame 3: series.osgt has 3 frames, counted from 0")
    message(FATAL_ERROR "--frame 3 of a series of 3 frames did not fail")
endif()

# The viewer renders the archives: the lattice of frame 0, the melt of frame 10.
foreach(number 0000 0010)
    run_in(gz "${VIEWER}" out${number}.osga --offscreen --size 320 240 --output out${number}.png)
    if(NOT result EQUAL 0 OR NOT out MATCHES "paged in")
        message(FATAL_ERROR "the viewer did not page out${number}.osga in")
    endif()
    run_in(gz "${CHECK}" coverage out${number}.png 0.05)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "out${number}.png shows no glyphs")
    endif()
endforeach()
run_in(gz "${CHECK}" differ out0000.png out0010.png 0.02)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "frames 0 and 10 look the same")
endif()
