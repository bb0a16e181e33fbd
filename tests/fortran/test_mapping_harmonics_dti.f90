!> Multi-harmonic layers with automatic H against the project's time integration (PHYSICS.md 7)
!> on blade A in gross slip, at the time integration's peak: gamma_P and sigma_a within 0.5 %,
!> f_res within 0.05 Hz (the single-harmonic method is 2-9 % off there). F_E = 5 and 10 N here;
!> 2 N (slower to reach its steady state) is measured in bench/bench_harmonics.py.
module test_mapping_harmonics_dti
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, backbone
  use udmap_baseline_linear_structure, only: structure_type, structure_from_blade
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_baseline_newmark, only: dti_settings_type, dti_point_type, dti_peak
  use fixtures, only: blade_a_beam_params, blade_a_band
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_mapping_harmonics_dti

contains

  !> Automatic H against Newmark in gross slip, on blade A.
  subroutine collect_mapping_harmonics_dti(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_harmonics_dti", run_mapping_harmonics_dti)]
  end subroutine collect_mapping_harmonics_dti

  !> Automatic H against the time integration's peak in gross slip, within 0.5 %.
  subroutine run_mapping_harmonics_dti(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: bp
    type(blade_type), target :: blade
    type(damper_type), target :: damper
    type(model_type) :: model
    type(analysis_type) :: an
    type(point_type), allocatable :: pa(:), p1(:)
    type(error_type), allocatable :: error
    type(structure_type) :: st
    type(contact_element_type) :: el
    type(dti_settings_type) :: dset
    type(dti_point_type) :: dp
    real(wp), parameter :: FE(2) = [5.0_wp, 10.0_wp]
    integer :: i
    character(len=16) :: tag

    bp = blade_a_beam_params()
    call new_beam_blade(blade, bp, error)
    call new_asymmetric_damper(damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
    call structure_from_blade(st, blade, error)
    call new_contact_element(el, blade_a_damper_params(), error)
    call blade_a_band(an)
    call new_model(model, blade, damper, an, error)
    call backbone(model, FE, p1, error)
    an%harmonics = 0
    call new_model(model, blade, damper, an, error)
    call backbone(model, FE, pa, error)
    call check_no_error(suite, "backbone auto", error)
    if (.not.allocated(pa)) return
    ! 256 steps per period: the Newmark error is below 0.1 % there (test_hbm_blade_a)
    dset%steps_per_period = 256
    do i = 1, size(FE)
      write(tag, '(a, f4.1, a)') "F_E =", FE(i), " N"
      call dti_peak(st, el, an%f_min, an%f_max, FE(i), dset, dp, error, f_center=pa(i)%f_res)
      call check_no_error(suite, "dti "//trim(tag), error)
      call check_close(suite, "auto gamma_P vs dti "//trim(tag), pa(i)%gamma_P, dp%gamma_1, 5e-3_wp)
      call check_close(suite, "auto sigma_a vs dti "//trim(tag), pa(i)%sigma_a, dp%sigma_1, 5e-3_wp)
      call check_true(suite, "auto f_res vs dti within 0.05 Hz "//trim(tag), &
        & abs(pa(i)%f_res - dp%f) <= 0.05_wp)
      call check_true(suite, "H = 1 is off by more than 1 % "//trim(tag), &
        & abs(p1(i)%gamma_P/dp%gamma_1 - 1) > 1e-2_wp)
    end do
  end subroutine run_mapping_harmonics_dti
end module test_mapping_harmonics_dti
