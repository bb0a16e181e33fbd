!> Response curves of blade A with a rotational Jenkins damper by amplitude layered force
!> mapping: points against dense solves of the coupled blade (independent of the receptances
!> and of Sherman-Morrison), the path structure (band edges, one turning point at the backbone
!> peak, branches on each side of it), the adaptive layer placement, and the eigenvalue-start
!> variants agreeing with each other.
module test_mapping_curves
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_damper_type, only: damper_type, new_jenkins_damper
  use udmap_mapping_model, only: model_type, analysis_type, point_type, curve_type, new_model, &
    & backbone, response_curves, BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING, EIGEN_DIRECT, &
    & EIGEN_MODAL
  use fixtures, only: blade_a_beam_params, blade_a_model, dense_gamma
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_mapping_curves

contains

  !> Response curves, path structure and eigenvalue starts on blade A.
  subroutine collect_mapping_curves(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_curves", run_mapping_curves)]
  end subroutine collect_mapping_curves

  !> Curve points against dense solves, the path structure and the eigenvalue starts.
  subroutine run_mapping_curves(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: params

    type(blade_type), target :: blade
    type(damper_type), target :: damper
    type(model_type) :: model, model_direct, model_modal
    type(analysis_type) :: analysis, variant
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:), p_direct(:), p_modal(:)
    type(curve_type), allocatable :: curves(:)
    real(wp), parameter :: forces(3) = [1.0_wp, 3.0_wp, 6.0_wp]
    integer, parameter :: layers = 40
    real(wp) :: worst, x1, y1, x2, y2, longest, band, lnrange, gmin, gmax
    integer :: i, j, n, top

    params = blade_a_beam_params()
    call new_beam_blade(blade, params, error)
    call new_jenkins_damper(damper, 3000.0_wp, 1.35_wp, error)
    call blade_a_model(suite, blade, damper, analysis, model, error)
    if (allocated(error)) return

    call backbone(model, forces, points, error)
    call response_curves(model, forces, layers, curves, error)
    call check_no_error(suite, "curves", error)
    if (allocated(error)) return

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
          worst = max(worst, abs(dense_gamma(blade, damper, c%gamma_P(j), c%F_E, 2*pi*c%f(j))/c%gamma_P(j) - 1))
        end do
        worst = max(worst, abs(dense_gamma(blade, damper, c%gamma_P(n), c%F_E, 2*pi*c%f(n))/c%gamma_P(n) - 1))
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

  end subroutine run_mapping_curves
end module test_mapping_curves
