# hypre from Debian (libhypre-dev, 32-bit indices, built on Open MPI): no CMake
# package is shipped, so the header and library are found here.
#
# Defines the imported target
#   Hypre::Hypre             libHYPRE + MPI (hypre runs on MPI_COMM_SELF in serial runs)

set(MPI_CXX_SKIP_MPICXX ON)     # the C interface is all hypre and we use
find_package(MPI REQUIRED COMPONENTS CXX)

find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre)
find_library(HYPRE_LIBRARY HYPRE)
if(NOT HYPRE_INCLUDE_DIR OR NOT HYPRE_LIBRARY)
    message(FATAL_ERROR
        "hypre not found (HYPRE.h, libHYPRE): run ./Allwmake (as root it installs libhypre-dev)")
endif()

add_library(Hypre::Hypre INTERFACE IMPORTED)
set_target_properties(Hypre::Hypre PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${HYPRE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${HYPRE_LIBRARY};MPI::MPI_CXX")
message(STATUS "hypre: ${HYPRE_LIBRARY}")
