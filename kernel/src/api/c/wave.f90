!> C API, the standard method of a traveling wave (wrappers/c/udmap.h, "Traveling waves"): the
!> baseline of the layered traveling-wave peaks (PHYSICS.md 2.6, 6).
module udmap_api_c_wave
  use, intrinsic :: iso_c_binding, only: c_ptr, c_f_pointer, c_int, c_double
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input
  use udmap_api_c_damper, only: damper_from_handle
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type, DAMPER_ASYMMETRIC
  use udmap_baseline_wave, only: wave_hbm_type, wave_hbm_point_type, new_wave_hbm, wave_hbm_peak
  implicit none
  private

contains

  !> Peaks of the traveling wave at the interblade phase ibpa_deg [deg] by the standard method
  !> for n forces F_E [N] with `harmonics` (1: harmonic 1 only, H > 1: 0..H): the continuation
  !> starts at f_start(i) [Hz] (above the peak; inside [f_min, f_max]) and goes down. Outputs per force:
  !> gamma_P [rad], f_res [Hz], sigma_a [Pa], u_E [m] (first harmonics), Newton iterations.
  function udmap_wave_hbm_peaks(ehandle, hblade, hdamper, f_min, f_max, ibpa_deg, harmonics, &
      & n, F_E, f_start, gamma_P, f_res, sigma_a, u_E, iterations) result(stat) &
      & bind(C, name="udmap_wave_hbm_peaks")
    type(c_ptr), value :: ehandle, hblade, hdamper
    real(c_double), value :: f_min, f_max, ibpa_deg
    integer(c_int), value :: harmonics, n
    real(c_double), intent(in) :: F_E(*), f_start(*)
    real(c_double), intent(out) :: gamma_P(*), f_res(*), sigma_a(*), u_E(*)
    integer(c_int), intent(out) :: iterations(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(blade_type), pointer :: blade
    type(damper_type), pointer :: damper
    type(wave_hbm_type) :: s
    type(wave_hbm_point_type) :: pt
    integer :: i
    call clear_error(ehandle)
    call check_handle(hblade, "blade", error)
    if (.not. allocated(error)) call damper_from_handle(hdamper, damper, "damper", error)
    call check_input(n >= 0, "wave_hbm_peaks: n must not be negative", error)
    call check_input(f_min > 0 .and. f_max > f_min, "wave_hbm_peaks: the band must be "// &
      & "0 < f_min < f_max [Hz]", error)
    if (.not. allocated(error)) call check_input(damper%kind == DAMPER_ASYMMETRIC, &
      & "wave_hbm_peaks: only the asymmetric damper depends on the interblade phase", error)
    if (.not. allocated(error)) then
      call c_f_pointer(hblade, blade)
      call new_wave_hbm(s, blade, damper%geometry, damper%params%CF, ibpa_deg*pi/180, &
        & int(harmonics), error)
    end if
    do i = 1, n
      if (allocated(error)) exit
      call check_input(f_start(i) > f_min .and. f_start(i) < f_max, "wave_hbm_peaks: "// &
        & "f_start must lie inside [f_min, f_max]", error)
      if (allocated(error)) exit
      call wave_hbm_peak(s, real(F_E(i), wp), 2*pi*real(f_start(i), wp), 2*pi*real(f_min, wp), &
        & pt, error)
      if (allocated(error)) exit
      gamma_P(i) = abs(pt%P(3, 1))
      f_res(i) = pt%omega/(2*pi)
      sigma_a(i) = abs(pt%sigma_1)
      u_E(i) = abs(pt%u_E1)
      iterations(i) = s%iterations
    end do
    stat = set_error(ehandle, error)
  end function udmap_wave_hbm_peaks
end module udmap_api_c_wave
