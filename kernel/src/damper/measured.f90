!> A measured stiffness table (PHYSICS.md 2.4, damper kind "table"): PCHIP in ln(gamma) of
!> k_re and k_im separately, constant below the first row, and beyond the last row the
!> extrapolation with a plateau moment difference delta_M if one is given.
module udmap_damper_measured
  use udmap_core_kinds, only: wp, pi
  use udmap_core_sorting, only: bisect
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  implicit none
  private
  public :: measured_table_type, new_measured_table, measured_stiffness

  !> Rows (gamma, k_re, k_im) with the PCHIP slopes against ln(gamma).
  type :: measured_table_type
    integer :: n = 0
    real(wp), allocatable :: gamma(:), x(:), k_re(:), k_im(:), d_re(:), d_im(:)
    logical :: has_delta_M = .false.
    real(wp) :: delta_M = 0
  end type measured_table_type

contains

  !> Checks the rows (at least 2, gamma > 0 ascending, k_re, k_im finite and >= 0, delta_M > 0)
  !> and prepares the interpolation.
  pure subroutine new_measured_table(tab, gamma, k_re, k_im, error, delta_M)
    type(measured_table_type), intent(out) :: tab
    real(wp), intent(in) :: gamma(:), k_re(:), k_im(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: delta_M
    integer :: n, i
    character(len=20) :: row

    n = size(gamma)
    if (n < 2) then
      call fatal_error(error, "damper table: needs at least 2 rows (gamma, k_re, k_im)", &
        & UDMAP_EINPUT)
      return
    end if
    if (size(k_re) /= n .or. size(k_im) /= n) then
      call fatal_error(error, "damper table: 'gamma', 'k_re' and 'k_im' differ in length", &
        & UDMAP_EINPUT)
      return
    end if
    do i = 1, n
      write(row, '(i0)') i
      if (.not. (gamma(i) > 0 .and. gamma(i) <= huge(1.0_wp))) then
        call fatal_error(error, "damper table: 'gamma' of row "//trim(row)// &
          & " must be a positive finite number", UDMAP_EINPUT)
        return
      end if
      if (.not. (k_re(i) >= 0 .and. k_re(i) <= huge(1.0_wp))) then
        call fatal_error(error, "damper table: 'k_re' of row "//trim(row)// &
          & " must be a finite non-negative number", UDMAP_EINPUT)
        return
      end if
      if (.not. (k_im(i) >= 0 .and. k_im(i) <= huge(1.0_wp))) then
        call fatal_error(error, "damper table: 'k_im' of row "//trim(row)// &
          & " must be a finite non-negative number", UDMAP_EINPUT)
        return
      end if
    end do
    do i = 2, n
      if (.not. (gamma(i) > gamma(i-1))) then
        write(row, '(i0)') i
        call fatal_error(error, "damper table: 'gamma' must increase strictly (row "// &
          & trim(row)//")", UDMAP_EINPUT)
        return
      end if
    end do
    if (present(delta_M)) then
      if (.not. (delta_M > 0 .and. delta_M <= huge(1.0_wp))) then
        call fatal_error(error, "damper table: 'delta_M' must be a positive finite number", &
          & UDMAP_EINPUT)
        return
      end if
      tab%has_delta_M = .true.
      tab%delta_M = delta_M
    end if
    tab%n = n
    tab%gamma = gamma
    tab%x = log(gamma)
    tab%k_re = k_re
    tab%k_im = k_im
    allocate(tab%d_re(n), tab%d_im(n))
    call pchip_slopes(tab%x, tab%k_re, tab%d_re)
    call pchip_slopes(tab%x, tab%k_im, tab%d_im)
  end subroutine new_measured_table

  !> k(gamma): constant below the first row, PCHIP in ln(gamma) inside, beyond the last row
  !> k_Im = (E_last + 2 delta_M (gamma - gamma_last))/(pi gamma^2) and
  !> k_Re = k_Re,last (gamma_last/gamma)^(3/2) with delta_M, else the last row; with
  !> derivative = .true. its derivative dk/dgamma instead.
  pure function measured_stiffness(tab, gamma, derivative) result(k)
    type(measured_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    logical, intent(in), optional :: derivative
    complex(wp) :: k
    real(wp) :: g, E_last
    integer :: n, i
    logical :: slope
    slope = .false.
    if (present(derivative)) slope = derivative
    n = tab%n
    if (.not. (gamma > tab%gamma(1))) then
      if (slope) then
        k = 0
      else
        k = cmplx(tab%k_re(1), tab%k_im(1), wp)
      end if
    else if (gamma >= tab%gamma(n)) then
      if (tab%has_delta_M) then
        g = tab%gamma(n)
        E_last = pi*g**2*tab%k_im(n)
        if (slope) then
          k = cmplx(-1.5_wp*tab%k_re(n)*(g/gamma)**1.5_wp/gamma, &
            & -((2*tab%delta_M*(1 - 2*g/gamma) + 2*E_last/gamma)/(pi*gamma))/gamma, wp)
        else
          k = cmplx(tab%k_re(n)*(g/gamma)**1.5_wp, &
            & (E_last/gamma + 2*tab%delta_M*(1 - g/gamma))/(pi*gamma), wp)
        end if
      else if (slope) then
        k = 0
      else
        k = cmplx(tab%k_re(n), tab%k_im(n), wp)
      end if
    else
      i = find_row(tab, gamma)
      k = cmplx(hermite(tab, i, log(gamma), tab%k_re, tab%d_re, slope), &
        & hermite(tab, i, log(gamma), tab%k_im, tab%d_im, slope), wp)
      if (slope) k = k/gamma
    end if
  end function measured_stiffness

  pure integer function find_row(tab, gamma) result(i)
    type(measured_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    i = max(1, bisect(tab%gamma(1:tab%n - 1), gamma, right=.true.))
  end function find_row

  !> The cubic Hermite piece of row i at x (values y, slopes d against x), or with slope its
  !> derivative against x.
  pure real(wp) function hermite(tab, i, x, y, d, slope) result(f)
    type(measured_table_type), intent(in) :: tab
    integer, intent(in) :: i
    real(wp), intent(in) :: x, y(:), d(:)
    logical, intent(in) :: slope
    real(wp) :: h, t
    h = tab%x(i+1) - tab%x(i)
    t = (x - tab%x(i))/h
    if (slope) then
      f = (y(i+1) - y(i))*6*t*(1 - t)/h + d(i)*(1 - t)*(1 - 3*t) + d(i+1)*t*(3*t - 2)
    else
      f = y(i)*(1 + 2*t)*(1 - t)**2 + h*d(i)*t*(1 - t)**2 + y(i+1)*t**2*(3 - 2*t) &
        & - h*d(i+1)*t**2*(1 - t)
    end if
  end function hermite

  !> Fritsch-Carlson slopes with the three-point end conditions (as scipy's PchipInterpolator).
  pure subroutine pchip_slopes(x, y, d)
    real(wp), intent(in) :: x(:), y(:)
    real(wp), intent(out) :: d(:)
    real(wp) :: h(size(x)-1), delta(size(x)-1), w1, w2
    integer :: n, k
    n = size(x)
    h = x(2:n) - x(1:n-1)
    delta = (y(2:n) - y(1:n-1))/h
    if (n == 2) then
      d = delta(1)
      return
    end if
    do k = 2, n - 1
      if (delta(k-1)*delta(k) <= 0) then
        d(k) = 0
      else
        w1 = 2*h(k) + h(k-1)
        w2 = h(k) + 2*h(k-1)
        d(k) = (w1 + w2)/(w1/delta(k-1) + w2/delta(k))
      end if
    end do
    d(1) = edge(h(1), h(2), delta(1), delta(2))
    d(n) = edge(h(n-1), h(n-2), delta(n-1), delta(n-2))

  contains

    pure real(wp) function edge(h0, h1, m0, m1) result(dd)
      real(wp), intent(in) :: h0, h1, m0, m1
      dd = ((2*h0 + h1)*m0 - h0*m1)/(h0 + h1)
      if (sign(1.0_wp, dd) /= sign(1.0_wp, m0) .or. m0 == 0) then
        dd = 0
      else if (sign(1.0_wp, m0) /= sign(1.0_wp, m1) .and. abs(dd) > 3*abs(m0)) then
        dd = 3*m0
      end if
    end function edge
  end subroutine pchip_slopes
end module udmap_damper_measured
