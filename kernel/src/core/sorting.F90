!> Sorting of the short lists the kernel keeps (roots of a waveform, event times), and the one
!> binary search (bisect) of the kernel's ascending tables, one body (sorting_bisect.inc) for
!> real and integer tables.
module udmap_core_sorting
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: sort_ascending, bisect

  !> bisect(a, x [, right]): the number of leading entries of the ascending a below x
  !> (a(i) < x), or with right = .true. at or below x (a(i) <= x); x is inserted after them.
  !> A NaN x counts as above every entry (left) or below every entry (right).
  interface bisect
    module procedure bisect_real, bisect_int
  end interface bisect

contains

  !> Sorts x in place, ascending (insertion sort: the lists are short, often nearly sorted).
  pure subroutine sort_ascending(x)
    real(wp), intent(inout) :: x(:)
    integer :: i, j
    real(wp) :: t
    do i = 2, size(x)
      t = x(i)
      j = i - 1
      do while (j >= 1)
        if (x(j) <= t) exit
        x(j+1) = x(j)
        j = j - 1
      end do
      x(j+1) = t
    end do
  end subroutine sort_ascending

#define BISECT_NAME bisect_real
#define BISECT_TYPE real(wp)
#include "sorting_bisect.inc"
#undef BISECT_NAME
#undef BISECT_TYPE

#define BISECT_NAME bisect_int
#define BISECT_TYPE integer
#include "sorting_bisect.inc"
#undef BISECT_NAME
#undef BISECT_TYPE
end module udmap_core_sorting
