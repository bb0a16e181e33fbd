!> The public Fortran interface of udmap in one module. `use udmap` gives everything a program
!> needs; the udmap_* modules behind it are the implementation and may change.
!>
!>   type(blade_type), target :: blade        ! the model borrows blade and damper
!>   type(damper_type), target :: damper
!>   type(model_type) :: model
!>   call new_beam_blade(blade, beam_params, error)            ! or read_matrices_blade
!>   call new_asymmetric_damper(damper, damper_params, error)  ! or jenkins, table
!>   call stiffness_table(damper, gamma, k, error)             ! k(gamma) [N m/rad]
!>   call new_model(model, blade, damper, analysis, error)     ! analysis%f_min, f_max [Hz]
!>   call limit_force(model, F_lim, error)
!>   call backbone(model, F_E, points, error)                  ! peaks, point_type(:)
!>   call response(model, f_exc, F_E, points, error)           ! at a given frequency
!>   call response_curves(model, F_E, layers, curves, error)   ! curve_type(:)
!>   call set_harmonics(model, 0, 1e-3_wp, error)              ! multi-harmonic layers, auto H
!>   call model_warnings(model, warnings)                      ! plausibility: kind, text
!>
!> analysis%harmonics (or set_harmonics): 1 the single-harmonic method, H > 1 harmonics 0..H,
!> 0 automatic (PHYSICS.md 4.1); points then carry gamma_max, sigma_max, harmonics, gamma_h(0:H)
!> and sigma_h(0:H).
!>
!> Every procedure reports failure through `type(error_type), allocatable :: error`: allocated
!> on failure, with error%stat (UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC) and a message
!> naming the parameter. The plain-array procedures (udmap_backbone_arrays, ...) are here too,
!> with explicit interfaces, for programs that mix both styles.
module udmap
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_core_version, only: udmap_version, udmap_version_major, udmap_version_minor, &
    & udmap_version_patch
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade, new_matrices_blade
  use udmap_blade_io_matrices, only: read_matrices_blade, export_blade
  use udmap_blade_platform, only: set_platform_translations, platform_translations_known
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper, &
    & new_jenkins_damper, new_table_damper, stiffness_table
  use udmap_mapping_model, only: analysis_type, point_type, curve_type, model_type, new_model, &
    & limit_force, backbone_curve, backbone, response, response_curves, set_harmonics, &
    & set_ibpa, admissible_force, REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT, &
    & BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
  use udmap_mapping_plausibility, only: warning_type, plausibility_warnings, model_warnings, &
    & WARNING_PLATFORM_MASS, WARNING_PLATFORM_INERTIA, WARNING_GAMMA_B_LARGE, &
    & WARNING_STUCK_SHIFT, WARNING_BAND_MISSES_MODE
  use udmap_api_legacy_interface, only: udmap_version_numbers, udmap_table_arrays, &
    & udmap_backbone_arrays, udmap_response_arrays, udmap_curve_arrays
  implicit none
  private

  public :: udmap_version, udmap_version_major, udmap_version_minor, udmap_version_patch
  public :: wp, error_type, UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  ! blade (PHYSICS.md 1)
  public :: beam_params_type, blade_type, new_beam_blade, new_matrices_blade, &
    & read_matrices_blade, export_blade, set_platform_translations, platform_translations_known
  ! damper (PHYSICS.md 2)
  public :: asymmetric_params_type, damper_type, new_asymmetric_damper, new_jenkins_damper, &
    & new_table_damper, stiffness_table
  ! mapping (PHYSICS.md 3-5)
  public :: analysis_type, point_type, curve_type, model_type, new_model, limit_force, &
    & backbone_curve, backbone, response, response_curves, set_harmonics, set_ibpa, &
    & admissible_force
  public :: REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT
  public :: BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
  ! plausibility warnings (docs/case-files.md, "Plausibility")
  public :: warning_type, plausibility_warnings, model_warnings, WARNING_PLATFORM_MASS, &
    & WARNING_PLATFORM_INERTIA, WARNING_GAMMA_B_LARGE, WARNING_STUCK_SHIFT, &
    & WARNING_BAND_MISSES_MODE
  ! plain arrays (kernel/src/api/legacy/arrays.f90, explicit interfaces only)
  public :: udmap_version_numbers, udmap_table_arrays, udmap_backbone_arrays, &
    & udmap_response_arrays, udmap_curve_arrays
end module udmap
