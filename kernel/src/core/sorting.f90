!> Sorting of the short lists the kernel keeps (roots of a waveform, event times).
module udmap_core_sorting
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: sort_ascending

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
end module udmap_core_sorting
