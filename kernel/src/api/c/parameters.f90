!> The C API's parameter structs in Fortran and their conversion to the kernel's types.
!> Generated from kernel/parameters.toml by cmake/generate_parameters.py: do not edit; edit the
!> table and run cmake/generate_parameters.py.
module udmap_api_c_parameters
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use udmap_beam, only: beam_params_type
  use udmap_damper_params, only: asymmetric_params_type
  implicit none
  private
  public :: c_beam_params, beam_from_c, udmap_asymmetric_params, asymmetric_from_c

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
end module udmap_api_c_parameters
