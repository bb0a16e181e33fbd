!> The whole wheel in time (PHYSICS.md 2.6 last bullet, 7): in phase (EO = 0) it reproduces the
!> single blade's time integration; in a traveling wave (blade A, N = 4, EO = 1) the blades stay
!> a traveling wave: equal amplitudes and the phase step phi between neighbours; the damper's
!> tangent against a difference quotient of its traced actions.
module test_hbm_wheel
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer_core, only: damper_state_type
  use udmap_damper_tracer, only: trace_path, platform_actions
  use udmap_baseline_linear_structure, only: structure_type, structure_from_blade
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_baseline_newmark, only: dti_settings_type, dti_point_type, dti_response
  use udmap_baseline_wheel, only: wheel_point_type, wheel_response, damper_tangent
  use fixtures, only: blade_a_with_damper
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_hbm_wheel

contains

  subroutine collect_hbm_wheel(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_wheel", run_hbm_wheel)]
  end subroutine collect_hbm_wheel

  subroutine run_hbm_wheel(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type) :: blade
    type(damper_type) :: damper
    type(structure_type) :: st
    type(contact_element_type) :: el
    type(error_type), allocatable :: error
    type(dti_settings_type) :: dset
    type(dti_point_type) :: dp
    type(wheel_point_type) :: wp0, wp1
    type(damper_state_type) :: s0, s1
    real(wp) :: X(6), dX(6), T(6,6), A0(3,2), A1(3,2), fd(6), h, worst
    integer :: k

    call blade_a_with_damper(suite, blade, damper, error)
    call structure_from_blade(st, blade, error)
    call new_contact_element(el, blade_a_damper_params(), error)
    call check_no_error(suite, "contact element", error)
    dset%steps_per_period = 128
    dset%ss_tol = 1.0e-9_wp

    ! the tangent of the actions: a one-sided difference quotient within the final states
    s0 = el%loaded
    X = [2.0e-6_wp, 0.0_wp, 4.0e-4_wp, -1.0e-6_wp, 0.0_wp, 3.0e-4_wp]
    call trace_path(el%geo, s0, X, error)
    call check_no_error(suite, "trace", error)
    call damper_tangent(el%geo, s0, T)
    A0 = platform_actions(el%geo, s0)
    worst = 0.0_wp
    do k = 1, 6
      dX = 0.0_wp
      h = merge(1.0e-9_wp, 1.0e-11_wp, mod(k - 1, 3) == 2)
      dX(k) = h
      s1 = s0
      call trace_path(el%geo, s1, X + dX, error)
      A1 = platform_actions(el%geo, s1)
      fd = [A1(:,1) - A0(:,1), A1(:,2) - A0(:,2)]/h
      worst = max(worst, maxval(abs(fd - T(:, k)))/max(maxval(abs(T(:, k))), 1.0_wp))
    end do
    call check_true(suite, "damper tangent = difference quotient (1e-5)", worst < 1.0e-5_wp)

    ! in phase: N = 3 blades at EO = 0 are the single blade
    call dti_response(st, el, 196.0_wp, 5.0_wp, dset, dp, error)
    call check_no_error(suite, "single blade", error)
    call wheel_response(st, el, 196.0_wp, 5.0_wp, 3, 0, dset, wp0, error)
    call check_no_error(suite, "wheel EO = 0", error)
    call check_close(suite, "EO = 0: gamma_1 = single blade", wp0%gamma_1, dp%gamma_1, 1.0e-9_wp)
    call check_close(suite, "EO = 0: sigma_1 = single blade", wp0%sigma_1, dp%sigma_1, 1.0e-9_wp)
    call check_close(suite, "EO = 0: gamma_max = single blade", wp0%gamma_max, dp%gamma_max, &
      & 1.0e-9_wp)
    write(*, '(a, 2i7, 3es12.4)') "# EO=0: periods wheel, single; spreads; rel diff ", &
      & wp0%periods, dp%periods, wp0%gamma_spread, wp0%phase_spread, &
      & abs(wp0%gamma_1 - dp%gamma_1)/dp%gamma_1
    ! the steady-state test sits on its threshold: a period or two either way
    call check_true(suite, "EO = 0: periods within 3", abs(wp0%periods - dp%periods) <= 3)
    call check_true(suite, "EO = 0: blades equal (1e-10)", wp0%gamma_spread < 1.0e-10_wp .and. &
      & wp0%phase_spread < 1.0e-10_wp)

    ! traveling wave: blade A, N = 4, EO = 1 near its resonance (backbone at ibpa 90 deg)
    dset%ss_tol = 1.0e-7_wp
    call wheel_response(st, el, 197.5_wp, 2.0_wp, 4, 1, dset, wp1, error)
    call check_no_error(suite, "wheel N = 4, EO = 1", error)
    call check_true(suite, "EO = 1: phi = pi/2", abs(wp1%phi - pi/2) < 1.0e-15_wp)
    call check_true(suite, "EO = 1: amplitudes equal (1e-6)", wp1%gamma_spread < 1.0e-6_wp &
      & .and. wp1%sigma_spread < 1.0e-6_wp)
    call check_true(suite, "EO = 1: phase steps = phi (1e-6 rad)", wp1%phase_spread < 1.0e-6_wp)
    call check_true(suite, "EO = 1: not the in-phase response", &
      & abs(wp1%gamma_1 - dp%gamma_1) > 1.0e-3_wp*dp%gamma_1)
    write(*, '(a, 3es12.4, i6)') "# wheel EO=1: gamma_1, spread, phase spread, periods ", &
      & wp1%gamma_1, wp1%gamma_spread, wp1%phase_spread, wp1%periods

    ! bad input
    call wheel_response(st, el, 197.5_wp, 2.0_wp, 1, 0, dset, wp1, error)
    call check_error(suite, "blades = 1 refused", error, UDMAP_EINPUT, "blades must be in 2..")
  end subroutine run_hbm_wheel
end module test_hbm_wheel
