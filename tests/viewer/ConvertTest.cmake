# osgglyphconvert (ctest -L viewer): a random dataset and a point file into tile archives that
# osgglyphviewer renders; bad command lines fail with one line.
#   cmake -DCONVERT=<osgglyphconvert> -DVIEWER=<osgglyphviewer> -DCHECK=<osgglyphviewer_image_check>
#         -DDATA_DIR=<data> -DSAMPLES_DIR=<share/data> -DWORK_DIR=<scratch> -P ConvertTest.cmake
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

macro(run)
    execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK_DIR}"
        RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "${ARGN}\n-> ${result}\n${out}${err}")
endmacro()

# The program fails with the exit code and one line on stderr matching "<program>: <pattern>".
function(expect_failure program code pattern)
    run(${ARGN})
    string(STRIP "${err}" line)
    if(NOT result EQUAL code OR line MATCHES "\n" OR NOT line MATCHES "^${program}: ${pattern}")
        message(FATAL_ERROR "expected exit code ${code} and one line matching '${program}: ${pattern}'")
    endif()
endfunction()

expect_failure(osgglyphconvert 2 "unknown option --bogus" "${CONVERT}" --bogus "${DATA_DIR}/spheres.lammpstrj" out.osga)
expect_failure(osgglyphconvert 2 "needs an input file and an output file" "${CONVERT}" out.osga)
expect_failure(osgglyphconvert 2 "out.ive: the output is an OSG archive" "${CONVERT}" --random 10 out.ive)
expect_failure(osgglyphconvert 2 "--tile-cells needs a power of two" "${CONVERT}" --tile-cells 3 --random 10 out.osga)
expect_failure(osgglyphconvert 2 "--threads needs a number from 1" "${CONVERT}" --threads 0 --random 10 out.osga)
expect_failure(osgglyphconvert 2 "--glyph-budget needs a whole number of glyphs" "${CONVERT}" --glyph-budget 2.5 --random 10 out.osga)
expect_failure(osgglyphconvert 1 ".*missing.xyz" "${CONVERT}" missing.xyz out.osga)
expect_failure(osgglyphconvert 1 ".*malformed.lammpstrj:12:.*" "${CONVERT}" "${DATA_DIR}/malformed.lammpstrj" out.osga)

# A random dataset in several levels of tiles, rendered by the viewer once paged in.
run("${CONVERT}" --random 60000 --tile-glyphs 4000 random.osga)
if(NOT result EQUAL 0 OR NOT err MATCHES "wrote random.osga: 60000 glyphs")
    message(FATAL_ERROR "the conversion failed")
endif()
run("${VIEWER}" random.osga --offscreen --size 320 240 --output random.png)
if(NOT result EQUAL 0 OR NOT out MATCHES "paged in tiles")
    message(FATAL_ERROR "the viewer did not page the tiles in")
endif()
run("${CHECK}" coverage random.png 0.05)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "random.png shows no glyphs")
endif()

# Files larger than the glyphs held in memory are read in parts, over passes until the mapping
# settles, and cut into tiles through temporary files: the archive is the one read whole (on one
# thread, which keeps the order of the files in the archive too).
foreach(sample "melt4k.lammpstrj" "galaxy.vtk;--glyph;arrow" "water64.xyz" "torus.ply" "probes.csv;--color-by;density")
    list(POP_FRONT sample file)
    set(options ${sample})
    run("${CONVERT}" "${SAMPLES_DIR}/${file}" ${options} --tile-glyphs 50 --tile-cells 4 --threads 1 whole.osga)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "the conversion of ${file} failed")
    endif()
    run("${CONVERT}" "${SAMPLES_DIR}/${file}" ${options} --tile-glyphs 50 --tile-cells 4 --memory-glyphs 500 --threads 1
        parts.osga)
    if(NOT result EQUAL 0 OR NOT err MATCHES "read [^\n]*${file} in [0-9]+ parts, [0-9]+ pass")
        message(FATAL_ERROR "${file} was not read in parts")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files whole.osga parts.osga
        WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "${file} read in parts gave another archive than read whole")
    endif()
    file(GLOB leftovers "${WORK_DIR}/osgglyphs-tiles-*")
    if(leftovers)
        message(FATAL_ERROR "temporary files left: ${leftovers}")
    endif()
endforeach()

# A LAMMPS dump coloured by a column, as cones.
run("${CONVERT}" "${DATA_DIR}/spheres.lammpstrj" --glyph cone --color-by vx dump.osga)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the conversion of the dump failed")
endif()
run("${VIEWER}" dump.osga --offscreen --size 320 240 --output dump.png)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the viewer failed on dump.osga")
endif()
run("${CHECK}" coverage dump.png 0.01)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "dump.png shows no glyphs")
endif()
expect_failure(osgglyphviewer 1 "not-there.osga: no such file" "${VIEWER}" not-there.osga --offscreen)
