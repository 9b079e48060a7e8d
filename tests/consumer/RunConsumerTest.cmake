# Installs the built osgGlyphs into a scratch prefix, then builds and runs the consumer
# against it: through find_package(osgGlyphs), through pkg-config, and once more with the
# installed shader files replacing the embedded ones. Every run renders the consumer's scene
# and compares it with BASELINE; OSGGLYPHS_BLESS=1 makes the first run rewrite BASELINE.
# Variables: BUILD_DIR, SOURCE_DIR, WORK_DIR, BASELINE, CXX, CXX_FLAGS, STOCK_TOOL_PRELOAD (the ASan
# runtime for stock OSG programs in sanitizer builds).

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    message("${output}")
    if(NOT result EQUAL 0)
        list(JOIN ARGN " " command)
        message(FATAL_ERROR "failed (${result}): ${command}")
    endif()
endfunction()

# The program must load libosgGlyphs from the prefix, not from the build tree.
function(check_loads_installed_library program)
    execute_process(COMMAND ldd "${program}" OUTPUT_VARIABLE output RESULT_VARIABLE result)
    string(REGEX MATCH "libosgGlyphs[^\n]*=> not found" missing "${output}")
    if(missing)
        message(FATAL_ERROR "${program} does not find the installed library (no RPATH?): ${missing}")
    endif()
    string(REGEX MATCH "libosgGlyphs[^\n]*=> ([^ \n]*)" line "${output}")
    set(library "${CMAKE_MATCH_1}")
    if(NOT result EQUAL 0 OR library STREQUAL "")
        message(FATAL_ERROR "ldd ${program} does not show libosgGlyphs:\n${output}")
    endif()
    file(REAL_PATH "${library}" library)
    file(REAL_PATH "${prefix}" real_prefix)
    string(FIND "${library}" "${real_prefix}/" at)
    if(NOT at EQUAL 0)
        message(FATAL_ERROR "${program} loads ${library}, not the installed library under ${real_prefix}")
    endif()
    message("${program} loads ${library}")
endfunction()

# Run the consumer (arguments: the program, the image it writes) without the blessing after the first run.
function(run_consumer program image)
    check_loads_installed_library("${program}")
    run("${program}" "${BASELINE}" "${WORK_DIR}/${image}")
    unset(ENV{OSGGLYPHS_BLESS})
endfunction()

set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
# Nothing from the build tree: no shader or plugin paths that ctest or the caller set.
unset(ENV{OSG_FILE_PATH})
unset(ENV{OSG_LIBRARY_PATH})
unset(ENV{LD_LIBRARY_PATH})
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")

# The installed programs and plugins find the installed libraries through their RPATH, with
# LD_LIBRARY_PATH unset: the programs render, the plugins resolve their libraries.
file(GLOB libdir LIST_DIRECTORIES true "${prefix}/lib*/osgPlugins-*" "${prefix}/lib/*/osgPlugins-*")
get_filename_component(libdir "${libdir}" DIRECTORY)
foreach(program osgglyphviewer osgglyphbench osgglyphexample)
    check_loads_installed_library("${prefix}/bin/${program}")
endforeach()
file(GLOB plugins "${libdir}/osgPlugins-*/osgdb_*glyphs*.so")
foreach(plugin IN LISTS plugins)
    check_loads_installed_library("${plugin}")
endforeach()
run("${prefix}/bin/osgglyphviewer" "${prefix}/share/osgGlyphs/data/melt500.lammpstrj" --offscreen --size 160 120
    --output "${WORK_DIR}/installed-viewer.png")
run("${prefix}/bin/osgglyphexample" --output "${WORK_DIR}/installed-example.png" --size 160 120)
run("${prefix}/bin/osgglyphbench" --help)

