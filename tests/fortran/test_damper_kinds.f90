!> Damper kinds "jenkins" and "table" (PHYSICS.md 2.4).
module test_damper_kinds
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_damper_type, only: damper_type, new_jenkins_damper, new_table_damper
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_damper_kinds

contains

  !> Damper kinds jenkins and table (PHYSICS.md 2.4).
  subroutine collect_damper_kinds(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_kinds", run_damper_kinds)]
  end subroutine collect_damper_kinds

  !> The jenkins and table kinds: closed forms, interpolation, extrapolation and their errors.
  subroutine run_damper_kinds(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: d, t
    type(error_type), allocatable :: error
    complex(wp) :: k, k1, k2
    real(wp) :: a(3), expect_re(3), expect_im(3), g(40), kre(40), kim(40), x, nan
    real(wp), allocatable :: tau(:), Mr(:)
    integer :: i, n

    ! Jenkins: the three values of PHYSICS.md 2.4 (kt = 2, slip limit 3).
    call new_jenkins_damper(d, 2.0_wp, 3.0_wp, error)
    call check_no_error(suite, "jenkins", error)
    a = [1.6_wp, 2.0_wp, 5.0_wp]
    expect_re = [1.947954_wp, 1.608998_wp, 0.504632_wp]
    expect_im = [0.149208_wp, 0.477465_wp, 0.534761_wp]
    do i = 1, 3
      k = d%stiffness(a(i))
      call check_close(suite, "jenkins k_Re", real(k, wp), expect_re(i), 0.0_wp, 1e-6_wp)
      call check_close(suite, "jenkins k_Im", aimag(k), expect_im(i), 0.0_wp, 1e-6_wp)
    end do
    call check_close(suite, "jenkins gamma_b = a_s", d%gamma_b, 1.5_wp, 1e-15_wp)
    call check_close(suite, "jenkins Delta_M", d%M_max - d%M_min, 6.0_wp, 1e-15_wp)
    call check_close(suite, "jenkins stuck", real(d%stiffness(1.0_wp), wp), 2.0_wp, 1e-15_wp)
    ! Its loop, integrated numerically, gives the same describing function; dk by differences.
    n = 40000
    allocate(tau(n), Mr(n))
    do i = 1, n
      tau(i) = 2*pi*(i - 1)/n
    end do
    do i = 1, 3
      call d%loop(a(i), tau, Mr, error)
      call check_no_error(suite, "jenkins loop", error)
      k = d%stiffness(a(i))
      call check_close(suite, "jenkins loop k_Re", sum(Mr*cos(tau))*(2/real(n, wp))/a(i), &
        & real(k, wp), 1e-6_wp)
      call check_close(suite, "jenkins loop k_Im", -sum(Mr*sin(tau))*(2/real(n, wp))/a(i), &
        & aimag(k), 1e-6_wp)
      k1 = d%stiffness(a(i)*(1 - 1e-6_wp))
      k2 = d%stiffness(a(i)*(1 + 1e-6_wp))
      call check_close(suite, "jenkins dk_Re", real(d%stiffness_derivative(a(i)), wp), &
        & real(k2 - k1, wp)/(2e-6_wp*a(i)), 1e-6_wp)
      call check_close(suite, "jenkins dk_Im", aimag(d%stiffness_derivative(a(i))), &
        & aimag(k2 - k1)/(2e-6_wp*a(i)), 1e-6_wp)
    end do
    call d%set_CF(100.0_wp, error)
    call check_error(suite, "jenkins has no CF", error, UDMAP_EINPUT, "CF")
    call new_jenkins_damper(d, -2.0_wp, 3.0_wp, error)
    call check_error(suite, "jenkins rejects negative kt", error, UDMAP_EINPUT, "kt")
    nan = ieee_value(nan, ieee_quiet_nan)
    call new_jenkins_damper(d, 2.0_wp, nan, error)
    call check_error(suite, "jenkins rejects NaN M_slip", error, UDMAP_EINPUT, "M_slip")

    ! Table: rows sampled from the Jenkins element.
    call new_jenkins_damper(d, 2.0_wp, 3.0_wp, error)
    do i = 1, 40
      g(i) = 10.0_wp**(-1 + 2*(i - 1)/39.0_wp)
      k = d%stiffness(g(i))
      kre(i) = real(k, wp)
      kim(i) = aimag(k)
    end do
    call new_table_damper(t, g, kre, kim, error, delta_M=6.0_wp)
    call check_no_error(suite, "table", error)
    do i = 1, 40
      k = t%stiffness(g(i))
      call check_close(suite, "table through its rows (re)", real(k, wp), kre(i), 1e-14_wp)
      call check_close(suite, "table through its rows (im)", aimag(k), kim(i), 0.0_wp, 1e-14_wp)
    end do
    ! Between rows PCHIP follows the smooth parts closely (the rows are 5% apart).
    k = t%stiffness(5.5_wp)
    call check_close(suite, "table between rows", real(k, wp), real(d%stiffness(5.5_wp), wp), 2e-3_wp)
    ! Constant below the first row; the extrapolation formula beyond the last, which for a
    ! Jenkins element with delta_M = 2 M_slip reproduces k_Im exactly.
    call check_close(suite, "table below first row", real(t%stiffness(1e-3_wp), wp), kre(1), 0.0_wp)
    x = 50.0_wp
    k = t%stiffness(x)
    call check_close(suite, "table extrapolated k_Im", aimag(k), aimag(d%stiffness(x)), 1e-12_wp)
    call check_close(suite, "table extrapolated k_Re", real(k, wp), kre(40)*(g(40)/x)**1.5_wp, 1e-14_wp)
    call check_true(suite, "table gamma_max unbounded with delta_M", t%gamma_max > 1e300_wp)
    ! Derivative of the interpolant by differences.
    k1 = t%stiffness(3.3_wp*(1 - 1e-7_wp))
    k2 = t%stiffness(3.3_wp*(1 + 1e-7_wp))
    call check_close(suite, "table dk_Re", real(t%stiffness_derivative(3.3_wp), wp), &
      & real(k2 - k1, wp)/(2e-7_wp*3.3_wp), 1e-6_wp)
    k1 = t%stiffness(30.0_wp*(1 - 1e-7_wp))
    k2 = t%stiffness(30.0_wp*(1 + 1e-7_wp))
    call check_close(suite, "table extrapolated dk_Re", real(t%stiffness_derivative(30.0_wp), wp), &
      & real(k2 - k1, wp)/(2e-7_wp*30), 1e-6_wp)
    call check_close(suite, "table extrapolated dk_Im", aimag(t%stiffness_derivative(30.0_wp)), &
      & aimag(k2 - k1)/(2e-7_wp*30), 1e-6_wp)
    call new_table_damper(t, g, kre, kim, error)
    call check_true(suite, "table without delta_M ends at its last row", t%gamma_max == g(40))
    call check_close(suite, "table without delta_M: gamma_s", t%gamma_s, g(count(g <= 1.5_wp)), 1e-15_wp)
    call t%loop(1.0_wp, tau(1:4), Mr(1:4), error)
    call check_error(suite, "table has no loop", error, UDMAP_EINPUT, "table")

    ! Table input checks.
    call new_table_damper(t, g(1:1), kre(1:1), kim(1:1), error)
    call check_error(suite, "table needs 2 rows", error, UDMAP_EINPUT, "2 rows")
    call new_table_damper(t, g(40:1:-1), kre, kim, error)
    call check_error(suite, "table gamma ascending", error, UDMAP_EINPUT, "gamma")
    kim(7) = -1
    call new_table_damper(t, g, kre, kim, error)
    call check_error(suite, "table rejects negative k_im", error, UDMAP_EINPUT, "k_im")
    kim(7) = 0
    kre(3) = nan
    call new_table_damper(t, g, kre, kim, error)
    call check_error(suite, "table rejects NaN k_re", error, UDMAP_EINPUT, "k_re")
    kre(3) = 1
    call new_table_damper(t, g, kre, kim, error, delta_M=-1.0_wp)
    call check_error(suite, "table rejects negative delta_M", error, UDMAP_EINPUT, "delta_M")
  end subroutine run_damper_kinds
end module test_damper_kinds
