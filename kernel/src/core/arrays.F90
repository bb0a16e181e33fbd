!> Growing allocatable arrays that are filled one entry at a time (lists of points, table
!> leaves, visited panels): a new allocation of the asked size with the first n entries kept
!> (grow), or the next entry stored with the storage grown as needed (put).
!> One body (arrays_grow.inc) for every element type, instantiated below by the preprocessor.
module udmap_core_arrays
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: grow, put

  !> call grow(a, n, size): a reallocated to size entries, a(1:n) kept, the rest undefined.
  interface grow
    module procedure grow_real, grow_int, grow_int64
  end interface grow

  !> call put(a, i, x): a(i) = x for the next entry i of a list filled one at a time; a is
  !> allocated (16 entries at least) or grown to twice its size when i is past its end, a(1:i-1)
  !> kept.
  interface put
    module procedure put_real, put_int, put_int64
  end interface put

contains

#define GROW_NAME grow_real
#define PUT_NAME put_real
#define GROW_TYPE real(wp)
#include "arrays_grow.inc"
#undef GROW_NAME
#undef PUT_NAME
#undef GROW_TYPE

#define GROW_NAME grow_int
#define PUT_NAME put_int
#define GROW_TYPE integer
#include "arrays_grow.inc"
#undef GROW_NAME
#undef PUT_NAME
#undef GROW_TYPE

#define GROW_NAME grow_int64
#define PUT_NAME put_int64
#define GROW_TYPE integer(int64)
#include "arrays_grow.inc"
#undef GROW_NAME
#undef PUT_NAME
#undef GROW_TYPE
end module udmap_core_arrays
