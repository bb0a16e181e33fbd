!> The wedge edges of the asymmetric damper (PHYSICS.md 2.1, 2.5):
!> - faces whose loops shake down only asymptotically (blade A's damper with both faces at
!>   5, 10 and 89 deg): the steady loop, whose cycle-to-cycle change is extrapolated to its
!>   limit (rho < 1) or skipped along its drift by whole cycles (rho > 1), against brute force:
!>   the cycles traced one by one from the same history, up to 20000 of them, until the
!>   contact forces repeat; compared at the reversal (M_r at tau = 0, the converged state), at
!>   the amplitude where 200 plain cycles did not suffice and 40 around it; the table at 5 and
!>   89 deg, at 10 deg a physics error naming mu and the angles (its limit loops change their
!>   topology from one amplitude to the next);
!> - the neutral wedge mu = tan(beta): an error naming mu and the angle where the loops for mu
!>   just below and just above tan(beta) differ, the limit where they agree.
module test_damper_wedge
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EPHYSICS
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer_core, only: damper_geometry_type, damper_state_type, contact_forces
  use udmap_damper_tracer, only: new_damper_geometry, trace_gamma, restoring_moment
  use udmap_damper_loops, only: ramp_type, loop_type, loop_workspace_type, trace_ramp, &
    & steady_loop, loop_moment
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_damper_wedge

