!> Numbers as text for error messages (one place, so that every message writes them alike).
module udmap_core_strings
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: itoa, ftoa, rtoa, gtoa, indexed_name

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

  !> x as Python's format(x, '.<digits>g') writes it, so that a text made here reads the same
  !> as one made in Python: `digits` significant digits, trailing zeros and a trailing point
  !> dropped, fixed notation for decimal exponents -4 to digits - 1, else d.ddde+XX (two
  !> exponent digits at least).
  pure function gtoa(x, digits) result(s)
    real(wp), intent(in) :: x
    integer, intent(in) :: digits
    character(len=:), allocatable :: s
    character(len=64) :: buf, fmt
    character(len=:), allocatable :: mantissa
    integer :: p, ex, at
    p = max(1, digits)
    if (x /= x) then
      s = "nan"
      return
    else if (abs(x) > huge(x)) then
      s = merge("inf ", "-inf", x > 0)
      s = trim(s)
      return
    else if (x == 0) then
      s = merge("-0", "0 ", sign(1.0_wp, x) < 0)
      s = trim(s)
      return
    end if
    ! the decimal exponent after rounding to p digits decides the notation (as Python's)
    write(fmt, '("(es40.", i0, "e4)")') p - 1
    write(buf, fmt) x
    buf = adjustl(buf)
    at = index(buf, "E")
    read(buf(at+1:), *) ex
    if (ex >= -4 .and. ex < p) then
      write(fmt, '("(f60.", i0, ")")') p - 1 - ex
      write(buf, fmt) x
      s = trim(adjustl(buf))
      if (s(1:1) == ".") s = "0"//s
      if (s(1:2) == "-.") s = "-0"//s(2:)
      s = strip_zeros(s)
    else
      mantissa = strip_zeros(buf(1:at-1))
      write(buf, '(sp, i0.2)') ex
      s = mantissa//"e"//trim(adjustl(buf))
    end if
  contains
    !> Trailing zeros of a decimal fraction dropped, and then its point if nothing follows it.
    pure function strip_zeros(t) result(r)
      character(len=*), intent(in) :: t
      character(len=:), allocatable :: r
      integer :: n
      r = trim(t)
      if (index(r, ".") == 0) return
      n = len(r)
      do while (n > 1 .and. r(n:n) == "0")
        n = n - 1
      end do
      if (r(n:n) == ".") n = n - 1
      r = r(1:n)
    end function strip_zeros
  end function gtoa

  !> name[i-1]: entry i of an array as the C API and Python index it (0-based).
  pure function indexed_name(name, i) result(s)
    character(len=*), intent(in) :: name
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    s = name//"["//itoa(i - 1)//"]"
  end function indexed_name
end module udmap_core_strings
