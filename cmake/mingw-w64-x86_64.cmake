# Cross-compilation to Windows x86-64 with Debian's MinGW-w64 compilers
# (gcc-mingw-w64-x86-64, gfortran-mingw-w64-x86-64). Used by the Windows FMU binaries
# (UDMAP_WINDOWS_FMU): cmake -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake ...
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(UDMAP_MINGW_TRIPLET x86_64-w64-mingw32)

find_program(CMAKE_C_COMPILER NAMES ${UDMAP_MINGW_TRIPLET}-gcc REQUIRED)
find_program(CMAKE_Fortran_COMPILER NAMES ${UDMAP_MINGW_TRIPLET}-gfortran REQUIRED)
find_program(CMAKE_RC_COMPILER NAMES ${UDMAP_MINGW_TRIPLET}-windres)

# Headers and libraries of the target only; programs (generators) of the build machine.
set(CMAKE_FIND_ROOT_PATH /usr/${UDMAP_MINGW_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