run(${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}/cmake-build" -DCMAKE_PREFIX_PATH=${prefix}
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" -DCMAKE_CXX_COMPILER=${CXX})
run(${CMAKE_COMMAND} --build "${WORK_DIR}/cmake-build" --target consumer)
run_consumer("${WORK_DIR}/cmake-build/consumer" consumer-cmake.png)

file(GLOB pc_dirs "${prefix}/lib*/pkgconfig" "${prefix}/lib/*/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "${pc_dirs}")
# A program linked by hand has no RPATH of its own.
execute_process(COMMAND pkg-config --cflags --libs osgGlyphs osgGlyphsHeadless OUTPUT_VARIABLE flags RESULT_VARIABLE result
    OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "pkg-config does not find osgGlyphs in ${pc_dirs}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
separate_arguments(cxx_flags UNIX_COMMAND "${CXX_FLAGS}")
run(${CXX} -std=c++17 ${cxx_flags} "${SOURCE_DIR}/consumer.cpp" ${flags} -o "${WORK_DIR}/consumer-pkgconfig")
set(ENV{LD_LIBRARY_PATH} "${libdir}")
run_consumer("${WORK_DIR}/consumer-pkgconfig" consumer-pkgconfig.png)

# The installed library reads the installed shaders (editable in place) before its embedded
# copies: it must say it uses them, and render the same image.
file(REAL_PATH "${prefix}/share/osgGlyphs/shaders" shader_dir)
set(ENV{OSG_NOTIFY_LEVEL} INFO)
execute_process(COMMAND "${WORK_DIR}/consumer-pkgconfig" "${BASELINE}" "${WORK_DIR}/consumer-installed-shaders.png"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
string(REGEX MATCHALL "[^\n]*(osgGlyphs: using|consumer|  ok  |  FAIL  )[^\n]*" lines "${output}")
list(JOIN lines "\n" lines)
message("installed shaders in ${shader_dir}:\n${lines}")
if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}) with the installed shaders:\n${output}")
endif()
if(NOT output MATCHES "osgGlyphs: using ${shader_dir}/osgGlyphs/")
    message(FATAL_ERROR "the consumer did not read its shaders from ${shader_dir}")
endif()

# The installed plugins and sample data: stock osgconv turns a shipped LAMMPS dump into a
# native OSG file of glyph clouds. OSG_LIBRARY_PATH is all it needs to find the plugins, which
# find the libraries by their RPATH.
find_program(OSGCONV osgconv)
if(OSGCONV)
    unset(ENV{OSG_NOTIFY_LEVEL})
    unset(ENV{LD_LIBRARY_PATH})
    set(ENV{OSG_LIBRARY_PATH} "${libdir}")
    set(sample "${prefix}/share/osgGlyphs/data/melt500.lammpstrj")
    set(converted "${WORK_DIR}/melt500.osgt")
    if(STOCK_TOOL_PRELOAD) # sanitizer builds: the ASan runtime before our plugin
        set(ENV{LD_PRELOAD} "${STOCK_TOOL_PRELOAD}")
        set(ENV{ASAN_OPTIONS} "detect_leaks=0")
    endif()
    run("${OSGCONV}" -O "glyph=cone color=speed" "${sample}" "${converted}")
    file(STRINGS "${converted}" clouds REGEX "osgGlyphs::GlyphCloud")
    file(STRINGS "${converted}" cones REGEX "Shape cone")
    list(LENGTH clouds num_clouds)
    list(LENGTH cones num_cones)
    if(num_clouds EQUAL 0 OR NOT num_cones EQUAL num_clouds)
        message(FATAL_ERROR "osgconv with the installed osgdb_glyphs wrote ${num_clouds} clouds, ${num_cones} of cones")
    endif()
    message("osgconv ${sample}: ${num_clouds} glyph clouds of cones")
    # A paper technique: osgdb_serializers_osgglyphspaper writes it and reads it back.
    run("${OSGCONV}" -O "technique=polygons frame=0" "${sample}" "${WORK_DIR}/melt500-polygons.osgt")
    run("${OSGCONV}" "${WORK_DIR}/melt500-polygons.osgt" "${WORK_DIR}/melt500-polygons.osgb")
    file(STRINGS "${WORK_DIR}/melt500-polygons.osgt" techniques REGEX "osgGlyphsPaper::PolygonsTechnique")
    if(NOT techniques)
        message(FATAL_ERROR "osgconv with the installed serializers wrote no osgGlyphsPaper::PolygonsTechnique")
    endif()
else()
    message("osgconv not installed: the installed plugins are not checked")
endif()
