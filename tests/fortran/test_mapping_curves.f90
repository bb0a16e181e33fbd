!> Response curves of blade A with a rotational Jenkins damper by amplitude layered force
!> mapping: points against dense solves of the coupled blade (independent of the receptances
!> and of Sherman-Morrison), the path structure (band edges, one turning point at the backbone
!> peak, branches on each side of it), the adaptive layer placement, and the eigenvalue-start
!> variants agreeing with each other.
program test_mapping_curves
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_blade_beam, only: beam_params_type
  use udmap_damper_type, only: damper_type, new_jenkins_damper
  use udmap_mapping_model, only: model_type, analysis_type, point_type, curve_type, new_model, &
    & backbone, response_curves, BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING, EIGEN_DIRECT, &
    & EIGEN_MODAL
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, finish
  implicit none

  interface
    subroutine zgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb
      complex(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine zgesv
  end interface

  type(test_suite) :: suite
  type(blade_type), target :: blade
  type(damper_type), target :: damper
  type(model_type) :: model, model_direct, model_modal
  type(analysis_type) :: analysis, variant
  type(error_type), allocatable :: error
  type(point_type), allocatable :: points(:), p_direct(:), p_modal(:)
  type(curve_type), allocatable :: curves(:)
  type(beam_params_type) :: params
  real(wp), parameter :: forces(3) = [1.0_wp, 3.0_wp, 6.0_wp]
  integer, parameter :: layers = 40
  real(wp) :: worst, x1, y1, x2, y2, longest, band, lnrange, gmin, gmax
  integer :: i, j, n, top

  params = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, neck_L=0.020_wp, &
    & neck_h=0.008_wp, neck_b=0.020_wp, platform_L=0.010_wp, platform_m=0.021_wp, &
    & platform_J=1.4e-6_wp, airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
    & neck_elements=8, airfoil_elements=24)
  call new_beam_blade(blade, params, error)
  call new_jenkins_damper(damper, 3000.0_wp, 1.35_wp, error)
  analysis%f_min = 150
  analysis%f_max = 230
  call new_model(model, blade, damper, analysis, error)
  call check_no_error(suite, "model", error)
  if (allocated(error)) call finish(suite)

  call backbone(model, forces, points, error)
  call response_curves(model, forces, layers, curves, error)
  call check_no_error(suite, "curves", error)
  if (allocated(error)) call finish(suite)

  band = analysis%f_max - analysis%f_min
  gmin = huge(1.0_wp)
  gmax = 0
  do i = 1, size(curves)
    gmin = min(gmin, minval(curves(i)%gamma_P))
    gmax = max(gmax, maxval(curves(i)%gamma_P))
  end do
  lnrange = log(gmax/gmin)
  do i = 1, size(curves)
    associate(c => curves(i))
      n = size(c%f)
      call check_true(suite, "many points", n > 80)
      call check_true(suite, "arrays agree", size(c%gamma_P) == n .and. size(c%sigma_a) == n &
        & .and. size(c%branch) == n .and. size(c%part) == n)
      ! ends at the band edges, one turning point at the backbone peak, one part
      call check_close(suite, "starts at f_min", c%f(1), analysis%f_min, 1e-14_wp)
      call check_close(suite, "ends at f_max", c%f(n), analysis%f_max, 1e-14_wp)
      call check_true(suite, "one part", all(c%part == 1))
      call check_true(suite, "one turning point", count(c%branch == BRANCH_TURNING) == 1)
      top = findloc(c%branch, BRANCH_TURNING, 1)
      call check_close(suite, "turning point = peak amplitude", c%gamma_P(top), &
        & points(i)%gamma_P, 1e-12_wp)
      call check_close(suite, "turning point = peak frequency", c%f(top), points(i)%f_res, 1e-13_wp)
      call check_close(suite, "turning point stress", c%sigma_a(top), points(i)%sigma_a, 1e-10_wp)
      call check_true(suite, "peak is the maximum", maxval(c%gamma_P) <= points(i)%gamma_P &
        & *(1 + 1e-12_wp))
      ! path order: frequency rises along the whole curve, gamma up to the peak then down
      call check_true(suite, "frequency rises", all(c%f(2:n) > c%f(1:n-1)))
      call check_true(suite, "lower branch before", all(c%branch(1:top-1) == BRANCH_LOWER))
      call check_true(suite, "upper branch after", all(c%branch(top+1:n) == BRANCH_UPPER))
      call check_true(suite, "gamma rises to the peak", all(c%gamma_P(2:top) > c%gamma_P(1:top-1)))
      call check_true(suite, "gamma falls after", all(c%gamma_P(top+1:n) < c%gamma_P(top:n-1)))
      ! adaptive layers: no segment longer than 2/layers of the (band, ln range) box
      longest = 0
      do j = 1, n - 1
        x1 = (c%f(j) - analysis%f_min)/band
        x2 = (c%f(j + 1) - analysis%f_min)/band
        y1 = log(c%gamma_P(j)/gmin)/lnrange
        y2 = log(c%gamma_P(j + 1)/gmin)/lnrange
        longest = max(longest, hypot(x2 - x1, y2 - y1))
      end do
      call check_true(suite, "segments short", longest <= 2.0_wp/layers*(1 + 1e-9_wp))
      ! every 7th point (and the edges) against a dense solve of the coupled blade
      worst = 0
      do j = 1, n, 7
        worst = max(worst, abs(dense_gamma(c%gamma_P(j), c%F_E, 2*pi*c%f(j))/c%gamma_P(j) - 1))
      end do
      worst = max(worst, abs(dense_gamma(c%gamma_P(n), c%F_E, 2*pi*c%f(n))/c%gamma_P(n) - 1))
      call check_close(suite, "points by dense solve", worst, 0.0_wp, 0.0_wp, 1e-9_wp)
    end associate
  end do

  ! the eigenvalue start changes the work, not the answer
  variant = analysis
  variant%eigen_method = EIGEN_DIRECT
  call new_model(model_direct, blade, damper, variant, error)
  call backbone(model_direct, forces, p_direct, error)
  call check_no_error(suite, "direct starts", error)
  variant%eigen_method = EIGEN_MODAL
  call new_model(model_modal, blade, damper, variant, error)
  call backbone(model_modal, forces, p_modal, error)
  call check_no_error(suite, "modal starts", error)
  do i = 1, size(forces)
    call check_close(suite, "direct start: same gamma_P", p_direct(i)%gamma_P, points(i)%gamma_P, 1e-10_wp)
    call check_close(suite, "direct start: same f_res", p_direct(i)%f_res, points(i)%f_res, 1e-12_wp)
    call check_close(suite, "modal start: same gamma_P", p_modal(i)%gamma_P, points(i)%gamma_P, 1e-10_wp)
    call check_close(suite, "modal start: same f_res", p_modal(i)%f_res, points(i)%f_res, 1e-12_wp)
  end do

  ! bad arguments
  call response_curves(model, forces, 2, curves, error)
  call check_error(suite, "too few layers", error, UDMAP_EINPUT, "layers")
  call finish(suite)

