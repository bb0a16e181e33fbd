!> In phase or traveling (PHYSICS.md 2.6): the backbone, the limit force, the response and the
!> response curves of a model, taken by the traveling-wave layers when the analysis has an
!> interblade phase other than 0 and the damper is the asymmetric one (the other kinds act on
!> gamma_P alone: phi does not change them), by the in-phase mapping otherwise. Below the
!> model's face and the admissible force, which both answer at the model's phase through it.
module udmap_mapping_traveling_dispatch
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_damper_type, only: DAMPER_ASYMMETRIC
  use udmap_mapping_model_data, only: model_type, point_type, curve_type, &
    & inphase_limit_force => limit_force
  use udmap_mapping_harmonic_mapping, only: inphase_points => layered, &
    & inphase_cover_forces => cover_forces, inphase_response_curves => response_curves
  use udmap_mapping_traveling_backbone, only: wave_backbone, wave_limit_force, &
    & wave_backbone_curve, wave_cover_forces, wave_response
  use udmap_mapping_traveling_curves, only: wave_curves
  use udmap_mapping_backbone, only: inphase_backbone_curve => backbone_curve
  implicit none
  private
  public :: is_traveling, limit_force, backbone, backbone_curve, cover_forces, response, &
    & response_curves

contains

  !> The model is a traveling wave: an interblade phase other than 0 (mod 360 deg) with the
  !> asymmetric damper, the one kind that feels it.
  pure logical function is_traveling(model)
    type(model_type), intent(in) :: model
    is_traveling = .false.
    if (.not. associated(model%damper)) return
    is_traveling = modulo(model%analysis%ibpa_deg, 360.0_wp) /= 0 .and. &
      & model%damper%kind == DAMPER_ASYMMETRIC
  end function is_traveling

  !> F_lim [N] (PHYSICS.md 5; at phi /= 0, F_lim(phi) of 2.6).
  subroutine limit_force(model, F_lim, error)
    type(model_type), intent(in) :: model
    real(wp), intent(out) :: F_lim
    type(error_type), allocatable, intent(out) :: error
    if (is_traveling(model)) then
      call wave_limit_force(model, F_lim, error)
    else
      call inphase_limit_force(model, F_lim, error)
    end if
  end subroutine limit_force

  !> The peaks of the non-linear response for the forces F_E [N] (PHYSICS.md 4, 4.1, 2.6).
  subroutine backbone(model, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    if (is_traveling(model)) then
      call wave_backbone(model, F_E, points, error)
    else
      call inphase_points(model, .true., 0.0_wp, F_E, points, error)
    end if
  end subroutine backbone

  !> Prepares the force table over [F_min, F_max] [N] (udmap_model_cover_forces), so that a
  !> later backbone call for a force of the range builds nothing.
  subroutine cover_forces(model, F_min, F_max, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_min, F_max
    type(error_type), allocatable, intent(out) :: error
    if (is_traveling(model)) then
      call wave_cover_forces(model, F_min, F_max, error)
    else
      call inphase_cover_forces(model, F_min, F_max, error)
    end if
  end subroutine cover_forces

  !> F_bb(gamma) [N] and the peak frequencies [Hz] (PHYSICS.md 4; at phi /= 0, 2.6).
  subroutine backbone_curve(model, gamma, F_bb, f_res, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: gamma(:)
    real(wp), intent(out) :: F_bb(:), f_res(:)
    type(error_type), allocatable, intent(out) :: error
    if (is_traveling(model)) then
      call wave_backbone_curve(model, gamma, F_bb, f_res, error)
    else
      call inphase_backbone_curve(model, gamma, F_bb, f_res, error)
    end if
  end subroutine backbone_curve
  !> The response at the excitation frequency f_exc [Hz] for the forces F_E [N].
  subroutine response(model, f_exc, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: f_exc
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    if (is_traveling(model)) then
      call wave_response(model, f_exc, F_E, points, error)
    else
      call inphase_points(model, .false., f_exc, F_E, points, error)
    end if
  end subroutine response

  !> The non-linear response curves for the forces F_E [N] (PHYSICS.md 3).
  subroutine response_curves(model, F_E, layers, curves, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    integer, intent(in) :: layers
    type(curve_type), allocatable, intent(out) :: curves(:)
    type(error_type), allocatable, intent(out) :: error
    if (is_traveling(model)) then
      call wave_curves(model, F_E, layers, curves, error)
    else
      call inphase_response_curves(model, F_E, layers, curves, error)
    end if
  end subroutine response_curves
end module udmap_mapping_traveling_dispatch
