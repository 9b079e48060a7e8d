# The point formats osgGlyphsData reads and the file names that select them: the one place to
# add a format or an extension. From this table CMake generates PointFormatTable.h, behind
# osgGlyphsData::getPointFormats(), readPointFile() and the osgdb_glyphs plugin's extensions,
# and the list of osgdb_<extension> links to osgdb_glyphs (OSGGLYPHS_PLUGIN_ALIASES).
#
# osgglyphs_point_format(<name> <reader> <description> EXTENSIONS <extension>...
#                        [PREFIXES <prefix>...] [FRAME_FILE] [NO_PLUGIN_ALIASES])
#   <reader>           the function of readers/Readers.h that reads it from a stream, or with
#                      FRAME_FILE the function of formats/Formats.h that opens it as a FrameFile
#                      (binary formats read at any frame; see osgGlyphsData/FrameFile)
#   EXTENSIONS         lower case, without the dot
#   PREFIXES           file names starting with one of these are of this format too
#   NO_PLUGIN_ALIASES  another osgDB plugin owns the extensions: osgdb_glyphs reads those files
#                      as <file>.glyphs or when loaded first, and no osgdb_<extension> link is made

set(OSGGLYPHS_POINT_FORMAT_ROWS "")
set(OSGGLYPHS_PLUGIN_ALIASES "")

function(osgglyphs_point_format name reader description)
    cmake_parse_arguments(ARG "NO_PLUGIN_ALIASES;FRAME_FILE" "" "EXTENSIONS;PREFIXES" ${ARGN})
    if(NOT ARG_EXTENSIONS OR ARG_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "osgglyphs_point_format(${name}): give EXTENSIONS, and nothing else unnamed")
    endif()
    list(JOIN ARG_EXTENSIONS " " extensions)
    list(JOIN ARG_PREFIXES " " prefixes)
    if(ARG_FRAME_FILE)
        set(functions "nullptr, formats::${reader}")
    else()
        set(functions "readers::${reader}, nullptr")
    endif()
    string(APPEND OSGGLYPHS_POINT_FORMAT_ROWS
        "    {\"${name}\", \"${description}\", ${functions}, \"${extensions}\", \"${prefixes}\"},\n")
    set(OSGGLYPHS_POINT_FORMAT_ROWS "${OSGGLYPHS_POINT_FORMAT_ROWS}" PARENT_SCOPE)
    if(NOT ARG_NO_PLUGIN_ALIASES)
        list(APPEND OSGGLYPHS_PLUGIN_ALIASES ${ARG_EXTENSIONS})
        set(OSGGLYPHS_PLUGIN_ALIASES "${OSGGLYPHS_PLUGIN_ALIASES}" PARENT_SCOPE)
    endif()
endfunction()

osgglyphs_point_format(csv readCsv "Comma-separated point columns" EXTENSIONS csv)
osgglyphs_point_format(xyz readXyz "XYZ / extended XYZ" EXTENSIONS xyz extxyz)
osgglyphs_point_format(lammps readLammps "LAMMPS text dump" EXTENSIONS lammpstrj lammps dump PREFIXES dump.)
# OSG's own ply plugin reads .ply files as meshes.
osgglyphs_point_format(ply readPly "PLY vertices as glyphs" EXTENSIONS ply NO_PLUGIN_ALIASES)
osgglyphs_point_format(vtk readVtk "Legacy VTK points as glyphs" EXTENSIONS vtk)
osgglyphs_point_format(dcd openDcd "DCD trajectory (CHARMM, NAMD, LAMMPS)" EXTENSIONS dcd FRAME_FILE)
osgglyphs_point_format(xtc openXtc "GROMACS XTC trajectory (compressed positions)" EXTENSIONS xtc FRAME_FILE)
osgglyphs_point_format(trr openTrr "GROMACS TRR trajectory (positions, velocities, forces)" EXTENSIONS trr FRAME_FILE)
osgglyphs_point_format(gsd openGsd "HOOMD-blue GSD trajectory" EXTENSIONS gsd FRAME_FILE)
osgglyphs_point_format(las openLas "ASPRS LAS lidar points (LAS 1.2-1.4)" EXTENSIONS las laz FRAME_FILE)
osgglyphs_point_format(pdb openPdb "Protein Data Bank coordinates (models as frames)" EXTENSIONS pdb ent FRAME_FILE)
osgglyphs_point_format(gro openGro "GROMACS GRO coordinates (frames)" EXTENSIONS gro FRAME_FILE)
osgglyphs_point_format(lammpsdata readLammpsData "LAMMPS data file (write_data): atoms, masses, velocities" EXTENSIONS data lammpsdata PREFIXES data.)
