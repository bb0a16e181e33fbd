!> Automatic H against the time integration (PHYSICS.md 7) on blade A at F_E = 1, 2, 5, 10 N,
!> at the time integration's peak (512 steps per period), with the single-harmonic backbone
!> beside it. 1 N is partial slip: there the time integration from rest and the replayed
!> history of PHYSICS.md 6 (which the layers follow) differ. One JSON object per line.
program harmonics_dti
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
  implicit none
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
  real(wp), parameter :: FE(4) = [1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp]
  integer :: i

  bp = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, neck_L=0.020_wp, &
    & neck_h=0.008_wp, neck_b=0.020_wp, platform_L=0.010_wp, platform_m=0.021_wp, &
    & platform_J=1.4e-6_wp, airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
    & neck_elements=8, airfoil_elements=24)
  call new_beam_blade(blade, bp, error)
  call new_asymmetric_damper(damper, blade_a_damper_params(), error)
  call structure_from_blade(st, blade, error)
  call new_contact_element(el, blade_a_damper_params(), error)
  an%f_min = 150.0_wp
  an%f_max = 230.0_wp
  call new_model(model, blade, damper, an, error)
  call backbone(model, FE, p1, error)
  an%harmonics = 0
  call new_model(model, blade, damper, an, error)
  call backbone(model, FE, pa, error)
  if (allocated(error)) then
    write(*, '(a)') '{"error": "'//error%message//'"}'
    stop 1
  end if
  dset%steps_per_period = 512
  do i = 1, size(FE)
    call dti_peak(st, el, an%f_min, an%f_max, FE(i), dset, dp, error, f_center=pa(i)%f_res)
    if (allocated(error)) then
      write(*, '(a)') '{"error": "'//error%message//'"}'
      stop 1
    end if
    write(*, '(a, f5.1, a, i0, 9(a, es23.16), a)') '{"F_E": ', FE(i), ', "harmonics": ', &
      & pa(i)%harmonics, ', "gamma_P": ', pa(i)%gamma_P, ', "sigma_a": ', pa(i)%sigma_a, &
      & ', "f_res": ', pa(i)%f_res, ', "dti_gamma_1": ', dp%gamma_1, ', "dti_sigma_1": ', &
      & dp%sigma_1, ', "dti_f": ', dp%f, ', "h1_gamma_P": ', p1(i)%gamma_P, &
      & ', "h1_sigma_a": ', p1(i)%sigma_a, ', "h1_f_res": ', p1(i)%f_res, '}'
    flush(6)
  end do
end program harmonics_dti
