!> The standard convergence-based method (PHYSICS.md 6, paper section 3): harmonic balance with
!> harmonics 1..H (harmonic 0 optional), the damper moment by alternating frequency-time on the
!> contact model with its loading history (udmap_aft), Newton-Raphson with a finite-difference
!> damper Jacobian, pseudo-arc-length continuation in frequency for each force, and the peak
!> of the first harmonic of gamma_P located on the continued curve by root finding.
!>
!> Two variants solve the same equations:
!> - condensed: one complex unknown per harmonic, Gamma_h, with the bare receptances
!>   (paper eqs. 3-4): R_h = Gamma_h - H_gE(h w) F_E delta_h1 + H_gg(h w) M_h(Gamma) = 0;
!> - full: all DOFs, R_h = D(h w) Q_h - F_E e_E delta_h1 + e_g M_h(Q_g) = 0, banded LU of the
!>   real (ndof x 2H) Jacobian at every Newton iteration.
!> The damper moment on the blade is -M_r (M_r = k gamma for a linear damper), so the H = 1
!> solutions equal the layer mapping's g~ = H_gE/(1 + k H_gg).
module udmap_hbm
  use udmap_kinds, only: wp, pi
  use udmap_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_lapack, only: dgesv, dgbtrf, dgbtrs, dgetrf, dgetrs
  use udmap_linear_structure, only: structure_type, structure_receptances_type, &
    & structure_receptances
  use udmap_hysteretic, only: hysteretic_element_type
  use udmap_aft, only: aft_workspace_type, aft_moment
  implicit none
  private
  public :: hbm_settings_type, hbm_point_type, hbm_curve_type
  public :: hbm_peaks, hbm_peak, hbm_response
  public :: HBM_CONDENSED, HBM_FULL, HBM_MAX_PEAKS

  !> Variant: condensed onto the damper DOF (one unknown per harmonic) or on all DOFs.
  integer, parameter :: HBM_CONDENSED = 0, HBM_FULL = 1
  !> Capacity of the list of local maxima reported per force.
  integer, parameter :: HBM_MAX_PEAKS = 8

  !> Numerical settings of the standard method (every knob of the run time vs error trade-off).
  type :: hbm_settings_type
    integer :: harmonics = 1            !< H: harmonics 1..H
    logical :: harmonic0 = .false.      !< also balance the static harmonic 0
    integer :: variant = HBM_CONDENSED  !< HBM_CONDENSED or HBM_FULL
    real(wp) :: tol = 1.0e-10_wp        !< Newton: relative step tolerance at the peak and outputs
    real(wp) :: tol_path = 1.0e-6_wp    !< Newton: relative step tolerance along the path
    integer :: max_iter = 30            !< Newton iterations per corrector
    real(wp) :: ds_initial = 0.05_wp    !< first arc-length step (relative amplitude/frequency units)
    real(wp) :: ds_min = 1.0e-9_wp      !< smallest step before giving up
    real(wp) :: ds_max = 0.3_wp         !< largest step
    integer :: target_iter = 4          !< step control: Newton iterations aimed at per step
    real(wp) :: max_angle = 0.35_wp     !< largest turn of the tangent per step [rad]
    integer :: max_steps = 20000        !< continuation steps per force
    real(wp) :: peak_tol = 1.0e-10_wp   !< peak refinement: tolerance on the arc-length parameter
    integer :: aft_samples = 0          !< 0: exact event-driven AFT; N > 0: N samples per period
    integer :: aft_min_periods = 1      !< AFT: least periods after the ramp
    integer :: aft_max_periods = 8      !< AFT: most periods until the loop repeats
    real(wp) :: aft_loop_rtol = 1.0e-12_wp  !< AFT: state agreement that closes the loop
    real(wp) :: fd_step = 1.0e-7_wp     !< relative finite-difference step of the damper Jacobian
    real(wp) :: gamma_limit = 10.0_wp   !< amplitude [rad] beyond which the response is unbounded
    logical :: full_band = .true.       !< continue to f_max; else stop when past the peak
    !> Keep the damper Jacobian from one Newton iteration (and step) to the next while Newton
    !> contracts well (chord steps: one AFT per iteration); .false.: new one every iteration.
    logical :: jacobian_reuse = .true.
  end type hbm_settings_type

  !> The peak of the response for one force (fields as the backbone's, plus statistics).
  type :: hbm_point_type
    real(wp) :: F_E = 0.0_wp       !< excitation force amplitude [N]
    real(wp) :: gamma_P = 0.0_wp   !< first-harmonic amplitude of gamma_P at the peak [rad]
    real(wp) :: f_res = 0.0_wp     !< frequency of the peak [Hz]
    real(wp) :: sigma_a = 0.0_wp   !< first-harmonic stress amplitude at f_res [Pa]
    real(wp) :: u_E = 0.0_wp       !< first-harmonic displacement amplitude at E [m]
    real(wp) :: k_re = 0.0_wp, k_im = 0.0_wp   !< M_1/Gamma_1 at the peak [N m/rad]
    real(wp) :: gamma_max = 0.0_wp !< largest gamma(t) over the period at the peak [rad]
    logical :: lift_off = .false.  !< a damper contact opens during the cycle at the peak
    integer :: npeaks = 0          !< number of local maxima of gamma_1 on the curve
    real(wp) :: peaks(HBM_MAX_PEAKS) = 0.0_wp   !< their gamma_1, ascending
    real(wp) :: peak_f(HBM_MAX_PEAKS) = 0.0_wp  !< their frequencies [Hz]
    real(wp), allocatable :: gamma_h(:)         !< |Gamma_h|, h = 1..H, at the peak [rad]
    integer :: steps = 0           !< accepted continuation steps
    integer :: iterations = 0      !< Newton iterations (all correctors)
    integer :: aft_calls = 0       !< AFT evaluations (including the Jacobians)
    real(wp) :: seconds = 0.0_wp   !< wall time of this force [s]
  end type hbm_point_type

  !> The continued response curve of one force (accepted points, in order).
  type :: hbm_curve_type
    integer :: n = 0
    real(wp), allocatable :: f(:)          !< frequency [Hz]
    real(wp), allocatable :: gamma_1(:)    !< |Gamma_1| [rad]
    real(wp), allocatable :: sigma_1(:)    !< first-harmonic stress amplitude [Pa]
    real(wp), allocatable :: gamma_max(:)  !< largest gamma(t) [rad]
  end type hbm_curve_type

  !> Everything one force's continuation needs; owned by the driver, nothing global.
  type :: problem_type
    type(hbm_settings_type) :: set
    integer :: H = 1, h0 = 0, m = 2, b = 2, nx = 2, goff = 0, n = 1
    real(wp) :: F = 0.0_wp, W_s = 1.0_wp, k_stuck = 0.0_wp, Hgg0 = 0.0_wp, M_ref = 0.0_wp
    class(hysteretic_element_type), allocatable :: el
    type(aft_workspace_type) :: ws
    ! damper moment at the last evaluation and its Jacobian d(M vector)/d(gamma unknowns)
    real(wp) :: M0 = 0.0_wp, gmax = 0.0_wp
    complex(wp), allocatable :: Mh(:)
    real(wp), allocatable :: JM(:,:)
    ! receptances at h*omega (condensed) and the omega they belong to
    type(structure_receptances_type), allocatable :: rec(:)
    real(wp) :: omega_rec = -1.0_wp
    ! factorised x-Jacobian: dense (condensed) or banded LU (full)
    real(wp), allocatable :: Jd(:,:), LU(:,:)
    integer, allocatable :: ipiv(:)
    integer :: kb = 0
    logical :: banded = .false.
    !> omega-derivative of the residual at the last Newton iterate (its J_x is still factorised)
    real(wp), allocatable :: Jw_last(:)
    !> p%JM holds a damper Jacobian that may be reused
    logical :: jm_valid = .false.
    integer :: iterations = 0
  end type problem_type

  !> A converged point of the curve with its tangent (unscaled) and metric.
  type :: curve_point_type
    real(wp), allocatable :: x(:), tx(:)
    real(wp) :: omega = 0.0_wp, tw = 0.0_wp, A = 0.0_wp, dA = 0.0_wp, A_s = 1.0_wp
  end type curve_point_type

contains

  ! ------------------------------------------------------------------ drivers

  !> Peaks of the response for each force F_E(i) over [f_min, f_max] [Hz].
  subroutine hbm_peaks(st, element, f_min, f_max, F_E, settings, points, error)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E(:)
    type(hbm_settings_type), intent(in) :: settings
    type(hbm_point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    integer :: i
    allocate(points(size(F_E)))
    do i = 1, size(F_E)
      call hbm_peak(st, element, f_min, f_max, F_E(i), settings, points(i), error)
      if (allocated(error)) return
    end do
  end subroutine hbm_peaks

  !> The peak for one force; `curve` (optional) receives the continued curve.
  subroutine hbm_peak(st, element, f_min, f_max, F_E, settings, point, error, curve)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    type(hbm_settings_type), intent(in) :: settings
    type(hbm_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(hbm_curve_type), intent(out), optional :: curve
    type(problem_type) :: p
    integer(8) :: c0, c1, rate
    call system_clock(c0, rate)
    call setup(p, st, element, f_min, f_max, F_E, settings, error)
    if (allocated(error)) return
    call continuation(p, st, 2.0_wp*pi*f_min, 2.0_wp*pi*f_max, .false., point, error, curve)
    call system_clock(c1)
    point%seconds = real(c1 - c0, wp)/real(rate, wp)
  end subroutine hbm_peak

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
    integer(8) :: c0, c1, rate
    call system_clock(c0, rate)
    if (.not.(f_exc >= f_min)) then
      call fatal_error(error, "hbm: f_exc must be >= f_min", UDMAP_EINPUT)
      return
    end if
    call setup(p, st, element, f_min, max(f_exc, f_min*(1.0_wp + 1.0e-12_wp)), F_E, settings, &
      & error)
    if (allocated(error)) return
    call continuation(p, st, 2.0_wp*pi*f_min, 2.0_wp*pi*f_exc, .true., point, error, curve)
    call system_clock(c1)
    point%seconds = real(c1 - c0, wp)/real(rate, wp)
  end subroutine hbm_response

  subroutine setup(p, st, element, f_min, f_max, F_E, settings, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    type(hbm_settings_type), intent(in) :: settings
    type(error_type), allocatable, intent(out) :: error
    type(structure_receptances_type) :: r0
    if (st%ndof < 1) then
      call fatal_error(error, "hbm: the structure is empty", UDMAP_EINPUT)
      return
    end if
    if (.not.(F_E > 0.0_wp) .or. F_E > huge(1.0_wp)) then
      call fatal_error(error, "hbm: F_E must be positive and finite", UDMAP_EINPUT)
      return
    end if
    if (.not.(f_min > 0.0_wp) .or. .not.(f_max > f_min) .or. f_max > huge(1.0_wp)) then
      call fatal_error(error, "hbm: need 0 < f_min < f_max (finite)", UDMAP_EINPUT)
      return
    end if
    if (settings%harmonics < 1 .or. settings%harmonics > 64) then
      call fatal_error(error, "hbm: harmonics must be in 1..64", UDMAP_EINPUT)
      return
    end if
    if (settings%variant /= HBM_CONDENSED .and. settings%variant /= HBM_FULL) then
      call fatal_error(error, "hbm: variant must be condensed (0) or full (1)", UDMAP_EINPUT)
      return
    end if
    if (.not.(settings%tol > 0.0_wp) .or. .not.(settings%tol_path > 0.0_wp) .or. &
        & .not.(settings%ds_min > 0.0_wp) .or. &
        & .not.(settings%ds_max >= settings%ds_min) .or. .not.(settings%ds_initial > 0.0_wp) &
        & .or. .not.(settings%fd_step > 0.0_wp) .or. .not.(settings%peak_tol > 0.0_wp) .or. &
        & .not.(settings%max_angle > 0.0_wp) .or. .not.(settings%gamma_limit > 0.0_wp) .or. &
        & settings%max_iter < 2 .or. settings%max_steps < 1 .or. settings%target_iter < 1 .or. &
        & settings%aft_samples < 0 .or. settings%aft_max_periods < 1 .or. &
        & .not.(settings%aft_loop_rtol > 0.0_wp)) then
      call fatal_error(error, "hbm: invalid numerical settings (tolerances and steps must be "// &
        & "positive, max_iter >= 2, aft_samples >= 0)", UDMAP_EINPUT)
      return
    end if
    if (settings%aft_samples > 0 .and. settings%aft_samples < 2*settings%harmonics + 1) then
      call fatal_error(error, "hbm: aft_samples must be 0 (exact) or >= 2 H + 1", UDMAP_EINPUT)
      return
    end if
    p%set = settings
    p%H = settings%harmonics
    p%h0 = merge(1, 0, settings%harmonic0)
    p%m = 2*p%H + p%h0
    p%F = F_E
    p%n = st%ndof
    p%W_s = 2.0_wp*pi*f_min
    if (settings%variant == HBM_CONDENSED) then
      p%b = p%m
      p%nx = p%m
      p%goff = 0
    else
      p%b = p%m
      p%nx = p%m*st%ndof
      p%goff = (st%gamma_dof - 1)*p%b
      if (st%kd >= 0) p%kb = (st%kd + 1)*p%b - 1
      p%banded = st%kd >= 0
    end if
    allocate(p%el, source=element)
    allocate(p%Mh(p%H), p%JM(p%m, p%m), p%rec(p%H))
    call p%el%load(error)
    if (allocated(error)) return
    p%k_stuck = p%el%stuck_stiffness()
    ! the static moment of the loaded damper is in equilibrium with the blade's reference state
    p%M_ref = p%el%moment()
    if (p%h0 == 1 .and. settings%variant == HBM_CONDENSED) then
      call structure_receptances(st, 0.0_wp, r0, error)
      if (allocated(error)) return
      p%Hgg0 = real(r0%gg, wp)
    end if
  end subroutine setup

  ! ------------------------------------------------------------------ continuation

  !> Continues the response from omega_a to omega_b; peaks refined on the way. With
  !> at_end, the result is the response at omega_b instead of the peak.
  subroutine continuation(p, st, omega_a, omega_b, at_end, point, error, curve)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega_a, omega_b
    logical, intent(in) :: at_end
    type(hbm_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(hbm_curve_type), intent(out), optional :: curve
    type(curve_point_type) :: cur, nxt, pk, best_pk
    real(wp) :: ds, cosang, fac, A_first, A_best, angle, angle_rejected
    integer :: steps, it, npk, k
    logical :: ok, last, have_best
    real(wp) :: pk_A(HBM_MAX_PEAKS), pk_f(HBM_MAX_PEAKS)
    character(len=24) :: buf

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
        write(buf, '(i0)') p%set%max_steps
        call fatal_error(error, "hbm: continuation did not cross the band in "//trim(buf)// &
          & " steps", UDMAP_ENUMERIC)
        return
      end if
      call corrector_step(p, st, cur, ds, nxt, ok, it, error)
      if (allocated(error)) return
      ! jumps to another part of the curve: a corrected point below the start, far from the
      ! predictor (a corner of angle theta puts it ds tan(theta) away), or an amplitude changed
      ! threefold in one step
      if (ok) ok = nxt%omega >= omega_a .and. nxt%A <= 3.0_wp*cur%A .and. 3.0_wp*nxt%A >= cur%A
      if (ok) ok = sqrt(scaled_dot(p, nxt%x - cur%x - ds*cur%tx, nxt%omega - cur%omega - &
        & ds*cur%tw, nxt%x - cur%x - ds*cur%tx, nxt%omega - cur%omega - ds*cur%tw, cur%A_s)) &
        & <= 3.0_wp*ds
      if (ok) then
        ! the tangent may turn by at most max_angle per step; a turn that does not shrink with
        ! a small step is a corner of the curve (stick-slip transition of the damper): accept it
        cosang = scaled_dot(p, cur%tx, cur%tw, nxt%tx, nxt%tw, cur%A_s)
        angle = acos(max(-1.0_wp, min(1.0_wp, cosang)))
        if (angle > p%set%max_angle .and. .not.(angle > 0.7_wp*angle_rejected .and. &
            & ds <= 0.01_wp .and. angle < 0.5_wp*pi)) then
          ok = .false.
          angle_rejected = angle
        end if
      end if
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
      if (nxt%A > p%set%gamma_limit) then
        call fatal_error(error, "hbm: the response exceeds gamma_limit (unbounded: F_E at or "// &
          & "above the limit force with little damping, or a force far beyond the model)", &
          & UDMAP_EPHYSICS)
        return
      end if
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
      ! step control on the Newton iterations of this step
      if (2*it <= p%set%target_iter) then
        fac = 2.0_wp
      else if (it < p%set%target_iter) then
        fac = 1.5_wp
      else if (it > p%set%target_iter + 1) then
        fac = 0.6_wp
      else
        fac = 1.0_wp
      end if
      ds = min(p%set%ds_max, ds*fac)
      call move_alloc(nxt%x, cur%x)
      call move_alloc(nxt%tx, cur%tx)
      cur%omega = nxt%omega
      cur%tw = nxt%tw
      cur%A = nxt%A
      cur%dA = nxt%dA
      cur%A_s = amplitude_scale(p, cur%x)
      call renormalise(p, cur)
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

  !> Predictor along the tangent of cur, pseudo-arc-length corrector; nxt gets its tangent.
  subroutine corrector_step(p, st, cur, ds, nxt, ok, it, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: cur
    real(wp), intent(in) :: ds
    type(curve_point_type), intent(out) :: nxt
    logical, intent(out) :: ok
    integer, intent(out) :: it
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: xp(:)
    real(wp) :: wp_
    xp = cur%x + ds*cur%tx
    wp_ = cur%omega + ds*cur%tw
    nxt%x = xp
    nxt%omega = wp_
    call newton_arclength(p, st, nxt%x, nxt%omega, cur, xp, wp_, p%set%tol_path, ok, it, error)
    if (allocated(error) .or. .not.ok) return
    nxt%A_s = cur%A_s
    allocate(nxt%tx(p%nx))
    ! tangent from a new Jacobian at the converged point; with jacobian_reuse it also serves
    ! the chord iterations of the next corrector
    call tangent(p, st, nxt, cur%tx, cur%tw, error, cur%A_s, reuse=.not.p%set%jacobian_reuse)
  end subroutine corrector_step

  !> Replaces nxt (beyond omega_end) by the point at omega_end, by Newton at fixed frequency
  !> from the linear interpolation between cur and nxt.
  subroutine land_at(p, st, cur, nxt, omega_end, tol, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: cur
    type(curve_point_type), intent(inout) :: nxt
    real(wp), intent(in) :: omega_end, tol
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: th
    real(wp), allocatable :: tx_old(:)
    real(wp) :: tw_old
    logical :: ok
    integer :: it
    th = 1.0_wp
    if (nxt%omega /= cur%omega) th = (omega_end - cur%omega)/(nxt%omega - cur%omega)
    nxt%x = cur%x + th*(nxt%x - cur%x)
    nxt%omega = omega_end
    call newton_fixed(p, st, nxt%x, nxt%omega, tol, ok, it, error)
    if (allocated(error)) return
    if (.not.ok) then
      call fatal_error(error, "hbm: Newton did not converge at the band end", UDMAP_ENUMERIC)
      return
    end if
    tx_old = nxt%tx
    tw_old = nxt%tw
    call tangent(p, st, nxt, tx_old, tw_old, error, cur%A_s)
  end subroutine land_at

  !> The local maximum of gamma_1 between a (dA > 0) and b (dA <= 0): Illinois root finding on
  !> dA/ds along the family of hyperplanes orthogonal to a's tangent.
  subroutine refine_peak(p, st, a, b, pk, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: a, b
    type(curve_point_type), intent(out) :: pk
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: s_lo, s_hi, g_lo, g_hi, s, g, w_lo, w_hi
    real(wp), allocatable :: x_lo(:), x_hi(:), xp(:)
    real(wp) :: wp_
    integer :: iter, side, it, retry
    logical :: ok
    type(curve_point_type) :: trial
    s_lo = 0.0_wp
    s_hi = scaled_dot(p, a%tx, a%tw, b%x - a%x, b%omega - a%omega, a%A_s)
    g_lo = a%dA
    g_hi = b%dA
    allocate(x_lo(p%nx), x_hi(p%nx))
    x_lo = a%x; w_lo = a%omega
    x_hi = b%x; w_hi = b%omega
    pk = b
    if (g_hi == 0.0_wp .or. s_hi <= 0.0_wp) return
    side = 0
    allocate(trial%tx(p%nx))
    do iter = 1, 200
      s = s_lo - g_lo*(s_hi - s_lo)/(g_hi - g_lo)
      if (.not.(s > s_lo .and. s < s_hi)) s = 0.5_wp*(s_lo + s_hi)
      ! predictor on the hyperplane at s: interpolate the bracket
      trial%x = x_lo + (s - s_lo)/(s_hi - s_lo)*(x_hi - x_lo)
      trial%omega = w_lo + (s - s_lo)/(s_hi - s_lo)*(w_hi - w_lo)
      xp = a%x + s*a%tx
      wp_ = a%omega + s*a%tw
      call newton_arclength(p, st, trial%x, trial%omega, a, xp, wp_, p%set%tol, ok, it, error)
      if (allocated(error)) return
      ! retry from the bracket ends (a kink of the damper law between them can defeat the
      ! interpolated guess)
      do retry = 1, 2
        if (ok) exit
        if (retry == 1) then
          trial%x = x_lo; trial%omega = w_lo
        else
          trial%x = x_hi; trial%omega = w_hi
        end if
        call newton_arclength(p, st, trial%x, trial%omega, a, xp, wp_, p%set%tol, ok, it, error)
        if (allocated(error)) return
      end do
      if (.not.ok) then
        ! at the rounding floor: the bracket already pins the peak, keep the best end
        if (s_hi - s_lo <= 1.0e-6_wp*max(1.0_wp, s_hi)) exit
        call fatal_error(error, "hbm: Newton did not converge while refining the peak", &
          & UDMAP_ENUMERIC)
        return
      end if
      trial%A_s = a%A_s
      call tangent(p, st, trial, a%tx, a%tw, error, a%A_s, central=.true.)
      if (allocated(error)) return
      g = trial%dA
      if (g > 0.0_wp) then
        s_lo = s; g_lo = g; x_lo = trial%x; w_lo = trial%omega
        if (side == -1) g_hi = 0.5_wp*g_hi
        side = -1
      else
        s_hi = s; g_hi = g; x_hi = trial%x; w_hi = trial%omega
        if (side == 1) g_lo = 0.5_wp*g_lo
        side = 1
      end if
      pk = trial
      if (g == 0.0_wp .or. s_hi - s_lo <= p%set%peak_tol*max(1.0_wp, s_hi)) exit
    end do
  end subroutine refine_peak

  ! ------------------------------------------------------------------ Newton

  !> Newton at fixed omega from x.
  subroutine newton_fixed(p, st, x, omega, tol, ok, it, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(inout) :: x(:)
    real(wp), intent(in) :: omega, tol
    logical, intent(out) :: ok
    integer, intent(out) :: it
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: R(:), Jw(:), dx(:), cx(:)
    real(wp) :: dw, A_s, stepn, prev, prev2
    allocate(R(p%nx), Jw(p%nx), dx(p%nx), cx(p%m))
    cx = 0.0_wp
    ok = .false.
    prev = huge(1.0_wp)
    prev2 = huge(1.0_wp)
    do it = 1, p%set%max_iter
      call evaluate(p, st, x, omega, R, error, Jw=Jw)
      if (allocated(error)) return
      call factor(p, st, omega, error)
      if (allocated(error)) return
      call bordered_solve(p, Jw, cx, 1.0_wp, -R, 0.0_wp, dx, dw, error)
      if (allocated(error)) return
      x = x + dx
      p%iterations = p%iterations + 1
      A_s = amplitude_scale(p, x)
      stepn = norm2(dx(p%goff+1:p%goff+p%m))/A_s
      if (.not.(stepn <= huge(1.0_wp))) return
      if (converged(tol, stepn, prev, prev2)) then
        ok = .true.
        return
      end if
      if (amplitude(p, x) > 10.0_wp*p%set%gamma_limit) return
      prev2 = prev
      prev = stepn
    end do
  end subroutine newton_fixed

  !> Newton on [R = 0; <t, y - y_p> = 0] with the tangent and metric of `base`.
  subroutine newton_arclength(p, st, x, omega, base, xp, omega_p, tol, ok, it, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(inout) :: x(:), omega
    type(curve_point_type), intent(in) :: base
    real(wp), intent(in) :: xp(:), omega_p, tol
    logical, intent(out) :: ok
    integer, intent(out) :: it
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: R(:), Jw(:), dx(:), cx(:)
    real(wp) :: dw, cw, Nres, stepn, prev, prev2
    integer :: grow
    logical :: fresh
    allocate(R(p%nx), Jw(p%nx), dx(p%nx))
    cx = base%tx(p%goff+1:p%goff+p%m)/base%A_s**2
    cw = base%tw/p%W_s**2
    ok = .false.
    prev = huge(1.0_wp)
    prev2 = huge(1.0_wp)
    grow = 0
    fresh = .not.(p%set%jacobian_reuse .and. p%jm_valid)
    do it = 1, p%set%max_iter
      call evaluate(p, st, x, omega, R, error, Jw=Jw, damper_jacobian=fresh)
      if (allocated(error)) return
      call factor(p, st, omega, error)
      if (allocated(error)) return
      Nres = dot_product(cx, x(p%goff+1:p%goff+p%m) - xp(p%goff+1:p%goff+p%m)) + &
        & cw*(omega - omega_p)
      call bordered_solve(p, Jw, cx, cw, -R, -Nres, dx, dw, error)
      if (allocated(error)) return
      p%Jw_last = Jw
      x = x + dx
      omega = omega + dw
      p%iterations = p%iterations + 1
      stepn = norm2(dx(p%goff+1:p%goff+p%m))/base%A_s + abs(dw)/p%W_s
      if (.not.(stepn <= huge(1.0_wp)) .or. .not.(omega > 0.0_wp)) exit
      ! converged when the step, or the next one predicted from the contraction rate, is small
      if (converged(tol, stepn, prev, prev2)) then
        ok = .true.
        return
      end if
      if (amplitude(p, x) > 10.0_wp*p%set%gamma_limit) exit
      ! divergence: the step keeps growing
      if (stepn > prev) then
        grow = grow + 1
        if (grow >= 3) exit
      end if
      ! a reused damper Jacobian that no longer contracts well is renewed
      fresh = .not.p%set%jacobian_reuse .or. stepn > 0.25_wp*prev
      prev2 = prev
      prev = stepn
    end do
    ! failed: start the next attempt with a new Jacobian
    p%jm_valid = .false.
  end subroutine newton_arclength

  !> Tangent at pt (converged): solves [J_x Jw; <t_ref, .>] t = [0; 1], normalises it in the
  !> metric and sets pt%A, pt%dA. With central, the damper Jacobian by central differences.
  subroutine tangent(p, st, pt, tx_ref, tw_ref, error, A_s, central, reuse)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(inout) :: pt
    real(wp), intent(in) :: tx_ref(:), tw_ref
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: A_s
    logical, intent(in), optional :: central
    !> Use the Jacobian of the last Newton iterate (already factorised) instead of a new one.
    logical, intent(in), optional :: reuse
    real(wp), allocatable :: R(:), Jw(:), cx(:), zero(:)
    real(wp) :: cw, tw, nrm, As
    logical :: again
    allocate(R(p%nx), Jw(p%nx), zero(p%nx))
    zero = 0.0_wp
    As = amplitude_scale(p, pt%x)
    if (present(A_s)) As = A_s
    again = .false.
    if (present(reuse)) again = reuse .and. allocated(p%Jw_last)
    if (again) then
      Jw = p%Jw_last
    else
      call evaluate(p, st, pt%x, pt%omega, R, error, Jw=Jw, central=central)
      if (allocated(error)) return
      call factor(p, st, pt%omega, error)
      if (allocated(error)) return
    end if
    cx = tx_ref(p%goff+1:p%goff+p%m)/As**2
    cw = tw_ref/p%W_s**2
    call bordered_solve(p, Jw, cx, cw, zero, 1.0_wp, pt%tx, tw, error)
    if (allocated(error)) return
    pt%tw = tw
    nrm = sqrt(scaled_dot(p, pt%tx, pt%tw, pt%tx, pt%tw, As))
    if (.not.(nrm > 0.0_wp) .or. nrm > huge(1.0_wp)) then
      call fatal_error(error, "hbm: the tangent of the response curve is degenerate", &
        & UDMAP_ENUMERIC)
      return
    end if
    pt%tx = pt%tx/nrm
    pt%tw = pt%tw/nrm
    pt%A_s = As
    pt%A = amplitude(p, pt%x)
    pt%dA = 0.0_wp
    if (pt%A > 0.0_wp) pt%dA = (pt%x(p%goff+p%h0+1)*pt%tx(p%goff+p%h0+1) + &
      & pt%x(p%goff+p%h0+2)*pt%tx(p%goff+p%h0+2))/pt%A/As
  end subroutine tangent

  !> Re-normalises the tangent of pt in its current metric (after A_s changed).
  subroutine renormalise(p, pt)
    type(problem_type), intent(in) :: p
    type(curve_point_type), intent(inout) :: pt
    real(wp) :: nrm
    nrm = sqrt(scaled_dot(p, pt%tx, pt%tw, pt%tx, pt%tw, pt%A_s))
    if (nrm > 0.0_wp) then
      pt%tx = pt%tx/nrm
      pt%tw = pt%tw/nrm
    end if
    if (pt%A > 0.0_wp) pt%dA = (pt%x(p%goff+p%h0+1)*pt%tx(p%goff+p%h0+1) + &
      & pt%x(p%goff+p%h0+2)*pt%tx(p%goff+p%h0+2))/pt%A/pt%A_s
  end subroutine renormalise

  !> Newton convergence: the step is below tol, or the next one, predicted from two successive
  !> contractions, is (saves the confirming iteration of a quadratically converging Newton), or
  !> the steps stagnate just above tol (the rounding floor of an ill-conditioned full system).
  pure logical function converged(tol, stepn, prev, prev2)
    real(wp), intent(in) :: tol, stepn, prev, prev2
    converged = stepn <= tol
    if (converged .or. prev >= huge(1.0_wp)) return
    converged = stepn <= 100.0_wp*tol .and. prev <= 100.0_wp*tol .and. stepn > 0.5_wp*prev
    if (converged .or. prev2 >= huge(1.0_wp)) return
    converged = stepn <= 0.2_wp*prev .and. prev <= 0.5_wp*prev2 .and. stepn**2/prev <= tol
  end function converged

  ! ------------------------------------------------------------------ residual and Jacobian

  !> The residual R(x, omega), its omega-derivative Jw and the damper Jacobian p%JM (finite
  !> differences of the AFT in the gamma unknowns, forward or central).
  subroutine evaluate(p, st, x, omega, R, error, Jw, central, damper_jacobian)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: x(:), omega
    real(wp), intent(out) :: R(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: Jw(:)
    logical, intent(in), optional :: central
    !> With Jw: also the damper Jacobian by finite differences (default); .false. keeps p%JM.
    logical, intent(in), optional :: damper_jacobian
    real(wp), allocatable :: xg(:), Mv(:), Mp(:), Mm(:)
    real(wp) :: delta, scale
    integer :: c
    logical :: cen, fd
    cen = .false.
    if (present(central)) cen = central
    fd = present(Jw)
    if (present(damper_jacobian)) fd = fd .and. damper_jacobian
    allocate(xg(p%m))
    xg = x(p%goff+1:p%goff+p%m)
    call damper_vector(p, xg, Mv, error)
    if (allocated(error)) return
    call unpack_moment(p, Mv)
    if (fd) then
      p%jm_valid = .true.
      scale = max(norm2(xg), tiny(1.0_wp))
      do c = 1, p%m
        delta = p%set%fd_step*scale
        xg(c) = x(p%goff+c) + delta
        call damper_vector(p, xg, Mp, error)
        if (allocated(error)) return
        if (cen) then
          xg(c) = x(p%goff+c) - delta
          call damper_vector(p, xg, Mm, error)
          if (allocated(error)) return
          p%JM(:, c) = (Mp - Mm)/(2.0_wp*delta)
        else
          p%JM(:, c) = (Mp - Mv)/delta
        end if
        xg(c) = x(p%goff+c)
      end do
      ! restore the moment of the base point (damper_vector overwrote nothing else)
      call unpack_moment(p, Mv)
    end if
    if (p%set%variant == HBM_CONDENSED) then
      call condensed_residual(p, st, x, omega, R, error, Jw)
    else
      call full_residual(p, st, x, omega, R, Jw)
    end if
  end subroutine evaluate

  !> The damper moment as a real vector in the layout of the gamma unknowns.
  subroutine damper_vector(p, xg, Mv, error)
    type(problem_type), intent(inout) :: p
    real(wp), intent(in) :: xg(:)
    real(wp), allocatable, intent(out) :: Mv(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: G0, M0
    complex(wp) :: G(p%H), M(p%H)
    integer :: h
    G0 = 0.0_wp
    if (p%h0 == 1) G0 = xg(1)
    do h = 1, p%H
      G(h) = cmplx(xg(p%h0+2*h-1), xg(p%h0+2*h), wp)
    end do
    call aft_moment(p%el, p%ws, G0, G, p%set%aft_samples, p%set%aft_min_periods, &
      & p%set%aft_max_periods, p%set%aft_loop_rtol, M0, M, error, gamma_max=p%gmax)
    allocate(Mv(p%m))
    if (allocated(error)) return
    if (p%h0 == 1) Mv(1) = M0
    do h = 1, p%H
      Mv(p%h0+2*h-1) = real(M(h), wp)
      Mv(p%h0+2*h) = aimag(M(h))
    end do
  end subroutine damper_vector

  pure subroutine unpack_moment(p, Mv)
    type(problem_type), intent(inout) :: p
    real(wp), intent(in) :: Mv(:)
    integer :: h
    p%M0 = 0.0_wp
    if (p%h0 == 1) p%M0 = Mv(1)
    do h = 1, p%H
      p%Mh(h) = cmplx(Mv(p%h0+2*h-1), Mv(p%h0+2*h), wp)
    end do
  end subroutine unpack_moment

  !> Receptances at h omega, h = 1..H (cached per omega).
  subroutine update_receptances(p, st, omega, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    type(error_type), allocatable, intent(out) :: error
    integer :: h
    if (omega == p%omega_rec) return
    do h = 1, p%H
      call structure_receptances(st, h*omega, p%rec(h), error)
      if (allocated(error)) return
    end do
    p%omega_rec = omega
  end subroutine update_receptances

  subroutine condensed_residual(p, st, x, omega, R, error, Jw)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: x(:), omega
    real(wp), intent(out) :: R(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: Jw(:)
    complex(wp) :: G, Rh, dR
    integer :: h, i
    call update_receptances(p, st, omega, error)
    if (allocated(error)) return
    if (p%h0 == 1) then
      R(1) = x(1) + p%Hgg0*(p%M0 - p%M_ref)
      if (present(Jw)) Jw(1) = 0.0_wp
    end if
    do h = 1, p%H
      i = p%h0 + 2*h - 1
      G = cmplx(x(i), x(i+1), wp)
      Rh = G + p%rec(h)%gg*p%Mh(h)
      if (h == 1) Rh = Rh - p%rec(1)%gE*p%F
      R(i) = real(Rh, wp)
      R(i+1) = aimag(Rh)
      if (present(Jw)) then
        dR = h*p%rec(h)%dgg*p%Mh(h)
        if (h == 1) dR = dR - p%rec(1)%dgE*p%F
        Jw(i) = real(dR, wp)
        Jw(i+1) = aimag(dR)
      end if
    end do
  end subroutine condensed_residual

  pure subroutine full_residual(p, st, x, omega, R, Jw)
    type(problem_type), intent(in) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: x(:), omega
    real(wp), intent(out) :: R(:)
    real(wp), intent(out), optional :: Jw(:)
    integer :: i, j, h, lo, hi, bi, bj, cr
    real(wp) :: kij, mij, cij, Om, a, bb, dm
    R = 0.0_wp
    if (present(Jw)) Jw = 0.0_wp
    do i = 1, p%n
      lo = 1; hi = p%n
      if (st%kd >= 0) then
        lo = max(1, i - st%kd); hi = min(p%n, i + st%kd)
      end if
      bi = (i - 1)*p%b
      do j = lo, hi
        kij = st%entry('K', i, j)
        mij = st%entry('M', i, j)
        cij = st%entry('C', i, j)
        bj = (j - 1)*p%b
        if (p%h0 == 1) R(bi+1) = R(bi+1) + kij*x(bj+1)
        do h = 1, p%H
          cr = p%h0 + 2*h - 1
          Om = h*omega
          a = kij - Om**2*mij
          bb = Om*cij
          R(bi+cr) = R(bi+cr) + a*x(bj+cr) - bb*x(bj+cr+1)
          R(bi+cr+1) = R(bi+cr+1) + bb*x(bj+cr) + a*x(bj+cr+1)
          if (present(Jw)) then
            ! d/domega of D(h omega) Q_h = h (-2 h omega M + i C) Q_h
            dm = -2.0_wp*h*Om*mij
            Jw(bi+cr) = Jw(bi+cr) + dm*x(bj+cr) - h*cij*x(bj+cr+1)
            Jw(bi+cr+1) = Jw(bi+cr+1) + h*cij*x(bj+cr) + dm*x(bj+cr+1)
          end if
        end do
      end do
    end do
    bi = (st%exc_dof - 1)*p%b
    R(bi+p%h0+1) = R(bi+p%h0+1) - p%F
    bi = p%goff
    if (p%h0 == 1) R(bi+1) = R(bi+1) + p%M0 - p%M_ref
    do h = 1, p%H
      cr = p%h0 + 2*h - 1
      R(bi+cr) = R(bi+cr) + real(p%Mh(h), wp)
      R(bi+cr+1) = R(bi+cr+1) + aimag(p%Mh(h))
    end do
  end subroutine full_residual

  !> Assembles and factorises J_x (dense for condensed, banded or dense LU for full).
  subroutine factor(p, st, omega, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    type(error_type), allocatable, intent(out) :: error
    integer :: i, j, h, c, cc, lo, hi, bi, bj, cr, info, ldab, kb, r0
    real(wp) :: kij, mij, cij, Om, a, bb, gr, gi
    character(len=12) :: buf
    if (p%set%variant == HBM_CONDENSED) then
      ! J_x = I + blockdiag(H_gg(h omega)) JM, complex products as 2x2 real blocks
      if (.not.allocated(p%Jd)) allocate(p%Jd(p%m, p%m))
      p%Jd = 0.0_wp
      do c = 1, p%m
        p%Jd(c, c) = 1.0_wp
      end do
      if (p%h0 == 1) p%Jd(1, :) = p%Jd(1, :) + p%Hgg0*p%JM(1, :)
      do h = 1, p%H
        cr = p%h0 + 2*h - 1
        gr = real(p%rec(h)%gg, wp)
        gi = aimag(p%rec(h)%gg)
        p%Jd(cr, :) = p%Jd(cr, :) + gr*p%JM(cr, :) - gi*p%JM(cr+1, :)
        p%Jd(cr+1, :) = p%Jd(cr+1, :) + gi*p%JM(cr, :) + gr*p%JM(cr+1, :)
      end do
      return
    end if
    kb = p%kb
    if (st%kd >= 0) then
      ldab = 3*kb + 1
      if (.not.allocated(p%LU)) allocate(p%LU(ldab, p%nx), p%ipiv(p%nx))
      p%LU = 0.0_wp
      r0 = 2*kb + 1
    else
      if (.not.allocated(p%LU)) allocate(p%LU(p%nx, p%nx), p%ipiv(p%nx))
      p%LU = 0.0_wp
      r0 = 0
    end if
    do i = 1, p%n
      lo = 1; hi = p%n
      if (st%kd >= 0) then
        lo = max(1, i - st%kd); hi = min(p%n, i + st%kd)
      end if
      bi = (i - 1)*p%b
      do j = lo, hi
        kij = st%entry('K', i, j)
        mij = st%entry('M', i, j)
        cij = st%entry('C', i, j)
        bj = (j - 1)*p%b
        if (p%h0 == 1) call put(bi+1, bj+1, kij)
        do h = 1, p%H
          cr = p%h0 + 2*h - 1
          Om = h*omega
          a = kij - Om**2*mij
          bb = Om*cij
          call put(bi+cr, bj+cr, a)
          call put(bi+cr, bj+cr+1, -bb)
          call put(bi+cr+1, bj+cr, bb)
          call put(bi+cr+1, bj+cr+1, a)
        end do
      end do
    end do
    do c = 1, p%m
      do cc = 1, p%m
        call put(p%goff+c, p%goff+cc, p%JM(c, cc))
      end do
    end do
    if (st%kd >= 0) then
      call dgbtrf(p%nx, p%nx, kb, kb, p%LU, size(p%LU, 1), p%ipiv, info)
    else
      call dgetrf(p%nx, p%nx, p%LU, p%nx, p%ipiv, info)
    end if
    if (info /= 0) then
      write(buf, '(i0)') info
      call fatal_error(error, "hbm: dgbtrf/dgetrf failed on the full Jacobian (info = "// &
        & trim(buf)//")", UDMAP_ENUMERIC)
    end if
  contains
    subroutine put(row, col, val)
      integer, intent(in) :: row, col
      real(wp), intent(in) :: val
      if (r0 > 0) then
        p%LU(r0+row-col, col) = p%LU(r0+row-col, col) + val
      else
        p%LU(row, col) = p%LU(row, col) + val
      end if
    end subroutine put
  end subroutine factor

  !> Solves [J_x Jw; cx^T cw] [dx; dw] = [rx; rn], cx acting on the gamma unknowns only.
  subroutine bordered_solve(p, Jw, cx, cw, rx, rn, dx, dw, error)
    type(problem_type), intent(inout) :: p
    real(wp), intent(in) :: Jw(:), cx(:), cw, rx(:), rn
    real(wp), intent(out) :: dx(:), dw
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: A(:,:), rhs(:,:)
    integer, allocatable :: ipiv(:)
    integer :: m, info
    real(wp) :: den
    character(len=12) :: buf
    if (p%set%variant == HBM_CONDENSED) then
      m = p%m
      allocate(A(m+1, m+1), rhs(m+1, 1), ipiv(m+1))
      A(1:m, 1:m) = p%Jd
      A(1:m, m+1) = Jw
      A(m+1, 1:m) = cx
      A(m+1, m+1) = cw
      rhs(1:m, 1) = rx
      rhs(m+1, 1) = rn
      call dgesv(m+1, 1, A, m+1, ipiv, rhs, m+1, info)
      if (info /= 0) then
        write(buf, '(i0)') info
        call fatal_error(error, "hbm: dgesv failed on the bordered Jacobian (info = "// &
          & trim(buf)//")", UDMAP_ENUMERIC)
        return
      end if
      dx = rhs(1:m, 1)
      dw = rhs(m+1, 1)
      return
    end if
    ! full: bordering with the LU of J_x
    allocate(rhs(p%nx, 2))
    rhs(:, 1) = rx
    rhs(:, 2) = Jw
    if (p%banded) then
      call dgbtrs('N', p%nx, p%kb, p%kb, 2, p%LU, size(p%LU, 1), p%ipiv, rhs, p%nx, info)
    else
      call dgetrs('N', p%nx, 2, p%LU, p%nx, p%ipiv, rhs, p%nx, info)
    end if
    if (info /= 0) then
      write(buf, '(i0)') info
      call fatal_error(error, "hbm: dgbtrs/dgetrs failed (info = "//trim(buf)//")", &
        & UDMAP_ENUMERIC)
      return
    end if
    den = cw - dot_product(cx, rhs(p%goff+1:p%goff+p%m, 2))
    if (den == 0.0_wp) then
      call fatal_error(error, "hbm: singular bordered system (fold of the response curve)", &
        & UDMAP_ENUMERIC)
      return
    end if
    dw = (rn - dot_product(cx, rhs(p%goff+1:p%goff+p%m, 1)))/den
    dx = rhs(:, 1) - rhs(:, 2)*dw
  end subroutine bordered_solve

  ! ------------------------------------------------------------------ helpers

  !> Linear response with the stuck damper (k_stuck) at omega: the starting guess.
  subroutine stuck_guess(p, st, omega, x, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    real(wp), intent(out) :: x(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: R(:), Jw(:), dx(:), cx(:)
    real(wp) :: dw, Msave0
    complex(wp), allocatable :: Msave(:)
    integer :: c
    allocate(R(p%nx), Jw(p%nx), dx(p%nx), cx(p%m))
    x = 0.0_wp
    cx = 0.0_wp
    ! residual at x = 0 with the damper linearised as k_stuck (no AFT needed)
    Msave = p%Mh
    Msave0 = p%M0
    p%Mh = (0.0_wp, 0.0_wp)
    p%M0 = p%M_ref
    p%JM = 0.0_wp
    do c = 1, p%m
      p%JM(c, c) = p%k_stuck
    end do
    if (p%set%variant == HBM_CONDENSED) then
      call condensed_residual(p, st, x, omega, R, error, Jw)
      if (allocated(error)) return
    else
      call full_residual(p, st, x, omega, R, Jw)
    end if
    call factor(p, st, omega, error)
    if (allocated(error)) return
    call bordered_solve(p, Jw, cx, 1.0_wp, -R, 0.0_wp, dx, dw, error)
    if (allocated(error)) return
    x = dx
    p%Mh = Msave
    p%M0 = Msave0
  end subroutine stuck_guess

  !> |Gamma_1| of the unknowns.
  pure real(wp) function amplitude(p, x)
    type(problem_type), intent(in) :: p
    real(wp), intent(in) :: x(:)
    amplitude = hypot(x(p%goff+p%h0+1), x(p%goff+p%h0+2))
  end function amplitude

  !> Amplitude scale of the metric: the norm of the gamma unknowns (never zero).
  pure real(wp) function amplitude_scale(p, x)
    type(problem_type), intent(in) :: p
    real(wp), intent(in) :: x(:)
    amplitude_scale = max(norm2(x(p%goff+1:p%goff+p%m)), 1.0e-300_wp)
  end function amplitude_scale

  !> <(x1, w1), (x2, w2)> in the metric: gamma unknowns over A_s, omega over W_s.
  pure real(wp) function scaled_dot(p, x1, w1, x2, w2, A_s)
    type(problem_type), intent(in) :: p
    real(wp), intent(in) :: x1(:), w1, x2(:), w2, A_s
    scaled_dot = dot_product(x1(p%goff+1:p%goff+p%m), x2(p%goff+1:p%goff+p%m))/A_s**2 + &
      & w1*w2/p%W_s**2
  end function scaled_dot

  !> The outputs at a converged point.
  subroutine fill_point(p, st, pt, point, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: pt
    type(hbm_point_type), intent(inout) :: point
    type(error_type), allocatable, intent(out) :: error
    complex(wp) :: G1, S1, U1
    real(wp), allocatable :: R(:)
    type(structure_receptances_type) :: r1
    integer :: h
    allocate(R(p%nx))
    call evaluate(p, st, pt%x, pt%omega, R, error)
    if (allocated(error)) return
    G1 = cmplx(pt%x(p%goff+p%h0+1), pt%x(p%goff+p%h0+2), wp)
    point%gamma_P = abs(G1)
    point%f_res = pt%omega/(2.0_wp*pi)
    point%gamma_max = p%gmax
    point%lift_off = p%ws%lift_off
    if (abs(G1) > 0.0_wp) then
      point%k_re = real(p%Mh(1)/G1, wp)
      point%k_im = aimag(p%Mh(1)/G1)
    end if
    allocate(point%gamma_h(p%H))
    do h = 1, p%H
      point%gamma_h(h) = hypot(pt%x(p%goff+p%h0+2*h-1), pt%x(p%goff+p%h0+2*h))
    end do
    if (p%set%variant == HBM_CONDENSED) then
      call structure_receptances(st, pt%omega, r1, error)
      if (allocated(error)) return
      S1 = r1%sE*p%F - r1%sg*p%Mh(1)
      U1 = r1%EE*p%F - r1%gE*p%Mh(1)
    else
      U1 = cmplx(pt%x((st%exc_dof-1)*p%b+p%h0+1), pt%x((st%exc_dof-1)*p%b+p%h0+2), wp)
      S1 = (0.0_wp, 0.0_wp)
      if (st%has_stress) then
        do h = 1, p%n
          S1 = S1 + (st%s_K(h) - pt%omega**2*st%s_M(h))* &
            & cmplx(pt%x((h-1)*p%b+p%h0+1), pt%x((h-1)*p%b+p%h0+2), wp)
        end do
      end if
    end if
    point%sigma_a = 0.0_wp
    if (st%has_stress) point%sigma_a = abs(S1)
    point%u_E = abs(U1)
  end subroutine fill_point

  subroutine curve_push(p, st, curve, pt)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(hbm_curve_type), intent(inout) :: curve
    type(curve_point_type), intent(in) :: pt
    type(hbm_point_type) :: tmp
    type(error_type), allocatable :: error
    real(wp), allocatable :: t(:)
    integer :: cap
    if (.not.allocated(curve%f)) then
      allocate(curve%f(64), curve%gamma_1(64), curve%sigma_1(64), curve%gamma_max(64))
    else if (curve%n >= size(curve%f)) then
      cap = 2*size(curve%f)
      allocate(t(cap)); t(1:curve%n) = curve%f(1:curve%n); call move_alloc(t, curve%f)
      allocate(t(cap)); t(1:curve%n) = curve%gamma_1(1:curve%n); call move_alloc(t, curve%gamma_1)
      allocate(t(cap)); t(1:curve%n) = curve%sigma_1(1:curve%n); call move_alloc(t, curve%sigma_1)
      allocate(t(cap)); t(1:curve%n) = curve%gamma_max(1:curve%n)
      call move_alloc(t, curve%gamma_max)
    end if
    call fill_point(p, st, pt, tmp, error)
    curve%n = curve%n + 1
    curve%f(curve%n) = pt%omega/(2.0_wp*pi)
    curve%gamma_1(curve%n) = amplitude(p, pt%x)
    curve%sigma_1(curve%n) = tmp%sigma_a
    curve%gamma_max(curve%n) = tmp%gamma_max
  end subroutine curve_push

  pure subroutine sort_pairs(a, b)
    real(wp), intent(inout) :: a(:), b(:)
    integer :: i, j
    real(wp) :: ta, tb
    do i = 2, size(a)
      ta = a(i); tb = b(i)
      j = i - 1
      do while (j >= 1)
        if (a(j) <= ta) exit
        a(j+1) = a(j); b(j+1) = b(j)
        j = j - 1
      end do
      a(j+1) = ta; b(j+1) = tb
    end do
  end subroutine sort_pairs
end module udmap_hbm