contains

  !> |q_g| of the coupled blade (K + k(gamma) e_g e_g^T - w^2 M + i w beta K) q = F_E e_E by a
  !> dense solve with two steps of refinement on quadruple-precision residuals.
  real(wp) function dense_gamma(gamma, F_E, w) result(amp)
    real(wp), intent(in) :: gamma, F_E, w
    integer, parameter :: qp = selected_real_kind(30)
    complex(wp), allocatable :: D(:, :), LU(:, :), q(:, :), dq(:, :)
    complex(qp), allocatable :: D_quad(:, :), res(:)
    integer, allocatable :: ipiv(:)
    integer :: nd, info, it
    nd = blade%ndof
    allocate(D_quad(nd, nd), res(nd), q(nd, 1), dq(nd, 1), ipiv(nd))
    D_quad = cmplx(real(blade%K, qp) - real(w, qp)**2*real(blade%M, qp), &
      & real(w, qp)*real(blade%beta, qp)*real(blade%K, qp), qp)
    D_quad(blade%gamma_dof, blade%gamma_dof) = D_quad(blade%gamma_dof, blade%gamma_dof) + &
      & cmplx(damper%stiffness(gamma), kind=qp)
    D = cmplx(D_quad, kind=wp)
    q = 0
    q(blade%exc_dof, 1) = F_E
    LU = D
    call zgesv(nd, 1, LU, nd, ipiv, q, nd, info)
    do it = 1, 2
      res = -matmul(D_quad, cmplx(q(:, 1), kind=qp))
      res(blade%exc_dof) = res(blade%exc_dof) + F_E
      dq(:, 1) = cmplx(res, kind=wp)
      LU = D
      call zgesv(nd, 1, LU, nd, ipiv, dq, nd, info)
      q = q + dq
    end do
    amp = abs(q(blade%gamma_dof, 1))
  end function dense_gamma
end program test_mapping_curves
