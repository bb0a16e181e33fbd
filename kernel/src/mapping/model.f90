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
!> response and response_curves.
module udmap_mapping_model
  use udmap_mapping_model_data, only: analysis_type, point_type, curve_type, model_type, new_model, &
    & set_damper, limit_force, limit_force_backbone, EIGEN_AUTO, EIGEN_DIRECT, EIGEN_MODAL, REGIME_STUCK, REGIME_PARTIAL_SLIP, &
    & REGIME_FULL_SLIP, REGIME_LIMIT, BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
  use udmap_mapping_backbone, only: backbone_curve
  use udmap_mapping_harmonic_mapping, only: backbone, response, response_curves, harmonics_near_modes, &
    & set_harmonics
  use udmap_mapping_admissible, only: admissible_force
  implicit none
  private
  public :: analysis_type, point_type, curve_type, model_type
  public :: limit_force_backbone, admissible_force
  public :: new_model, set_damper, limit_force, backbone_curve, backbone, response, &
    & response_curves, harmonics_near_modes, set_harmonics
  public :: EIGEN_AUTO, EIGEN_DIRECT, EIGEN_MODAL
  public :: REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT
  public :: BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
end module udmap_mapping_model
