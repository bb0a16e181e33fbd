# What `pip install .` puts into the wheel (scikit-build-core installs only the component
# python, see pyproject.toml): the kernel library and the FMUs inside the udmap package,
#   udmap/libudmap.so          (one file: wheels keep no symlinks, and ctypes loads it by path)
#   udmap/fmu/udmap.fmu, udmap/fmu/udmap-fmi3.fmu   (when the build makes them)
# The Python sources come from wrappers/python/udmap (wheel.packages). The library links
# libgfortran, LAPACK/BLAS and ARPACK of the building machine dynamically: the wheel is for
# that machine (or one with the same Debian runtime packages), not a manylinux wheel.
# EXCLUDE_FROM_ALL: `cmake --install build` (the development install) leaves them out;
# `cmake --install build --component python --prefix P` gives the wheel's layout under P
# (tests/python/test_package.py).
install(FILES "$<TARGET_FILE:udmap>" DESTINATION udmap RENAME libudmap.so COMPONENT python
  EXCLUDE_FROM_ALL)
foreach(_udmap_fmu udmap-fmi2:udmap.fmu udmap-fmi3:udmap-fmi3.fmu)
  string(REPLACE ":" ";" _udmap_fmu "${_udmap_fmu}")
  list(GET _udmap_fmu 0 _udmap_fmu_target)
  list(GET _udmap_fmu 1 _udmap_fmu_file)
  if(TARGET ${_udmap_fmu_target}-archive)
    install(FILES "${PROJECT_BINARY_DIR}/${_udmap_fmu_file}" DESTINATION udmap/fmu
      COMPONENT python EXCLUDE_FROM_ALL)
  endif()
endforeach()
