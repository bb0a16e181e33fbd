!> Numbers as text for error messages (one place, so that every message writes them alike).
module udmap_core_strings
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: itoa, ftoa

contains

  !> An integer without blanks.
  pure function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write(buf, '(i0)') i
    s = trim(buf)
  end function itoa

  !> A real with ten significant digits, without blanks.
  pure function ftoa(x) result(s)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=32) :: buf
    write(buf, '(g0.10)') x
    s = trim(adjustl(buf))
  end function ftoa
end module udmap_core_strings
