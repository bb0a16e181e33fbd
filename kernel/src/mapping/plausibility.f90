!> Plausibility checks (docs/case-files.md, "Plausibility"), apart from the range checks: a blade,
!> damper and band inside every range can still be physically implausible, most often because a
!> value was typed in another unit. Each check gives a warning of a fixed kind whose text names
!> the quantity, says why it looks wrong and suggests the likely unit error; nothing is refused
!> and nothing computed changes, but for the one backbone point the stuck peak needs (as
!> udmap_model_backbone_curve would compute it). Every interface (command line, JSON, C API,
!> FMU log, DOE summary) takes these texts and kinds from here.
!>
!> The checks:
!> - the platform heavier than the rest of the beam blade (neck and airfoil): grams for kg;
!> - the platform's rotary inertia over plausibility_inertia_factor times m L^2/12 of a rigid bar
!>   of its mass and length: kg mm^2 for kg m^2;
!> - the asymmetric damper's gamma_b above plausibility_gamma_b_max: contact stiffnesses in N/mm;
!> - with a model, the stuck damper shifting the first frequency by less than 0.1 % or more than
!>   100 % (the asymmetric damper);
!> - the band missing the bare first mode, or (with a model) the stuck first mode.
module udmap_mapping_plausibility
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_core_strings, only: gtoa
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type, DAMPER_ASYMMETRIC
  use udmap_mapping_model, only: model_type, backbone_curve
  implicit none
  private
  public :: warning_type, plausibility_warnings, model_warnings
  public :: WARNING_PLATFORM_MASS, WARNING_PLATFORM_INERTIA, WARNING_GAMMA_B_LARGE, &
    & WARNING_STUCK_SHIFT, WARNING_BAND_MISSES_MODE
  public :: plausibility_gamma_b_max, plausibility_shift_min, plausibility_shift_max, &
    & plausibility_inertia_factor

  !> The kinds of warning (UDMAP_WARNING_* of udmap.h): one per check.
  integer, parameter :: WARNING_PLATFORM_MASS = 1, WARNING_PLATFORM_INERTIA = 2, &
    & WARNING_GAMMA_B_LARGE = 3, WARNING_STUCK_SHIFT = 4, WARNING_BAND_MISSES_MODE = 5

  !> Largest plausible gamma_b [rad]: the contacts of a real damper slip long before they
  !> deflect by degrees.
  real(wp), parameter :: plausibility_gamma_b_max = 1e-2_wp
  !> Plausible relative shift of the first frequency by the stuck damper.
  real(wp), parameter :: plausibility_shift_min = 1e-3_wp, plausibility_shift_max = 1.0_wp
  !> Rotary inertia above this times m L^2/12 of the platform looks like kg mm^2.
  real(wp), parameter :: plausibility_inertia_factor = 1e3_wp
  !> The stuck peak is taken at this fraction of gamma_s (or gamma_b without a stuck range).
  real(wp), parameter :: stuck_fraction = 1e-3_wp

  !> One warning: its kind (WARNING_*) and its text.
  type :: warning_type
    integer :: kind = 0
    character(len=:), allocatable :: text
  end type warning_type

