!> Stress test of the standard method and the time integration with the asymmetric damper on
!> blade A over extreme but legal damper parameters (mu 1e-4..2, CF 1e-3..1e5 N, contact
!> stiffnesses scaled by 1e-3..1e3), amplitudes 1e-12..1 rad in the AFT, zeta 0 and 1e-5, and
!> forces around the limit force: every call returns finite numbers or a clear error.
module test_hbm_stress_contact
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_damper_params, only: asymmetric_params_type, blade_a_damper_params
  use udmap_baseline_linear_structure, only: structure_type, structure_from_blade
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_contact_aft_moment, only: aft_moment
  use udmap_baseline_hbm, only: hbm_peak
  use udmap_baseline_newmark, only: dti_response
  use fixtures, only: blade_a_beam_params, stress_run_type, stress_run, check_finite_or_error
  use testing, only: test_suite, check_error, unittest_type, new_unittest
  implicit none
  private
  public :: collect_hbm_stress_contact

contains

  !> Extreme damper parameters (mu, CF, contact stiffness) on blade A.
  subroutine collect_hbm_stress_contact(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_stress_contact", run_hbm_stress_contact)]
  end subroutine collect_hbm_stress_contact

  !> Extreme asymmetric damper parameters on blade A: finite results or a clear error.
  subroutine run_hbm_stress_contact(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: bp
    type(blade_type) :: blade
    type(structure_type) :: st
    type(asymmetric_params_type) :: par
    type(contact_element_type) :: el
    type(error_type), allocatable :: error
    type(stress_run_type) :: run
    real(wp), parameter :: mus(3) = [1.0e-4_wp, 0.3_wp, 2.0_wp]
    real(wp), parameter :: CFs(3) = [1.0e-3_wp, 900.0_wp, 1.0e5_wp]
    real(wp), parameter :: kscale(3) = [1.0e-3_wp, 1.0_wp, 1.0e3_wp]
    real(wp), parameter :: zetas(2) = [0.0_wp, 1.0e-5_wp]
    real(wp), parameter :: fracs(3) = [0.99_wp, 1.0_wp, 1.01_wp]
    real(wp) :: M0, gmax, Flim
    complex(wp) :: G(3), M(3)
    integer :: im, ic, ik, ig, iz, jf
    character(len=96) :: tag

    bp = blade_a_beam_params()
    call new_beam_blade(blade, bp, error)
    call structure_from_blade(st, blade, error)
    run = stress_run(max_periods=300)
    run%dset%min_periods = 5

    ! damper parameter sweep: AFT over amplitudes, then the standard method on blade A
    do im = 1, size(mus)
      do ic = 1, size(CFs)
        do ik = 1, size(kscale)
          par = blade_a_damper_params()
          par%mu = mus(im)
          par%CF = CFs(ic)
          par%kn_flat = par%kn_flat*kscale(ik)
          par%kt_flat = par%kt_flat*kscale(ik)
          par%kn_curved = par%kn_curved*kscale(ik)
          par%kt_curved = par%kt_curved*kscale(ik)
          write(tag, '(a, es8.1, a, es8.1, a, es8.1)') "mu", mus(im), " CF", CFs(ic), " k x", &
            & kscale(ik)
          call new_contact_element(el, par, error)
          call check_finite_or_error(suite, trim(tag)//" element", error, el%k_stuck, 1.0_wp)
          if (el%k_stuck <= 0.0_wp) cycle
          do ig = -12, 0, 3
            G = [cmplx(10.0_wp**ig, 0.0_wp, wp), (0.0_wp, 0.0_wp), &
              & cmplx(0.0_wp, 0.2_wp*10.0_wp**ig, wp)]
            call aft_moment(el, run%ws, 0.0_wp, G, 0, 1, 8, 1.0e-12_wp, M0, M, error, gmax)
            call check_finite_or_error(suite, trim(tag)//" aft", error, &
              & abs(M(1)) + abs(M(3)) + abs(M0), gmax)
          end do
          ! force scaled with the slip moments, about mu CF times a lever arm of a few mm
          call hbm_peak(st, el, 150.0_wp, 230.0_wp, 1.0e-2_wp*par%mu*par%CF, run%set, run%pt, &
            & error)
          call check_finite_or_error(suite, trim(tag)//" hbm", error, run%pt%gamma_P, &
            & run%pt%f_res)
        end do
      end do
    end do

    ! blade A damping 0 and 1e-5, forces just below, at and above the limit force
    do iz = 1, size(zetas)
      bp%zeta = zetas(iz)
      call new_beam_blade(blade, bp, error)
      call structure_from_blade(st, blade, error)
      call new_contact_element(el, blade_a_damper_params(), error)
      ! F_lim of blade A's damper (measured by the backbone): 21.677 N
      Flim = 21.677454956969921_wp
      do jf = 1, 3
        write(tag, '(a, es8.1, a, f6.3)') "zeta", zetas(iz), " F/F_lim", fracs(jf)
        call hbm_peak(st, el, 150.0_wp, 230.0_wp, Flim*fracs(jf), run%set, run%pt, &
          & error)
        call check_finite_or_error(suite, trim(tag)//" hbm", error, run%pt%gamma_P, &
          & run%pt%f_res)
        call dti_response(st, el, 190.0_wp, Flim*fracs(jf), run%dset, run%dp, error)
        call check_finite_or_error(suite, trim(tag)//" dti", error, run%dp%gamma_1, run%dp%f)
      end do
    end do

    ! invalid damper parameters are rejected with the field's name
    par = blade_a_damper_params()
    par%mu = -1.0_wp
    call new_contact_element(el, par, error)
    call check_error(suite, "negative mu", error, UDMAP_EINPUT, "mu")
    par = blade_a_damper_params()
    par%CF = ieee_value(1.0_wp, ieee_quiet_nan)
    call new_contact_element(el, par, error)
    call check_error(suite, "NaN CF", error, UDMAP_EINPUT, "CF")
  end subroutine run_hbm_stress_contact
end module test_hbm_stress_contact
