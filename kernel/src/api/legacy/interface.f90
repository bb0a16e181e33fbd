!> The plain-array API's declarations: its explicit interfaces (for Fortran 90+ callers of
!> `use udmap`) and the lengths of its arrays. The implementation, on the Fortran API, is the
!> submodule in api/legacy/arrays.f90, so the public module carries the interfaces without
!> depending on it.
module udmap_api_legacy_interface
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  ! the array lengths, generated from kernel/parameters.toml
  use udmap_api_legacy_parameters, only: LEGACY_NBEAM, LEGACY_NDAMPER_ASYMMETRIC, &
    & LEGACY_NDAMPER_JENKINS, LEGACY_NANALYSIS_MIN, LEGACY_NANALYSIS_MAX
  implicit none
  private
  public :: udmap_version_numbers, udmap_table_arrays, udmap_backbone_arrays, &
    & udmap_response_arrays, udmap_curve_arrays
  public :: LEGACY_NBEAM, LEGACY_NDAMPER_ASYMMETRIC, LEGACY_NDAMPER_JENKINS, &
    & LEGACY_NANALYSIS_MIN, LEGACY_NANALYSIS_MAX, LEGACY_REGIME_UNBOUNDED

  !> REGIME value of a point without a finite response (zeta = 0 and F_E >= F_lim).
  integer, parameter :: LEGACY_REGIME_UNBOUNDED = 4

  interface
    !> UDMAP_VERSION_NUMBERS: documented at its implementation (api/legacy/arrays.f90).
    module subroutine udmap_version_numbers(major, minor, patch) &
        & bind(C, name="udmap_version_numbers_")
      integer(c_int), intent(out) :: major, minor, patch
    end subroutine udmap_version_numbers

    !> UDMAP_TABLE_ARRAYS: documented at its implementation (api/legacy/arrays.f90).
    module subroutine udmap_table_arrays(damper, ndamper, ngamma, gamma, k_re, k_im, base, info) &
        & bind(C, name="udmap_table_arrays_")
      integer(c_int), intent(in) :: ndamper, ngamma
      real(c_double), intent(in) :: damper(ndamper), gamma(ngamma)
      real(c_double), intent(out) :: k_re(ngamma), k_im(ngamma), base(6)
      integer(c_int), intent(out) :: info
    end subroutine udmap_table_arrays

    !> UDMAP_BACKBONE_ARRAYS: documented at its implementation (api/legacy/arrays.f90).
    module subroutine udmap_backbone_arrays(beam, nbeam, damper, ndamper, analysis, nanalysis, &
        & nforce, F_E, gamma_P, f_res, sigma_a, u_E, regime, F_lim, info) &
        & bind(C, name="udmap_backbone_arrays_")
      integer(c_int), intent(in) :: nbeam, ndamper, nanalysis, nforce
      real(c_double), intent(in) :: beam(nbeam), damper(ndamper), analysis(nanalysis), &
        & F_E(nforce)
      real(c_double), intent(out) :: gamma_P(nforce), f_res(nforce), sigma_a(nforce), &
        & u_E(nforce), F_lim
      integer(c_int), intent(out) :: regime(nforce), info
    end subroutine udmap_backbone_arrays

    !> UDMAP_RESPONSE_ARRAYS: documented at its implementation (api/legacy/arrays.f90).
    module subroutine udmap_response_arrays(beam, nbeam, damper, ndamper, analysis, nanalysis, &
        & f_exc, nforce, F_E, gamma_P, sigma_a, u_E, regime, F_lim, info) &
        & bind(C, name="udmap_response_arrays_")
      integer(c_int), intent(in) :: nbeam, ndamper, nanalysis, nforce
      real(c_double), intent(in) :: beam(nbeam), damper(ndamper), analysis(nanalysis), f_exc, &
        & F_E(nforce)
      real(c_double), intent(out) :: gamma_P(nforce), sigma_a(nforce), u_E(nforce), F_lim
      integer(c_int), intent(out) :: regime(nforce), info
    end subroutine udmap_response_arrays

    !> UDMAP_CURVE_ARRAYS: documented at its implementation (api/legacy/arrays.f90).
    module subroutine udmap_curve_arrays(beam, nbeam, damper, ndamper, analysis, nanalysis, F_E, &
        & layers, maxpts, npts, f, gamma_P, sigma_a, branch, info) &
        & bind(C, name="udmap_curve_arrays_")
      integer(c_int), intent(in) :: nbeam, ndamper, nanalysis, layers, maxpts
      real(c_double), intent(in) :: beam(nbeam), damper(ndamper), analysis(nanalysis), F_E
      integer(c_int), intent(out) :: npts, branch(maxpts), info
      real(c_double), intent(out) :: f(maxpts), gamma_P(maxpts), sigma_a(maxpts)
    end subroutine udmap_curve_arrays
  end interface
end module udmap_api_legacy_interface
