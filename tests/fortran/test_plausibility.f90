!> The plausibility checks (udmap_mapping_plausibility) and the number text they write
!> (udmap_core_strings' gtoa): gtoa against Python's format(x, '.Ng') (the strings below are
!> Python's, ties included), blade A without a warning, and blade A with a unit mistake giving
!> the warning's kind and exact text (the texts docs/case-files.md and the Python tests quote).
module test_plausibility
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_core_strings, only: gtoa
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_damper_params, only: asymmetric_params_type, blade_a_damper_params
  use udmap_mapping_model, only: analysis_type, model_type, new_model
  use udmap_mapping_plausibility, only: warning_type, plausibility_warnings, model_warnings, &
    & WARNING_PLATFORM_MASS, WARNING_PLATFORM_INERTIA, WARNING_GAMMA_B_LARGE, &
    & WARNING_STUCK_SHIFT, WARNING_BAND_MISSES_MODE
  use fixtures, only: scene_type, blade_a_beam_params, blade_a_with_damper, blade_a_model
  use testing, only: test_suite, check_true, check_no_error, unittest_type, new_unittest
  implicit none
  private
  public :: collect_plausibility

contains

  subroutine collect_plausibility(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("gtoa_as_python", run_gtoa), &
      & new_unittest("blade_a_none", run_blade_a_none), &
      & new_unittest("unit_mistakes", run_unit_mistakes)]
  end subroutine collect_plausibility

  !> gtoa(x, 4), gtoa(x, 3) and gtoa(x, 6) as Python writes them.
  subroutine run_gtoa(suite)
    type(test_suite), intent(inout) :: suite
    call same(21.0_wp, "21", "21", "21")
    call same(0.14432_wp, "0.1443", "0.144", "0.14432")
    call same(2.1e-5_wp, "2.1e-05", "2.1e-05", "2.1e-05")
    call same(1e3_wp, "1000", "1e+03", "1000")
    call same(187.1234_wp, "187.1", "187", "187.123")
    call same(12345.0_wp, "1.234e+04", "1.23e+04", "12345")
    call same(0.00012345_wp, "0.0001234", "0.000123", "0.00012345")
    call same(9.99951_wp, "10", "10", "9.99951")
    call same(9.99949_wp, "9.999", "10", "9.99949")
    call same(-0.5_wp, "-0.5", "-0.5", "-0.5")
    call same(1e-300_wp, "1e-300", "1e-300", "1e-300")
    call same(123456789.0_wp, "1.235e+08", "1.23e+08", "1.23457e+08")
    call same(0.0001_wp, "0.0001", "0.0001", "0.0001")
    call same(9.999e-5_wp, "9.999e-05", "0.0001", "9.999e-05")
    call same(6e7_wp, "6e+07", "6e+07", "6e+07")
    call same(-3.14159e-7_wp, "-3.142e-07", "-3.14e-07", "-3.14159e-07")
    call same(0.0_wp, "0", "0", "0")
  contains
    subroutine same(x, g4, g3, g6)
      real(wp), intent(in) :: x
      character(len=*), intent(in) :: g4, g3, g6
      call check_true(suite, "gtoa("//g6//", 4) = "//g4//" (got "//gtoa(x, 4)//")", &
        & gtoa(x, 4) == g4)
      call check_true(suite, "gtoa("//g6//", 3) = "//g3//" (got "//gtoa(x, 3)//")", &
        & gtoa(x, 3) == g3)
      call check_true(suite, "gtoa("//g6//", 6) = "//g6//" (got "//gtoa(x, 6)//")", &
        & gtoa(x, 6) == g6)
    end subroutine same
  end subroutine run_gtoa

  !> Blade A, its damper and band: no warning, with or without the model.
  subroutine run_blade_a_none(suite)
    type(test_suite), intent(inout) :: suite
    type(scene_type), target :: scene
    type(error_type), allocatable :: error
    type(warning_type), allocatable :: w(:)
    call blade_a_with_damper(suite, scene%blade, scene%damper, error)
    if (allocated(error)) return
    call plausibility_warnings(scene%blade, 150.0_wp, 230.0_wp, w, scene%damper)
    call check_true(suite, "blade A: no warning without the model", size(w) == 0)
    call blade_a_model(suite, scene%blade, scene%damper, scene%analysis, scene%model, error)
    if (allocated(error)) return
    call model_warnings(scene%model, w)
    call check_true(suite, "blade A: no warning with the model", size(w) == 0)
  end subroutine run_blade_a_none

  !> The platform in grams, J in kg mm^2, the stiffnesses in N/mm, the band below the mode.
  subroutine run_unit_mistakes(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type), target :: blade, heavy, inert
    type(damper_type), target :: damper, soft
    type(beam_params_type) :: p
    type(asymmetric_params_type) :: d
    type(analysis_type) :: analysis
    type(model_type) :: model
    type(error_type), allocatable :: error
    type(warning_type), allocatable :: w(:)
    call blade_a_with_damper(suite, blade, damper, error)
    if (allocated(error)) return

    p = blade_a_beam_params()
    p%platform_m = 21
    call new_beam_blade(heavy, p, error)
    call check_no_error(suite, "blade A with m = 21 kg", error)
    call plausibility_warnings(heavy, 150.0_wp, 230.0_wp, w, damper)
    call check_true(suite, "platform in grams: one warning", size(w) >= 1)
    if (size(w) >= 1) then
      call check_true(suite, "platform in grams: kind", w(1)%kind == WARNING_PLATFORM_MASS)
      call check_true(suite, "platform in grams: text", w(1)%text == "blade.platform.m = 21 kg " &
        & //"is heavier than the rest of the blade (0.1443 kg of neck and airfoil): was it " &
        & //"given in grams? (21 g would be 0.021 kg)")
    end if

    p = blade_a_beam_params()
    p%platform_J = 1.4_wp
    call new_beam_blade(inert, p, error)
    call check_no_error(suite, "blade A with J = 1.4 kg m^2", error)
    call plausibility_warnings(inert, 150.0_wp, 230.0_wp, w)
    call check_true(suite, "J in kg mm^2: two warnings", size(w) == 2)
    if (size(w) == 2) then
      call check_true(suite, "J in kg mm^2: kinds", w(1)%kind == WARNING_PLATFORM_INERTIA .and. &
        & w(2)%kind == WARNING_BAND_MISSES_MODE)
      call check_true(suite, "J in kg mm^2: text", w(1)%text == "blade.platform.J = 1.4 kg " &
        & //"m^2 is over 1000 times that of a rigid bar of the platform's mass and length " &
        & //"(1.75e-07 kg m^2): was it given in kg mm^2? (1 kg mm^2 = 1e-6 kg m^2)")
      call check_true(suite, "J in kg mm^2: the band misses the bare mode", w(2)%text == &
        & "the band [analysis.f_min, analysis.f_max] = [150, 230] Hz misses the first mode " &
        & //"(bare first mode at 11.45 Hz): are the band or the blade in other units (Hz for " &
        & //"rad/s, mm-t-s for SI)?")
    end if

    call plausibility_warnings(blade, 10.0_wp, 100.0_wp, w, damper)
    call check_true(suite, "band below the mode: one warning", size(w) == 1)
    if (size(w) == 1) call check_true(suite, "band below the mode: kind and text", &
      & w(1)%kind == WARNING_BAND_MISSES_MODE .and. w(1)%text == "the band [analysis.f_min, " &
      & //"analysis.f_max] = [10, 100] Hz misses the first mode (bare first mode at 187.1 Hz)" &
      & //": are the band or the blade in other units (Hz for rad/s, mm-t-s for SI)?")

    d = blade_a_damper_params()
    d%kn_flat = d%kn_flat/1000
    d%kt_flat = d%kt_flat/1000
    d%kn_curved = d%kn_curved/1000
    d%kt_curved = d%kt_curved/1000
    call new_asymmetric_damper(soft, d, error)
    call check_no_error(suite, "damper with stiffnesses in N/mm", error)
    if (allocated(error)) return
    call blade_a_model(suite, blade, soft, analysis, model, error)
    if (allocated(error)) return
    call model_warnings(model, w)
    call check_true(suite, "stiffnesses in N/mm: two warnings", size(w) == 2)
    if (size(w) == 2) then
      call check_true(suite, "stiffnesses in N/mm: kinds", w(1)%kind == WARNING_GAMMA_B_LARGE &
        & .and. w(2)%kind == WARNING_STUCK_SHIFT)
      call check_true(suite, "stiffnesses in N/mm: gamma_b text", w(1)%text == "the base-cycle " &
        & //"amplitude gamma_b = 0.5483 rad is above 0.01 rad (the contacts deflect by " &
        & //"degrees before they slip): were the contact stiffnesses given in N/mm? (kn_flat " &
        & //"= 6e+04 N/m; 1 N/mm = 1e3 N/m)")
      call check_true(suite, "stiffnesses in N/mm: shift text", w(2)%text == "the stuck damper " &
        & //"shifts the first frequency by 0.0137 % (187.1 Hz bare, 187.1 Hz stuck), outside " &
        & //"0.1 % to 100 %: are the contact stiffnesses or the blade in another unit?")
    end if
  end subroutine run_unit_mistakes
end module test_plausibility
