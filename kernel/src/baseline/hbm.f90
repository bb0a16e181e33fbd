!> The standard convergence-based method (PHYSICS.md 6, paper section 3): harmonic balance with
!> harmonics 1..H (harmonic 0 optional), the damper moment by alternating frequency-time on the
!> contact model with its loading history (udmap_contact_aft_moment), Newton-Raphson with a
!> finite-difference damper Jacobian, pseudo-arc-length continuation in frequency for each force,
!> and the peak
!> of the first harmonic of gamma_P located on the continued curve by root finding.
!>
!> Two variants solve the same equations:
!> - condensed: one complex unknown per harmonic, Gamma_h, with the bare receptances
!>   (paper eqs. 3-4): R_h = Gamma_h - H_gE(h w) F_E delta_h1 + H_gg(h w) M_h(Gamma) = 0;
!> - full: all DOFs, R_h = D(h w) Q_h - F_E e_E delta_h1 + e_g M_h(Q_g) = 0, banded LU of the
!>   real (ndof x 2H) Jacobian at every Newton iteration.
!> The damper moment on the blade is -M_r (M_r = k gamma for a linear damper), so the H = 1
!> solutions equal the layer mapping's g~ = H_gE/(1 + k H_gg).
module udmap_baseline_hbm
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, &
    & UDMAP_ENUMERIC
  use udmap_core_strings, only: itoa
  use udmap_baseline_linear_structure, only: structure_type
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_baseline_types, only: hbm_settings_type, hbm_point_type, hbm_curve_type, &
    & HBM_CONDENSED, HBM_FULL, HBM_MAX_PEAKS, amplitude_scale, problem_type, curve_point_type, &
    & seconds_since
  use udmap_baseline_residual, only: setup, stuck_guess
  use udmap_baseline_continuation, only: newton_fixed, tangent, check_step, corrector_step, &
    & land_at, check_bounded, accept_step
  use udmap_baseline_peak, only: refine_peak, stuck_peak, fill_point, curve_push, sort_pairs
  implicit none
  private
  public :: hbm_peaks, hbm_peak, hbm_response, hbm_settings_type, hbm_point_type, hbm_curve_type, &
    & HBM_CONDENSED, HBM_FULL, HBM_MAX_PEAKS

