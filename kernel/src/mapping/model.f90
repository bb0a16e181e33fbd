!> The mapping, in one place: a blade and a damper coupled over a band (model_type), the limit
!> force (PHYSICS.md 5), the backbone and the peaks of the non-linear response (PHYSICS.md 4),
!> the response at a given frequency, and the response curves by amplitude layered force
!> mapping (PHYSICS.md 3).
!>
!>   call new_model(model, blade, damper, analysis, error)
!>   call set_damper(model, other_damper, error)          ! after a change of damper parameters
!>   call limit_force(model, F_lim, error)
!>   call backbone_curve(model, gamma, F_bb, f_res, error)
!>   call backbone(model, F_E, points, error)
!>   call response(model, f_exc, F_E, points, error)
!>   call response_curves(model, F_E, layers, curves, error)
!>   call admissible_force(model, F_lim, sigma_all, rtol, F_adm, error)  ! a design's F_adm
!>
!> analysis%harmonics = 1 (default) is the paper's single-harmonic method; H > 1 or 0 (auto)
!> takes the multi-harmonic layers of PHYSICS.md 4.1 (udmap_mapping_harmonic_mapping) in backbone,
!> response and response_curves. analysis%ibpa_deg /= 0 with the asymmetric damper is a traveling
!> wave (PHYSICS.md 2.6, udmap_mapping_traveling_*): backbone and limit_force take it; the other
!> damper kinds act on gamma_P alone, so phi does not change them (the in-phase answer).
module udmap_mapping_model
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, require, UDMAP_EINPUT
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type
  use udmap_mapping_eigen_start, only: new_secular
  use udmap_mapping_band_receptances, only: new_band_receptances
  use udmap_mapping_model_data, only: analysis_type, point_type, curve_type, model_type, &
    & check_model_damper, set_damper, limit_force_backbone, EIGEN_AUTO, &
    & EIGEN_DIRECT, EIGEN_MODAL, REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, &
    & REGIME_LIMIT, BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
  use udmap_mapping_harmonic_mapping, only: harmonics_near_modes, set_harmonics, check_harmonics
  use udmap_mapping_admissible, only: admissible_force
  use udmap_mapping_traveling_dispatch, only: is_traveling, limit_force, backbone, &
    & backbone_curve, cover_forces, response, response_curves
  implicit none
  private
  public :: analysis_type, point_type, curve_type, model_type
  public :: limit_force_backbone, admissible_force, is_traveling, cover_forces
  public :: new_model, set_damper, limit_force, backbone_curve, backbone, response, &
    & response_curves, harmonics_near_modes, set_harmonics, set_ibpa
  public :: EIGEN_AUTO, EIGEN_DIRECT, EIGEN_MODAL
  public :: REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT
  public :: BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING

