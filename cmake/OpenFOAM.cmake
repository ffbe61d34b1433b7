# OpenFOAM v1912 from Debian: libraries in the system library directory, headers
# unpacked by bin/tools/sphDependencies from the same version's source package
# into <project>/.cache/openfoam/<version>/<lib>/lnInclude.
#
# Defines the imported targets
#   OpenFOAM::OpenFOAM       libOpenFOAM (+ Pstream, dl, m)
#   OpenFOAM::finiteVolume   libfiniteVolume + libmeshTools, for tools reading FV results
#   OpenFOAM::dynamicMesh    libdynamicMesh, for solidBodyMotionFunction

execute_process(
    COMMAND dpkg-query -W -f=\${Version} openfoam
    OUTPUT_VARIABLE OPENFOAM_DEB_VERSION
    RESULT_VARIABLE dpkgResult
    OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT dpkgResult EQUAL 0 OR OPENFOAM_DEB_VERSION STREQUAL "")
    message(FATAL_ERROR
        "The Debian package 'openfoam' is not installed: run ./Allwmake (as root it installs it)")
endif()

set(SPHFOAM_OPENFOAM_CACHE "${PROJECT_SOURCE_DIR}/.cache/openfoam"
    CACHE PATH "Folder holding the OpenFOAM headers, one sub-folder per version")
set(OPENFOAM_HEADERS "${SPHFOAM_OPENFOAM_CACHE}/${OPENFOAM_DEB_VERSION}")

if(NOT EXISTS "${OPENFOAM_HEADERS}/VERSION")
    message(FATAL_ERROR
        "No OpenFOAM headers for the installed openfoam ${OPENFOAM_DEB_VERSION} in "
        "${SPHFOAM_OPENFOAM_CACHE}: run bin/tools/sphDependencies (./Allwmake does)")
endif()
file(STRINGS "${OPENFOAM_HEADERS}/VERSION" headerVersion LIMIT_COUNT 1)
if(NOT headerVersion STREQUAL OPENFOAM_DEB_VERSION)
    message(FATAL_ERROR
        "OpenFOAM headers are version '${headerVersion}' but the installed library is "
        "'${OPENFOAM_DEB_VERSION}': remove ${OPENFOAM_HEADERS} and run ./Allwmake")
endif()

find_library(OPENFOAM_LIBRARY OpenFOAM PATHS /usr/lib /usr/lib/openfoam REQUIRED)
get_filename_component(OPENFOAM_LIBDIR "${OPENFOAM_LIBRARY}" DIRECTORY)
message(STATUS "OpenFOAM ${OPENFOAM_DEB_VERSION}: ${OPENFOAM_LIBRARY}")

add_library(OpenFOAM::OpenFOAM INTERFACE IMPORTED)
target_include_directories(OpenFOAM::OpenFOAM SYSTEM INTERFACE
    "${OPENFOAM_HEADERS}/OpenFOAM/lnInclude"
    "${OPENFOAM_HEADERS}/OSspecific_POSIX/lnInclude")
target_compile_definitions(OpenFOAM::OpenFOAM INTERFACE
    WM_DP WM_LABEL_SIZE=32 NoRepository OPENFOAM=1912)
target_compile_options(OpenFOAM::OpenFOAM INTERFACE
    -ftemplate-depth-100 -m64 -pthread
    -Wno-deprecated-declarations -Wno-attributes -Wno-old-style-cast)
target_link_directories(OpenFOAM::OpenFOAM INTERFACE "${OPENFOAM_LIBDIR}")
target_link_options(OpenFOAM::OpenFOAM INTERFACE
    -pthread "LINKER:--add-needed" "LINKER:--no-as-needed")
target_link_libraries(OpenFOAM::OpenFOAM INTERFACE OpenFOAM dl m)

add_library(OpenFOAM::finiteVolume INTERFACE IMPORTED)
target_include_directories(OpenFOAM::finiteVolume SYSTEM INTERFACE
    "${OPENFOAM_HEADERS}/finiteVolume/lnInclude"
    "${OPENFOAM_HEADERS}/meshTools/lnInclude"
    "${OPENFOAM_HEADERS}/surfMesh/lnInclude"
    "${OPENFOAM_HEADERS}/fileFormats/lnInclude")
target_link_libraries(OpenFOAM::finiteVolume INTERFACE
    OpenFOAM::OpenFOAM finiteVolume meshTools)

# libdynamicMesh: solidBodyMotionFunction (rotatingMotion, linearMotion, ...)
# for the wall motion of constant/dynamicMeshDict
add_library(OpenFOAM::dynamicMesh INTERFACE IMPORTED)
target_include_directories(OpenFOAM::dynamicMesh SYSTEM INTERFACE
    "${OPENFOAM_HEADERS}/dynamicMesh/lnInclude")
target_link_libraries(OpenFOAM::dynamicMesh INTERFACE
    OpenFOAM::finiteVolume dynamicMesh)
