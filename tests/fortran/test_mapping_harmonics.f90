!> Multi-harmonic layers (PHYSICS.md 4.1) against the standard method with the same harmonics
!> (condensed variant, harmonics 0..H): blade A with its asymmetric damper at F_E = 1, 2, 5,
!> 10 N and with a Jenkins damper, H = 3, 5 (and 9 on blade A at 5 N). Same equations, so the
!> same answers to 1e-6. Also: H = 1 is the single-harmonic path (bit-identical), a cold layer
!> equals a warm one, a measured table is refused with H > 1, and auto includes the harmonics
!> that sit near bare mode 2.
module test_mapping_harmonics
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type, new_jenkins_damper, new_table_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, backbone, &
    & response, harmonics_near_modes
  use udmap_baseline_linear_structure, only: structure_type, structure_from_blade
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_peaks, hbm_response
  use udmap_mapping_harmonic_types, only: harmonic_state_type
  use udmap_mapping_harmonic_layer, only: harmonic_resize, harmonic_solve
  use udmap_mapping_model_data, only: model_type
  use fixtures, only: blade_a_with_damper, blade_a_band
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_mapping_harmonics

contains

  !> Multi-harmonic layers against the standard method (PHYSICS.md 4.1).
  subroutine collect_mapping_harmonics(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("mapping_harmonics", run_mapping_harmonics)]
  end subroutine collect_mapping_harmonics

  !> Multi-harmonic layers against the standard method with the same harmonics.
  subroutine run_mapping_harmonics(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type), target :: blade
    type(damper_type), target :: damper, jdamper, tdamper
    type(model_type) :: model
    type(analysis_type) :: an
    type(point_type), allocatable :: p1(:), ph(:), p1b(:)
    type(structure_type) :: st
    type(contact_element_type) :: el
    type(jenkins_element_type) :: jen
    type(error_type), allocatable :: error
    type(hbm_settings_type) :: set
    type(hbm_point_type), allocatable :: hp(:)
    type(hbm_point_type) :: hr
    type(harmonic_state_type) :: cold, warm
    real(wp), parameter :: FE(4) = [1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp]
    real(wp), parameter :: FJ(3) = [2.0_wp, 5.0_wp, 10.0_wp]
    integer :: i, k, H
    character(len=48) :: tag

    call blade_a_with_damper(suite, blade, damper, error)
    call structure_from_blade(st, blade, error)
    call new_contact_element(el, blade_a_damper_params(), error)
    call check_no_error(suite, "contact element", error)
    call blade_a_band(an)

    ! H = 1 is the single-harmonic method: the same numbers, bit for bit
    call new_model(model, blade, damper, an, error)
    call backbone(model, FE, p1, error)
    call check_no_error(suite, "backbone H = 1", error)
    do i = 1, size(FE)
      call check_true(suite, "H = 1: gamma_max = gamma_P, sigma_max = sigma_a", &
        & p1(i)%gamma_max == p1(i)%gamma_P .and. p1(i)%sigma_max == p1(i)%sigma_a .and. &
        & p1(i)%harmonics == 1)
    end do

    ! blade A: layered backbone = standard method with harmonics 0..H (condensed)
    set%variant = 0
    set%harmonic0 = .true.
    set%warm_start = 2
    set%full_band = .false.
    call layers_against_hbm(damper, el, FE, "", "blade A", .true.)

    ! H = 9 at 5 N
    an%harmonics = 9
    call new_model(model, blade, damper, an, error)
    call backbone(model, [5.0_wp], ph, error)
    call check_no_error(suite, "backbone H = 9", error)
    set%harmonics = 9
    call hbm_peaks(st, el, an%f_min, an%f_max, [5.0_wp], set, hp, error)
    call check_no_error(suite, "hbm H = 9", error)
    if (allocated(ph) .and. allocated(hp)) then
      call check_close(suite, "blade A gamma_P H = 9, 5 N", ph(1)%gamma_P, hp(1)%gamma_P, 1e-6_wp)
      call check_close(suite, "blade A sigma_a H = 9, 5 N", ph(1)%sigma_a, hp(1)%sigma_a, 1e-6_wp)
      call check_close(suite, "blade A f_res H = 9, 5 N", ph(1)%f_res, hp(1)%f_res, 1e-6_wp)
    end if

    ! response at a given frequency, H = 5, 5 N
    an%harmonics = 5
    call new_model(model, blade, damper, an, error)
    call response(model, 190.0_wp, [5.0_wp], ph, error)
    call check_no_error(suite, "response H = 5", error)
    set%harmonics = 5
    set%warm_start = 0
    call hbm_response(st, el, an%f_min, 190.0_wp, 5.0_wp, set, hr, error)
    call check_no_error(suite, "hbm response H = 5", error)
    if (allocated(ph)) then
      call check_close(suite, "response gamma_P H = 5", ph(1)%gamma_P, hr%gamma_P, 1e-6_wp)
      call check_close(suite, "response sigma_a H = 5", ph(1)%sigma_a, hr%sigma_a, 1e-6_wp)
    end if
    set%warm_start = 2

    ! after a change of F_E alone the root starts from the last one (fewer traces), and equals
    ! the root found cold by a new model
    an%harmonics = 5
    call new_model(model, blade, damper, an, error)
    call backbone(model, [5.0_wp], ph, error)
    k = model%harm%traces
    call backbone(model, [5.5_wp], ph, error)
    call check_no_error(suite, "F_E change, warm", error)
    k = model%harm%traces - k
    call new_model(model, blade, damper, an, error)
    call backbone(model, [5.5_wp], p1b, error)
    call check_no_error(suite, "F_E change, cold", error)
    if (allocated(ph) .and. allocated(p1b)) then
      call check_close(suite, "F_E change: warm gamma_P = cold", ph(1)%gamma_P, p1b(1)%gamma_P, &
        & 1e-9_wp)
      call check_close(suite, "F_E change: warm f_res = cold", ph(1)%f_res, p1b(1)%f_res, 1e-7_wp)
      call check_close(suite, "F_E change: warm sigma_max = cold", ph(1)%sigma_max, &
        & p1b(1)%sigma_max, 1e-7_wp)
      call check_true(suite, "F_E change: fewer traces than cold", k < model%harm%traces)
    end if

    ! a layer solved cold equals the same layer solved from a neighbour's solution
    call harmonic_resize(warm, 5)
    call harmonic_solve(model%harm, blade, 1.05e-3_wp, 2*pi*191.0_wp, warm, error)
    call harmonic_solve(model%harm, blade, 1.0e-3_wp, 2*pi*190.0_wp, warm, error)
    call check_no_error(suite, "warm layer", error)
    call harmonic_resize(cold, 5)
    call harmonic_solve(model%harm, blade, 1.0e-3_wp, 2*pi*190.0_wp, cold, error)
    call check_no_error(suite, "cold layer", error)
    call check_close(suite, "cold = warm: |P|", abs(cold%P), abs(warm%P), 1e-10_wp)
    call check_close(suite, "cold = warm: |Gamma_3|", abs(cold%G(3)), abs(warm%G(3)), 1e-8_wp)
    call check_close(suite, "cold = warm: Gamma_0", cold%G0, warm%G0, 1e-8_wp, 1e-12_wp*1e-3_wp)

    ! Jenkins damper on blade A (the damper's stuck stiffness and half its moment range)
    call new_jenkins_damper(jdamper, damper%k_stuck, 0.5_wp*(damper%M_max - damper%M_min), error)
    call check_no_error(suite, "jenkins damper", error)
    call new_jenkins_element(jen, damper%k_stuck, 0.5_wp*(damper%M_max - damper%M_min), error)
    call layers_against_hbm(jdamper, jen, FJ, "jenkins ", "jenkins", .false.)

    ! auto includes the harmonics near bare mode 2 (blade A: the 5th and 6th)
    an%harmonics = 0
    call new_model(model, blade, damper, an, error)
    call check_true(suite, "blade A: harmonic 6 sits near mode 2", &
      & harmonics_near_modes(model, 2*pi*190.0_wp, 6) == 6)
    call backbone(model, [5.0_wp], ph, error)
    call check_no_error(suite, "backbone auto", error)
    if (allocated(ph)) call check_true(suite, "auto: H >= 6", ph(1)%harmonics >= 6)

    ! a measured table has no loop to trace
    call new_table_damper(tdamper, [1e-5_wp, 1e-4_wp, 1e-3_wp], [1.0_wp, 1.0_wp, 1.0_wp], &
      & [0.0_wp, 0.1_wp, 0.1_wp], error, delta_M=1.0_wp)
    an%harmonics = 3
    call new_model(model, blade, tdamper, an, error)
    call backbone(model, [1.0_wp], p1b, error)
    call check_error(suite, "table damper with H = 3", error, UDMAP_EINPUT, "analysis.harmonics")
  contains

    !> The layered backbone of blade A with damper d against the standard method with the
    !> element of the same damper (condensed, harmonics 0..H) for H = 3 and 5, at the forces F:
    !> gamma_P, sigma_a and f_res within 1e-6; with `more`, the harmonics reported and the bounds
    !> of gamma_max too. Labels start with `what` (the runs) and `label` (the values).
    subroutine layers_against_hbm(d, element, F, what, label, more)
      type(damper_type), target, intent(in) :: d
      class(hysteretic_element_type), intent(in) :: element
      real(wp), intent(in) :: F(:)
      character(len=*), intent(in) :: what, label
      logical, intent(in) :: more
      do k = 1, 2
        H = 2*k + 1
        an%harmonics = H
        call new_model(model, blade, d, an, error)
        call backbone(model, F, ph, error)
        write(tag, '(a, i0)') what//"backbone H = ", H
        call check_no_error(suite, trim(tag), error)
        set%harmonics = H
        call hbm_peaks(st, element, an%f_min, an%f_max, F, set, hp, error)
        call check_no_error(suite, "hbm "//trim(tag), error)
        if (.not.allocated(ph) .or. .not.allocated(hp)) cycle
        do i = 1, size(F)
          write(tag, '(a, i0, a, f4.1, a)') "H = ", H, ", F_E = ", F(i), " N"
          call check_close(suite, label//" gamma_P "//trim(tag), ph(i)%gamma_P, hp(i)%gamma_P, &
            & 1e-6_wp)
          call check_close(suite, label//" sigma_a "//trim(tag), ph(i)%sigma_a, hp(i)%sigma_a, &
            & 1e-6_wp)
          call check_close(suite, label//" f_res "//trim(tag), ph(i)%f_res, hp(i)%f_res, 1e-6_wp)
          if (.not.more) cycle
          call check_true(suite, "harmonics reported "//trim(tag), ph(i)%harmonics == H)
          call check_true(suite, "gamma_max >= gamma_P - |Gamma_h>1| "//trim(tag), &
            & ph(i)%gamma_max >= ph(i)%gamma_P - sum(ph(i)%gamma_h(2:)) .and. &
            & ph(i)%gamma_max <= sum(ph(i)%gamma_h(1:)))
        end do
      end do
    end subroutine layers_against_hbm
  end subroutine run_mapping_harmonics
end module test_mapping_harmonics
