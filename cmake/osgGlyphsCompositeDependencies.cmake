# The optional dependencies of osgGlyphsComposite: MPI and IceT. IceT 2.2 ships inside ParaView
# on Debian (libraries libvtkIceTCore-pv5.11 and libvtkIceTMPI-pv5.11 in package paraview, headers
# under paraview-5.11/vtkicet/src/include in paraview-dev). Sets OSGGLYPHS_HAVE_COMPOSITE and, when
# both are found, the targets MPI::MPI_CXX and IceT::IceT.

find_package(MPI QUIET COMPONENTS CXX)
find_path(OSGGLYPHS_ICET_INCLUDE_DIR IceT.h PATH_SUFFIXES paraview-5.11/vtkicet/src/include)
find_library(OSGGLYPHS_ICET_CORE_LIBRARY NAMES IceTCore vtkIceTCore-pv5.11)
find_library(OSGGLYPHS_ICET_MPI_LIBRARY NAMES IceTMPI vtkIceTMPI-pv5.11)
if(MPI_CXX_FOUND AND OSGGLYPHS_ICET_INCLUDE_DIR AND OSGGLYPHS_ICET_CORE_LIBRARY AND OSGGLYPHS_ICET_MPI_LIBRARY)
    set(OSGGLYPHS_HAVE_COMPOSITE ON)
    if(NOT TARGET IceT::IceT)
        add_library(IceT::IceT INTERFACE IMPORTED)
        target_include_directories(IceT::IceT INTERFACE "${OSGGLYPHS_ICET_INCLUDE_DIR}")
        target_link_libraries(IceT::IceT INTERFACE
            "${OSGGLYPHS_ICET_MPI_LIBRARY}" "${OSGGLYPHS_ICET_CORE_LIBRARY}" MPI::MPI_CXX)
    endif()
else()
    set(OSGGLYPHS_HAVE_COMPOSITE OFF)
endif()
