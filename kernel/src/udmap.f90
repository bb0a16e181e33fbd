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
  use udmap_core_error, only: error_type, fatal_error, UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_core_version, only: udmap_version_string, udmap_version_major, &
    & udmap_version_minor, udmap_version_patch
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade, new_matrices_blade
  use udmap_blade_io_matrices, only: read_matrices_blade, export_blade
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper, &
    & new_jenkins_damper, new_table_damper
  use udmap_mapping_model, only: analysis_type, point_type, curve_type, model_type, new_model, &
    & limit_force, backbone_curve, backbone, response, response_curves, set_harmonics, &
    & admissible_force, REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT, &
    & BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
  use udmap_api_legacy_arrays, only: udmap_version_numbers, udmap_table_arrays, &
    & udmap_backbone_arrays, udmap_response_arrays, udmap_curve_arrays
  implicit none
  private

  public :: udmap_version, udmap_version_major, udmap_version_minor, udmap_version_patch
  public :: wp, error_type, UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  ! blade (PHYSICS.md 1)
  public :: beam_params_type, blade_type, new_beam_blade, new_matrices_blade, &
    & read_matrices_blade, export_blade
  ! damper (PHYSICS.md 2)
  public :: asymmetric_params_type, damper_type, new_asymmetric_damper, new_jenkins_damper, &
    & new_table_damper, stiffness_table
  ! mapping (PHYSICS.md 3-5)
  public :: analysis_type, point_type, curve_type, model_type, new_model, limit_force, &
    & backbone_curve, backbone, response, response_curves, set_harmonics, admissible_force
  public :: REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT
  public :: BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING
  ! plain arrays (kernel/src/api_legacy.f90)
  public :: udmap_version_numbers, udmap_table_arrays, udmap_backbone_arrays, &
    & udmap_response_arrays, udmap_curve_arrays

contains

  !> The library version as "major.minor.patch" (the version of the linked library, which
  !> may differ from the .mod files a program was compiled against if it was swapped later).
  pure function udmap_version() result(version)
    character(len=:), allocatable :: version
    version = udmap_version_string
  end function udmap_version

  !> The damper's complex stiffness k(gamma) = k_Re + i k_Im [N m/rad] (PHYSICS.md 2.2) at the
  !> amplitudes gamma [rad]: the table of the damper, with the amplitudes checked (positive,
  !> finite, within the range of a measured table without extrapolation).
  subroutine stiffness_table(damper, gamma, k, error)
    type(damper_type), intent(in) :: damper
    real(wp), intent(in) :: gamma(:)
    complex(wp), intent(out) :: k(:)
    type(error_type), allocatable, intent(out) :: error
    character(len=24) :: buf
    integer :: i
    k = 0
    if (damper%kind == 0) then
      call fatal_error(error, "stiffness_table: the damper has not been created", UDMAP_EINPUT)
      return
    end if
    if (size(k) /= size(gamma)) then
      call fatal_error(error, "stiffness_table: k must have the size of gamma", UDMAP_EINPUT)
      return
    end if
    do i = 1, size(gamma)
      if (.not.(gamma(i) > 0 .and. gamma(i) <= damper%gamma_max)) then
        write(buf, '(es24.16)') gamma(i)
        if (gamma(i) > damper%gamma_max .and. gamma(i) <= huge(1.0_wp)) then
          call fatal_error(error, "stiffness_table: gamma = "//trim(adjustl(buf))//" rad lies "// &
            & "beyond the last row of the measured table (give delta_M to extrapolate)", &
            & UDMAP_EINPUT)
        else
          call fatal_error(error, "stiffness_table: gamma must be a positive finite amplitude "// &
            & "[rad], got "//trim(adjustl(buf)), UDMAP_EINPUT)
        end if
        return
      end if
    end do
    k = damper%stiffness(gamma)
  end subroutine stiffness_table
end module udmap
