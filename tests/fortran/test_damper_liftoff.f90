!> A flat pad too short to hold the damper: a flat contact opens during the cycle, the lift-off
!> flag is raised and k is still traced exactly. Input checks and physics errors.
module test_damper_liftoff
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_damper_liftoff

contains

  !> Lift-off: a flat pad too short to hold the damper.
  subroutine collect_damper_liftoff(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_liftoff", run_damper_liftoff)]
  end subroutine collect_damper_liftoff

  !> A pad too short to hold the damper: lift-off flagged, k traced exactly, errors raised.
  subroutine run_damper_liftoff(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: d
    type(asymmetric_params_type) :: params, bad
    type(error_type), allocatable :: error
    complex(wp) :: k, kd
    real(wp) :: mid(2), half(2), g, worst, nan
    integer :: i

    ! Shorten the flat pad to half its length about its middle.
    params = blade_a_damper_params()
    mid = (params%flat(:,1) + params%flat(:,2))/2
    half = (params%flat(:,2) - params%flat(:,1))/2
    params%flat(:,1) = mid - half/2
    params%flat(:,2) = mid + half/2
    call new_asymmetric_damper(d, params, error)
    call check_no_error(suite, "short flat pad", error)
    if (allocated(error)) return
    call check_true(suite, "lift-off flag raised", d%lift_off)
    call check_true(suite, "plateaus not symmetric", abs(d%M_max + d%M_min) > 1e-3_wp)
    write(*, '(a, 4es14.6)') "short pad: gamma_b, gamma_s, M_max, M_min = ", d%gamma_b, d%gamma_s, &
      & d%M_max, d%M_min
    worst = 0
    do i = 1, 120
      g = d%gamma_b*10.0_wp**(-1.5_wp + 3*(i - 0.5_wp)/120)
      k = d%stiffness(g)
      call d%stiffness_direct(g, kd, error)
      call check_no_error(suite, "direct loop", error)
      worst = max(worst, abs(k - kd)/abs(kd))
      call check_true(suite, "k_Im >= 0", aimag(k) >= 0)
    end do
    write(*, '(a, es10.3)') "short pad: table vs direct loops, max rel. error ", worst
    call check_true(suite, "table within 1e-6 of direct loops", worst < 1e-6_wp)

    ! Every parameter checked by name: one field of blade A's damper made bad at a time
    ! (expect_input restores the others).
    nan = ieee_value(nan, ieee_quiet_nan)
    bad = blade_a_damper_params()
    bad%CF = nan; call expect_input("CF")
    bad%mu = -0.1_wp; call expect_input("mu")
    bad%pitch = 0; call expect_input("pitch")
    bad%y_P = nan; call expect_input("y_P")
    bad%beta_L_deg = 95; call expect_input("beta_L_deg")
    bad%beta_R_deg = -5; call expect_input("beta_R_deg")
    bad%flat(2,2) = nan; call expect_input("flat2_y")
    bad%curved(1) = nan; call expect_input("curved_x")
    bad%kn_flat = -60e6_wp; call expect_input("kn_flat")
    bad%kt_flat = nan; call expect_input("kt_flat")
    bad%kn_curved = 0; call expect_input("kn_curved")
    bad%kt_curved = -1; call expect_input("kt_curved")
    bad%flat(:,2) = bad%flat(:,1); call expect_input("flat_points")

    ! A self-locking damper (mu = 5 on 45 degree faces) jams: a physics error, no NaN.
    bad = blade_a_damper_params()
    bad%mu = 5
    call new_asymmetric_damper(d, bad, error)
    call check_error(suite, "self-locking damper jams", error, UDMAP_EPHYSICS, "jams")

    ! set_CF checks its argument.
    call new_asymmetric_damper(d, blade_a_damper_params(), error)
    call d%set_CF(-900.0_wp, error)
    call check_error(suite, "set_CF rejects negative CF", error, UDMAP_EINPUT, "CF")
    call d%stiffness_direct(nan, k, error)
    call check_error(suite, "stiffness_direct rejects NaN", error, UDMAP_EINPUT, "gamma")

  contains

    !> The damper of the parameters bad is refused naming the field name; bad is blade A's
    !> damper again afterwards.
    subroutine expect_input(name)
      character(len=*), intent(in) :: name
      type(damper_type) :: dd
      type(error_type), allocatable :: err
      call new_asymmetric_damper(dd, bad, err)
      call check_error(suite, "rejects bad "//name, err, UDMAP_EINPUT, name)
      bad = blade_a_damper_params()
    end subroutine expect_input
  end subroutine run_damper_liftoff
end module test_damper_liftoff
