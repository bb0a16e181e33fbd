!> Sorting of the short lists the kernel keeps (roots of a waveform, event times), and the one
!> binary search (bisect) of the kernel's ascending tables.
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

  pure integer function bisect_real(a, x, right) result(n)
    real(wp), intent(in) :: a(:), x
    logical, intent(in), optional :: right
    integer :: lo, hi, mid
    logical :: r
    r = .false.
    if (present(right)) r = right
    lo = 1
    hi = size(a) + 1
    do while (lo < hi)
      mid = (lo + hi)/2
      if (r) then
        if (a(mid) <= x) then
          lo = mid + 1
        else
          hi = mid
        end if
      else
        if (x <= a(mid)) then
          hi = mid
        else
          lo = mid + 1
        end if
      end if
    end do
    n = lo - 1
  end function bisect_real

  pure integer function bisect_int(a, x) result(n)
    integer, intent(in) :: a(:), x
    integer :: lo, hi, mid
    lo = 1
    hi = size(a) + 1
    do while (lo < hi)
      mid = (lo + hi)/2
      if (x <= a(mid)) then
        hi = mid
      else
        lo = mid + 1
      end if
    end do
    n = lo - 1
  end function bisect_int
end module udmap_core_sorting
