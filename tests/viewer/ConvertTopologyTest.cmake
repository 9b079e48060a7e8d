# osgglyphconvert --topology (ctest -L viewer): the melt's DCD (coordinates only) given its atoms'
# species and elements by the PDB that MDAnalysis wrote (tests/data/formats/pdb), and its types and
# masses by LAMMPS' data file; an atom count that differs fails with one line naming both files.
# The viewer takes the option too.
#   cmake -DCONVERT=<osgglyphconvert> -DVIEWER=<osgglyphviewer> -DFORMAT_DIR=<tests/data/formats>
#         -DWORK_DIR=<scratch> -P ConvertTopologyTest.cmake
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(DCD "${FORMAT_DIR}/melt.dcd")

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

# The PDB's species colour the glyphs, its elements size them.
run("${CONVERT}" --topology "${FORMAT_DIR}/pdb/melt.pdb" --frame 3 --color-by species "${DCD}" species.osga)
if(NOT result EQUAL 0 OR NOT err MATCHES "coloured by species" OR NOT err MATCHES "covalent radii"
   OR NOT EXISTS "${WORK_DIR}/species.osga")
    message(FATAL_ERROR "the DCD with the PDB's species was not converted")
endif()
# Without the topology the DCD has no species.
expect_failure(osgglyphconvert 1 "--color-by: no column 'species'"
    "${CONVERT}" --frame 3 --color-by species "${DCD}" none.osga)

# The data file's masses, through --frame-range.
run("${CONVERT}" --topology "${FORMAT_DIR}/pdb/melt.data" --frame-range 0:5:5 --color-by mass "${DCD}" mass%d.osga)
if(NOT result EQUAL 0 OR NOT err MATCHES "coloured by mass \\(viridis, 0.5 .. 1\\)"
   OR NOT EXISTS "${WORK_DIR}/mass0.osga" OR NOT EXISTS "${WORK_DIR}/mass5.osga")
    message(FATAL_ERROR "the DCD with the data file's masses was not converted")
endif()

# One atom is not the DCD's 500.
file(WRITE "${WORK_DIR}/one.pdb"
    "ATOM      1  Ar  LJ1 A   1       0.000   0.000   0.000  1.00  1.50          AR\n")
string(REPLACE "." "\\." dcdPattern "${DCD}")
expect_failure(osgglyphconvert 1 "${dcdPattern}: frame 0 has 500 atoms, its topology one\\.pdb 1$"
    "${CONVERT}" --topology one.pdb "${DCD}" bad.osga)
expect_failure(osgglyphconvert 2 "--topology needs a file of frames, not --random"
    "${CONVERT}" --topology one.pdb --random 10 random.osga)

# The viewer reads the option (and needs a file for it).
expect_failure(osgglyphviewer 1 "--topology needs a file of frames" "${VIEWER}" --topology one.pdb)
run("${VIEWER}" --help)
if(NOT out MATCHES "--topology <file>")
    message(FATAL_ERROR "osgglyphviewer --help does not describe --topology")
endif()
