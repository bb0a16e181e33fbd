!> The one-DOF Jenkins oscillator of PHYSICS.md 8 through the matrices blade kind:
!> m = 1, c = 0.01 (explicit C), k = 1, Jenkins kt = 0.25, slip 0.2 on the same DOF.
!> Published single-harmonic peaks, the stuck and free backbone limits, and every point of
!> the response at a frequency and of the mapped curves checked against the scalar equation
!> a |1 + k(a) H(omega)| = F |H(omega)|, H = 1/(1 - omega^2 + i c omega), evaluated here
!> independently of the blade module.
module test_mapping_oscillator
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_mapping_model, only: point_type, curve_type, limit_force, backbone, backbone_curve, &
    & response, response_curves, REGIME_FULL_SLIP, REGIME_LIMIT, REGIME_STUCK, BRANCH_TURNING
  use fixtures, only: scene_type, jenkins_oscillator, oscillator_model
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_mapping_oscillator

contains

  !> Jenkins oscillator (PHYSICS.md 8) from Matrix Market files.
  subroutine collect_mapping_oscillator(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_oscillator", run_mapping_oscillator)]
  end subroutine collect_mapping_oscillator

  !> The Jenkins oscillator through imported matrices: peaks, responses and curves.
  subroutine run_mapping_oscillator(suite)
    type(test_suite), intent(inout) :: suite
    type(scene_type), target :: osc
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:)
    type(curve_type), allocatable :: curves(:)
    real(wp) :: F_lim, F_bb(2), f_res(2), worst, omega
    real(wp), parameter :: c_visc = 0.01_wp, kt = 0.25_wp, slip = 0.2_wp
    ! PHYSICS.md 8: F, amplitude, omega [rad/s]
    real(wp), parameter :: published(3, 3) = reshape([0.05_wp, 0.946956_wp, 1.106824_wp, &
      & 0.1_wp, 1.214018_wp, 1.083677_wp, 0.3_wp, 7.279801_wp, 1.007341_wp], [3, 3])
    integer :: i, j

    call jenkins_oscillator(suite, osc, c_visc, kt, slip, error)
    call oscillator_model(suite, osc, 0.8_wp, 1.4_wp, error)
    if (allocated(error)) return

    ! F_lim = 2 Delta_M/(pi |phi_E/phi_g|) = 2 (2 slip)/pi with phi_E = phi_g
    call limit_force(osc%model, F_lim, error)
    call check_close(suite, "F_lim", F_lim, 4*slip/pi, 1e-14_wp)

    ! the three published peaks, amplitude and frequency to 1e-6
    call backbone(osc%model, published(1, :), points, error)
    call check_no_error(suite, "backbone", error)
    do i = 1, 3
      call check_close(suite, "peak amplitude", points(i)%gamma_P, published(2, i), 1e-6_wp)
      call check_close(suite, "peak omega", 2*pi*points(i)%f_res, published(3, i), 1e-6_wp)
      call check_true(suite, "one root", size(points(i)%roots) == 1)
      ! u_E = gamma_P (E is the gamma DOF); the peak satisfies the scalar equation
      call check_close(suite, "u_E", points(i)%u_E, points(i)%gamma_P, 1e-12_wp)
      call check_close(suite, "peak on the response", residual(points(i)%gamma_P, &
        & 2*pi*points(i)%f_res, points(i)%F_E), 0.0_wp, 0.0_wp, 1e-11_wp)
      call check_true(suite, "not unbounded (explicit damping)", .not.points(i)%unbounded)
    end do
    call check_true(suite, "regime full slip", points(1)%regime == REGIME_FULL_SLIP)
    ! F = 0.3 > F_lim: finite (viscous damping), regime 3, not HCF-admissible
    call check_true(suite, "regime at F_lim", points(3)%regime == REGIME_LIMIT)
    call check_true(suite, "hcf at F_lim", .not.points(3)%hcf_ok)
    call check_true(suite, "hcf below", points(1)%hcf_ok)

    ! backbone frequency: stuck sqrt(1.25), free 1 (each within the viscous peak shift c^2)
    call backbone_curve(osc%model, [1e-3_wp, 1e3_wp], F_bb, f_res, error)
    call check_no_error(suite, "backbone_curve", error)
    call check_close(suite, "stuck backbone frequency", 2*pi*f_res(1), sqrt(1.25_wp), 1e-4_wp)
    call check_close(suite, "free backbone frequency", 2*pi*f_res(2), 1.0_wp, 1e-4_wp)
    ! stuck: F_bb = gamma |1.25 - w^2 + i c w| at the peak w^2 = 1.25 - c^2/2
    omega = sqrt(1.25_wp - c_visc**2/2)
    call check_close(suite, "stuck F_bb", F_bb(1), &
      & 1e-3_wp*abs(cmplx(1.25_wp - omega**2, c_visc*omega, wp)), 1e-12_wp)
    call backbone(osc%model, [1e-4_wp], points, error)
    call check_true(suite, "stuck regime", points(1)%regime == REGIME_STUCK)

    ! response at a frequency: every root satisfies the scalar equation
    call response(osc%model, 1.05_wp/(2*pi), [0.05_wp, 0.1_wp, 0.3_wp], points, error)
    call check_no_error(suite, "response", error)
    worst = 0
    do i = 1, size(points)
      do j = 1, size(points(i)%roots)
        worst = max(worst, abs(residual(points(i)%roots(j), 1.05_wp, points(i)%F_E)))
      end do
      call check_close(suite, "response f", points(i)%f_res, 1.05_wp/(2*pi), 1e-15_wp)
    end do
    call check_close(suite, "response roots on the equation", worst, 0.0_wp, 0.0_wp, 1e-11_wp)

    ! outside the band [0.8, 1.4] rad/s but within 3 f_max: answered, on the scalar equation
    ! with the oscillator's exact receptances
    call response(osc%model, 2.5_wp/(2*pi), [0.05_wp, 0.3_wp], points, error)
    call check_no_error(suite, "response outside the band", error)
    if (.not.allocated(error)) then
      do i = 1, size(points)
        call check_close(suite, "response outside the band on the equation", &
          & residual(points(i)%gamma_P, 2.5_wp, points(i)%F_E), 0.0_wp, 0.0_wp, 1e-11_wp)
      end do
    end if
    ! f_exc beyond 3 f_max, bad forces
    call response(osc%model, 1.0_wp, [0.1_wp], points, error)
    call check_error(suite, "f_exc beyond 3 f_max", error, UDMAP_EINPUT, "f_exc")
    call backbone(osc%model, [0.1_wp, -1.0_wp], points, error)
    call check_error(suite, "negative force", error, UDMAP_EINPUT, "F_E(2)")

    ! mapped curves: every point on the scalar equation, a turning point at each peak
    call response_curves(osc%model, [0.05_wp, 0.1_wp, 0.3_wp], 30, curves, error)
    call check_no_error(suite, "curves", error)
    worst = 0
    do i = 1, size(curves)
      do j = 1, size(curves(i)%f)
        worst = max(worst, abs(residual(curves(i)%gamma_P(j), 2*pi*curves(i)%f(j), curves(i)%F_E)))
      end do
      call check_true(suite, "curve has many points", size(curves(i)%f) > 60)
      call check_true(suite, "curve has its peak", count(curves(i)%branch == BRANCH_TURNING) == 1)
      call check_close(suite, "curve max = peak", maxval(curves(i)%gamma_P), published(2, i), 1e-6_wp)
      call check_close(suite, "curve starts at f_min", curves(i)%f(1), osc%analysis%f_min, &
        & 1e-14_wp)
      call check_close(suite, "curve ends at f_max", curves(i)%f(size(curves(i)%f)), &
        & osc%analysis%f_max, 1e-14_wp)
    end do
    call check_close(suite, "curve points on the equation", worst, 0.0_wp, 0.0_wp, 1e-9_wp)

  contains

    !> Jenkins describing function (PHYSICS.md 2.4), written out again here.
    complex(wp) function jenkins(a) result(k)
      real(wp), intent(in) :: a
      real(wp) :: a_s, beta
      a_s = slip/kt
      if (a <= a_s) then
        k = kt
      else
        beta = acos(1 - 2*a_s/a)
        k = cmplx(kt/pi*(beta - sin(2*beta)/2), 4*slip/(pi*a)*(1 - a_s/a), wp)
      end if
    end function jenkins

    !> (a |1 + k(a) H| - F |H|) / (F |H|) for the oscillator at omega [rad/s].
    real(wp) function residual(a, w, F) result(res)
      real(wp), intent(in) :: a, w, F
      complex(wp) :: H
      H = 1/cmplx(1 - w**2, c_visc*w, wp)
      res = (a*abs(1 + jenkins(a)*H) - F*abs(H))/(F*abs(H))
    end function residual
  end subroutine run_mapping_oscillator
end module test_mapping_oscillator
