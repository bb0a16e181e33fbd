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
  end type c_analysis_type

contains

  !> The kernel's beam_params_type of the C struct udmap_beam_params.
  pure function beam_from_c(c) result(p)
    type(c_beam_params), intent(in) :: c
    type(beam_params_type) :: p
    p%E = c%E
    p%rho = c%rho
    p%zeta = c%zeta
    p%neck_L = c%neck_L
    p%neck_h = c%neck_h
    p%neck_b = c%neck_b
    p%platform_L = c%platform_L
    p%platform_m = c%platform_m
    p%platform_J = c%platform_J
    p%airfoil_L = c%airfoil_L
    p%airfoil_h = c%airfoil_h
    p%airfoil_b = c%airfoil_b
    p%neck_elements = int(c%neck_elements)
    p%airfoil_elements = int(c%airfoil_elements)
  end function beam_from_c

  !> The kernel's asymmetric_params_type of the C struct udmap_asymmetric_params.
  pure function asymmetric_from_c(c) result(p)
    type(udmap_asymmetric_params), intent(in) :: c
    type(asymmetric_params_type) :: p
    p%CF = c%CF
    p%mu = c%mu
    p%pitch = c%pitch
    p%y_P = c%y_P
    p%beta_L_deg = c%beta_L_deg
    p%beta_R_deg = c%beta_R_deg
    p%flat(1,1) = c%flat1_x
    p%flat(2,1) = c%flat1_y
    p%flat(1,2) = c%flat2_x
    p%flat(2,2) = c%flat2_y
    p%curved(1) = c%curved_x
    p%curved(2) = c%curved_y
    p%kn_flat = c%kn_flat
    p%kt_flat = c%kt_flat
    p%kn_curved = c%kn_curved
    p%kt_curved = c%kt_curved
  end function asymmetric_from_c

  !> The kernel's analysis_type of the C struct udmap_analysis.
  pure function analysis_from_c(c) result(p)
    type(c_analysis_type), intent(in) :: c
    type(analysis_type) :: p
    p%f_min = c%f_min
    p%f_max = c%f_max
    p%sigma_all = c%sigma_all
    p%rtol = c%rtol
    p%grid_per_decade = int(c%grid_per_decade)
    p%eigen_method = int(c%eigen_method)
    p%dense_max = int(c%dense_max)
    p%sweep_points = int(c%sweep_points)
    p%harmonics = int(c%harmonics)
    p%harmonic_tol = c%harmonic_tol
  end function analysis_from_c

  !> The C struct udmap_analysis of the kernel's analysis_type.
  pure function analysis_to_c(p) result(c)
    type(analysis_type), intent(in) :: p
    type(c_analysis_type) :: c
    c%f_min = real(p%f_min, c_double)
    c%f_max = real(p%f_max, c_double)
    c%sigma_all = real(p%sigma_all, c_double)
    c%rtol = real(p%rtol, c_double)
    c%grid_per_decade = int(p%grid_per_decade, c_int)
    c%eigen_method = int(p%eigen_method, c_int)
    c%dense_max = int(p%dense_max, c_int)
    c%sweep_points = int(p%sweep_points, c_int)
    c%harmonics = int(p%harmonics, c_int)
    c%harmonic_tol = real(p%harmonic_tol, c_double)
  end function analysis_to_c
end module udmap_api_c_parameters
