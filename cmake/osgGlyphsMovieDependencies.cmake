# The optional dependencies of osgGlyphsMovie: FFmpeg's libavcodec, libavformat, libavutil and
# libswscale (Debian packages libavcodec-dev, libavformat-dev, libavutil-dev, libswscale-dev).
# Sets OSGGLYPHS_HAVE_MOVIE and, when all four are found, the targets PkgConfig::AVCODEC,
# PkgConfig::AVFORMAT, PkgConfig::AVUTIL and PkgConfig::SWSCALE. FFmpeg 5.1 (Debian bookworm)
# is the one tested; the versions asked for are FFmpeg 4.0's.

set(OSGGLYPHS_HAVE_MOVIE OFF)
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
    set(_osgglyphs_movie_found ON)
    foreach(_pair AVCODEC:libavcodec>=58 AVFORMAT:libavformat>=58 AVUTIL:libavutil>=56 SWSCALE:libswscale>=5)
        string(REPLACE ":" ";" _pair "${_pair}")
        list(GET _pair 0 _prefix)
        list(GET _pair 1 _module)
        if(NOT TARGET PkgConfig::${_prefix})
            pkg_check_modules(${_prefix} QUIET IMPORTED_TARGET GLOBAL ${_module})
        endif()
        if(NOT TARGET PkgConfig::${_prefix})
            set(_osgglyphs_movie_found OFF)
        endif()
    endforeach()
    set(OSGGLYPHS_HAVE_MOVIE ${_osgglyphs_movie_found})
    unset(_osgglyphs_movie_found)
    unset(_pair)
    unset(_prefix)
    unset(_module)
endif()
