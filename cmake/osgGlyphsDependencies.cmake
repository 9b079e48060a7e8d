# Finds osgGlyphs' third-party dependencies as Debian bookworm packages provide them.
# Included by the build and by the installed osgGlyphsConfig.cmake, so that a consumer
# gets the same OpenSceneGraph targets the library was built against.
# Every missing dependency stops configuration with the Debian package that provides it.

find_package(PkgConfig QUIET)
if(NOT PkgConfig_FOUND)
    message(FATAL_ERROR "osgGlyphs: pkg-config was not found. Install the Debian package 'pkg-config'.")
endif()

# osgglyphs_require(<prefix> <pkg-config module> <Debian package>)
# Creates the imported target PkgConfig::<prefix> or fails with the package to install.
function(osgglyphs_require prefix module debian_package)
    if(TARGET PkgConfig::${prefix})
        return()
    endif()
    pkg_check_modules(${prefix} QUIET IMPORTED_TARGET GLOBAL ${module})
    if(NOT ${prefix}_FOUND)
        message(FATAL_ERROR
            "osgGlyphs: the dependency '${module}' was not found. "
            "Install the Debian package '${debian_package}' (apt-get install ${debian_package}).")
    endif()
endfunction()

set(_osgglyphs_osg_package libopenscenegraph-dev)
osgglyphs_require(OSG "openscenegraph-osg>=3.6" ${_osgglyphs_osg_package})
foreach(_module osgDB osgUtil osgGA osgViewer osgText)
    osgglyphs_require(${_module} openscenegraph-${_module} ${_osgglyphs_osg_package})
endforeach()

# The private dependencies are only needed while building osgGlyphs itself.
if(NOT OSGGLYPHS_FIND_PUBLIC_ONLY)
    # osgShadow: the viewer's --shadows and the shadow tests (the libraries do not use it).
    osgglyphs_require(osgShadow openscenegraph-osgShadow ${_osgglyphs_osg_package})
    osgglyphs_require(OSMesa osmesa libosmesa6-dev)
    osgglyphs_require(EGL egl libegl-dev)
    osgglyphs_require(GL gl libgl-dev)
    osgglyphs_require(GLM glm libglm-dev)
    # Compressed trajectories (.gz, .zst), read by osgGlyphsData.
    osgglyphs_require(ZLIB zlib zlib1g-dev)
    osgglyphs_require(ZSTD libzstd libzstd-dev)
    find_package(Threads REQUIRED)
    # fast_float: locale-independent number parsing for the point readers (header-only).
    if(NOT TARGET FastFloat::fast_float)
        find_package(FastFloat CONFIG QUIET)
        if(NOT FastFloat_FOUND)
            message(FATAL_ERROR
                "osgGlyphs: the dependency 'fast_float' (FastFloatConfig.cmake) was not found. "
                "Install the Debian package 'libfast-float-dev' (apt-get install libfast-float-dev).")
        endif()
    endif()
endif()
