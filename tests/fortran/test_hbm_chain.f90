!> Standard method on a 12-DOF spring-mass chain (banded) with a Jenkins element on DOF 4:
!> condensed and full variants agree with each other for H = 1 and H = 3 (with harmonic 0),
!> and the H = 1 peaks, stress and u_E agree with an independent computation (numpy/scipy:
!> dense solves for the receptances, closed-form k(a), F_bb(a) = F_E solved by Brent).
module test_hbm_chain
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_baseline_linear_structure, only: structure_type, new_structure
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_peak, HBM_FULL
  use fixtures, only: spring_chain
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_hbm_chain

contains

  !> Standard method on a banded 12-DOF chain.
  subroutine collect_hbm_chain(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_chain", run_hbm_chain)]
  end subroutine collect_hbm_chain

  !> Condensed and full variants agree on the 12-DOF chain, against reference peaks.
  subroutine run_hbm_chain(suite)
    type(test_suite), intent(inout) :: suite
    integer, parameter :: n = 12, gdof = 4, edof = 12
    type(structure_type) :: st
    type(jenkins_element_type) :: jen
    type(error_type), allocatable :: error
    type(hbm_settings_type) :: cond, full
    type(hbm_point_type) :: pc, pf
    real(wp) :: M(n,n), K(n,n), sK(n), sM(n)
    real(wp), parameter :: F(2) = [1.0e-3_wp, 6.0e-3_wp]
    real(wp), parameter :: gam_x(2) = [0.0004850227790807728_wp, 0.0012995070261538587_wp]
    real(wp), parameter :: f_x(2) = [0.17943179148726665_wp, 0.16435483702568116_wp]
    real(wp), parameter :: sig_x(2) = [0.021111520711460392_wp, 0.02331307949530857_wp]
    real(wp), parameter :: uE_x(2) = [0.0022215441126723088_wp, 0.003847769817286283_wp]
    integer :: i, H
    character(len=16) :: tag

    call spring_chain(M, K)
    sK = K(gdof, :)
    sM = 0.0_wp
    sM(5) = 0.1_wp
    call new_structure(st, M, K, 1.0e-3_wp*K, gdof, edof, error, sK, sM)
    call check_no_error(suite, "structure", error)
    call check_true(suite, "banded storage", st%kd == 1)
    call new_jenkins_element(jen, 50.0_wp, 0.02_wp, error)
    full%variant = HBM_FULL
    do i = 1, 2
      write(tag, '(es8.1)') F(i)
      call hbm_peak(st, jen, 0.12_wp, 0.25_wp, F(i), cond, pc, error)
      call check_no_error(suite, "condensed F ="//tag, error)
      call hbm_peak(st, jen, 0.12_wp, 0.25_wp, F(i), full, pf, error)
      call check_no_error(suite, "full F ="//tag, error)
      if (allocated(error)) cycle
      call check_close(suite, "gamma_P F ="//tag, pc%gamma_P, gam_x(i), 1.0e-9_wp)
      call check_close(suite, "f_res F ="//tag, pc%f_res, f_x(i), 1.0e-7_wp)
      call check_close(suite, "sigma_a F ="//tag, pc%sigma_a, sig_x(i), 1.0e-7_wp)
      call check_close(suite, "u_E F ="//tag, pc%u_E, uE_x(i), 1.0e-7_wp)
      call check_close(suite, "full = condensed gamma_P F ="//tag, pf%gamma_P, pc%gamma_P, 1.0e-10_wp)
      call check_close(suite, "full = condensed f_res F ="//tag, pf%f_res, pc%f_res, 1.0e-9_wp)
      call check_close(suite, "full = condensed sigma_a F ="//tag, pf%sigma_a, pc%sigma_a, 1.0e-9_wp)
      call check_close(suite, "full = condensed u_E F ="//tag, pf%u_E, pc%u_E, 1.0e-9_wp)
    end do
    ! three harmonics and the static one: the variants still solve the same equations
    do H = 2, 3
      cond%harmonics = H
      cond%harmonic0 = H == 3
      full%harmonics = H
      full%harmonic0 = H == 3
      write(tag, '(a, i0)') "H = ", H
      call hbm_peak(st, jen, 0.12_wp, 0.25_wp, F(2), cond, pc, error)
      call check_no_error(suite, "condensed "//tag, error)
      call hbm_peak(st, jen, 0.12_wp, 0.25_wp, F(2), full, pf, error)
      call check_no_error(suite, "full "//tag, error)
      if (allocated(error)) cycle
      call check_close(suite, "full = condensed gamma_P "//tag, pf%gamma_P, pc%gamma_P, 1.0e-9_wp)
      call check_close(suite, "full = condensed f_res "//tag, pf%f_res, pc%f_res, 1.0e-9_wp)
      call check_close(suite, "full = condensed sigma_a "//tag, pf%sigma_a, pc%sigma_a, 1.0e-8_wp)
      ! the multi-harmonic peak differs from the single-harmonic one, but not by much
      if (H == 2) then
        ! a symmetric element makes no even harmonics: H = 2 is H = 1
        call check_close(suite, "H = 2 equals H = 1", pc%gamma_P, gam_x(2), 1.0e-9_wp)
        call check_true(suite, "no second harmonic", pc%gamma_h(2) < 1.0e-12_wp*pc%gamma_P)
      else
        ! 3 f_res lies near the second mode: a superharmonic resonance makes H = 3 differ
        call check_true(suite, "third harmonic present", pc%gamma_h(3) > 0.1_wp*pc%gamma_P)
      end if
    end do
  end subroutine run_hbm_chain
end module test_hbm_chain
