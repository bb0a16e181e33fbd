!> The C API's parameter structs in Fortran and their conversion to the kernel's types.
!> Generated from kernel/parameters.toml by cmake/generate_parameters.py: do not edit; edit the
!> table and run cmake/generate_parameters.py.
module udmap_api_c_parameters
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use udmap_blade_beam, only: beam_params_type
  use udmap_damper_params, only: asymmetric_params_type
  use udmap_mapping_model, only: analysis_type
  implicit none
  private
  public :: c_beam_params, beam_from_c, udmap_asymmetric_params, asymmetric_from_c, &
    & c_analysis_type, analysis_from_c, analysis_to_c

  !> struct udmap_beam_params (wrappers/c/udmap.h).
  type, bind(C) :: c_beam_params
    real(c_double) :: E, rho, zeta
    real(c_double) :: neck_L, neck_h, neck_b
    real(c_double) :: platform_L, platform_m, platform_J
    real(c_double) :: airfoil_L, airfoil_h, airfoil_b
    integer(c_int) :: neck_elements, airfoil_elements
  end type c_beam_params

  !> struct udmap_asymmetric_params (wrappers/c/udmap.h).
  type, bind(C) :: udmap_asymmetric_params
    real(c_double) :: CF, mu, pitch, y_P, beta_L_deg, beta_R_deg
    real(c_double) :: flat1_x, flat1_y, flat2_x, flat2_y, curved_x, curved_y
    real(c_double) :: kn_flat, kt_flat, kn_curved, kt_curved
  end type udmap_asymmetric_params

  !> struct udmap_analysis (wrappers/c/udmap.h).
  type, bind(C) :: c_analysis_type
    real(c_double) :: f_min, f_max
    real(c_double) :: sigma_all
    real(c_double) :: rtol
    integer(c_int) :: grid_per_decade
    integer(c_int) :: eigen_method
    integer(c_int) :: dense_max
    integer(c_int) :: sweep_points
    integer(c_int) :: harmonics
    real(c_double) :: harmonic_tol
    real(c_double) :: ibpa_deg
  end type c_analysis_type

contains

  !> The kernel's beam_params_type of the C struct udmap_beam_params.
  pure function beam_from_c(c) result(p)
    type(c_beam_params), intent(in) :: c
    type(beam_params_type) :: p
    p = beam_params_type(E=c%E, rho=c%rho, zeta=c%zeta, neck_L=c%neck_L, neck_h=c%neck_h, &
      & neck_b=c%neck_b, platform_L=c%platform_L, platform_m=c%platform_m, &
      & platform_J=c%platform_J, airfoil_L=c%airfoil_L, airfoil_h=c%airfoil_h, &
      & airfoil_b=c%airfoil_b, neck_elements=int(c%neck_elements), &
      & airfoil_elements=int(c%airfoil_elements))
  end function beam_from_c

  !> The kernel's asymmetric_params_type of the C struct udmap_asymmetric_params.
  pure function asymmetric_from_c(c) result(p)
    type(udmap_asymmetric_params), intent(in) :: c
    type(asymmetric_params_type) :: p
    p = asymmetric_params_type(CF=c%CF, mu=c%mu, pitch=c%pitch, y_P=c%y_P, &
      & beta_L_deg=c%beta_L_deg, beta_R_deg=c%beta_R_deg, flat=reshape([c%flat1_x, c%flat1_y, &
      & c%flat2_x, c%flat2_y], [2, 2]), curved=[c%curved_x, c%curved_y], kn_flat=c%kn_flat, &
      & kt_flat=c%kt_flat, kn_curved=c%kn_curved, kt_curved=c%kt_curved)
  end function asymmetric_from_c

  !> The kernel's analysis_type of the C struct udmap_analysis.
  pure function analysis_from_c(c) result(p)
    type(c_analysis_type), intent(in) :: c
    type(analysis_type) :: p
    p = analysis_type(f_min=c%f_min, f_max=c%f_max, sigma_all=c%sigma_all, rtol=c%rtol, &
      & grid_per_decade=int(c%grid_per_decade), eigen_method=int(c%eigen_method), &
      & dense_max=int(c%dense_max), sweep_points=int(c%sweep_points), harmonics=int(c%harmonics), &
      & harmonic_tol=c%harmonic_tol, ibpa_deg=c%ibpa_deg)
  end function analysis_from_c

  !> The C struct udmap_analysis of the kernel's analysis_type.
  pure function analysis_to_c(p) result(c)
    type(analysis_type), intent(in) :: p
    type(c_analysis_type) :: c
    c = c_analysis_type(f_min=real(p%f_min, c_double), f_max=real(p%f_max, c_double), &
      & sigma_all=real(p%sigma_all, c_double), rtol=real(p%rtol, c_double), &
      & grid_per_decade=int(p%grid_per_decade, c_int), eigen_method=int(p%eigen_method, c_int), &
      & dense_max=int(p%dense_max, c_int), sweep_points=int(p%sweep_points, c_int), &
      & harmonics=int(p%harmonics, c_int), harmonic_tol=real(p%harmonic_tol, c_double), &
      & ibpa_deg=real(p%ibpa_deg, c_double))
  end function analysis_to_c
end module udmap_api_c_parameters
