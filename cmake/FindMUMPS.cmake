# Finds sequential MUMPS (double precision), e.g. Debian's libmumps-seq-dev, which ships no
# CMake config: the Fortran header dmumps_struc.h and libdmumps_seq (which brings its own
# mumps_common_seq, mpiseq_seq, pord_seq and orderings as dependencies).
# Provides MUMPS_FOUND, MUMPS_INCLUDE_DIR and the imported target MUMPS::MUMPS.
find_path(MUMPS_INCLUDE_DIR dmumps_struc.h PATH_SUFFIXES mumps_seq mumps)
find_library(MUMPS_LIBRARY NAMES dmumps_seq)
find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common_seq)
find_library(MUMPS_MPISEQ_LIBRARY NAMES mpiseq_seq mpiseq)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_LIBRARY MUMPS_INCLUDE_DIR)
if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS UNKNOWN IMPORTED)
  set(_mumps_extra)
  foreach(_lib ${MUMPS_COMMON_LIBRARY} ${MUMPS_MPISEQ_LIBRARY})
    if(_lib)
      list(APPEND _mumps_extra ${_lib})
    endif()
  endforeach()
  set_target_properties(MUMPS::MUMPS PROPERTIES IMPORTED_LOCATION "${MUMPS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${_mumps_extra}")
endif()
mark_as_advanced(MUMPS_INCLUDE_DIR MUMPS_LIBRARY MUMPS_COMMON_LIBRARY MUMPS_MPISEQ_LIBRARY)
