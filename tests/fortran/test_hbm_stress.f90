!> Stress test of the standard method, the AFT and the time integration over extreme but legal
!> inputs: every call returns finite numbers or a clear error, never NaN, a crash or a hang.
!> One-DOF oscillator (m = 1, k = 1) with a Jenkins element; damping zeta 0, 1e-5 and 0.005;
!> stiffness ratios kt/k 1e-3..1e3; slip moments over 12 decades; forces below, at and above
!> the limit force F_lim = 2 Delta_M/pi (zeta = 0); a band without resonance; amplitudes
!> 1e-12..1 rad in the AFT; non-finite inputs.
module test_hbm_stress
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_baseline_linear_structure, only: structure_type, new_structure
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_contact_aft_moment, only: aft_moment
  use udmap_baseline_hbm, only: hbm_peak
  use udmap_baseline_newmark, only: dti_response
  use fixtures, only: stress_run_type, stress_run, check_finite_or_error, ieee_nan
  use testing, only: test_suite, check_true, check_error, unittest_type, new_unittest
  implicit none
  private
  public :: collect_hbm_stress

contains

  !> Extreme inputs to the standard method, AFT and time integration.
  subroutine collect_hbm_stress(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_stress", run_hbm_stress)]
  end subroutine collect_hbm_stress

  !> Extreme but legal inputs give finite numbers or a clear error, never NaN or a hang.
  subroutine run_hbm_stress(suite)
    type(test_suite), intent(inout) :: suite
    type(structure_type) :: st
    type(jenkins_element_type) :: jen
    type(error_type), allocatable :: error
    type(stress_run_type) :: run
    real(wp), parameter :: zetas(3) = [0.0_wp, 1.0e-5_wp, 5.0e-3_wp]
    real(wp), parameter :: ratios(4) = [1.0e-3_wp, 1.0_wp, 30.0_wp, 1.0e3_wp]
    real(wp), parameter :: slips(3) = [1.0e-10_wp, 1.0e-2_wp, 1.0e2_wp]
    real(wp), parameter :: frac(4) = [0.3_wp, 0.99_wp, 1.0_wp, 1.5_wp]
    real(wp) :: M0, gmax, Flim, F, f_lo, f_hi, kt
    complex(wp) :: M(3), G(3)
    integer :: iz, ir, is, jf, ig, nok, nerr
    character(len=80) :: tag

    nok = 0
    nerr = 0
    ! AFT over amplitudes 1e-12..1 rad and slip limits over 12 decades
    do ir = 1, size(ratios)
      do is = 1, size(slips)
        call new_jenkins_element(jen, ratios(ir), slips(is), error)
        do ig = -12, 0, 2
          G = [cmplx(10.0_wp**ig, 0.0_wp, wp), (0.0_wp, 0.0_wp), cmplx(0.0_wp, 0.3_wp*10.0_wp**ig, wp)]
          call aft_moment(jen, run%ws, 0.0_wp, G, 0, 1, 8, 1.0e-12_wp, M0, M, error, gmax)
          write(tag, '(a, 2es9.1, i4)') "aft kt, M_slip, log gamma", ratios(ir), slips(is), ig
          call check_true(suite, trim(tag)//" finite", .not.allocated(error) .and. &
            & all(abs(M) <= huge(1.0_wp)) .and. abs(M0) <= huge(1.0_wp) .and. gmax > 0.0_wp)
          ! passivity: the first harmonic never generates energy
          call check_true(suite, trim(tag)//" dissipative", aimag(M(1)*conjg(G(1))) >= &
            & -1.0e-12_wp*abs(M(1))*abs(G(1)))
        end do
      end do
    end do
    call new_jenkins_element(jen, 1.0_wp, 1.0_wp, error)
    G = [cmplx(ieee_value(1.0_wp, ieee_positive_inf), 0.0_wp, wp), (0.0_wp, 0.0_wp), &
      & (0.0_wp, 0.0_wp)]
    call aft_moment(jen, run%ws, 0.0_wp, G, 0, 1, 8, 1.0e-12_wp, M0, M, error)
    call check_error(suite, "aft infinite amplitude", error, UDMAP_EINPUT, "not finite")

    ! standard method and time integration over damping, stiffness ratio, slip limit and force
    run = stress_run(max_periods=4000)
    do iz = 1, size(zetas)
      call new_structure(st, reshape([1.0_wp], [1,1]), reshape([1.0_wp], [1,1]), &
        & reshape([2.0_wp*zetas(iz)], [1,1]), 1, 1, error)
      do ir = 1, size(ratios)
        kt = ratios(ir)
        f_lo = 0.5_wp/(2.0_wp*pi)
        f_hi = 2.0_wp*sqrt(1.0_wp + kt)/(2.0_wp*pi)
        do is = 1, size(slips)
          call new_jenkins_element(jen, kt, slips(is), error)
          Flim = 4.0_wp*slips(is)/pi
          do jf = 1, size(frac)
            F = frac(jf)*Flim
            write(tag, '(a, es8.1, a, es8.1, a, es8.1, a, f5.2)') "zeta", zetas(iz), " kt", kt, &
              & " M_slip", slips(is), " F/F_lim", frac(jf)
            call hbm_peak(st, jen, f_lo, f_hi, F, run%set, run%pt, error)
            call account(trim(tag)//" hbm", run%pt%gamma_P, run%pt%f_res)
            ! time integration at the stuck resonance frequency, a few hundred periods at most
            call dti_response(st, jen, sqrt(1.0_wp + kt)/(2.0_wp*pi)*1.01_wp, F, run%dset, &
              & run%dp, error)
            call account(trim(tag)//" dti", run%dp%gamma_1, run%dp%f)
          end do
        end do
      end do
    end do
    call check_true(suite, "some calls succeed", nok > 0)

    ! a band without resonance; non-finite and invalid inputs
    call new_structure(st, reshape([1.0_wp], [1,1]), reshape([1.0_wp], [1,1]), &
      & reshape([0.01_wp], [1,1]), 1, 1, error)
    call new_jenkins_element(jen, 0.25_wp, 0.2_wp, error)
    call hbm_peak(st, jen, 2.0_wp, 3.0_wp, 0.1_wp, run%set, run%pt, error)
    call check_error(suite, "band without resonance", error, UDMAP_EPHYSICS, "no resonance")
    call hbm_peak(st, jen, 0.1_wp, 0.3_wp, ieee_nan(), run%set, run%pt, error)
    call check_error(suite, "NaN force", error, UDMAP_EINPUT, "F_E")
    call hbm_peak(st, jen, 0.3_wp, 0.1_wp, 0.1_wp, run%set, run%pt, error)
    call check_error(suite, "inverted band", error, UDMAP_EINPUT, "f_min")
    call dti_response(st, jen, ieee_nan(), 0.1_wp, run%dset, run%dp, error)
    call check_error(suite, "NaN frequency", error, UDMAP_EINPUT, "frequency")
    call new_jenkins_element(jen, -1.0_wp, 0.2_wp, error)
    call check_error(suite, "negative kt", error, UDMAP_EINPUT, "kt")
    call new_structure(st, reshape([1.0_wp], [1,1]), reshape([ieee_nan()], [1,1]), &
      & reshape([0.01_wp], [1,1]), 1, 1, error)
    call check_error(suite, "NaN stiffness", error, UDMAP_EINPUT, "non-finite")
    ! near-singular: a nearly massless, nearly rigid-body DOF pair
    call new_structure(st, reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0e-12_wp], [2,2]), &
      & reshape([1.0_wp + 1.0e-9_wp, -1.0_wp, -1.0_wp, 1.0_wp], [2,2]), &
      & reshape([1.0e-3_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2,2]), 1, 2, error)
    call new_jenkins_element(jen, 1.0e-6_wp, 1.0e-6_wp, error)
    call hbm_peak(st, jen, 1.0e-6_wp, 1.0e-2_wp, 1.0e-6_wp, run%set, run%pt, error)
    call account("near-singular hbm", run%pt%gamma_P, run%pt%f_res)

  contains

    !> check_finite_or_error, counting the calls that succeeded and those that failed.
    subroutine account(name, a, b)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: a, b
      logical :: failed
      call check_finite_or_error(suite, name, error, a, b, failed)
      if (failed) then
        nerr = nerr + 1
      else
        nok = nok + 1
      end if
    end subroutine account
  end subroutine run_hbm_stress
end module test_hbm_stress
