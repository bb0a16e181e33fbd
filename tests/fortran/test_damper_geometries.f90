!> Other asymmetric geometries (friction and face angles varied around blade_a): the table
!> against loops traced directly from the virgin state, below and above gamma_b, and the
!> plateau moments against full-slip statics where both plateaus slip everywhere.
module test_damper_geometries
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer, only: full_slip_moment
  use udmap_damper_tracer_core, only: CONTACT_SLIP_POS, CONTACT_SLIP_NEG
  use fixtures, only: sign_of
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_damper_geometries

contains

  !> Asymmetric dampers other than blade_a's.
  subroutine collect_damper_geometries(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_geometries", run_damper_geometries)]
  end subroutine collect_damper_geometries

  !> Friction and face angles around blade A: table vs direct loops, plateaus vs statics.
  subroutine run_damper_geometries(suite)
    type(test_suite), intent(inout) :: suite
    real(wp), parameter :: mus(6) = [0.1_wp, 0.2_wp, 0.3_wp, 0.5_wp, 0.5_wp, 1.0_wp]
    real(wp), parameter :: betas(6) = [30.0_wp, 45.0_wp, 20.0_wp, 60.0_wp, 30.0_wp, 20.0_wp]
    type(damper_type) :: d
    type(asymmetric_params_type) :: params
    type(error_type), allocatable :: error
    complex(wp) :: k, kd
    real(wp) :: g, worst, M, N(3)
    logical :: admissible
    integer :: ig, i, signs(3)
    character(len=40) :: name

    do ig = 1, size(mus)
      params = blade_a_damper_params()
      params%mu = mus(ig)
      params%beta_L_deg = betas(ig)
      params%beta_R_deg = betas(ig)
      write(name, '(a, f4.2, a, f4.1)') "mu = ", mus(ig), ", beta = ", betas(ig)
      call new_asymmetric_damper(d, params, error)
      call check_no_error(suite, trim(name), error)
      if (allocated(error)) cycle
      worst = 0
      do i = 1, 150
        g = d%gamma_b*10.0_wp**(-1.5_wp + 2.5_wp*(i - 0.5_wp)/150)
        k = d%stiffness(g)
        call d%stiffness_direct(g, kd, error)
        call check_no_error(suite, trim(name)//": direct loop", error)
        worst = max(worst, abs(k - kd)/abs(kd))
        call check_true(suite, trim(name)//": k_Im >= 0", aimag(k) >= 0)
      end do
      write(*, '(a, a, i4, a, es10.3, a, l2)') trim(name), ": ", d%table%n_int, &
        & " topology intervals, max rel. error vs direct loops ", worst, ", lift-off", d%lift_off
      call check_true(suite, trim(name)//": table within 1e-6 of direct loops", worst < 1e-6_wp)
      signs = sign_of(d%table%base%mode_max)
      if (all(signs /= 0)) then
        call full_slip_moment(d%geometry, params%CF, signs, M, N, admissible, error)
        call check_close(suite, trim(name)//": M_max = full-slip statics", d%M_max, M, 1e-9_wp)
      end if
      signs = sign_of(d%table%base%mode_min)
      if (all(signs /= 0)) then
        call full_slip_moment(d%geometry, params%CF, signs, M, N, admissible, error)
        call check_close(suite, trim(name)//": M_min = full-slip statics", d%M_min, M, 1e-9_wp)
      end if
    end do

  end subroutine run_damper_geometries
end module test_damper_geometries
