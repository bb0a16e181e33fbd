!> C API, standard method and time integration (wrappers/c/udmap.h, last section): the damper's
!> contact law as a time-domain element (udmap_contact), the harmonic balance peaks, response
!> and curve, and the Newmark ground truth.
module udmap_api_c_baseline
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, c_loc, &
    & c_int, c_double
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input, take_handle, &
    & copy_out
  use udmap_blade_type, only: blade_type
  use udmap_baseline_linear_structure, only: structure_type, structure_from_blade
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_api_c_damper, only: udmap_asymmetric_params, asymmetric_from_c
  use udmap_contact_aft_moment, only: aft_workspace_type, aft_moment
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_curve_type, hbm_peak, &
    & hbm_peaks, hbm_response, HBM_MAX_PEAKS
  use udmap_baseline_newmark, only: dti_settings_type, dti_point_type, dti_response, dti_peak
  use udmap_baseline_wheel, only: wheel_point_type, wheel_response, wheel_peak
  implicit none
  private

  !> Largest number of harmonics reported per point (UDMAP_HBM_MAX_HARMONICS).
  integer, parameter :: max_harmonics = 64

  !> What a udmap_contact handle points to.
  type :: c_contact_type
    class(hysteretic_element_type), allocatable :: element
  end type c_contact_type

  !> udmap_hbm_settings.
  type, bind(C) :: c_hbm_settings
    integer(c_int) :: harmonics, harmonic0, variant
    real(c_double) :: tol
    integer(c_int) :: max_iter
    real(c_double) :: ds_initial, ds_min, ds_max
    integer(c_int) :: target_iter
    real(c_double) :: max_angle
    integer(c_int) :: max_steps
    real(c_double) :: peak_tol
    integer(c_int) :: aft_samples, aft_max_periods
    real(c_double) :: fd_step, gamma_limit
    integer(c_int) :: full_band, jacobian_reuse
    real(c_double) :: tol_path
    integer(c_int) :: warm_start
  end type c_hbm_settings

  !> udmap_hbm_point.
  type, bind(C) :: c_hbm_point
    real(c_double) :: F_E, gamma_P, f_res, sigma_a, u_E, k_re, k_im, gamma_max
    integer(c_int) :: npeaks
    real(c_double) :: peaks(HBM_MAX_PEAKS), peak_f(HBM_MAX_PEAKS)
    integer(c_int) :: harmonics
    real(c_double) :: gamma_h(max_harmonics)
    integer(c_int) :: steps, iterations, aft_calls
    real(c_double) :: seconds
    integer(c_int) :: lift_off
  end type c_hbm_point

  !> udmap_dti_settings.
  type, bind(C) :: c_dti_settings
    integer(c_int) :: steps_per_period
    real(c_double) :: ss_tol
    integer(c_int) :: min_periods, max_periods
    real(c_double) :: peak_rtol, peak_window, gamma_limit
  end type c_dti_settings

  !> udmap_dti_point.
  type, bind(C) :: c_dti_point
    real(c_double) :: F_E, f, gamma_1, sigma_1, gamma_max, gamma_0, ss_error
    integer(c_int) :: periods, runs
    real(c_double) :: seconds
    integer(c_int) :: lift_off
  end type c_dti_point

  !> udmap_dti_wheel_point.
  type, bind(C) :: c_dti_wheel_point
    type(c_dti_point) :: blade0
    integer(c_int) :: blades, engine_order
    real(c_double) :: phi, gamma_spread, sigma_spread, phase_spread
  end type c_dti_wheel_point

