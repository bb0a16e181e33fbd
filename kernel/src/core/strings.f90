!> Numbers as text for error messages (one place, so that every message writes them alike).
module udmap_core_strings
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: itoa, ftoa, rtoa, indexed_name

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

  !> A real in the edit descriptor fmt (such as '(es11.4)'), without blanks.
  pure function rtoa(x, fmt) result(s)
    real(wp), intent(in) :: x
    character(len=*), intent(in) :: fmt
    character(len=:), allocatable :: s
    character(len=32) :: buf
    write(buf, fmt) x
    s = trim(adjustl(buf))
  end function rtoa

  !> name[i-1]: entry i of an array as the C API and Python index it (0-based).
  pure function indexed_name(name, i) result(s)
    character(len=*), intent(in) :: name
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    s = name//"["//itoa(i - 1)//"]"
  end function indexed_name
end module udmap_core_strings
