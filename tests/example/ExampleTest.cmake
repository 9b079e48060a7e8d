# The example's headless mode (ctest -L viewer):
#   cmake -DEXAMPLE=<osgglyphexample> -DCHECK=<osgglyphviewer_image_check> -DBASELINE=<png>
#         -DWORK_DIR=<scratch> -P ExampleTest.cmake
# The PNG must exist, show the scene over a fifth of the view, and match the baseline: at most
# 0.5% of the pixels more than 4 levels off. OSGGLYPHS_BLESS=1 rewrites the baseline instead.
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(image "${WORK_DIR}/osgglyphexample.png")

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
    list(JOIN ARGN " " command)
    message(STATUS "${command}\n-> ${result}\n${out}")
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "failed: ${command}")
    endif()
endfunction()

run("${EXAMPLE}" --output "${image}" --size 320 240)
if(NOT EXISTS "${image}")
    message(FATAL_ERROR "${image} was not written")
endif()
run("${CHECK}" coverage "${image}" 0.2)
if("$ENV{OSGGLYPHS_BLESS}" STREQUAL "1")
    file(COPY_FILE "${image}" "${BASELINE}")
    message(STATUS "[ BLESSED  ] ${BASELINE}")
elseif(NOT EXISTS "${BASELINE}")
    message(FATAL_ERROR "missing baseline ${BASELINE}; run with OSGGLYPHS_BLESS=1 to create it")
else()
    run("${CHECK}" match "${image}" "${BASELINE}" 4 0.005)
endif()