contains

  ! ------------------------------------------------------------------ contact elements

  !> A rotational Jenkins element as a contact handle (PHYSICS.md 2.4).
  function udmap_new_contact_jenkins(ehandle, kt, M_slip, contact) result(stat) &
      & bind(C, name="udmap_new_contact_jenkins")
    type(c_ptr), value :: ehandle
    real(c_double), value :: kt, M_slip
    type(c_ptr), intent(out) :: contact
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(jenkins_element_type) :: jen
    call clear_error(ehandle)
    call new_jenkins_element(jen, real(kt, wp), real(M_slip, wp), error)
    call hand_over_contact(jen, error, contact)
    stat = set_error(ehandle, error)
  end function udmap_new_contact_jenkins

  !> The asymmetric damper as a contact handle: geometry, CF ramp, stuck stiffness.
  function udmap_new_contact_asymmetric(ehandle, params, contact) result(stat) &
      & bind(C, name="udmap_new_contact_asymmetric")
    type(c_ptr), value :: ehandle
    type(udmap_asymmetric_params), intent(in) :: params
    type(c_ptr), intent(out) :: contact
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(contact_element_type) :: el
    call clear_error(ehandle)
    call new_contact_element(el, asymmetric_from_c(params), error)
    call hand_over_contact(el, error, contact)
    stat = set_error(ehandle, error)
  end function udmap_new_contact_asymmetric

  !> Frees a contact handle (NULL allowed) and sets it to NULL.
  subroutine udmap_delete_contact(contact) bind(C, name="udmap_delete_contact")
    type(c_ptr), intent(inout) :: contact
    type(c_contact_type), pointer :: c
    if (.not.c_associated(contact)) return
    call c_f_pointer(take_handle(contact), c)
    deallocate(c)
  end subroutine udmap_delete_contact

  !> One AFT evaluation with the loading history: gamma = G0 + Re(sum G_h e^{i h tau}).
  function c_contact_aft(ehandle, contact, H, G0, G, samples, M0, M, gamma_max) &
      & result(stat) bind(C, name="udmap_contact_aft")
    type(c_ptr), value :: ehandle, contact
    integer(c_int), value :: H, samples
    real(c_double), value :: G0
    real(c_double), intent(in) :: G(*)
    real(c_double), intent(out) :: M0, M(*), gamma_max
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_contact_type), pointer :: c
    type(aft_workspace_type) :: ws
    complex(wp), allocatable :: Gc(:), Mc(:)
    real(wp) :: m0_, gm
    integer :: k
    call clear_error(ehandle)
    M0 = 0.0_c_double
    gamma_max = 0.0_c_double
    call check_handle(contact, "contact", error)
    call check_input(H >= 1 .and. H <= max_harmonics, "contact_aft: H must be in 1..64", error)
    ! 2 H + 1 is computed for a valid H only
    if (.not.allocated(error)) call check_input(samples == 0 .or. samples >= 2*H + 1, &
      & "contact_aft: samples must be 0 (exact) or >= 2 H + 1", error)
    if (.not.allocated(error)) then
      call c_f_pointer(contact, c)
      allocate(Gc(H), Mc(H))
      do k = 1, H
        Gc(k) = cmplx(G(2*k-1), G(2*k), wp)
      end do
      call aft_moment(c%element, ws, real(G0, wp), Gc, int(samples), 1, 8, 1.0e-12_wp, m0_, Mc, &
        & error, gamma_max=gm)
      if (.not.allocated(error)) then
        M0 = m0_
        gamma_max = gm
        do k = 1, H
          M(2*k-1) = real(Mc(k), c_double)
          M(2*k) = aimag(Mc(k))
        end do
      end if
    end if
    stat = set_error(ehandle, error)
  end function c_contact_aft

  ! ------------------------------------------------------------------ standard method

  !> The default settings of the standard method.
  subroutine udmap_hbm_defaults(settings) bind(C, name="udmap_hbm_defaults")
    type(c_hbm_settings), intent(out) :: settings
    type(hbm_settings_type) :: d
    settings = settings_to_c(d)
  end subroutine udmap_hbm_defaults

  !> Peaks of the response for n forces (udmap_hbm_point each).
  function udmap_hbm_peaks(ehandle, blade, contact, f_min, f_max, settings, n, F_E, points) &
      & result(stat) bind(C, name="udmap_hbm_peaks")
    type(c_ptr), value :: ehandle, blade, contact
    real(c_double), value :: f_min, f_max
    type(c_hbm_settings), intent(in) :: settings
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_hbm_point), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = hbm_points(ehandle, blade, contact, f_min, f_max, settings, n, F_E, points, &
      & at_peak=.true.)
  end function udmap_hbm_peaks

  !> Response at f_exc for n forces, by continuation from f_min.
  function udmap_hbm_response(ehandle, blade, contact, f_min, f_exc, settings, n, F_E, points) &
      & result(stat) bind(C, name="udmap_hbm_response")
    type(c_ptr), value :: ehandle, blade, contact
    real(c_double), value :: f_min, f_exc
    type(c_hbm_settings), intent(in) :: settings
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_hbm_point), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = hbm_points(ehandle, blade, contact, f_min, f_exc, settings, n, F_E, points, &
      & at_peak=.false.)
  end function udmap_hbm_response

  !> The standard method for n forces: the peaks in [f_a, f_b] or, not at_peak, the response at
  !> f_b reached by continuation from f_a; the points before a failure are returned; the status.
  function hbm_points(ehandle, blade, contact, f_a, f_b, settings, n, F_E, points, at_peak) &
      & result(stat)
    type(c_ptr), intent(in) :: ehandle, blade, contact
    real(c_double), intent(in) :: f_a, f_b
    type(c_hbm_settings), intent(in) :: settings
    integer(c_int), intent(in) :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_hbm_point), intent(out) :: points(*)
    logical, intent(in) :: at_peak
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(structure_type) :: st
    type(c_contact_type), pointer :: c
    type(hbm_settings_type) :: set
    type(hbm_point_type), allocatable :: pts(:)
    integer :: i, m
    call clear_error(ehandle)
    call prepare(blade, contact, n, st, c, error, settings, set)
    if (.not.allocated(error)) then
      m = n
      if (at_peak) then
        call hbm_peaks(st, c%element, real(f_a, wp), real(f_b, wp), real(F_E(1:n), wp), set, &
          & pts, error)
      else
        allocate(pts(n))
        do m = 0, n - 1
          call hbm_response(st, c%element, real(f_a, wp), real(f_b, wp), real(F_E(m+1), wp), &
            & set, pts(m+1), error)
          if (allocated(error)) exit
        end do
      end if
      do i = 1, m
        if (.not.allocated(pts(i)%gamma_h)) exit
        points(i) = point_to_c(pts(i))
      end do
    end if
    stat = set_error(ehandle, error)
  end function hbm_points

  !> The continued response curve of one force.
  function udmap_hbm_curve(ehandle, blade, contact, f_min, f_max, settings, F_E, capacity, &
      & npoints, f, gamma_1, sigma_1, gamma_max) result(stat) bind(C, name="udmap_hbm_curve")
    type(c_ptr), value :: ehandle, blade, contact
    real(c_double), value :: f_min, f_max, F_E
    type(c_hbm_settings), intent(in) :: settings
    integer(c_int), value :: capacity
    integer(c_int), intent(out) :: npoints
    real(c_double), intent(out) :: f(*), gamma_1(*), sigma_1(*), gamma_max(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(structure_type) :: st
    type(c_contact_type), pointer :: c
    type(hbm_settings_type) :: set
    type(hbm_point_type) :: pt
    type(hbm_curve_type) :: curve
    integer :: m
    call clear_error(ehandle)
    npoints = 0
    call prepare(blade, contact, 1, st, c, error, settings, set)
    call check_input(capacity >= 1, "hbm_curve: capacity must be >= 1", error)
    if (.not.allocated(error)) then
      call hbm_peak(st, c%element, real(f_min, wp), real(f_max, wp), real(F_E, wp), set, pt, &
        & error, curve)
      ! the curve is returned even when no peak is found in the band
      if (curve%n > 0) then
        m = curve%n
        npoints = int(m, c_int)
        call copy_out(curve%f(1:m), f, int(capacity))
        call copy_out(curve%gamma_1(1:m), gamma_1, int(capacity))
        call copy_out(curve%sigma_1(1:m), sigma_1, int(capacity))
        call copy_out(curve%gamma_max(1:m), gamma_max, int(capacity))
      end if
    end if
    stat = set_error(ehandle, error)
  end function udmap_hbm_curve

  ! ------------------------------------------------------------------ time integration

  !> The default settings of the time integration.
  subroutine udmap_dti_defaults(settings) bind(C, name="udmap_dti_defaults")
    type(c_dti_settings), intent(out) :: settings
    type(dti_settings_type) :: d
    settings = c_dti_settings(steps_per_period=d%steps_per_period, ss_tol=d%ss_tol, &
      & min_periods=d%min_periods, max_periods=d%max_periods, peak_rtol=d%peak_rtol, &
      & peak_window=d%peak_window, gamma_limit=d%gamma_limit)
  end subroutine udmap_dti_defaults

  !> Steady state by time integration at f_exc for n forces.
  function udmap_dti_response(ehandle, blade, contact, settings, f_exc, n, F_E, points) &
      & result(stat) bind(C, name="udmap_dti_response")
    type(c_ptr), value :: ehandle, blade, contact
    type(c_dti_settings), intent(in) :: settings
    real(c_double), value :: f_exc
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_dti_point), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = dti_points(ehandle, blade, contact, settings, f_exc, f_exc, 0.0_c_double, n, F_E, &
      & at_peak=.false., points=points)
  end function udmap_dti_response

  !> Time integration at the frequency of the largest gamma_1 near the H = 1 peak.
  function udmap_dti_peak(ehandle, blade, contact, settings, f_min, f_max, n, F_E, points) &
      & result(stat) bind(C, name="udmap_dti_peak")
    type(c_ptr), value :: ehandle, blade, contact
    type(c_dti_settings), intent(in) :: settings
    real(c_double), value :: f_min, f_max
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_dti_point), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = dti_points(ehandle, blade, contact, settings, f_min, f_max, 0.0_c_double, n, F_E, &
      & at_peak=.true., points=points)
  end function udmap_dti_peak

  !> The whole wheel (N blades, N dampers) at f_exc for n forces.
  function udmap_dti_wheel_response(ehandle, blade, contact, settings, f_exc, blades, &
      & engine_order, n, F_E, points) result(stat) bind(C, name="udmap_dti_wheel_response")
    type(c_ptr), value :: ehandle, blade, contact
    type(c_dti_settings), intent(in) :: settings
    real(c_double), value :: f_exc
    integer(c_int), value :: blades, engine_order, n
    real(c_double), intent(in) :: F_E(*)
    type(c_dti_wheel_point), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = dti_points(ehandle, blade, contact, settings, f_exc, f_exc, 0.0_c_double, n, F_E, &
      & at_peak=.false., blades=blades, engine_order=engine_order, wheel=points)
  end function udmap_dti_wheel_response

  !> The whole wheel at the frequency of blade 0's largest gamma_1, searched around f_center
  !> (f_center <= 0: the in-phase H = 1 peak in [f_min, f_max]).
  function udmap_dti_wheel_peak(ehandle, blade, contact, settings, f_min, f_max, f_center, &
      & blades, engine_order, n, F_E, points) result(stat) bind(C, name="udmap_dti_wheel_peak")
    type(c_ptr), value :: ehandle, blade, contact
    type(c_dti_settings), intent(in) :: settings
    real(c_double), value :: f_min, f_max, f_center
    integer(c_int), value :: blades, engine_order, n
    real(c_double), intent(in) :: F_E(*)
    type(c_dti_wheel_point), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = dti_points(ehandle, blade, contact, settings, f_min, f_max, f_center, n, F_E, &
      & at_peak=.true., blades=blades, engine_order=engine_order, wheel=points)
  end function udmap_dti_wheel_peak

  !> Time integration for n forces at f_a (f_b unused) or, at_peak, at the peak in [f_a, f_b]
  !> (the wheel's searched around f_center > 0): of one blade into points or, given wheel, of
  !> the whole wheel of `blades` blades at `engine_order`. The points before a failure are
  !> returned; the status.
  function dti_points(ehandle, blade, contact, settings, f_a, f_b, f_center, n, F_E, at_peak, &
      & points, blades, engine_order, wheel) result(stat)
    type(c_ptr), intent(in) :: ehandle, blade, contact
    type(c_dti_settings), intent(in) :: settings
    real(c_double), intent(in) :: f_a, f_b, f_center
    integer(c_int), intent(in) :: n
    real(c_double), intent(in) :: F_E(*)
    logical, intent(in) :: at_peak
    type(c_dti_point), intent(out), optional :: points(*)
    integer(c_int), intent(in), optional :: blades, engine_order
    type(c_dti_wheel_point), intent(out), optional :: wheel(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(structure_type) :: st
    type(c_contact_type), pointer :: c
    ! one blade's point is the wheel point's blade 0 part
    type(wheel_point_type) :: pt
    integer :: i
    call clear_error(ehandle)
    call prepare(blade, contact, n, st, c, error)
    if (.not.allocated(error)) then
      do i = 1, n
        if (.not.present(wheel)) then
          if (at_peak) then
            call dti_peak(st, c%element, real(f_a, wp), real(f_b, wp), real(F_E(i), wp), &
              & dti_from_c(settings), pt%dti_point_type, error)
          else
            call dti_response(st, c%element, real(f_a, wp), real(F_E(i), wp), &
              & dti_from_c(settings), pt%dti_point_type, error)
          end if
        else if (at_peak .and. f_center > 0) then
          call wheel_peak(st, c%element, real(f_a, wp), real(f_b, wp), real(F_E(i), wp), &
            & blades, engine_order, dti_from_c(settings), pt, error, real(f_center, wp))
        else if (at_peak) then
          call wheel_peak(st, c%element, real(f_a, wp), real(f_b, wp), real(F_E(i), wp), &
            & blades, engine_order, dti_from_c(settings), pt, error)
        else
          call wheel_response(st, c%element, real(f_a, wp), real(F_E(i), wp), blades, &
            & engine_order, dti_from_c(settings), pt, error)
        end if
        if (allocated(error)) exit
        if (present(wheel)) then
          wheel(i) = c_dti_wheel_point(blade0=dti_point_to_c(pt%dti_point_type), &
            & blades=pt%blades, engine_order=pt%engine_order, phi=pt%phi, &
            & gamma_spread=pt%gamma_spread, sigma_spread=pt%sigma_spread, &
            & phase_spread=pt%phase_spread)
        else
          points(i) = dti_point_to_c(pt%dti_point_type)
        end if
      end do
    end if
    stat = set_error(ehandle, error)
  end function dti_points

  ! ------------------------------------------------------------------ helpers

  !> Hands a new contact element to the caller's handle; NULL after an error.
  subroutine hand_over_contact(element, error, contact)
    class(hysteretic_element_type), intent(in) :: element
    type(error_type), allocatable, intent(in) :: error
    type(c_ptr), intent(out) :: contact
    type(c_contact_type), pointer :: c
    contact = c_null_ptr
    if (allocated(error)) return
    allocate(c)
    allocate(c%element, source=element)
    contact = c_loc(c)
  end subroutine hand_over_contact

  !> The structure of the blade handle, the contact element of the contact handle and, when
  !> given, the settings of the standard method.
  subroutine prepare(blade, contact, n, st, c, error, settings, set)
    type(c_ptr), intent(in) :: blade, contact
    integer(c_int), intent(in) :: n
    type(structure_type), intent(out) :: st
    type(c_contact_type), pointer, intent(out) :: c
    type(error_type), allocatable, intent(out) :: error
    type(c_hbm_settings), intent(in), optional :: settings
    type(hbm_settings_type), intent(out), optional :: set
    type(blade_type), pointer :: b
    nullify(c)
    call check_handle(blade, "blade", error)
    call check_handle(contact, "contact", error)
    call check_input(n >= 0, "argument 'n' must be >= 0", error)
    if (allocated(error)) return
    call c_f_pointer(blade, b)
    call structure_from_blade(st, b, error)
    if (allocated(error)) return
    call c_f_pointer(contact, c)
    if (present(settings)) call settings_from_c(settings, set, error)
  end subroutine prepare

  ! The conversions to and from the C structs are structure constructors with keywords: the
  ! compiler checks that every field of a C struct is set.

  pure function settings_to_c(s) result(c)
    type(hbm_settings_type), intent(in) :: s
    type(c_hbm_settings) :: c
    c = c_hbm_settings(harmonics=s%harmonics, harmonic0=merge(1, 0, s%harmonic0), &
      & variant=s%variant, tol=s%tol, max_iter=s%max_iter, ds_initial=s%ds_initial, &
      & ds_min=s%ds_min, ds_max=s%ds_max, target_iter=s%target_iter, max_angle=s%max_angle, &
      & max_steps=s%max_steps, peak_tol=s%peak_tol, aft_samples=s%aft_samples, &
      & aft_max_periods=s%aft_max_periods, fd_step=s%fd_step, gamma_limit=s%gamma_limit, &
      & full_band=merge(1, 0, s%full_band), jacobian_reuse=merge(1, 0, s%jacobian_reuse), &
      & tol_path=s%tol_path, warm_start=s%warm_start)
  end function settings_to_c

  subroutine settings_from_c(c, s, error)
    type(c_hbm_settings), intent(in) :: c
    type(hbm_settings_type), intent(out) :: s
    type(error_type), allocatable, intent(out) :: error
    if (c%harmonics > max_harmonics) then
      call fatal_error(error, "hbm: harmonics must be in 1..64", UDMAP_EINPUT)
      return
    end if
    ! the fields without a C counterpart keep their defaults
    s = hbm_settings_type(harmonics=c%harmonics, harmonic0=c%harmonic0 /= 0, &
      & variant=c%variant, tol=c%tol, max_iter=c%max_iter, ds_initial=c%ds_initial, &
      & ds_min=c%ds_min, ds_max=c%ds_max, target_iter=c%target_iter, max_angle=c%max_angle, &
      & max_steps=c%max_steps, peak_tol=c%peak_tol, aft_samples=c%aft_samples, &
      & aft_max_periods=c%aft_max_periods, fd_step=c%fd_step, gamma_limit=c%gamma_limit, &
      & full_band=c%full_band /= 0, jacobian_reuse=c%jacobian_reuse /= 0, &
      & tol_path=c%tol_path, warm_start=c%warm_start)
  end subroutine settings_from_c

  !> The C point of p: at most max_harmonics values of gamma_h, the rest 0.
  pure function point_to_c(p) result(c)
    type(hbm_point_type), intent(in) :: p
    type(c_hbm_point) :: c
    real(c_double) :: gamma_h(max_harmonics)
    integer :: nh
    gamma_h = 0.0_c_double
    nh = 0
    if (allocated(p%gamma_h)) nh = min(size(p%gamma_h), max_harmonics)
    gamma_h(1:nh) = p%gamma_h(1:nh)
    c = c_hbm_point(F_E=p%F_E, gamma_P=p%gamma_P, f_res=p%f_res, sigma_a=p%sigma_a, u_E=p%u_E, &
      & k_re=p%k_re, k_im=p%k_im, gamma_max=p%gamma_max, npeaks=p%npeaks, peaks=p%peaks, &
      & peak_f=p%peak_f, harmonics=nh, gamma_h=gamma_h, steps=p%steps, &
      & iterations=p%iterations, aft_calls=p%aft_calls, seconds=p%seconds, &
      & lift_off=merge(1, 0, p%lift_off))
  end function point_to_c

  pure function dti_from_c(c) result(s)
    type(c_dti_settings), intent(in) :: c
    type(dti_settings_type) :: s
    s = dti_settings_type(steps_per_period=c%steps_per_period, ss_tol=c%ss_tol, &
      & min_periods=c%min_periods, max_periods=c%max_periods, peak_rtol=c%peak_rtol, &
      & peak_window=c%peak_window, gamma_limit=c%gamma_limit)
  end function dti_from_c

  pure function dti_point_to_c(p) result(c)
    type(dti_point_type), intent(in) :: p
    type(c_dti_point) :: c
    c = c_dti_point(F_E=p%F_E, f=p%f, gamma_1=p%gamma_1, sigma_1=p%sigma_1, &
      & gamma_max=p%gamma_max, gamma_0=p%gamma_0, ss_error=p%ss_error, periods=p%periods, &
      & runs=p%runs, seconds=p%seconds, lift_off=merge(1, 0, p%lift_off))
  end function dti_point_to_c
end module udmap_api_c_baseline
