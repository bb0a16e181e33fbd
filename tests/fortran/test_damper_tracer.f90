!> The contact-level primitive: replaying gamma(t) sample by sample with advance is exact,
!> however coarse the samples (events inside a step are resolved).
module test_damper_tracer
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer_core, only: damper_state_type, CONTACT_OPEN
  use udmap_damper_tracer, only: virgin_state, ramp_CF, advance, restoring_moment
  use fixtures, only: ieee_nan
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_damper_tracer

contains

  !> The contact-level tracer primitive, advance.
  subroutine collect_damper_tracer(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_tracer", run_damper_tracer)]
  end subroutine collect_damper_tracer

  !> Sample-by-sample replay with advance is exact however coarse the samples are.
  subroutine run_damper_tracer(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: d
    type(damper_state_type) :: st
    type(error_type), allocatable :: error
    real(wp) :: amps(3), M, Mloop(1), worst
    integer :: ia, nper, k, cyc, nsamples(2), is

    call new_asymmetric_damper(d, blade_a_damper_params(), error)
    call check_no_error(suite, "blade_a damper", error)
    if (allocated(error)) return

    call virgin_state(d%geometry, st)
    call check_true(suite, "virgin state open and unloaded", all(st%mode == CONTACT_OPEN) .and. &
      & all(st%q == 0) .and. all(st%w == 0))
    call check_close(suite, "virgin moment", restoring_moment(d%geometry, st), 0.0_wp, 0.0_wp, 0.0_wp)

    ! Samples of gamma_a cos(tau): 6 per cycle (coarse, several events inside each step) and 600.
    amps = [0.5_wp, 0.9_wp, 2.5_wp]*d%gamma_b
    nsamples = [6, 600]
    do is = 1, 2
      nper = nsamples(is)
      do ia = 1, 3
        worst = 0
        call virgin_state(d%geometry, st)
        call ramp_CF(d%geometry, st, d%params%CF, error)
        call check_no_error(suite, "ramp_CF", error)
        call advance(d%geometry, st, amps(ia), M, error)
        call check_no_error(suite, "advance (ramp)", error)
        do cyc = 1, 3
          do k = 1, nper
            call advance(d%geometry, st, amps(ia)*cos(2*pi*k/nper), M, error)
            if (allocated(error)) exit
            if (cyc == 3) then
              call d%loop(amps(ia), [2*pi*k/nper], Mloop, error)
              worst = max(worst, abs(M - Mloop(1)))
            end if
          end do
        end do
        call check_no_error(suite, "advance (cycles)", error)
        call check_close(suite, "advance replay = steady loop", worst, 0.0_wp, 0.0_wp, &
          & 1e-10_wp*d%M_max)
      end do
    end do

    ! A monotonic path split into many small steps ends where one step does.
    call virgin_state(d%geometry, st)
    call ramp_CF(d%geometry, st, d%params%CF, error)
    call advance(d%geometry, st, -2*d%gamma_b, M, error)
    block
      type(damper_state_type) :: st2
      real(wp) :: M2
      call virgin_state(d%geometry, st2)
      call ramp_CF(d%geometry, st2, d%params%CF, error)
      do k = 1, 1000
        call advance(d%geometry, st2, -2*d%gamma_b*k/1000, M2, error)
      end do
      call check_close(suite, "split path = one step", M2, M, 1e-12_wp)
    end block

    call advance(d%geometry, st, ieee_nan(), M, error)
    call check_error(suite, "advance rejects NaN", error, UDMAP_EINPUT, "gamma_target")
    call ramp_CF(d%geometry, st, -1.0_wp, error)
    call check_error(suite, "ramp_CF rejects negative CF", error, UDMAP_EINPUT, "CF")

  end subroutine run_damper_tracer
end module test_damper_tracer
