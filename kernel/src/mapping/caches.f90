!> The caches a model keeps for the single-harmonic mapping (data only; the algorithms that fill
!> and read them sit above): the band interpolant of the receptances
!> (udmap_mapping_band_receptances), the bare blade as the mapping sees it and a layer's peak
!> (udmap_mapping_layer), and the secular
!> equation of the eigenvalue start (udmap_mapping_eigen_start).
module udmap_mapping_caches
  use udmap_core_kinds, only: wp
  use udmap_blade_type, only: blade_type, receptances_type
  implicit none
  private
  public :: band_receptances_type, PEAK_OK, PEAK_BELOW_BAND, PEAK_ABOVE_BAND, bare_type, &
    & layer_peak_type, secular_type

  !> The band interpolant (active only when it passed its check).
  type :: band_receptances_type
    logical :: active = .false.
    !> Band [rad/s], sample step [rad/s], beta of C = beta K.
    real(wp) :: omega_lo = 0, omega_hi = 0, h = 0, beta = 0
    !> Number of samples.
    integer :: n = 0
    !> Modes summed exactly: omega_r^2, phi_g, phi_E, s_K.phi, s_M.phi.
    real(wp), allocatable :: w2(:), pg(:), pE(:), psK(:), psM(:)
    !> Remainders of gE, gg, EE, sE, sg at the samples and their d/d omega, (5, n).
    complex(wp), allocatable :: rem(:, :), drem(:, :)
  end type band_receptances_type

  !> Peak found inside the band.
  integer, parameter :: PEAK_OK = 0

  !> |g~| still grows at the lower band edge: the resonance lies below the band.
  integer, parameter :: PEAK_BELOW_BAND = 1

  !> |g~| still grows at the upper band edge: the resonance lies above the band.
  integer, parameter :: PEAK_ABOVE_BAND = 2

  !> The bare blade as seen by the mapping: the blade it borrows, the fast interpolant of its
  !> receptances over the band (udmap_mapping_band_receptances, when active) and a count of
  !> receptance evaluations (the unit of cost of everything here).
  type :: bare_type
    type(blade_type), pointer :: blade => null()
    type(band_receptances_type) :: band
    integer :: evaluations = 0
  end type bare_type

  !> The peak of one layer's unit-force response |g~(omega)|.
  type :: layer_peak_type
    !> Circular frequency of the peak [rad/s] and |g~| there [rad/N].
    real(wp) :: omega = 0, amplitude = 0
    !> Bare receptances at the peak.
    type(receptances_type) :: r
    !> PEAK_OK, or PEAK_BELOW_BAND / PEAK_ABOVE_BAND when the maximum is at a band edge.
    integer :: status = PEAK_OK
    !> d psi / ds at the peak as last measured (psi = dP/ds, P = 1/|g~|^2, s = omega^2), the
    !> slope hint for a neighbouring layer (0 if unknown).
    real(wp) :: dpsi = 0
  end type layer_peak_type

  !> The rank-one secular equation of the gamma DOF over the bare modes.
  type :: secular_type
    !> omega_r^2 [rad^2/s^2] and phi_g,r^2 of the kept bare modes (mass-normalised).
    real(wp), allocatable :: s(:), w(:)
    !> Static residual of the modes left out: (K^-1)_gg - sum_r phi_g,r^2/omega_r^2.
    real(wp) :: R0 = 0
    !> Higher residuals: sums of phi_g,r^2/omega_r^4 and phi_g,r^2/omega_r^6 over the
    !> computed modes left out.
    real(wp) :: R1 = 0, R2 = 0
  end type secular_type
end module udmap_mapping_caches
