!> The plain-array layout of the legacy API: the arrays hold the fields of the C structs
!> in their order (wrappers/c/udmap.h).
!> Generated from kernel/parameters.toml by cmake/generate_parameters.py: do not edit; edit the
!> table and run cmake/generate_parameters.py.
module udmap_api_legacy_parameters
  use, intrinsic :: iso_c_binding, only: c_double
  use udmap_core_kinds, only: wp
  use udmap_blade_beam, only: beam_params_type
  use udmap_damper_params, only: asymmetric_params_type
  implicit none
  private
  public :: LEGACY_NBEAM, LEGACY_BEAM_E, LEGACY_BEAM_RHO, LEGACY_BEAM_ZETA, LEGACY_BEAM_NECK_L, &
    & LEGACY_BEAM_NECK_H, LEGACY_BEAM_NECK_B, LEGACY_BEAM_PLATFORM_L, LEGACY_BEAM_PLATFORM_M, &
    & LEGACY_BEAM_PLATFORM_J, LEGACY_BEAM_AIRFOIL_L, LEGACY_BEAM_AIRFOIL_H, &
    & LEGACY_BEAM_AIRFOIL_B, LEGACY_BEAM_NECK_ELEMENTS, LEGACY_BEAM_AIRFOIL_ELEMENTS, &
    & beam_from_array, LEGACY_NDAMPER_ASYMMETRIC, LEGACY_ASYMMETRIC_CF, LEGACY_ASYMMETRIC_MU, &
    & LEGACY_ASYMMETRIC_PITCH, LEGACY_ASYMMETRIC_Y_P, LEGACY_ASYMMETRIC_BETA_L_DEG, &
    & LEGACY_ASYMMETRIC_BETA_R_DEG, LEGACY_ASYMMETRIC_FLAT1_X, LEGACY_ASYMMETRIC_FLAT1_Y, &
    & LEGACY_ASYMMETRIC_FLAT2_X, LEGACY_ASYMMETRIC_FLAT2_Y, LEGACY_ASYMMETRIC_CURVED_X, &
    & LEGACY_ASYMMETRIC_CURVED_Y, LEGACY_ASYMMETRIC_KN_FLAT, LEGACY_ASYMMETRIC_KT_FLAT, &
    & LEGACY_ASYMMETRIC_KN_CURVED, LEGACY_ASYMMETRIC_KT_CURVED, asymmetric_from_array, &
    & LEGACY_NDAMPER_JENKINS, LEGACY_JENKINS_KT, LEGACY_JENKINS_M_SLIP, LEGACY_NANALYSIS_MAX, &
    & LEGACY_NANALYSIS_MIN, LEGACY_ANALYSIS_F_MIN, LEGACY_ANALYSIS_F_MAX, &
    & LEGACY_ANALYSIS_SIGMA_ALL, LEGACY_ANALYSIS_RTOL, LEGACY_ANALYSIS_GRID_PER_DECADE, &
    & LEGACY_ANALYSIS_HARMONICS, LEGACY_ANALYSIS_HARMONIC_TOL, LEGACY_ANALYSIS_IBPA_DEG

  !> BEAM(14), the blade (beam): its length and the index of each entry.
  integer, parameter :: LEGACY_NBEAM = 14
  integer, parameter :: LEGACY_BEAM_E = 1, LEGACY_BEAM_RHO = 2, LEGACY_BEAM_ZETA = 3, &
    & LEGACY_BEAM_NECK_L = 4, LEGACY_BEAM_NECK_H = 5, LEGACY_BEAM_NECK_B = 6, &
    & LEGACY_BEAM_PLATFORM_L = 7, LEGACY_BEAM_PLATFORM_M = 8, LEGACY_BEAM_PLATFORM_J = 9, &
    & LEGACY_BEAM_AIRFOIL_L = 10, LEGACY_BEAM_AIRFOIL_H = 11, LEGACY_BEAM_AIRFOIL_B = 12, &
    & LEGACY_BEAM_NECK_ELEMENTS = 13, LEGACY_BEAM_AIRFOIL_ELEMENTS = 14
  !> DAMPER(16), the damper (asymmetric): its length and the index of each entry.
  integer, parameter :: LEGACY_NDAMPER_ASYMMETRIC = 16
  integer, parameter :: LEGACY_ASYMMETRIC_CF = 1, LEGACY_ASYMMETRIC_MU = 2, &
    & LEGACY_ASYMMETRIC_PITCH = 3, LEGACY_ASYMMETRIC_Y_P = 4, LEGACY_ASYMMETRIC_BETA_L_DEG = 5, &
    & LEGACY_ASYMMETRIC_BETA_R_DEG = 6, LEGACY_ASYMMETRIC_FLAT1_X = 7, &
    & LEGACY_ASYMMETRIC_FLAT1_Y = 8, LEGACY_ASYMMETRIC_FLAT2_X = 9, &
    & LEGACY_ASYMMETRIC_FLAT2_Y = 10, LEGACY_ASYMMETRIC_CURVED_X = 11, &
    & LEGACY_ASYMMETRIC_CURVED_Y = 12, LEGACY_ASYMMETRIC_KN_FLAT = 13, &
    & LEGACY_ASYMMETRIC_KT_FLAT = 14, LEGACY_ASYMMETRIC_KN_CURVED = 15, &
    & LEGACY_ASYMMETRIC_KT_CURVED = 16
  !> DAMPER(2), the damper (jenkins): its length and the index of each entry.
  integer, parameter :: LEGACY_NDAMPER_JENKINS = 2
  integer, parameter :: LEGACY_JENKINS_KT = 1, LEGACY_JENKINS_M_SLIP = 2
  !> ANALYS(8), the analysis: its length and the index of each entry.
  integer, parameter :: LEGACY_NANALYSIS_MAX = 8
  !> The least length of ANALYS: its entries without defaults.
  integer, parameter :: LEGACY_NANALYSIS_MIN = 2
  integer, parameter :: LEGACY_ANALYSIS_F_MIN = 1, LEGACY_ANALYSIS_F_MAX = 2, &
    & LEGACY_ANALYSIS_SIGMA_ALL = 3, LEGACY_ANALYSIS_RTOL = 4, &
    & LEGACY_ANALYSIS_GRID_PER_DECADE = 5, LEGACY_ANALYSIS_HARMONICS = 6, &
    & LEGACY_ANALYSIS_HARMONIC_TOL = 7, LEGACY_ANALYSIS_IBPA_DEG = 8