contains

  ! ------------------------------------------------------------------ drivers

  !> Peaks of the response for each force F_E(i) over [f_min, f_max] [Hz] (warm-started from
  !> the previous force's peak with settings%warm_start).
  subroutine hbm_peaks(st, element, f_min, f_max, F_E, settings, points, error)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E(:)
    type(hbm_settings_type), intent(in) :: settings
    type(hbm_point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(curve_point_type) :: last
    real(wp) :: F_last
    integer :: i
    allocate(points(size(F_E)))
    F_last = 0.0_wp
    do i = 1, size(F_E)
      if (settings%warm_start >= 2 .or. (settings%warm_start == 1 .and. F_last > 0.0_wp)) &
        & then
        call peak_warm(st, element, f_min, f_max, F_E(i), settings, last, F_last, points(i), &
          & error)
      else
        call hbm_peak(st, element, f_min, f_max, F_E(i), settings, points(i), error, last=last)
      end if
      if (allocated(error)) return
      F_last = F_E(i)
    end do
  end subroutine hbm_peaks

  !> The peak for one force by continuation over the band; `curve` (optional) receives the
  !> continued curve, `last` (optional) the peak's state.
  subroutine hbm_peak(st, element, f_min, f_max, F_E, settings, point, error, curve, last)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    type(hbm_settings_type), intent(in) :: settings
    type(hbm_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(hbm_curve_type), intent(out), optional :: curve
    type(curve_point_type), intent(out), optional :: last
    type(problem_type) :: p
    integer(8) :: c0, rate
    call system_clock(c0, rate)
    call setup(p, st, element, f_min, f_max, F_E, settings, error)
    if (allocated(error)) return
    call continuation(p, st, 2.0_wp*pi*f_min, 2.0_wp*pi*f_max, .false., point, error, curve, &
      & last)
    point%seconds = seconds_since(c0, rate)
  end subroutine hbm_peak

  !> The peak for force F_E started from the peak `last` of the force F_last: that state scaled
  !> by F_E/F_last at the same frequency (F_last = 0: the stuck linear response at the peak
  !> frequency of the stuck linear response), corrected by Newton at fixed frequency, then
  !> arc-length steps uphill in gamma_1 (gamma_1 is unimodal along a single-peak curve, folds
  !> or not) until the peak is passed, refined as in the sweep. `last` becomes the new peak.
  !> A warm start that does not converge or a climb that leaves the band falls back to the
  !> sweep (the statistics then count both).
  subroutine peak_warm(st, element, f_min, f_max, F_E, settings, last, F_last, point, error)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E, F_last
    type(hbm_settings_type), intent(in) :: settings
    type(curve_point_type), intent(inout) :: last
    type(hbm_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(problem_type) :: p
    type(curve_point_type) :: cur, nxt, pk
    real(wp), allocatable :: tx0(:)
    real(wp) :: ds, omega_a, omega_b, angle_rejected
    integer :: steps, it, spent_iter, spent_aft
    logical :: ok, found
    integer(8) :: c0, rate
    call system_clock(c0, rate)
    call setup(p, st, element, f_min, f_max, F_E, settings, error)
    if (allocated(error)) return
    omega_a = 2.0_wp*pi*f_min
    omega_b = 2.0_wp*pi*f_max
    found = .false.
    steps = 0
    if (F_last > 0.0_wp) then
      ok = allocated(last%x)
      if (ok) ok = size(last%x) == p%nx
      if (ok) then
        cur%x = last%x*(F_E/F_last)
        cur%omega = last%omega
      end if
    else
      call stuck_peak(p, st, omega_a, omega_b, cur%omega, error)
      if (allocated(error)) return
      allocate(cur%x(p%nx))
      call stuck_guess(p, st, cur%omega, cur%x, error)
      if (allocated(error)) return
      ok = .true.
    end if
    if (ok) then
      call newton_fixed(p, st, cur%x, cur%omega, p%set%tol_path, ok, it, error)
      if (allocated(error)) return
    end if
    if (ok) then
      allocate(cur%tx(p%nx), tx0(p%nx))
      tx0 = 0.0_wp
      call tangent(p, st, cur, tx0, 1.0_wp, error)
      if (allocated(error)) return
      ! climb: travel in the direction in which gamma_1 grows
      if (cur%dA < 0.0_wp) then
        cur%tx = -cur%tx
        cur%tw = -cur%tw
        cur%dA = -cur%dA
      end if
      ds = p%set%ds_initial
      angle_rejected = huge(1.0_wp)
      do while (steps < p%set%max_steps)
        call corrector_step(p, st, cur, ds, nxt, ok, it, error)
        if (allocated(error)) return
        if (ok) call check_step(p, cur, nxt, ds, angle_rejected, ok)
        if (.not.ok) then
          ds = 0.5_wp*ds
          if (ds < p%set%ds_min) exit
          cycle
        end if
        ! left the band: no peak inside it on this side
        if (nxt%omega < omega_a .or. nxt%omega > omega_b) exit
        steps = steps + 1
        angle_rejected = huge(1.0_wp)
        call check_bounded(p, nxt, error)
        if (allocated(error)) return
        if (cur%dA > 0.0_wp .and. nxt%dA <= 0.0_wp) then
          call refine_peak(p, st, cur, nxt, pk, error)
          if (allocated(error)) return
          found = .true.
          exit
        end if
        call accept_step(p, it, ds, cur, nxt)
      end do
    end if
    if (.not.found) then
      spent_iter = p%iterations
      spent_aft = p%ws%calls
      call hbm_peak(st, element, f_min, f_max, F_E, settings, point, error, last=last)
      if (allocated(error)) return
      point%iterations = point%iterations + spent_iter
      point%aft_calls = point%aft_calls + spent_aft
      point%steps = point%steps + steps
    else
      call fill_point(p, st, pk, point, error)
      if (allocated(error)) return
      point%F_E = F_E
      point%npeaks = 1
      point%peaks(1) = point%gamma_P
      point%peak_f(1) = point%f_res
      point%steps = steps
      point%iterations = p%iterations
      point%aft_calls = p%ws%calls
      last = pk
    end if
    point%seconds = seconds_since(c0, rate)
  end subroutine peak_warm

  !> The response at the excitation frequency f_exc [Hz], reached by continuation from f_min.
  !> The point's gamma_P, sigma_a, u_E, k are those at f_exc (f_res = f_exc).
  subroutine hbm_response(st, element, f_min, f_exc, F_E, settings, point, error, curve)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_exc, F_E
    type(hbm_settings_type), intent(in) :: settings
    type(hbm_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(hbm_curve_type), intent(out), optional :: curve
    type(problem_type) :: p
    integer(8) :: c0, rate
    call system_clock(c0, rate)
    if (.not.(f_exc >= f_min)) then
      call fatal_error(error, "hbm: f_exc must be >= f_min", UDMAP_EINPUT)
      return
    end if
    call setup(p, st, element, f_min, max(f_exc, f_min*(1.0_wp + 1.0e-12_wp)), F_E, settings, &
      & error)
    if (allocated(error)) return
    call continuation(p, st, 2.0_wp*pi*f_min, 2.0_wp*pi*f_exc, .true., point, error, curve)
    point%seconds = seconds_since(c0, rate)
  end subroutine hbm_response

  ! ------------------------------------------------------------------ continuation

  !> Continues the response from omega_a to omega_b; peaks refined on the way. With
  !> at_end, the result is the response at omega_b instead of the peak.
  subroutine continuation(p, st, omega_a, omega_b, at_end, point, error, curve, peak_state)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega_a, omega_b
    logical, intent(in) :: at_end
    type(hbm_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(hbm_curve_type), intent(out), optional :: curve
    !> The point of the peak (not with at_end), for a warm start of the next force.
    type(curve_point_type), intent(out), optional :: peak_state
    type(curve_point_type) :: cur, nxt, pk, best_pk
    real(wp) :: ds, A_first, A_best, angle_rejected
    integer :: steps, it, npk, k
    logical :: ok, last, have_best
    real(wp) :: pk_A(HBM_MAX_PEAKS), pk_f(HBM_MAX_PEAKS)

    point%F_E = p%F
    ! start: stuck linear guess at omega_a, Newton at fixed frequency
    allocate(cur%x(p%nx), cur%tx(p%nx))
    call stuck_guess(p, st, omega_a, cur%x, error)
    if (allocated(error)) return
    cur%omega = omega_a
    call newton_fixed(p, st, cur%x, cur%omega, p%set%tol_path, ok, it, error)
    if (allocated(error)) return
    if (.not.ok) then
      call fatal_error(error, "hbm: Newton did not converge at f_min (try more iterations or "// &
        & "a lower tolerance)", UDMAP_ENUMERIC)
      return
    end if
    cur%A_s = amplitude_scale(p, cur%x)
    cur%tx = 0.0_wp
    cur%tw = 1.0_wp
    call tangent(p, st, cur, cur%tx, cur%tw, error)
    if (allocated(error)) return
    if (present(curve)) call curve_push(p, st, curve, cur)
    A_first = cur%A
    npk = 0
    have_best = .false.
    A_best = -1.0_wp
    ds = p%set%ds_initial
    steps = 0
    last = .false.
    angle_rejected = huge(1.0_wp)
    do while (.not.last)
      if (steps >= p%set%max_steps) then
        call fatal_error(error, "hbm: continuation did not cross the band in "// &
          & itoa(p%set%max_steps)//" steps", UDMAP_ENUMERIC)
        return
      end if
      call corrector_step(p, st, cur, ds, nxt, ok, it, error)
      if (allocated(error)) return
      ! a corrected point below the start has jumped to another part of the curve
      if (ok) ok = nxt%omega >= omega_a
      if (ok) call check_step(p, cur, nxt, ds, angle_rejected, ok)
      if (.not.ok) then
        ds = 0.5_wp*ds
        if (ds < p%set%ds_min) then
          call fatal_error(error, "hbm: continuation step fell below ds_min (Newton does not "// &
            & "converge on the curve)", UDMAP_ENUMERIC)
          return
        end if
        cycle
      end if
      if (nxt%omega >= omega_b) then
        ! land exactly on the band end
        call land_at(p, st, cur, nxt, omega_b, merge(p%set%tol, p%set%tol_path, at_end), error)
        if (allocated(error)) return
        last = .true.
      end if
      steps = steps + 1
      angle_rejected = huge(1.0_wp)
      call check_bounded(p, nxt, error)
      if (allocated(error)) return
      if (present(curve)) call curve_push(p, st, curve, nxt)
      ! a local maximum of gamma_1 between cur and nxt: refine it
      if (.not.at_end .and. cur%dA > 0.0_wp .and. nxt%dA <= 0.0_wp) then
        call refine_peak(p, st, cur, nxt, pk, error)
        if (allocated(error)) return
        if (npk < HBM_MAX_PEAKS) then
          npk = npk + 1
          pk_A(npk) = pk%A
          pk_f(npk) = pk%omega/(2.0_wp*pi)
        end if
        if (pk%A > A_best) then
          A_best = pk%A
          best_pk = pk
          have_best = .true.
        end if
      end if
      if (.not.at_end .and. .not.p%set%full_band .and. have_best) then
        if (nxt%A < 0.5_wp*A_best .and. nxt%dA < 0.0_wp) last = .true.
      end if
      call accept_step(p, it, ds, cur, nxt)
    end do
    point%steps = steps
    if (at_end) then
      call fill_point(p, st, cur, point, error)
    else
      if (.not.have_best .or. max(A_first, cur%A) >= A_best) then
        call fatal_error(error, "hbm: no resonance in the band (the largest response is at a "// &
          & "band edge)", UDMAP_EPHYSICS)
        return
      end if
      call fill_point(p, st, best_pk, point, error)
      if (present(peak_state)) peak_state = best_pk
      ! every local maximum, ascending in amplitude
      point%npeaks = npk
      do k = 1, npk
        point%peaks(k) = pk_A(k)
        point%peak_f(k) = pk_f(k)
      end do
      call sort_pairs(point%peaks(1:npk), point%peak_f(1:npk))
    end if
    point%iterations = p%iterations
    point%aft_calls = p%ws%calls
  end subroutine continuation
end module udmap_baseline_hbm