contains

  !> The warnings of a blade, a damper (optional: without it the damper's check is left out)
  !> and the band [f_min, f_max] [Hz], without a model: the checks that need the stuck peak are
  !> left out (the band is checked against the bare first mode alone).
  subroutine plausibility_warnings(blade, f_min, f_max, warnings, damper)
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: f_min, f_max
    type(warning_type), allocatable, intent(out) :: warnings(:)
    type(damper_type), intent(in), optional :: damper
    real(wp) :: f1
    allocate(warnings(0))
    call platform_checks(blade, warnings)
    if (present(damper)) call damper_checks(damper, warnings)
    f1 = first_frequency(blade)
    if (.not. (f_min <= f1 .and. f1 <= f_max)) call push(warnings, WARNING_BAND_MISSES_MODE, &
      & band_text(f_min, f_max, "bare first mode at "//gtoa(f1, 4)//" Hz"))
  end subroutine plausibility_warnings

  !> The warnings of a model: its blade, damper and band, and the stuck peak, a backbone point
  !> at stuck_fraction gamma_s (gamma_b without a stuck range) computed on the model as
  !> backbone_curve does (the one thing this changes: that point is in the model's backbone
  !> table afterwards, as after udmap_model_backbone_curve).
  subroutine model_warnings(model, warnings)
    type(model_type), intent(inout) :: model
    type(warning_type), allocatable, intent(out) :: warnings(:)
    type(error_type), allocatable :: error
    real(wp) :: f1, g_small, shift, F_bb(1), f_res(1)
    logical :: in_band, stuck
    character(len=:), allocatable :: found
    allocate(warnings(0))
    call platform_checks(model%blade, warnings)
    call damper_checks(model%damper, warnings)
    f1 = first_frequency(model%blade)
    in_band = model%analysis%f_min <= f1 .and. f1 <= model%analysis%f_max
    g_small = model%damper%gamma_s
    if (.not. g_small > 0) g_small = model%damper%gamma_b
    g_small = stuck_fraction*g_small
    stuck = .false.
    if (g_small > 0) then
      call backbone_curve(model, [g_small], F_bb, f_res, error)
      stuck = .not. allocated(error)  ! an error: no stuck peak inside the band
    end if
    if (.not. in_band .or. .not. stuck) then
      found = "bare first mode at "//gtoa(f1, 4)//" Hz"
      if (stuck) then
        found = found//", stuck at "//gtoa(f_res(1), 4)//" Hz"
      else
        found = found//", no stuck peak inside the band"
      end if
      call push(warnings, WARNING_BAND_MISSES_MODE, &
        & band_text(model%analysis%f_min, model%analysis%f_max, found))
    else if (model%damper%kind == DAMPER_ASYMMETRIC) then
      shift = f_res(1)/f1 - 1
      if (.not. (plausibility_shift_min <= shift .and. shift <= plausibility_shift_max)) &
        & call push(warnings, WARNING_STUCK_SHIFT, "the stuck damper shifts the first " &
        & //"frequency by "//gtoa(100*shift, 3)//" % ("//gtoa(f1, 4)//" Hz bare, " &
        & //gtoa(f_res(1), 4)//" Hz stuck), outside "//gtoa(100*plausibility_shift_min, 6) &
        & //" % to "//gtoa(100*plausibility_shift_max, 6)//" %: are the contact " &
        & //"stiffnesses or the blade in another unit?")
    end if
  end subroutine model_warnings

  !> The beam's platform against its neck and airfoil (nothing for an imported blade).
  subroutine platform_checks(blade, warnings)
    type(blade_type), intent(in) :: blade
    type(warning_type), allocatable, intent(inout) :: warnings(:)
    real(wp) :: rest, m, J, L
    if (.not. allocated(blade%beam)) return
    associate(p => blade%beam)
      rest = p%rho*(p%neck_b*p%neck_h*p%neck_L + p%airfoil_b*p%airfoil_h*p%airfoil_L)
      m = p%platform_m
      J = p%platform_J
      L = p%platform_L
    end associate
    if (m > rest) call push(warnings, WARNING_PLATFORM_MASS, "blade.platform.m = " &
      & //gtoa(m, 4)//" kg is heavier than the rest of the blade ("//gtoa(rest, 4) &
      & //" kg of neck and airfoil): was it given in grams? ("//gtoa(m, 4)//" g would be " &
      & //gtoa(m/1000, 4)//" kg)")
    if (J > plausibility_inertia_factor*m*L**2/12) call push(warnings, &
      & WARNING_PLATFORM_INERTIA, "blade.platform.J = "//gtoa(J, 4)//" kg m^2 is over " &
      & //gtoa(plausibility_inertia_factor, 6)//" times that of a rigid bar of the " &
      & //"platform's mass and length ("//gtoa(m*L**2/12, 4)//" kg m^2): was it given in " &
      & //"kg mm^2? (1 kg mm^2 = 1e-6 kg m^2)")
  end subroutine platform_checks

  !> The asymmetric damper's gamma_b (its contact stiffnesses as they are now).
  subroutine damper_checks(damper, warnings)
    type(damper_type), intent(in) :: damper
    type(warning_type), allocatable, intent(inout) :: warnings(:)
    if (damper%kind /= DAMPER_ASYMMETRIC) return
    if (damper%gamma_b > plausibility_gamma_b_max) call push(warnings, &
      & WARNING_GAMMA_B_LARGE, "the base-cycle amplitude gamma_b = "//gtoa(damper%gamma_b, 4) &
      & //" rad is above "//gtoa(plausibility_gamma_b_max, 6)//" rad (the contacts deflect " &
      & //"by degrees before they slip): were the contact stiffnesses given in N/mm? " &
      & //"(kn_flat = "//gtoa(damper%params%kn_flat, 4)//" N/m; 1 N/mm = 1e3 N/m)")
  end subroutine damper_checks

  !> The band's warning with what was found.
  function band_text(f_min, f_max, found) result(text)
    real(wp), intent(in) :: f_min, f_max
    character(len=*), intent(in) :: found
    character(len=:), allocatable :: text
    text = "the band [analysis.f_min, analysis.f_max] = ["//gtoa(f_min, 4)//", " &
      & //gtoa(f_max, 4)//"] Hz misses the first mode ("//found//"): are the band or the " &
      & //"blade in other units (Hz for rad/s, mm-t-s for SI)?"
  end function band_text

  !> The bare first natural frequency [Hz].
  function first_frequency(blade) result(f1)
    type(blade_type), intent(in) :: blade
    real(wp) :: f1, f(1)
    type(error_type), allocatable :: error
    call blade%natural_frequencies(f, error)  ! a built blade keeps one mode at least
    f1 = f(1)
  end function first_frequency

  !> Appends a warning.
  subroutine push(warnings, kind, text)
    type(warning_type), allocatable, intent(inout) :: warnings(:)
    integer, intent(in) :: kind
    character(len=*), intent(in) :: text
    type(warning_type), allocatable :: grown(:)
    integer :: i
    allocate(grown(size(warnings) + 1))
    do i = 1, size(warnings)
      call move_alloc(warnings(i)%text, grown(i)%text)
      grown(i)%kind = warnings(i)%kind
    end do
    grown(size(grown))%kind = kind
    grown(size(grown))%text = text
    call move_alloc(grown, warnings)
  end subroutine push
end module udmap_mapping_plausibility
