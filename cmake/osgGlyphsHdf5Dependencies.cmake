# The optional dependency of osgGlyphsHdf5: HDF5's C library (Debian package libhdf5-dev, whose
# pkg-config module is hdf5; elsewhere CMake's FindHDF5). Sets OSGGLYPHS_HAVE_HDF5 and, when it
# is found, OSGGLYPHS_HDF5_TARGET to the target to link: PkgConfig::H5 or HDF5::HDF5. HDF5 1.10
# (Debian bookworm's 1.10.8) is the one tested and the oldest asked for.

set(OSGGLYPHS_HAVE_HDF5 OFF)
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND AND NOT TARGET PkgConfig::H5)
    pkg_check_modules(H5 QUIET IMPORTED_TARGET GLOBAL hdf5>=1.10)
endif()
if(TARGET PkgConfig::H5)
    set(OSGGLYPHS_HAVE_HDF5 ON)
    set(OSGGLYPHS_HDF5_TARGET PkgConfig::H5)
else()
    find_package(HDF5 1.10 QUIET COMPONENTS C)
    if(HDF5_FOUND AND TARGET HDF5::HDF5)
        set(OSGGLYPHS_HAVE_HDF5 ON)
        set(OSGGLYPHS_HDF5_TARGET HDF5::HDF5)
    endif()
endif()
