!> The acceptance checks of the backbone on the reference case itself: blade A (beam) with its
!> asymmetric flat/curved damper (cases/blade_a.json). Backbone points on the mapped curves
!> (double crossing, no layer above reaching F_E), eigenvalue start against the refined peak,
!> stuck limit, zeta = 0 limit, converged defaults, and a set_damper round trip.
module test_mapping_blade_a
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade
  use udmap_blade_beam, only: beam_params_type
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params, asymmetric_params_type
  use udmap_mapping_eigen_start, only: direct_eigen_start
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, set_damper, &
    & limit_force, backbone, backbone_curve, response, REGIME_STUCK, REGIME_PARTIAL_SLIP
  use fixtures, only: blade_a_beam_params, blade_a_model, refined_backbone_change, layer_force, &
    & band_min_force
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_mapping_blade_a

contains

  !> Acceptance checks of the reference case blade_a.
  subroutine collect_mapping_blade_a(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_blade_a", run_mapping_blade_a)]
  end subroutine collect_mapping_blade_a

  !> The acceptance numbers of the reference case on its backbone and mapped curves.
  subroutine run_mapping_blade_a(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type), target :: blade, blade0
    type(damper_type), target :: damper, damper2
    type(model_type) :: model, model0
    type(analysis_type) :: analysis
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:), again(:)
    type(beam_params_type) :: params
    type(asymmetric_params_type) :: dparams
    real(wp), allocatable :: gam(:), F_bb(:), f_res(:)
    real(wp) :: F_lim, F, dF, w, worst, F_bb1(1), f_res1(1), stuck_Fbb(2), stuck_freq(2)
    complex(wp) :: k, lambda
    integer :: i, j

    params = blade_a_beam_params()
    call new_beam_blade(blade, params, error)
    call check_no_error(suite, "blade", error)
    call new_asymmetric_damper(damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
    call blade_a_model(suite, blade, damper, analysis, model, error)
    if (allocated(error)) return
    call limit_force(model, F_lim, error)
    call check_close(suite, "F_lim = 2 Delta_M/(pi |phi_E/phi_g|)", F_lim, 2*(damper%M_max - &
      & damper%M_min)/(pi*abs(blade%phi(blade%exc_dof, 1)/blade%phi(blade%gamma_dof, 1))), 1e-14_wp)

    ! backbone points on the mapped curves, for forces from partial slip to above F_lim
    call backbone(model, [1.0_wp, 5.0_wp, 10.0_wp, 0.9_wp*F_lim, 1.2_wp*F_lim], points, error)
    call check_no_error(suite, "backbone", error)
    call check_true(suite, "partial slip at 1 N", points(1)%regime == REGIME_PARTIAL_SLIP)
    do i = 1, size(points)
      w = 2*pi*points(i)%f_res
      k = damper%stiffness(points(i)%gamma_P)
      call layer_force(blade, points(i)%gamma_P, k, w, F, dF, error)
      call check_close(suite, "F(f_res) = F_E", F, points(i)%F_E, 1e-10_wp)
      call check_close(suite, "dF/domega = 0", dF*w/F, 0.0_wp, 0.0_wp, 1e-8_wp)
      do j = 0, 12
        call check_true(suite, "no layer above reaches F_E", &
          & band_min_force(blade, damper, analysis, &
          & points(i)%gamma_P*(1 + 1e-8_wp)*10.0_wp**(0.25_wp*j), error) > points(i)%F_E)
      end do
    end do

    ! eigenvalue start (dense zggev) within 1e-3 of the refined peak, stuck to full slip
    gam = damper%gamma_s*10.0_wp**[(0.125_wp*i, i = -8, 16)]
    allocate(F_bb(size(gam)), f_res(size(gam)))
    call backbone_curve(model, gam, F_bb, f_res, error)
    call check_no_error(suite, "backbone curve", error)
    worst = 0
    do i = 1, size(gam)
      call direct_eigen_start(blade, damper%stiffness(gam(i)), 200, lambda, error)
      worst = max(worst, abs(real(sqrt(lambda), wp)/(2*pi*f_res(i)) - 1))
    end do
    call check_close(suite, "eigenvalue start within 1e-3", worst, 0.0_wp, 0.0_wp, 1e-3_wp)

    ! stuck limit: F_bb proportional to gamma, the peak of K + k_stuck
    call backbone_curve(model, [1e-3_wp, 1e-1_wp]*damper%gamma_s, stuck_Fbb, stuck_freq, error)
    call check_close(suite, "stuck F_bb linear", stuck_Fbb(2)/stuck_Fbb(1), 100.0_wp, 1e-12_wp)
    call check_close(suite, "stuck peak frequency constant", stuck_freq(2), stuck_freq(1), 1e-13_wp)
    call check_close(suite, "stuck stiffness", real(damper%stiffness(1e-3_wp*damper%gamma_s), wp), &
      & damper%k_stuck, 1e-12_wp)
    call direct_eigen_start(blade, cmplx(damper%k_stuck, 0.0_wp, wp), 200, lambda, error)
    call check_close(suite, "stuck peak near the stuck eigenfrequency", stuck_freq(1), &
      & real(sqrt(lambda), wp)/(2*pi), 1e-4_wp)
    call backbone(model, [0.5_wp*stuck_Fbb(1)/(1e-3_wp*damper%gamma_s)*damper%gamma_s], again, error)
    call check_true(suite, "stuck regime", again(1)%regime == REGIME_STUCK)
    call check_close(suite, "stuck root", again(1)%gamma_P, 0.5_wp*damper%gamma_s, 1e-12_wp)

    ! converged defaults: halving the tolerance and the grid step
    call refined_backbone_change(model, blade, damper, analysis, points, worst, error)
    call check_close(suite, "converged defaults", worst, 0.0_wp, 0.0_wp, 1e-8_wp)

    ! a new damper object with the same parameters through set_damper: same answers
    call new_asymmetric_damper(damper2, blade_a_damper_params(), error)
    call set_damper(model, damper2, error)
    call check_no_error(suite, "set_damper", error)
    call backbone(model, [(real(i, wp), i = 1, 10)], again, error)
    worst = 0
    do i = 1, 10
      worst = max(worst, abs(again(i)%gamma_P/points(i)%gamma_P - 1), &
        & abs(again(i)%f_res/points(i)%f_res - 1))
    end do
    call check_close(suite, "set_damper round trip", worst, 0.0_wp, 0.0_wp, 1e-12_wp)

    ! zeta = 0: F_bb(1e3 gamma_b) within 0.5 % of F_lim
    params%zeta = 0
    call new_beam_blade(blade0, params, error)
    call new_model(model0, blade0, damper, analysis, error)
    call backbone_curve(model0, [1e3_wp*damper%gamma_b], F_bb1, f_res1, error)
    call check_no_error(suite, "undamped backbone curve", error)
    call check_true(suite, "F_bb(1e3 gamma_b) within 0.5% of F_lim", abs(F_bb1(1)/F_lim - 1) <= 5e-3_wp)
    call check_true(suite, "F_bb(1e3 gamma_b) below F_lim", F_bb1(1) < F_lim)

    ! a damper with lift-off (mu = 0.6) dissipates less than 2 Delta_M per unit rotation at large
    ! amplitude, so without damping F_bb saturates below F_lim: forces above its asymptote are
    ! unbounded too, forces below it are not
    dparams = blade_a_damper_params()
    dparams%mu = 0.6_wp
    call new_asymmetric_damper(damper2, dparams, error)
    call check_true(suite, "lift-off damper", damper2%lift_off)
    call set_damper(model0, damper2, error)
    call limit_force(model0, F_lim, error)
    call backbone_curve(model0, [1e6_wp*damper2%gamma_b], F_bb1, f_res1, error)
    call backbone(model0, [0.3_wp*F_lim, 0.95_wp*F_bb1(1), 1.05_wp*F_bb1(1), 0.9_wp*F_lim], &
      & again, error)
    call check_no_error(suite, "lift-off backbone", error)
    call check_true(suite, "bounded below the asymptote", .not.any(again(1:2)%unbounded))
    call check_true(suite, "unbounded above the asymptote", all(again(3:4)%unbounded))
    ! the response at the peak frequency has the three roots of the overhang, the peak among them
    call set_damper(model, damper2, error)
    call backbone(model, [0.5_wp*F_lim], points, error)
    call response(model, points(1)%f_res, [0.5_wp*F_lim], again, error)
    call check_no_error(suite, "lift-off response", error)
    call check_true(suite, "three roots at the peak frequency", size(again(1)%roots) == 3)
    call check_close(suite, "the peak is the largest", again(1)%gamma_P, points(1)%gamma_P, 1e-9_wp)

  end subroutine run_mapping_blade_a
end module test_mapping_blade_a
