!> Growing allocatable arrays that are filled one entry at a time (lists of points, table
!> leaves, visited panels): a new allocation of the asked size with the first n entries kept.
module udmap_core_arrays
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: grow

  !> call grow(a, n, size): a reallocated to size entries, a(1:n) kept, the rest undefined.
  interface grow
    module procedure grow_real, grow_int, grow_int64
  end interface grow

contains

  pure subroutine grow_real(a, n, new_size)
    real(wp), allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n, new_size
    real(wp), allocatable :: t(:)
    allocate(t(new_size))
    t(1:n) = a(1:n)
    call move_alloc(t, a)
  end subroutine grow_real

  pure subroutine grow_int(a, n, new_size)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n, new_size
    integer, allocatable :: t(:)
    allocate(t(new_size))
    t(1:n) = a(1:n)
    call move_alloc(t, a)
  end subroutine grow_int

  pure subroutine grow_int64(a, n, new_size)
    integer(int64), allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n, new_size
    integer(int64), allocatable :: t(:)
    allocate(t(new_size))
    t(1:n) = a(1:n)
    call move_alloc(t, a)
  end subroutine grow_int64
end module udmap_core_arrays
