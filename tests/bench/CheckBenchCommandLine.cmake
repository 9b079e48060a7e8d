# Runs osgglyphbench with ARGS and checks that it fails (EXPECT_RESULT failure) or succeeds
# (success), that its output matches every regular expression of the list EXPECT_OUTPUT and none
# of REJECT_OUTPUT. With BROKEN_SHADER (a name such as osgGlyphs/sphere.glsl), runs it with a file
# of that name that does not compile on OSG's data path, in SHADER_DIR.
#   cmake -DBENCH=osgglyphbench -DARGS=--a;--b -DEXPECT_RESULT=failure -DEXPECT_OUTPUT=re1;re2 -P ...
cmake_minimum_required(VERSION 3.25)

if(BROKEN_SHADER)
    file(WRITE "${SHADER_DIR}/${BROKEN_SHADER}" "// broken\n\nthis is not GLSL;\n")
    set(ENV{OSG_FILE_PATH} "${SHADER_DIR}")
endif()

execute_process(COMMAND "${BENCH}" ${ARGS} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(EXPECT_RESULT STREQUAL "failure" AND result EQUAL 0)
    message(FATAL_ERROR "osgglyphbench ${ARGS} succeeded; expected a failure:\n${output}")
elseif(EXPECT_RESULT STREQUAL "success" AND NOT result EQUAL 0)
    message(FATAL_ERROR "osgglyphbench ${ARGS} failed (${result}); expected success:\n${output}")
endif()
foreach(expected IN LISTS EXPECT_OUTPUT)
    if(NOT output MATCHES "${expected}")
        message(FATAL_ERROR "osgglyphbench ${ARGS}: output does not match '${expected}':\n${output}")
    endif()
endforeach()
foreach(rejected IN LISTS REJECT_OUTPUT)
    if(output MATCHES "${rejected}")
        message(FATAL_ERROR "osgglyphbench ${ARGS}: output matches '${rejected}':\n${output}")
    endif()
endforeach()
message(STATUS "osgglyphbench ${ARGS}: ${result}\n${output}")
