!> Standard method on the one-DOF oscillator with a Jenkins element (PHYSICS.md 8): the H = 1
!> peaks against the published single-harmonic values and, to more digits, against the closed
!> form (k(a) of PHYSICS.md 2.4 in g~ = H/(1 + k H), peak where d|g~|/domega = 0, F_bb(a) = F
!> solved by Brent in double precision, outside this code); both variants, harmonic 0, exact and
!> sampled AFT, response at a frequency, errors.
module test_hbm_oscillator
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_baseline_linear_structure, only: structure_type, new_structure
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_core_error, only: UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_peak, hbm_response, &
    & HBM_FULL
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_hbm_oscillator

contains

  !> Standard method on the one-DOF Jenkins oscillator (PHYSICS.md 8).
  subroutine collect_hbm_oscillator(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_oscillator", run_hbm_oscillator)]
  end subroutine collect_hbm_oscillator

  !> The one-DOF Jenkins oscillator's peaks, published and closed-form, in both variants.
  subroutine run_hbm_oscillator(suite)
    type(test_suite), intent(inout) :: suite
    type(structure_type) :: st
    type(jenkins_element_type) :: jen
    type(error_type), allocatable :: error
    type(hbm_settings_type) :: set
    type(hbm_point_type) :: pt
    real(wp), parameter :: F(3) = [0.05_wp, 0.1_wp, 0.3_wp]
    real(wp), parameter :: amp(3) = [0.946956_wp, 1.214018_wp, 7.279801_wp]
    real(wp), parameter :: om(3) = [1.106824_wp, 1.083677_wp, 1.007341_wp]
    ! the same peaks to more digits from the closed form (computed independently, see above)
    real(wp), parameter :: amp_x(3) = [0.9469564718668427_wp, 1.2140181728873205_wp, &
      & 7.279801303437081_wp]
    real(wp), parameter :: om_x(3) = [1.1068237144698176_wp, 1.0836767732610326_wp, &
      & 1.0073413133645486_wp]
    real(wp) :: kim_x(3)
    real(wp) :: f_min, f_max
    type(hbm_settings_type) :: full, h0, sampled, bad
    type(hbm_point_type) :: pf
    integer :: i
    character(len=8) :: tag

    call new_structure(st, reshape([1.0_wp], [1,1]), reshape([1.0_wp], [1,1]), &
      & reshape([0.01_wp], [1,1]), 1, 1, error)
    call check_no_error(suite, "structure", error)
    call new_jenkins_element(jen, 0.25_wp, 0.2_wp, error)
    call check_no_error(suite, "jenkins", error)
    full%variant = HBM_FULL
    h0%harmonic0 = .true.
    sampled%aft_samples = 128
    ! k_Im of the Jenkins element at the exact peak amplitudes (PHYSICS.md 2.4)
    kim_x = 4.0_wp*0.2_wp/(pi*amp_x)*(1.0_wp - 0.8_wp/amp_x)
    f_min = 0.8_wp/(2.0_wp*pi)
    f_max = 1.3_wp/(2.0_wp*pi)
    do i = 1, 3
      write(tag, '(f5.2)') F(i)
      call hbm_peak(st, jen, f_min, f_max, F(i), set, pt, error)
      call check_no_error(suite, "condensed F ="//tag, error)
      if (allocated(error)) cycle
      call check_close(suite, "amplitude F ="//tag, pt%gamma_P, amp(i), 1.0e-6_wp)
      call check_close(suite, "omega F ="//tag, 2.0_wp*pi*pt%f_res, om(i), 1.0e-6_wp)
      ! closed-form describing function, peak by the exact root of d|g~|/domega (independent)
      call check_close(suite, "amplitude exact F ="//tag, pt%gamma_P, amp_x(i), 1.0e-11_wp)
      call check_close(suite, "omega exact F ="//tag, 2.0_wp*pi*pt%f_res, om_x(i), 1.0e-9_wp)
      call check_close(suite, "k_im F ="//tag, pt%k_im, kim_x(i), 1.0e-9_wp)
      call check_close(suite, "u_E = gamma_P (same DOF) F ="//tag, pt%u_E, pt%gamma_P, 1.0e-12_wp)
      call check_true(suite, "one peak F ="//tag, pt%npeaks == 1)
      ! the full variant solves the same equations
      call hbm_peak(st, jen, f_min, f_max, F(i), full, pf, error)
      call check_no_error(suite, "full F ="//tag, error)
      if (allocated(error)) cycle
      call check_close(suite, "full amplitude F ="//tag, pf%gamma_P, amp_x(i), 1.0e-11_wp)
      call check_close(suite, "full omega F ="//tag, 2.0_wp*pi*pf%f_res, om_x(i), 1.0e-9_wp)
      ! static harmonic of a symmetric element: zero, same peak
      call hbm_peak(st, jen, f_min, f_max, F(i), h0, pf, error)
      call check_no_error(suite, "harmonic 0 F ="//tag, error)
      if (allocated(error)) cycle
      call check_close(suite, "harmonic 0 amplitude F ="//tag, pf%gamma_P, amp_x(i), 1.0e-10_wp)
      ! classical sampled AFT: close, not exact
      call hbm_peak(st, jen, f_min, f_max, F(i), sampled, pf, error)
      call check_no_error(suite, "sampled F ="//tag, error)
      if (allocated(error)) cycle
      call check_close(suite, "sampled amplitude F ="//tag, pf%gamma_P, amp_x(i), 2.0e-4_wp)
    end do

    ! response at a given frequency in gross slip against the closed form: a |1 + k(a) H| = F |H|
    call hbm_response(st, jen, f_min, 1.08_wp/(2.0_wp*pi), 0.1_wp, set, pt, error)
    call check_no_error(suite, "response", error)
    call check_close(suite, "response amplitude", pt%gamma_P, 1.2104045112269104_wp, 1.0e-11_wp)

    ! errors: no resonance in a band below it, bad inputs
    call hbm_peak(st, jen, 0.5_wp/(2.0_wp*pi), 0.7_wp/(2.0_wp*pi), 0.1_wp, set, pt, error)
    call check_error(suite, "no resonance in band", error, UDMAP_EPHYSICS, "no resonance")
    call hbm_peak(st, jen, f_min, f_max, -1.0_wp, set, pt, error)
    call check_error(suite, "negative force", error, UDMAP_EINPUT, "F_E")
    bad = set
    bad%harmonics = 0
    call hbm_peak(st, jen, f_min, f_max, 0.1_wp, bad, pt, error)
    call check_error(suite, "harmonics 0", error, UDMAP_EINPUT, "harmonics")
  end subroutine run_hbm_oscillator
end module test_hbm_oscillator