contains

  !> The beam_params_type of the array BEAM (whole-number entries rounded).
  pure function beam_from_array(a) result(p)
    real(c_double), intent(in) :: a(LEGACY_NBEAM)
    type(beam_params_type) :: p
    p = beam_params_type(E=real(a(LEGACY_BEAM_E), wp), rho=real(a(LEGACY_BEAM_RHO), wp), &
      & zeta=real(a(LEGACY_BEAM_ZETA), wp), neck_L=real(a(LEGACY_BEAM_NECK_L), wp), &
      & neck_h=real(a(LEGACY_BEAM_NECK_H), wp), neck_b=real(a(LEGACY_BEAM_NECK_B), wp), &
      & platform_L=real(a(LEGACY_BEAM_PLATFORM_L), wp), &
      & platform_m=real(a(LEGACY_BEAM_PLATFORM_M), wp), &
      & platform_J=real(a(LEGACY_BEAM_PLATFORM_J), wp), &
      & airfoil_L=real(a(LEGACY_BEAM_AIRFOIL_L), wp), &
      & airfoil_h=real(a(LEGACY_BEAM_AIRFOIL_H), wp), &
      & airfoil_b=real(a(LEGACY_BEAM_AIRFOIL_B), wp), &
      & neck_elements=nint(a(LEGACY_BEAM_NECK_ELEMENTS)), &
      & airfoil_elements=nint(a(LEGACY_BEAM_AIRFOIL_ELEMENTS)))
  end function beam_from_array

  !> The asymmetric_params_type of the array DAMPER (whole-number entries rounded).
  pure function asymmetric_from_array(a) result(p)
    real(c_double), intent(in) :: a(LEGACY_NDAMPER_ASYMMETRIC)
    type(asymmetric_params_type) :: p
    p = asymmetric_params_type(CF=real(a(LEGACY_ASYMMETRIC_CF), wp), &
      & mu=real(a(LEGACY_ASYMMETRIC_MU), wp), pitch=real(a(LEGACY_ASYMMETRIC_PITCH), wp), &
      & y_P=real(a(LEGACY_ASYMMETRIC_Y_P), wp), &
      & beta_L_deg=real(a(LEGACY_ASYMMETRIC_BETA_L_DEG), wp), &
      & beta_R_deg=real(a(LEGACY_ASYMMETRIC_BETA_R_DEG), wp), &
      & flat=reshape([real(a(LEGACY_ASYMMETRIC_FLAT1_X), wp), &
      & real(a(LEGACY_ASYMMETRIC_FLAT1_Y), wp), real(a(LEGACY_ASYMMETRIC_FLAT2_X), wp), &
      & real(a(LEGACY_ASYMMETRIC_FLAT2_Y), wp)], [2, 2]), &
      & curved=[real(a(LEGACY_ASYMMETRIC_CURVED_X), wp), real(a(LEGACY_ASYMMETRIC_CURVED_Y), wp)], &
      & kn_flat=real(a(LEGACY_ASYMMETRIC_KN_FLAT), wp), &
      & kt_flat=real(a(LEGACY_ASYMMETRIC_KT_FLAT), wp), &
      & kn_curved=real(a(LEGACY_ASYMMETRIC_KN_CURVED), wp), &
      & kt_curved=real(a(LEGACY_ASYMMETRIC_KT_CURVED), wp))
  end function asymmetric_from_array
end module udmap_api_legacy_parameters
