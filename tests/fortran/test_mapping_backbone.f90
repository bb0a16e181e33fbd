!> Backbone of blade A (beam) with a rotational Jenkins damper, checked against independent
!> computations: dense complex solves of the full blade, sampled layer responses, bisection on
!> the sign of d|g~|/d omega, LAPACK eigenvalues, closed-form limits.
module test_mapping_backbone
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EPHYSICS, UDMAP_EINPUT
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade
  use udmap_blade_beam, only: beam_params_type
  use udmap_damper_type, only: damper_type, new_jenkins_damper
  use udmap_mapping_eigen_start, only: direct_eigen_start, secular_root
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, limit_force, &
    & backbone, backbone_curve, response, REGIME_LIMIT, REGIME_STUCK, REGIME_FULL_SLIP
  use fixtures, only: blade_a_beam_params, blade_a_model, refined_backbone_change, dense_gamma, &
    & layer_force, band_min_force
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_mapping_backbone

contains

  !> Backbone of blade A, rotational Jenkins damper: independent checks.
  subroutine collect_mapping_backbone(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_backbone", run_mapping_backbone)]
  end subroutine collect_mapping_backbone

  !> Backbone points against dense solves, sampled layers, bisection and eigenvalue limits.
  subroutine run_mapping_backbone(suite)
    type(test_suite), intent(inout) :: suite

    type(blade_type), target :: blade, blade0
    type(damper_type), target :: damper
    type(model_type) :: model, model0, model_fine
    type(analysis_type) :: analysis, fine
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:)
    type(beam_params_type) :: params
    real(wp), parameter :: kt = 3000.0_wp, M_slip = 1.35_wp
    real(wp), allocatable :: gam(:), F_bb(:), f_res(:)
    real(wp) :: F_lim, F_lim0, F, dF, w, fmin_layer, f_direct, worst, rel
    complex(wp) :: k, lambda, lambda_sec, lambda_arpack
    logical :: ok
    integer :: i, j

    params = blade_a_beam_params()
    call new_beam_blade(blade, params, error)
    call check_no_error(suite, "blade", error)
    call new_jenkins_damper(damper, kt, M_slip, error)
    call check_no_error(suite, "damper", error)
    call blade_a_model(suite, blade, damper, analysis, model, error)
    if (allocated(error)) return
    call limit_force(model, F_lim, error)

    ! ---- backbone points lie on the mapped response curves
    call backbone(model, [1.0_wp, 3.0_wp, 6.0_wp, 0.3_wp*F_lim], points, error)
    call check_no_error(suite, "backbone", error)
    do i = 1, size(points)
      w = 2*pi*points(i)%f_res
      k = damper%stiffness(points(i)%gamma_P)
      call layer_force(blade, points(i)%gamma_P, k, w, F, dF, error)
      ! the layer gamma_P reaches F_E at f_res, with a double crossing (dF/domega = 0)
      call check_close(suite, "F(f_res) = F_E", F, points(i)%F_E, 1e-10_wp)
      call check_close(suite, "dF/domega = 0", dF*w/F, 0.0_wp, 0.0_wp, 1e-8_wp)
      ! no layer above gamma_P reaches F_E anywhere in the band
      do j = 0, 12
        fmin_layer = band_min_force(blade, damper, analysis, &
          & points(i)%gamma_P*(1 + 1e-8_wp)*10.0_wp**(0.25_wp*j), error)
        call check_true(suite, "layers above stay above F_E", fmin_layer > points(i)%F_E)
      end do
      ! Sherman-Morrison against a dense solve of the coupled blade at the peak
      call check_close(suite, "gamma_P by dense solve", dense_gamma(blade, damper, points(i)%gamma_P, &
        & points(i)%F_E, w), points(i)%gamma_P, 1e-9_wp)
    end do
    call check_true(suite, "regime full slip", points(2)%regime == REGIME_FULL_SLIP)

    ! ---- eigenvalue start within 1e-3 of the refined peak; refinement converged to 1e-10
    gam = damper%gamma_b*10.0_wp**[(0.25_wp*i, i = -4, 8)]
    allocate(F_bb(size(gam)), f_res(size(gam)))
    call backbone_curve(model, gam, F_bb, f_res, error)
    call check_no_error(suite, "backbone_curve", error)
    do i = 1, size(gam)
      k = damper%stiffness(gam(i))
      call direct_eigen_start(blade, k, 200, lambda, error)
      call check_no_error(suite, "zggev", error)
      call check_close(suite, "eigenvalue start near the peak", &
        & real(sqrt(lambda), wp)/(2*pi), f_res(i), 1e-3_wp)
      call check_close(suite, "peak by bisection", f_res(i), peak_by_bisection(k)/(2*pi), 1e-10_wp)
      ! the secular equation on the bare modes agrees with the dense eigenvalue
      call secular_root(model%secular, k, lambda_sec, ok)
      call check_true(suite, "secular converged", ok)
      ! zggev itself is accurate to about eps omega_max^2/omega_1^2 ~ 1e-8 here
      call check_close(suite, "secular = zggev", abs(lambda_sec - lambda)/abs(lambda), 0.0_wp, &
        & 0.0_wp, 1e-7_wp)
    end do
    ! ARPACK shift-invert on the band storage (dense_max = 10 forces it) agrees with zggev to
    ! zggev's accuracy, and with the secular equation more closely (both resolve the low mode
    ! without the high modes' rounding)
    k = damper%stiffness(2*damper%gamma_b)
    call direct_eigen_start(blade, k, 200, lambda, error)
    call direct_eigen_start(blade, k, 10, lambda_arpack, error)
    if (allocated(error)) then
      ! a build without ARPACK says so
      call check_error(suite, "no ARPACK", error, UDMAP_EINPUT, "ARPACK")
    else
      call check_close(suite, "ARPACK = zggev", abs(lambda_arpack - lambda)/abs(lambda), 0.0_wp, &
        & 0.0_wp, 1e-7_wp)
      call secular_root(model%secular, k, lambda_sec, ok)
      call check_close(suite, "ARPACK = secular", abs(lambda_arpack - lambda_sec)/abs(lambda), &
        & 0.0_wp, 0.0_wp, 1e-10_wp)
    end if

    ! ---- stuck limit: F_bb proportional to gamma, peak of the linear blade with K + k_stuck
    call backbone_curve(model, [1e-3_wp, 1e-2_wp]*damper%gamma_b, F_bb(1:2), f_res(1:2), error)
    call check_close(suite, "stuck F_bb linear", F_bb(2)/F_bb(1), 10.0_wp, 1e-12_wp)
    call check_close(suite, "stuck frequencies equal", f_res(2), f_res(1), 1e-13_wp)
    f_direct = dense_stuck_peak()
    call check_close(suite, "stuck peak = K + k_stuck peak", f_res(1), f_direct, 1e-7_wp)
    call backbone(model, [1e-3_wp], points, error)
    call check_true(suite, "stuck regime", points(1)%regime == REGIME_STUCK)

    ! ---- convergence: halving the tolerance and the grid step changes nothing beyond 1e-8
    call refined_backbone_change(model, blade, damper, analysis, points, worst, error)
    call check_no_error(suite, "fine backbone", error)
    call check_close(suite, "converged defaults", worst, 0.0_wp, 0.0_wp, 1e-8_wp)

    ! ---- a band without the resonance is a physics error, not a band-edge answer
    call check_band(100.0_wp, 150.0_wp, "above the band")
    call check_band(200.0_wp, 260.0_wp, "below the band")
    call check_band(120.0_wp, 180.0_wp, "above the band")

    ! ---- a band holding a second bare mode is refused (the backbone follows mode 1)
    fine = analysis
    fine%f_max = 1200
    call new_model(model_fine, blade, damper, fine, error)
    call check_error(suite, "second mode in band", error, UDMAP_EINPUT, "bare mode")

    ! ---- zeta = 0: F_bb tends to F_lim, unbounded at and above F_lim
    params%zeta = 0
    call new_beam_blade(blade0, params, error)
    call new_model(model0, blade0, damper, analysis, error)
    call check_no_error(suite, "undamped model", error)
    call limit_force(model0, F_lim0, error)
    call check_close(suite, "F_lim independent of zeta", F_lim0, F_lim, 1e-6_wp)
    call check_close(suite, "F_lim formula", F_lim0, 2*(2*M_slip)/(pi*abs(blade0%phi(blade0%exc_dof, 1) &
      & /blade0%phi(blade0%gamma_dof, 1))), 1e-13_wp)
    call backbone_curve(model0, [1e3_wp*damper%gamma_b], F_bb(1:1), f_res(1:1), error)
    call check_no_error(suite, "undamped backbone curve", error)
    rel = F_bb(1)/F_lim0
    call check_true(suite, "F_bb(1e3 gamma_b) within 0.5% of F_lim", abs(rel - 1) <= 5e-3_wp)
    call backbone(model0, [0.5_wp*F_lim0, 0.99_wp*F_lim0, F_lim0, 2*F_lim0], points, error)
    call check_no_error(suite, "undamped backbone", error)
    call check_true(suite, "bounded below F_lim", .not.any(points(1:2)%unbounded))
    call check_true(suite, "finite gamma_P", points(2)%gamma_P > points(1)%gamma_P .and. &
      & points(2)%gamma_P < huge(1.0_wp))
    do i = 3, 4
      call check_true(suite, "unbounded at/above F_lim", points(i)%unbounded .and. &
        & points(i)%regime == REGIME_LIMIT .and. .not.points(i)%hcf_ok)
      call check_true(suite, "unbounded numbers are zero", points(i)%gamma_P == 0 .and. &
        & points(i)%sigma_a == 0 .and. points(i)%f_res == 0 .and. points(i)%u_E == 0 .and. &
        & size(points(i)%roots) == 0)
    end do

    ! ---- the response at a frequency against dense solves
    call response(model, 190.0_wp, [1.0_wp, 5.0_wp, 10.0_wp], points, error)
    call check_no_error(suite, "response", error)
    do i = 1, size(points)
      do j = 1, size(points(i)%roots)
        call check_close(suite, "response root by dense solve", dense_gamma(blade, damper, points(i)%roots(j), &
          & points(i)%F_E, 2*pi*190.0_wp), points(i)%roots(j), 1e-9_wp)
      end do
    end do

  contains

    !> Frequency [rad/s] of the maximum of |g~| for stiffness k: bisection on the sign of
    !> d|g~|/d omega over a bracket found by sampling.
    real(wp) function peak_by_bisection(kk) result(wpk)
      complex(wp), intent(in) :: kk
      real(wp) :: a, b, m, Fa, dFa, Fm, dFm, w0, h, Fv, dFv
      integer :: n, it
      w0 = 2*pi*analysis%f_min
      h = 2*pi*(analysis%f_max - analysis%f_min)/2000
      a = w0
      call layer_force(blade, 1.0_wp, kk, a, Fa, dFa, error)
      b = a
      do n = 1, 2000
        call layer_force(blade, 1.0_wp, kk, w0 + n*h, Fv, dFv, error)
        ! dF/domega changes sign from negative to positive at the minimum of F (peak of |g~|)
        if (dFa < 0 .and. dFv >= 0) then
          b = w0 + n*h
          exit
        end if
        a = w0 + n*h
        dFa = dFv
      end do
      do it = 1, 200
        m = 0.5_wp*(a + b)
        if (m <= a .or. m >= b) exit
        call layer_force(blade, 1.0_wp, kk, m, Fm, dFm, error)
        if (dFm < 0) then
          a = m
        else
          b = m
        end if
      end do
      wpk = 0.5_wp*(a + b)
    end function peak_by_bisection

    !> Peak frequency [Hz] of |q_g| for the blade with K + kt on gamma, by dense solves and
    !> golden section.
    real(wp) function dense_stuck_peak() result(f)
      real(wp) :: a, b, c, d, Fc, Fd, h, best_w, best
      integer :: n, it
      ! the stuck amplitude is 1e-3 gamma_b: k = kt; sample to bracket, then golden section
      h = 2*pi*(analysis%f_max - analysis%f_min)/400
      best = 0
      best_w = 0
      do n = 0, 400
        c = 2*pi*analysis%f_min + n*h
        Fc = dense_gamma(blade, damper, 1e-3_wp*damper%gamma_b, 1.0_wp, c)
        if (Fc > best) then
          best = Fc
          best_w = c
        end if
      end do
      a = best_w - h
      b = best_w + h
      c = b - (b - a)*0.618033988749895_wp
      d = a + (b - a)*0.618033988749895_wp
      Fc = dense_gamma(blade, damper, 1e-3_wp*damper%gamma_b, 1.0_wp, c)
      Fd = dense_gamma(blade, damper, 1e-3_wp*damper%gamma_b, 1.0_wp, d)
      do it = 1, 80
        if (Fc > Fd) then
          b = d; d = c; Fd = Fc
          c = b - (b - a)*0.618033988749895_wp
          Fc = dense_gamma(blade, damper, 1e-3_wp*damper%gamma_b, 1.0_wp, c)
        else
          a = c; c = d; Fc = Fd
          d = a + (b - a)*0.618033988749895_wp
          Fd = dense_gamma(blade, damper, 1e-3_wp*damper%gamma_b, 1.0_wp, d)
        end if
      end do
      f = 0.25_wp*(a + b + c + d)/(2*pi)
    end function dense_stuck_peak

    !> A model on [f_lo, f_hi] must refuse the backbone with a physics error naming the side.
    subroutine check_band(f_lo, f_hi, needle)
      real(wp), intent(in) :: f_lo, f_hi
      character(len=*), intent(in) :: needle
      type(model_type) :: m
      type(analysis_type) :: a
      type(point_type), allocatable :: p(:)
      a%f_min = f_lo
      a%f_max = f_hi
      call new_model(m, blade, damper, a, error)
      call check_no_error(suite, "band model", error)
      call backbone(m, [1.0_wp, 5.0_wp], p, error)
      call check_error(suite, "no resonance in band", error, UDMAP_EPHYSICS, "no resonance")
      if (allocated(error)) then
        call check_true(suite, "says "//needle, index(error%message, needle) > 0)
        if (index(error%message, needle) == 0) print '(a)', error%message
      end if
    end subroutine check_band
  end subroutine run_mapping_backbone
end module test_mapping_backbone