contains

  !> Wedge edges of the asymmetric damper (PHYSICS.md 2.1, 2.5).
  subroutine collect_damper_wedge(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_wedge", run_damper_wedge)]
  end subroutine collect_damper_wedge

  !> Faces that shake down slowly, neutral and self-locking wedges, and their messages.
  subroutine run_damper_wedge(suite)
    type(test_suite), intent(inout) :: suite
    real(wp), parameter :: betas(3) = [5.0_wp, 10.0_wp, 89.0_wp]
    ! amplitudes [rad] where 200 plain cycles did not repeat (found by the table's march)
    real(wp), parameter :: hard(3) = [3.810325e-4_wp, 4.00092e-4_wp, 9.80966e-5_wp]
    type(damper_type) :: d, d2
    type(asymmetric_params_type) :: params
    type(damper_geometry_type) :: geo
    type(ramp_type) :: ramp
    type(error_type), allocatable :: error
    real(wp) :: worst, amp
    integer :: ib, i, cycles, n_extrapolated
    character(len=60) :: name

    do ib = 1, size(betas)
      params = blade_a_damper_params()
      params%beta_L_deg = betas(ib)
      params%beta_R_deg = betas(ib)
      write(name, '(a, f4.1, a)') "beta = ", betas(ib), " deg"
      call new_damper_geometry(geo, params, error)
      call check_no_error(suite, trim(name)//": geometry", error)
      call trace_ramp(geo, params%CF, ramp, error)
      call check_no_error(suite, trim(name)//": ramp", error)
      if (allocated(error)) cycle
      worst = 0
      n_extrapolated = 0
      do i = 0, 40
        amp = hard(ib)
        if (i > 0) amp = hard(ib)*10.0_wp**(-1 + 2*(i - 1)/39.0_wp)
        call compare(amp, worst, cycles)
        if (i == 0) write(*, '(a, a, es12.5, a, i0, a)') trim(name), ": amplitude ", amp, &
          & " repeats after ", cycles, " brute-force cycles"
      end do
      write(*, '(a, a, es10.3, a, i0, a)') trim(name), ": loops vs brute force, max |dM|/M_ref ", &
        & worst, " (", n_extrapolated, " of 41 loops extrapolated)"
      ! brute force stops at a change of 1e-12 CF per cycle; with rho up to 0.965 the limit is
      ! up to rho/(1 - rho) = 28 such changes further: 1e-7 of the loop's moment is that margin
      call check_true(suite, trim(name)//": loops within 1e-7 of brute force", worst <= 1e-7_wp)
      call check_true(suite, trim(name)//": some loops extrapolated", n_extrapolated > 0)
      ! the damper: a table at 5 and 89 deg; at 10 deg the limit loops change their topology
      ! from one amplitude to the next (hundreds of jumps of k): a physics error naming mu and
      ! the angles
      call new_asymmetric_damper(d, params, error)
      if (betas(ib) == 10) then
        call check_error(suite, trim(name)//": no table", error, UDMAP_EPHYSICS, &
          & "only asymptotically")
        call check_error(suite, trim(name)//": names mu", error, UDMAP_EPHYSICS, "mu = 0.3")
        call check_error(suite, trim(name)//": names beta", error, UDMAP_EPHYSICS, &
          & "beta_L = 10.0")
      else
        call check_no_error(suite, trim(name)//": damper", error)
      end if
    end do

    ! neutral wedge, both faces at 45 deg: the two sides differ (an error naming mu and beta)
    params = blade_a_damper_params()
    params%mu = 1
    call new_asymmetric_damper(d, params, error)
    call check_error(suite, "mu = tan(45 deg)", error, UDMAP_EPHYSICS, "neutral wedge")
    call check_error(suite, "mu = tan(45 deg) names mu", error, UDMAP_EPHYSICS, "mu = 1.0")
    call check_error(suite, "mu = tan(45 deg) names the angle", error, UDMAP_EPHYSICS, &
      & "beta_R_deg = 45.0")
    params%mu = 1 + 5e-9_wp
    call new_asymmetric_damper(d, params, error)
    call check_error(suite, "mu = tan(45 deg) + 5e-9", error, UDMAP_EPHYSICS, "neutral wedge")
    ! outside the tolerance both sides are ordinary dampers, and they differ
    params%mu = 1 - 1e-7_wp
    call new_asymmetric_damper(d, params, error)
    call check_no_error(suite, "mu = 1 - 1e-7", error)
    params%mu = 1 + 1e-7_wp
    call new_asymmetric_damper(d2, params, error)
    call check_no_error(suite, "mu = 1 + 1e-7", error)
    call check_true(suite, "the two sides of tan(beta) differ", &
      & abs(d%energy_slope() - d2%energy_slope()) > 0.1_wp*d%energy_slope())
    ! only the curved face neutral (flat at 20 deg): both sides agree, the limit is the answer
    params = blade_a_damper_params()
    params%beta_L_deg = 20
    params%mu = tan(45*pi/180)
    call new_asymmetric_damper(d, params, error)
    call check_no_error(suite, "mu = tan(beta_R), beta_L = 20: the limit", error)
    params%mu = 1 - 1e-7_wp
    call new_asymmetric_damper(d2, params, error)
    call check_no_error(suite, "mu = 1 - 1e-7, beta_L = 20", error)
    if (.not. allocated(error)) then
      worst = 0
      do i = 0, 40
        amp = d%gamma_b*10.0_wp**(-2 + 4*i/40.0_wp)
        worst = max(worst, abs(d%stiffness(amp) - d2%stiffness(amp))/d%k_stuck)
      end do
      call check_true(suite, "neutral limit = the damper just below tan(beta) to 1e-6", &
        & worst < 1e-6_wp)
    end if

  contains

    !> The steady loop at amplitude amp (M_r at its reversal, tau = 0) against the cycles
    !> traced one by one from the same history until the contact forces repeat to 1e-12 CF;
    !> relative to the largest |M_r| on the loop.
    subroutine compare(amp, worst, cycles)
      real(wp), intent(in) :: amp
      real(wp), intent(inout) :: worst
      integer, intent(out) :: cycles
      type(loop_type) :: lp
      type(loop_workspace_type) :: work
      type(damper_state_type) :: st, prev
      real(wp) :: g(3), s(3), N(3), T(3), Np(3), Tp(3), M_ref, Mb
      integer :: j, c
      call steady_loop(geo, ramp, amp, lp, work, error)
      call check_no_error(suite, trim(name)//": loop", error)
      if (allocated(error)) return
      if (lp%extrapolated) n_extrapolated = n_extrapolated + 1
      M_ref = 0
      do j = 0, 63
        M_ref = max(M_ref, abs(loop_moment(lp, 2*pi*j/64)))
      end do
      j = ramp%n
      do while (j > 1)
        if (ramp%gamma(j) <= amp) exit
        j = j - 1
      end do
      st = ramp%states(j)
      call trace_gamma(geo, st, amp, 1.0_wp, error)
      do c = 1, 20000
        prev = st
        call trace_gamma(geo, st, -amp, -1.0_wp, error)
        if (allocated(error)) exit
        call trace_gamma(geo, st, amp, 1.0_wp, error)
        if (allocated(error)) exit
        call contact_forces(geo, prev%mode, prev%q, prev%gamma, prev%w, g, s, Np, Tp)
        call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T)
        if (all(st%mode == prev%mode) .and. maxval(abs([N - Np, T - Tp])) <= 1e-12_wp*params%CF) &
          & exit
      end do
      cycles = c
      call check_no_error(suite, trim(name)//": brute force", error)
      call check_true(suite, trim(name)//": brute force repeats", c <= 20000)
      Mb = restoring_moment(geo, st)
      worst = max(worst, abs(Mb - loop_moment(lp, 0.0_wp))/M_ref)
    end subroutine compare
  end subroutine run_damper_wedge
end module test_damper_wedge
