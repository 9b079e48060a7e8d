# Runs osgglyphbench with ARGS and checks that it fails (EXPECT_RESULT failure) or succeeds
# (success) and that its output matches every regular expression of the list EXPECT_OUTPUT.
#   cmake -DBENCH=osgglyphbench -DARGS=--a;--b -DEXPECT_RESULT=failure -DEXPECT_OUTPUT=re1;re2 -P ...
cmake_minimum_required(VERSION 3.25)

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
message(STATUS "osgglyphbench ${ARGS}: ${result}\n${output}")
