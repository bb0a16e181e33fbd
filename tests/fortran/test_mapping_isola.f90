!> A backbone with three roots and a detached response curve (isola): the one-DOF oscillator
!> (m = 1, c = 0.01, k = 1) with a measured damper table whose damping rises, falls as
!> 1/gamma^2 and levels off, so that F_bb ~ gamma (c omega + k_Im) rises, falls and rises again.
!> Checks: the three roots, the two parts of the curve with their turning points on the
!> backbone, every point on the scalar equation a |1 + k(a) H| = F |H| (H evaluated here), and
!> the response at a frequency inside the isola with all its roots.
module test_mapping_isola
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_damper_type, only: new_table_damper
  use udmap_mapping_model, only: point_type, curve_type, backbone, backbone_curve, response, &
    & response_curves, BRANCH_TURNING
  use fixtures, only: scene_type, one_dof_blade, oscillator_model
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_mapping_isola

contains

  !> Three backbone roots; the isola of the one-DOF oscillator.
  subroutine collect_mapping_isola(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_isola", run_mapping_isola)]
  end subroutine collect_mapping_isola

  !> Three backbone roots and a detached response curve of the one-DOF oscillator.
  subroutine run_mapping_isola(suite)
    type(test_suite), intent(inout) :: suite
    type(scene_type), target :: osc
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:), resp(:)
    type(curve_type), allocatable :: curves(:)
    real(wp) :: worst, fmid
    real(wp), allocatable :: g(:), kre(:), kim(:)
    integer :: i, n, first, last
    real(wp), parameter :: F = 0.1_wp

    call one_dof_blade(osc%blade, 0.01_wp, error)
    n = 161
    g = [1e-4_wp, (1e-3_wp*10.0_wp**(5*real(i, wp)/(n - 2)), i = 0, n - 2)]
    kre = spread(0.25_wp, 1, n)
    kim = damping(g)
    call new_table_damper(osc%damper, g, kre, kim, error)
    call check_no_error(suite, "table damper", error)
    call oscillator_model(suite, osc, 0.7_wp, 1.4_wp, error)
    if (allocated(error)) return

    call backbone(osc%model, [F], points, error)
    call check_no_error(suite, "backbone", error)
    call check_true(suite, "three roots", size(points(1)%roots) == 3)
    if (size(points(1)%roots) /= 3) return
    do i = 1, 3
      call check_close(suite, "roots on the scalar equation at their peaks", &
        & residual(points(1)%roots(i), peak_omega(points(1)%roots(i))), 0.0_wp, 0.0_wp, 1e-9_wp)
    end do

    call response_curves(osc%model, [F], 60, curves, error)
    call check_no_error(suite, "curves", error)
    associate(cv => curves(1))
      n = size(cv%f)
      call check_true(suite, "two parts", maxval(cv%part) == 2 .and. minval(cv%part) == 1)
      call check_true(suite, "main part turns once", &
        & count(cv%part == 1 .and. cv%branch == BRANCH_TURNING) == 1)
      ! the isola starts and ends at its bottom turning point and turns at its top
      first = findloc(cv%part, 2, 1)
      last = findloc(cv%part, 2, 1, back=.true.)
      call check_true(suite, "isola closed", cv%branch(first) == BRANCH_TURNING .and. &
        & cv%branch(last) == BRANCH_TURNING .and. cv%f(first) == cv%f(last))
      call check_close(suite, "isola bottom = second root", cv%gamma_P(first), points(1)%roots(2), &
        & 1e-12_wp)
      call check_close(suite, "isola top = largest root", maxval(cv%gamma_P(first:last)), &
        & points(1)%roots(3), 1e-12_wp)
      call check_close(suite, "main part top = first root", maxval(cv%gamma_P(1:first - 1)), &
        & points(1)%roots(1), 1e-12_wp)
      call check_true(suite, "isola has points", last - first > 20)
      worst = 0
      do i = 1, n
        worst = max(worst, abs(residual(cv%gamma_P(i), 2*pi*cv%f(i))))
      end do
      call check_close(suite, "curve points on the equation", worst, 0.0_wp, 0.0_wp, 1e-9_wp)
      ! the response at a frequency through the middle of the isola: the main curve and both
      ! isola branches
      fmid = 0.5_wp*(minval(cv%f(first:last)) + maxval(cv%f(first:last)))
      call response(osc%model, fmid, [F], resp, error)
      call check_no_error(suite, "response", error)
      call check_true(suite, "response roots: main curve and both isola branches", &
        & size(resp(1)%roots) == 3)
      worst = 0
      do i = 1, size(resp(1)%roots)
        worst = max(worst, abs(residual(resp(1)%roots(i), 2*pi*fmid)))
      end do
      call check_close(suite, "response roots on the equation", worst, 0.0_wp, 0.0_wp, 1e-10_wp)
    end associate

  contains

    !> k_Im of the table: rising as gamma^2 to 0.3 at 0.5, falling as 1/gamma^2 to 5, level after.
    elemental real(wp) function damping(a)
      real(wp), intent(in) :: a
      if (a <= 1e-4_wp) then
        damping = 0
      else if (a <= 0.5_wp) then
        damping = 0.3_wp*(a/0.5_wp)**2
      else if (a <= 5) then
        damping = 0.3_wp*(0.5_wp/a)**2
      else
        damping = 0.003_wp
      end if
    end function damping

    !> (a |1 + k(a) H| - F |H|)/(F |H|), H = 1/(1 - w^2 + i c w), k from the damper.
    real(wp) function residual(a, w) result(res)
      real(wp), intent(in) :: a, w
      complex(wp) :: H
      H = 1/cmplx(1 - w**2, 0.01_wp*w, wp)
      res = (a*abs(1 + osc%damper%stiffness(a)*H) - F*abs(H))/(F*abs(H))
    end function residual

    !> The peak frequency of the layer a [rad/s] (by the model).
    real(wp) function peak_omega(a) result(w)
      real(wp), intent(in) :: a
      real(wp) :: Fb(1), fr(1)
      call backbone_curve(osc%model, [a], Fb, fr, error)
      w = 2*pi*fr(1)
    end function peak_omega
  end subroutine run_mapping_isola
end module test_mapping_isola
