# Installation of the kernel: shared and static libraries, the C header, the Fortran .mod files,
# a CMake package (udmapConfig.cmake, target udmap::udmap) and a pkg-config file (udmap.pc).
#
# Layout under the prefix P (GNUInstallDirs):
#   lib/libudmap.so*, lib/libudmap.a
#   include/udmap.h
#   include/udmap/<compiler id>-<major version>/*.mod   (e.g. include/udmap/GNU-12)
#   lib/cmake/udmap/udmapConfig.cmake, udmapConfigVersion.cmake, udmapTargets*.cmake,
#                   FindARPACK.cmake (Debian's arpack ships no CMake package)
#   lib/pkgconfig/udmap.pc
#   share/udmap/udmap.fmu, udmap-fmi3.fmu (when the build makes them)
# .mod files are specific to the compiler and its major version (gfortran's module format),
# hence the versioned directory: programs must be compiled with the same compiler family.
# Everything is relocatable: `cmake --install build --prefix P` works for any P.
include(CMakePackageConfigHelpers)

string(REGEX MATCH "^[0-9]+" _udmap_fc_major "${CMAKE_Fortran_COMPILER_VERSION}")
set(UDMAP_INSTALL_MODDIR
  "${CMAKE_INSTALL_INCLUDEDIR}/udmap/${CMAKE_Fortran_COMPILER_ID}-${_udmap_fc_major}"
  CACHE STRING "Where the Fortran .mod files are installed (relative to the prefix)")
set(UDMAP_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/udmap"
  CACHE STRING "Where udmapConfig.cmake is installed (relative to the prefix)")
set(UDMAP_INSTALL_PKGCONFIGDIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig"
  CACHE STRING "Where udmap.pc is installed (relative to the prefix)")
mark_as_advanced(UDMAP_INSTALL_MODDIR UDMAP_INSTALL_CMAKEDIR UDMAP_INSTALL_PKGCONFIGDIR)

foreach(lib udmap udmap-static)
  target_include_directories(${lib} PUBLIC
    "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>"
    "$<INSTALL_INTERFACE:${UDMAP_INSTALL_MODDIR}>")
endforeach()
if(NOT TARGET udmap::udmap-static)
  add_library(udmap::udmap-static ALIAS udmap-static)
endif()

install(TARGETS udmap udmap-static EXPORT udmapTargets
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT udmap
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT udmap
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT udmap)
install(FILES "${PROJECT_SOURCE_DIR}/wrappers/c/udmap.h"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" COMPONENT udmap)
# Every module of the kernel: `use udmap` is enough in programs, but gfortran may read the
# .mod files of the modules udmap re-exports from.
get_target_property(_udmap_mod_dir udmap-objects Fortran_MODULE_DIRECTORY)
install(DIRECTORY "${_udmap_mod_dir}/"
  DESTINATION "${UDMAP_INSTALL_MODDIR}" COMPONENT udmap
  FILES_MATCHING PATTERN "*.mod")

install(EXPORT udmapTargets NAMESPACE udmap:: FILE udmapTargets.cmake
  DESTINATION "${UDMAP_INSTALL_CMAKEDIR}" COMPONENT udmap)
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/udmapConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/udmapConfig.cmake"
  INSTALL_DESTINATION "${UDMAP_INSTALL_CMAKEDIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR UDMAP_INSTALL_MODDIR)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/udmapConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
set(_udmap_config_files "${PROJECT_BINARY_DIR}/udmapConfig.cmake"
  "${PROJECT_BINARY_DIR}/udmapConfigVersion.cmake")
if(UDMAP_WITH_ARPACK)
  list(APPEND _udmap_config_files "${PROJECT_SOURCE_DIR}/cmake/FindARPACK.cmake")
  if(UDMAP_WITH_MUMPS)
    list(APPEND _udmap_config_files "${PROJECT_SOURCE_DIR}/cmake/FindMUMPS.cmake")
  endif()
endif()
install(FILES ${_udmap_config_files}
  DESTINATION "${UDMAP_INSTALL_CMAKEDIR}" COMPONENT udmap)

# pkg-config: the prefix is found from the .pc file's own place (${pcfiledir}), so the file
# stays right whatever --prefix `cmake --install` is given.
file(RELATIVE_PATH UDMAP_PC_TO_PREFIX "/prefix/${UDMAP_INSTALL_PKGCONFIGDIR}" "/prefix")
string(REGEX REPLACE "/$" "" UDMAP_PC_TO_PREFIX "${UDMAP_PC_TO_PREFIX}")
set(UDMAP_PC_REQUIRES_PRIVATE "lapack")
if(UDMAP_WITH_ARPACK)
  set(UDMAP_PC_REQUIRES_PRIVATE "arpack ${UDMAP_PC_REQUIRES_PRIVATE}")
endif()
# Debian's MUMPS ships no .pc file: its libraries go to Libs.private directly.
set(UDMAP_PC_LIBS_PRIVATE "")
if(UDMAP_WITH_MUMPS)
  set(UDMAP_PC_LIBS_PRIVATE "-ldmumps_seq -lmumps_common_seq -lmpiseq_seq ")
endif()
configure_file("${PROJECT_SOURCE_DIR}/cmake/udmap.pc.in" "${PROJECT_BINARY_DIR}/udmap.pc" @ONLY)
# The same from the build tree (the pkg-config convention NAME-uninstalled.pc, which pkg-config
# prefers when build/ is on PKG_CONFIG_PATH): C and Fortran programs link before an install.
configure_file("${PROJECT_SOURCE_DIR}/cmake/udmap-uninstalled.pc.in"
  "${PROJECT_BINARY_DIR}/udmap-uninstalled.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/udmap.pc"
  DESTINATION "${UDMAP_INSTALL_PKGCONFIGDIR}" COMPONENT udmap)

# The FMUs, when this build makes them (fmu/CMakeLists.txt).
foreach(_udmap_fmu udmap-fmi2:udmap.fmu udmap-fmi3:udmap-fmi3.fmu)
  string(REPLACE ":" ";" _udmap_fmu "${_udmap_fmu}")
  list(GET _udmap_fmu 0 _udmap_fmu_target)
  list(GET _udmap_fmu 1 _udmap_fmu_file)
  if(TARGET ${_udmap_fmu_target}-archive)
    install(FILES "${PROJECT_BINARY_DIR}/${_udmap_fmu_file}"
      DESTINATION "${CMAKE_INSTALL_DATADIR}/udmap" COMPONENT udmap)
  endif()
endforeach()