contains

  !> Couples blade and damper over analysis%f_min..f_max. Both are borrowed.
  subroutine new_model(model, blade, damper, analysis, error)
    type(model_type), intent(out) :: model
    type(blade_type), target, intent(in) :: blade
    type(damper_type), target, intent(in) :: damper
    type(analysis_type), intent(in) :: analysis
    type(error_type), allocatable, intent(out) :: error
    !> Relative distance of a frequency that repeats mode 1's (its eigenspace).
    real(wp), parameter :: repeat_tol = 1e-6_wp
    real(wp) :: phi_g, phi_E
    integer :: r, nrep
    character(len=32) :: buf
    associate(a => analysis)
      call require(a%f_min > 0 .and. a%f_min < huge(1.0_wp), &
        & "analysis.f_min must be a positive number [Hz]", error)
      call require(a%f_max > a%f_min .and. a%f_max < huge(1.0_wp), &
        & "analysis.f_max must be a number above f_min [Hz]", error)
      call require(a%sigma_all > 0 .and. a%sigma_all < huge(1.0_wp), &
        & "analysis.sigma_all must be a positive number [Pa]", error)
      call require(a%rtol >= 1e-15_wp .and. a%rtol <= 1e-3_wp, &
        & "analysis.rtol must lie in [1e-15, 1e-3]", error)
      call require(a%grid_per_decade >= 2 .and. a%grid_per_decade <= 1000, &
        & "analysis.grid_per_decade must lie in [2, 1000]", error)
      call require(a%eigen_method >= EIGEN_AUTO .and. a%eigen_method <= EIGEN_MODAL, &
        & "analysis.eigen_method must be 0 (auto), 1 (direct) or 2 (modal)", error)
      call require(a%dense_max >= 1, "analysis.dense_max must be positive", error)
      call require(a%sweep_points >= 16 .and. a%sweep_points <= 1000000, &
        & "analysis.sweep_points must lie in [16, 1e6]", error)
      call check_harmonics(a%harmonics, a%harmonic_tol, error)
    end associate
    if (allocated(error)) return
    if (blade%ndof < 1 .or. .not.allocated(blade%phi) .or. .not.allocated(blade%omega)) then
      call fatal_error(error, "model: the blade is not built (no DOFs or no bare modes)", &
        & UDMAP_EINPUT)
      return
    end if
    call check_model_damper(damper, error)
    if (allocated(error)) return
    model%blade => blade
    model%damper => damper
    model%analysis = analysis
    model%bare%blade => blade
    model%omega_lo = 2*pi*analysis%f_min
    model%omega_hi = 2*pi*analysis%f_max
    ! Mode 1 and the modes that repeat its frequency (a symmetric section's pair: its eigenspace,
    ! in whichever basis the eigen-solver gave): the one vector of that eigenspace that moves
    ! gamma_P, P P^T e_g normalised, with phi_g = sqrt(sum phi_g,r^2) and
    ! phi_E = sum phi_E,r phi_g,r / phi_g; the rest of the eigenspace leaves gamma_P at rest.
    nrep = 1
    do r = 2, size(blade%omega)
      if (blade%omega(r) > (1 + repeat_tol)*blade%omega(1)) exit
      nrep = r
    end do
    phi_g = blade%phi(blade%gamma_dof, 1)
    phi_E = blade%phi(blade%exc_dof, 1)
    if (nrep > 1) then
      phi_g = norm2(blade%phi(blade%gamma_dof, 1:nrep))
      if (phi_g > 0) phi_E = dot_product(blade%phi(blade%exc_dof, 1:nrep), &
        & blade%phi(blade%gamma_dof, 1:nrep))/phi_g
    end if
    if (phi_g == 0) then
      call fatal_error(error, "model: the bare first mode does not rotate the platform "// &
        & "(phi_g = 0), the damper cannot act on it", UDMAP_EINPUT)
      return
    end if
    model%phi_ratio = abs(phi_E/phi_g)
    ! the backbone follows the resonance of mode 1: a second bare mode inside the band would
    ! make "the maximum over the band" jump between resonances (a repeat of mode 1 is no second
    ! resonance)
    do r = nrep + 1, size(blade%omega)
      if (blade%omega(r) >= model%omega_lo .and. blade%omega(r) <= model%omega_hi) then
        write(buf, '(g0.6)') blade%omega(r)/(2*pi)
        call fatal_error(error, "analysis: the band [f_min, f_max] contains the bare mode "// &
          & "at "//trim(buf)//" Hz besides mode 1; the mapping follows the first-mode "// &
          & "resonance: narrow the band", UDMAP_EINPUT)
        return
      end if
    end do
    if (blade%explicit_C .and. allocated(blade%C)) then
      model%c1 = dot_product(blade%phi(:, 1), matmul(blade%C, blade%phi(:, 1)))
      model%undamped = all(blade%C == 0)
    else if (blade%explicit_C) then
      ! band storage only: the width estimate does without the viscous part
      model%c1 = 0
      model%undamped = .false.
      if (allocated(blade%Cb)) model%undamped = all(blade%Cb == 0)
    else
      model%c1 = blade%beta*blade%omega1**2
      model%undamped = .not.blade%explicit_C .and. blade%zeta == 0
    end if
    call new_secular(model%secular, blade, error)
    if (allocated(error)) return
    if (analysis%band_interpolation) &
      & call new_band_receptances(model%bare%band, blade, model%omega_lo, model%omega_hi)
  end subroutine new_model

  !> The interblade phase angle [deg] of the next calls (analysis%ibpa_deg: 0 in phase, else a
  !> traveling wave, PHYSICS.md 2.6), keeping every cache of the model: a sweep over engine
  !> orders builds the bare blade and the in-phase backbone table once.
  subroutine set_ibpa(model, ibpa_deg, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: ibpa_deg
    type(error_type), allocatable, intent(out) :: error
    call require(abs(ibpa_deg) < huge(1.0_wp), &
      & "analysis.ibpa_deg must be a finite angle [deg]", error)
    if (allocated(error)) return
    model%analysis%ibpa_deg = ibpa_deg
  end subroutine set_ibpa

end module udmap_mapping_model
