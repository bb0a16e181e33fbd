!> The wedge edges of the asymmetric damper (PHYSICS.md 2.1, 2.5):
!> - faces whose loops shake down only asymptotically (blade A's damper with both faces at
!>   5, 10 and 89 deg): the steady loop, whose cycle-to-cycle change is extrapolated to its
!>   limit (rho < 1) or jumped along its drift (rho > 1), against brute force: the cycles traced
!>   one by one from the same history, up to 20000 of them, until the contact forces repeat;
!>   the loops are compared at their reversal (M_r at tau = 0, the converged state), at the
!>   amplitudes where 200 plain cycles did not suffice and on a grid around gamma_b;
!> - the neutral wedge mu = tan(beta): an error naming mu and the angle where the loops for mu
!>   just below and just above tan(beta) differ, the limit where they agree.
program test_damper_wedge
  use udmap_kinds, only: wp, pi
  use udmap_error, only: error_type, UDMAP_EPHYSICS
  use udmap_damper, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer, only: damper_state_type, trace_gamma, contact_forces, &
    & restoring_moment
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, finish
  implicit none
  type(test_suite) :: suite
  real(wp), parameter :: betas(3) = [5.0_wp, 10.0_wp, 89.0_wp]
  ! amplitudes [rad] where 200 plain cycles did not repeat (found by the table's march)
  real(wp), parameter :: hard(3) = [3.810325e-4_wp, 4.00092e-4_wp, 9.80966e-5_wp]
  type(damper_type) :: d, d2
  type(asymmetric_params_type) :: params
  type(error_type), allocatable :: error
  real(wp) :: worst, amp
  integer :: ib, i, cycles
  character(len=60) :: name

  do ib = 1, size(betas)
    params = blade_a_damper_params()
    params%beta_L_deg = betas(ib)
    params%beta_R_deg = betas(ib)
    write(name, '(a, f4.1, a)') "beta = ", betas(ib), " deg"
    call new_asymmetric_damper(d, params, error)
    call check_no_error(suite, trim(name)//": damper", error)
    if (allocated(error)) cycle
    worst = 0
    do i = 0, 12
      amp = hard(ib)
      if (i > 0) amp = d%gamma_b*10.0_wp**(-1.2_wp + 1.4_wp*(i - 1)/11.0_wp)
      call compare(d, amp, worst, cycles)
      if (i == 0) write(*, '(a, a, es12.5, a, i0, a)') trim(name), ": amplitude ", amp, &
        & " repeats after ", cycles, " brute-force cycles"
    end do
    write(*, '(a, a, es10.3)') trim(name), ": loops vs brute force, max |dM|/Delta_M ", worst
    call check_true(suite, trim(name)//": loops within 1e-8 Delta_M of brute force", &
      & worst <= 1e-8_wp)
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
  call finish(suite)

contains

  !> The loop of d at amplitude amp (M_r at 64 instants) against the cycles traced one by one
  !> from the same history until the contact forces repeat to 1e-12 CF.
  subroutine compare(d, amp, worst, cycles)
    type(damper_type), intent(in) :: d
    real(wp), intent(in) :: amp
    real(wp), intent(inout) :: worst
    integer, intent(out) :: cycles
    integer, parameter :: ns = 64
    type(damper_state_type) :: st, prev
    real(wp) :: tau(ns), M(ns), Mb, g(3), s(3), N(3), T(3), Np(3), Tp(3), dM
    integer :: j, c
    do j = 1, ns
      tau(j) = 2*pi*(j - 1)/ns
    end do
    call d%loop(amp, tau, M, error)
    call check_no_error(suite, trim(name)//": loop", error)
    if (allocated(error)) return
    j = d%ramp%n
    do while (j > 1)
      if (d%ramp%gamma(j) <= amp) exit
      j = j - 1
    end do
    st = d%ramp%states(j)
    call trace_gamma(d%geometry, st, amp, 1.0_wp, error)
    do c = 1, 20000
      prev = st
      call trace_gamma(d%geometry, st, -amp, -1.0_wp, error)
      if (allocated(error)) exit
      call trace_gamma(d%geometry, st, amp, 1.0_wp, error)
      if (allocated(error)) exit
      call contact_forces(d%geometry, prev%mode, prev%q, prev%gamma, prev%w, g, s, Np, Tp)
      call contact_forces(d%geometry, st%mode, st%q, st%gamma, st%w, g, s, N, T)
      if (all(st%mode == prev%mode) .and. maxval(abs([N - Np, T - Tp])) <= 1e-12_wp*params%CF) &
        & exit
    end do
    cycles = c
    call check_no_error(suite, trim(name)//": brute force", error)
    call check_true(suite, trim(name)//": brute force repeats", c <= 20000)
    ! the converged reversal state (what the extrapolation of the shakedown determines)
    dM = d%M_max - d%M_min
    Mb = restoring_moment(d%geometry, st)
    worst = max(worst, abs(Mb - M(1))/dM)
  end subroutine compare
end program test_damper_wedge
