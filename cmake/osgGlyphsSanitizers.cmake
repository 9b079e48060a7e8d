# OSGGLYPHS_SANITIZE: which sanitizer everything is built with.
#   address (or ON)  AddressSanitizer and UndefinedBehaviorSanitizer
#   thread           ThreadSanitizer (tests: ctest -L threads)
#   OFF              none
# Sets OSGGLYPHS_SANITIZE_FLAGS (compile and link flags, for projects the tests build) and
# OSGGLYPHS_SANITIZER_RUNTIME (the runtime library stock OSG programs need preloaded to load our
# plugins), both empty without a sanitizer.

set(OSGGLYPHS_SANITIZE OFF CACHE STRING
    "Build everything with a sanitizer: address (ASan + UBSan; ON is the same), thread (TSan) or OFF")
set_property(CACHE OSGGLYPHS_SANITIZE PROPERTY STRINGS OFF address thread)

string(TOLOWER "${OSGGLYPHS_SANITIZE}" sanitizer)
set(OSGGLYPHS_SANITIZE_FLAGS "")
set(OSGGLYPHS_SANITIZER_RUNTIME "")
if(sanitizer MATCHES "^(address|on|yes|true|1)$")
    # GCC's undefined leaves out float-cast-overflow (clang's has it): NaN or 1e39 cast to an int.
    set(OSGGLYPHS_SANITIZE_FLAGS -fsanitize=address,undefined,float-cast-overflow)
    set(OSGGLYPHS_SANITIZER_RUNTIME libasan.so)
    add_compile_options(-fno-sanitize-recover=undefined)
elseif(sanitizer STREQUAL "thread")
    set(OSGGLYPHS_SANITIZE_FLAGS -fsanitize=thread)
    set(OSGGLYPHS_SANITIZER_RUNTIME libtsan.so)
elseif(NOT sanitizer MATCHES "^(off|no|false|0|)$")
    message(FATAL_ERROR "osgGlyphs: OSGGLYPHS_SANITIZE=${OSGGLYPHS_SANITIZE}: use address, thread or OFF")
endif()
if(OSGGLYPHS_SANITIZE_FLAGS)
    add_compile_options(${OSGGLYPHS_SANITIZE_FLAGS} -fno-omit-frame-pointer)
    add_link_options(${OSGGLYPHS_SANITIZE_FLAGS})
endif()
