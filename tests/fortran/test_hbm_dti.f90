!> Time integration to steady state (PHYSICS.md 7): Newmark against the closed-form linear
!> response with its second-order convergence, against the standard method converged in H on a
!> Jenkins oscillator and on a banded chain (first harmonics of gamma and of the stress), the
!> peak search, and the unbounded response above the limit force without damping.
module test_hbm_dti
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EPHYSICS
  use udmap_baseline_linear_structure, only: structure_type, new_structure
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_peak, hbm_response
  use udmap_baseline_newmark, only: dti_settings_type, dti_point_type, dti_response, dti_peak
  use fixtures, only: spring_chain
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_hbm_dti

contains

  !> Newmark time integration to steady state (PHYSICS.md 7), three cases.
  subroutine collect_hbm_dti(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_dti", run_hbm_dti)]
  end subroutine collect_hbm_dti

  !> Newmark against the linear closed form and against the standard method converged in H.
  subroutine run_hbm_dti(suite)
    type(test_suite), intent(inout) :: suite
    integer, parameter :: n = 12, gdof = 4, edof = 12
    type(structure_type) :: osc, osc0, chain
    type(jenkins_element_type) :: stuck, jen, jchain
    type(error_type), allocatable :: error
    type(hbm_settings_type) :: hset
    type(hbm_point_type) :: hp, h1
    type(dti_settings_type) :: dset
    type(dti_point_type) :: dp
    real(wp) :: M(n,n), K(n,n), sK(n), sM(n), err(3), exact, w, val(4), ref, order
    integer :: j
    integer, parameter :: Ns(4) = [128, 256, 1024, 4096]

    ! one DOF: m = 1, k = 1, c = 0.01 (PHYSICS.md 8)
    call new_structure(osc, reshape([1.0_wp], [1,1]), reshape([1.0_wp], [1,1]), &
      & reshape([0.01_wp], [1,1]), 1, 1, error)
    call check_no_error(suite, "oscillator", error)

    ! (a) linear: a Jenkins element that never slips adds kt; error O(dt^2), ratio 4 per halving
    call new_jenkins_element(stuck, 0.25_wp, 1.0e6_wp, error)
    w = 1.08_wp
    exact = 0.1_wp/abs(cmplx(1.25_wp - w**2, 0.01_wp*w, wp))
    do j = 1, 3
      dset%steps_per_period = 32*2**j
      call dti_response(osc, stuck, w/(2.0_wp*pi), 0.1_wp, dset, dp, error)
      call check_no_error(suite, "linear dti", error)
      err(j) = abs(dp%gamma_1 - exact)/exact
    end do
    call check_true(suite, "linear: second order (ratio 4 per halving)", &
      & abs(err(1)/err(2) - 4.0_wp) < 0.2_wp .and. abs(err(2)/err(3) - 4.0_wp) < 0.2_wp)
    ! near the stuck resonance (zeta about 0.5 %) the period error (omega dt)^2/12 is amplified
    call check_true(suite, "linear: N = 256 within 2e-3", err(3) < 2.0e-3_wp)
    call check_true(suite, "linear: steady state reached", dp%ss_error < 1.0e-8_wp)

    ! (b) Jenkins in gross slip at omega = 1.08, F_E = 0.1: the standard method converged in H
    call new_jenkins_element(jen, 0.25_wp, 0.2_wp, error)
    hset%harmonics = 15
    call hbm_response(osc, jen, 0.8_wp/(2.0_wp*pi), w/(2.0_wp*pi), 0.1_wp, hset, hp, error)
    call check_no_error(suite, "hbm H = 15", error)
    do j = 1, 4
      dset%steps_per_period = Ns(j)
      call dti_response(osc, jen, w/(2.0_wp*pi), 0.1_wp, dset, dp, error)
      call check_no_error(suite, "jenkins dti", error)
      val(j) = dp%gamma_1
    end do
    ref = val(4)
    call check_close(suite, "dti N = 4096 vs hbm H = 15", ref, hp%gamma_P, 5.0e-6_wp)
    call check_close(suite, "dti N = 1024 vs hbm H = 15", val(3), hp%gamma_P, 2.0e-5_wp)
    ! events inside steps make the error irregular from one N to the next; over a factor of 8
    ! in N the order is two
    order = log(abs(val(1) - ref)/abs(val(3) - ref))/log(8.0_wp)
    call check_true(suite, "jenkins: observed order about 2", order > 1.6_wp .and. order < 2.6_wp)
    call check_close(suite, "gamma_max vs hbm", dp%gamma_max, hp%gamma_max, 1.0e-5_wp)
    call check_close(suite, "no static offset", dp%gamma_0, 0.0_wp, 0.0_wp, 1.0e-9_wp)

    ! (c) banded chain, Jenkins on DOF 4, at the single-harmonic peak frequency: strong third
    ! harmonic (3 f near the second mode), so H = 1 is far off while H = 13 and Newmark agree
    call spring_chain(M, K)
    sK = K(gdof, :)
    sM = 0.0_wp
    sM(5) = 0.1_wp
    call new_structure(chain, M, K, 1.0e-2_wp*K, gdof, edof, error, sK, sM)
    call new_jenkins_element(jchain, 50.0_wp, 0.02_wp, error)
    hset%harmonics = 1
    call hbm_peak(chain, jchain, 0.12_wp, 0.25_wp, 6.0e-3_wp, hset, h1, error)
    call check_no_error(suite, "chain H = 1", error)
    hset%harmonics = 13
    call hbm_response(chain, jchain, 0.12_wp, h1%f_res, 6.0e-3_wp, hset, hp, error)
    call check_no_error(suite, "chain H = 13", error)
    dset%steps_per_period = 512
    call dti_response(chain, jchain, h1%f_res, 6.0e-3_wp, dset, dp, error)
    call check_no_error(suite, "chain dti", error)
    call check_close(suite, "chain gamma_1 dti vs H = 13", dp%gamma_1, hp%gamma_P, 2.0e-3_wp)
    call check_close(suite, "chain sigma_1 dti vs H = 13", dp%sigma_1, hp%sigma_a, 2.0e-3_wp)
    call check_close(suite, "chain gamma_max dti vs H = 13", dp%gamma_max, hp%gamma_max, 2.0e-3_wp)
    call check_true(suite, "chain: H = 1 misses the superharmonic", h1%gamma_P > 1.5_wp*dp%gamma_1)

    ! (d) peak search on the oscillator against the standard method's peak at H = 15
    hset%harmonics = 15
    call hbm_peak(osc, jen, 0.8_wp/(2.0_wp*pi), 1.3_wp/(2.0_wp*pi), 0.1_wp, hset, hp, error)
    call check_no_error(suite, "hbm peak H = 15", error)
    dset%steps_per_period = 1024
    call dti_peak(osc, jen, 0.8_wp/(2.0_wp*pi), 1.3_wp/(2.0_wp*pi), 0.1_wp, dset, dp, error)
    call check_no_error(suite, "dti peak", error)
    call check_close(suite, "peak gamma_1", dp%gamma_1, hp%gamma_P, 3.0e-5_wp)
    call check_close(suite, "peak frequency", dp%f, hp%f_res, 1.0e-4_wp)

    ! (e) no damping, F_E above F_lim = 2 Delta_M/pi = 0.2546: unbounded
    call new_structure(osc0, reshape([1.0_wp], [1,1]), reshape([1.0_wp], [1,1]), &
      & reshape([0.0_wp], [1,1]), 1, 1, error)
    dset%steps_per_period = 64
    call dti_response(osc0, jen, 1.0_wp/(2.0_wp*pi), 0.3_wp, dset, dp, error)
    call check_error(suite, "unbounded dti", error, UDMAP_EPHYSICS, "unbounded")
    hset%harmonics = 1
    call hbm_peak(osc0, jen, 0.8_wp/(2.0_wp*pi), 1.3_wp/(2.0_wp*pi), 0.3_wp, hset, hp, error)
    call check_error(suite, "unbounded hbm", error, UDMAP_EPHYSICS, "unbounded")
  end subroutine run_hbm_dti
end module test_hbm_dti
