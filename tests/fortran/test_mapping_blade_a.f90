!> The acceptance checks of the backbone on the reference case itself: blade A (beam) with its
!> asymmetric flat/curved damper (cases/blade_a.json). Backbone points on the mapped curves
!> (double crossing, no layer above reaching F_E), eigenvalue start against the refined peak,
!> stuck limit, zeta = 0 limit, converged defaults, and a set_damper round trip.
program test_mapping_blade_a
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade
  use udmap_blade_beam, only: beam_params_type
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params, asymmetric_params_type
  use udmap_mapping_eigen_start, only: direct_eigen_start
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, set_damper, &
    & limit_force, backbone, backbone_curve, response, REGIME_STUCK, REGIME_PARTIAL_SLIP
  use testing, only: test_suite, check_close, check_true, check_no_error, finish
  implicit none
  type(test_suite) :: suite
  type(blade_type), target :: blade, blade0
  type(damper_type), target :: damper, damper2
  type(model_type) :: model, model0, model_fine
  type(analysis_type) :: analysis, fine
  type(error_type), allocatable :: error
  type(point_type), allocatable :: points(:), again(:), points_fine(:)
  type(beam_params_type) :: params
  type(asymmetric_params_type) :: dparams
  real(wp), allocatable :: gam(:), F_bb(:), f_res(:)
  real(wp) :: F_lim, F, dF, w, worst, F_bb1(1), f_res1(1), stuck_Fbb(2), stuck_freq(2)
  complex(wp) :: k, lambda
  integer :: i, j

  params = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, neck_L=0.020_wp, &
    & neck_h=0.008_wp, neck_b=0.020_wp, platform_L=0.010_wp, platform_m=0.021_wp, &
    & platform_J=1.4e-6_wp, airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
    & neck_elements=8, airfoil_elements=24)
  call new_beam_blade(blade, params, error)
  call check_no_error(suite, "blade", error)
  call new_asymmetric_damper(damper, blade_a_damper_params(), error)
  call check_no_error(suite, "damper", error)
  analysis%f_min = 150
  analysis%f_max = 230
  call new_model(model, blade, damper, analysis, error)
  call check_no_error(suite, "model", error)
  if (allocated(error)) call finish(suite)
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
    call layer_force(points(i)%gamma_P, k, w, F, dF)
    call check_close(suite, "F(f_res) = F_E", F, points(i)%F_E, 1e-10_wp)
    call check_close(suite, "dF/domega = 0", dF*w/F, 0.0_wp, 0.0_wp, 1e-8_wp)
    do j = 0, 12
      call check_true(suite, "no layer above reaches F_E", &
        & band_min_force(points(i)%gamma_P*(1 + 1e-8_wp)*10.0_wp**(0.25_wp*j)) > points(i)%F_E)
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
  call backbone(model, [(real(i, wp), i = 1, 10)], points, error)
  fine = analysis
  fine%rtol = analysis%rtol/2
  fine%grid_per_decade = 2*analysis%grid_per_decade
  call new_model(model_fine, blade, damper, fine, error)
  call backbone(model_fine, [(real(i, wp), i = 1, 10)], points_fine, error)
  worst = 0
  do i = 1, 10
    worst = max(worst, abs(points_fine(i)%gamma_P/points(i)%gamma_P - 1), &
      & abs(points_fine(i)%f_res/points(i)%f_res - 1), &
      & abs(points_fine(i)%sigma_a/points(i)%sigma_a - 1))
  end do
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
  call finish(suite)

contains

  !> F(omega) = gamma/|g~| and dF/d omega of the layer gamma (stiffness k).
  subroutine layer_force(gamma, kk, wk, Fk, dFk)
    real(wp), intent(in) :: gamma, wk
    complex(wp), intent(in) :: kk
    real(wp), intent(out) :: Fk, dFk
    type(receptances_type) :: r
    complex(wp) :: g, dg
    call blade%receptances(wk, r, error, derivatives=.true.)
    g = r%gE/(1 + kk*r%gg)
    dg = r%dgE/(1 + kk*r%gg) - r%gE*kk*r%dgg/(1 + kk*r%gg)**2
    Fk = gamma/abs(g)
    dFk = -Fk*real(dg*conjg(g), wp)/abs(g)**2
  end subroutine layer_force

  !> min over the band of F(omega) for the layer gamma: 4000 samples, then golden section.
  real(wp) function band_min_force(gamma) result(Fmin)
    real(wp), intent(in) :: gamma
    real(wp), parameter :: gr = 0.618033988749895_wp
    complex(wp) :: kk
    real(wp) :: a, b, c, d, Fc, Fd, dummy, w0, h, vals(0:4000)
    integer :: n, best, it
    kk = damper%stiffness(gamma)
    w0 = 2*pi*analysis%f_min
    h = 2*pi*(analysis%f_max - analysis%f_min)/4000
    do n = 0, 4000
      call layer_force(gamma, kk, w0 + n*h, vals(n), dummy)
    end do
    best = minloc(vals, 1) - 1
    a = w0 + max(best - 1, 0)*h
    b = w0 + min(best + 1, 4000)*h
    c = b - (b - a)*gr
    d = a + (b - a)*gr
    call layer_force(gamma, kk, c, Fc, dummy)
    call layer_force(gamma, kk, d, Fd, dummy)
    do it = 1, 100
      if (Fc < Fd) then
        b = d; d = c; Fd = Fc
        c = b - (b - a)*gr
        call layer_force(gamma, kk, c, Fc, dummy)
      else
        a = c; c = d; Fc = Fd
        d = a + (b - a)*gr
        call layer_force(gamma, kk, d, Fd, dummy)
      end if
    end do
    Fmin = min(minval(vals), Fc, Fd)
  end function band_min_force
end program test_mapping_blade_a
