!> Ground truth in time (PHYSICS.md 7): Newmark average-acceleration integration of the whole
!> linear blade with the quasi-static damper (a hysteretic element driven exactly along the
!> computed gamma_P), from rest to a true steady state, and the first harmonics of gamma_P and
!> of the stress by exact Fourier integration of the Newmark trajectory over the last period.
!>
!> Each step: K_eff q_{n+1} = r_{n+1} - e_g (M_r(gamma_{n+1}) - M_ref) with the constant
!> K_eff = K + (2/dt) C + (4/dt^2) M factorised once (banded Cholesky); with x_g = K_eff^-1 e_g
!> the damper enters through the scalar equation gamma + c (M_r(gamma) - M_ref) = gamma_lin,
!> c = x_g(gamma_dof) > 0, solved exactly (M_r is piecewise linear along the step's path) by
!> Newton with the element's tangent, safeguarded by bisection. M_ref is the static moment of the
!> loaded damper at gamma = 0, in equilibrium with the blade's reference state.
!>
!> Steady state: the first harmonic Gamma_1^(p) of each period p approaches its limit like
!> c mu^p (the slowest free mode seen at the forcing frequency); the remaining error is
!> estimated as |Delta_p| |mu|/|1 - mu| with mu = Delta_p/Delta_{p-1}, and the run stops when
!> that estimate is below ss_tol |Gamma_1| for three successive periods.
module udmap_baseline_newmark
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_core_lapack, only: dpbtrf, dpbtrs, dpotrf, dpotrs
  use udmap_core_strings, only: itoa
  use udmap_baseline_linear_structure, only: structure_type
  use udmap_baseline_types, only: seconds_since
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_peak
  use udmap_core_minimise, only: brent_min_type, brent_min_start, brent_min_next, &
    & brent_min_update
  implicit none
  private
  public :: dti_settings_type, dti_point_type, dti_response, dti_peak
  ! shared with the whole-wheel integration (udmap_baseline_wheel)
  public :: dti_runner_type, check_inputs, keff_solve
  public :: newmark_type, newmark_setup, newmark_load, newmark_commit
  public :: ss_tracker_type, ss_track, ss_relative, step_trace_type

  !> Settings of the time integration.
  type :: dti_settings_type
    integer :: steps_per_period = 1024  !< time steps per excitation period (>= 8)
    real(wp) :: ss_tol = 1.0e-8_wp      !< estimated remaining relative error of Gamma_1
    integer :: min_periods = 20         !< least periods before the steady-state test
    integer :: max_periods = 200000     !< most periods before giving up
    real(wp) :: peak_rtol = 1.0e-6_wp   !< --peak: relative tolerance on the frequency
    real(wp) :: peak_window = 0.01_wp   !< --peak: half-width of the first bracket (relative)
    real(wp) :: gamma_limit = 10.0_wp   !< |gamma| beyond which the response is unbounded [rad]
  end type dti_settings_type

  !> Steady-state response at one frequency.
  type :: dti_point_type
    real(wp) :: F_E = 0.0_wp        !< excitation force amplitude [N]
    real(wp) :: f = 0.0_wp          !< excitation frequency [Hz]
    real(wp) :: gamma_1 = 0.0_wp    !< first-harmonic amplitude of gamma_P [rad]
    real(wp) :: sigma_1 = 0.0_wp    !< first-harmonic amplitude of the stress [Pa]
    real(wp) :: gamma_max = 0.0_wp  !< largest gamma_P(t) over the last period [rad]
    real(wp) :: gamma_0 = 0.0_wp    !< mean of gamma_P(t) over the last period [rad]
    logical :: lift_off = .false.   !< a damper contact opened during the last period
    real(wp) :: ss_error = 0.0_wp   !< estimated remaining relative error of gamma_1
    integer :: periods = 0          !< periods integrated (last run)
    integer :: runs = 0             !< time integrations done (several for --peak)
    real(wp) :: seconds = 0.0_wp    !< wall time [s]
  end type dti_point_type

  !> The time integrations of one response or peak search, the single blade's or the whole
  !> wheel's: the inputs they share, and run(f, gamma_1), which integrates at f [Hz] and keeps
  !> its point, a failed run's too (the response returns it). The driver (drive) checks the
  !> inputs, counts and times the runs and names the one whose point is the answer.
  type, abstract :: dti_runner_type
    type(structure_type), pointer :: st => null()
    class(hysteretic_element_type), pointer :: element => null()
    real(wp) :: F_E = 0.0_wp
    type(dti_settings_type) :: settings
    integer :: best = 0             !< the run whose point is the answer (1-based; 0: none)
    integer :: runs = 0             !< time integrations done
    real(wp) :: seconds = 0.0_wp    !< wall time [s]
  contains
    procedure(dti_run), deferred :: run
    procedure(dti_check), deferred :: check
    procedure :: drive => runner_drive
    procedure :: stamp => runner_stamp
  end type dti_runner_type

  abstract interface
    subroutine dti_run(self, f, gamma_1, error)
      import :: dti_runner_type, wp, error_type
      class(dti_runner_type), intent(inout) :: self
      real(wp), intent(in) :: f
      real(wp), intent(out) :: gamma_1
      type(error_type), allocatable, intent(out) :: error
    end subroutine dti_run

    !> The runner's input checks.
    subroutine dti_check(self, error)
      import :: dti_runner_type, error_type
      class(dti_runner_type), intent(in) :: self
      type(error_type), allocatable, intent(out) :: error
    end subroutine dti_check
  end interface

  !> The steady-state test of one first harmonic: successive period differences and their
  !> contraction (module header).
  type :: ss_tracker_type
    complex(wp) :: G1_prev = (0.0_wp, 0.0_wp), d_prev = (0.0_wp, 0.0_wp)
    logical :: have_prev = .false., have_d = .false.
    real(wp) :: est = huge(1.0_wp)
  end type ss_tracker_type

  !> Running Fourier integrals of gamma_P and the stress over one period (Newmark trajectory).
  type :: step_trace_type
    complex(wp) :: G1 = (0.0_wp, 0.0_wp), S1 = (0.0_wp, 0.0_wp)
    real(wp) :: gmean = 0.0_wp, gmax = 0.0_wp
    real(wp) :: sq = 0.0_wp, sv = 0.0_wp, sa = 0.0_wp, sma = 0.0_wp
  end type step_trace_type

  !> The constants of the Newmark scheme at one frequency and the period's Fourier weights.
  type :: newmark_type
    integer :: Ns = 0                      !< steps per period
    real(wp) :: T = 0, dt = 0, a0 = 0, a1 = 0, a2 = 0
    real(wp), allocatable :: Keff(:,:)     !< K + a1 C + a0 M, factorised
    complex(wp) :: I0 = 0, I1 = 0, I2 = 0  !< step integrals (step_integrals)
    complex(wp), allocatable :: phase(:)   !< e^{-i 2 pi j/Ns}, j = 0..Ns-1
    real(wp), allocatable :: sK(:), sM(:)  !< stress rows (zero without stress)
  end type newmark_type

  !> The single blade's runs, each run's point kept.
  type, extends(dti_runner_type) :: blade_runner_type
    type(dti_point_type), allocatable :: points(:)
  contains
    procedure :: run => blade_run
    procedure :: check => blade_check
  end type blade_runner_type

contains

  !> Steady-state response at f [Hz] to F_E sin(2 pi f t) at E, from rest.
  subroutine dti_response(st, element, f, F_E, settings, point, error)
    type(structure_type), intent(in), target :: st
    class(hysteretic_element_type), intent(in), target :: element
    real(wp), intent(in) :: f, F_E
    type(dti_settings_type), intent(in) :: settings
    type(dti_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    call blade_dti(st, element, F_E, settings, point, error, f=f)
  end subroutine dti_response

  !> The frequency of the largest gamma_1 near the single-harmonic peak: the H = 1 standard
  !> method gives the centre, then Brent's maximisation over time integrations from rest.
  subroutine dti_peak(st, element, f_min, f_max, F_E, settings, point, error, f_center)
    type(structure_type), intent(in), target :: st
    class(hysteretic_element_type), intent(in), target :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    type(dti_settings_type), intent(in) :: settings
    type(dti_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f_center
    call blade_dti(st, element, F_E, settings, point, error, f_min=f_min, f_max=f_max, &
      & f_center=f_center)
  end subroutine dti_peak

  !> The single blade's response (f) or peak (f_min, f_max, f_center) by its runner.
  subroutine blade_dti(st, element, F_E, settings, point, error, f, f_min, f_max, f_center)
    type(structure_type), intent(in), target :: st
    class(hysteretic_element_type), intent(in), target :: element
    real(wp), intent(in) :: F_E
    type(dti_settings_type), intent(in) :: settings
    type(dti_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f, f_min, f_max, f_center
    type(blade_runner_type) :: runner
    runner = blade_runner_type(st=st, element=element, F_E=F_E, settings=settings, &
      & points=[dti_point_type::])
    call runner%drive(error, f, f_min, f_max, f_center)
    if (runner%best > 0) point = runner%points(runner%best)
    call runner%stamp(point)
  end subroutine blade_dti

  !> With f: the response at f [Hz], one run; else the peak search in [f_min, f_max] around
  !> f_center (peak_centre, dti_peak_search). The inputs checked first, the runs timed.
  subroutine runner_drive(self, error, f, f_min, f_max, f_center)
    class(dti_runner_type), intent(inout) :: self
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f, f_min, f_max, f_center
    real(wp) :: fc, gamma_1
    integer :: best, runs
    integer(8) :: c0, rate
    call system_clock(c0, rate)
    call self%check(error)
    if (allocated(error)) return
    if (present(f)) then
      if (.not.(f > 0.0_wp) .or. f > huge(1.0_wp)) then
        call fatal_error(error, "dti: the frequency f must be positive and finite", UDMAP_EINPUT)
        return
      end if
      ! a failed run's point and time are the answer too
      call self%run(f, gamma_1, error)
      self%best = 1
      self%runs = 1
    else
      call peak_centre(self%st, self%element, f_min, f_max, self%F_E, fc, error, f_center)
      if (allocated(error)) return
      call dti_peak_search(self, fc, best, runs, error)
      if (allocated(error)) return
      self%best = best
      self%runs = runs
    end if
    self%seconds = seconds_since(c0, rate)
  end subroutine runner_drive

  !> The runs and the time into the answer, the best run's point (none: left as it is).
  subroutine runner_stamp(self, point)
    class(dti_runner_type), intent(in) :: self
    class(dti_point_type), intent(inout) :: point
    if (self%best < 1) return
    point%runs = self%runs
    point%seconds = self%seconds
  end subroutine runner_stamp

  !> The centre of the peak search: f_center if given, else the H = 1 standard method's peak.
  subroutine peak_centre(st, element, f_min, f_max, F_E, fc, error, f_center)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    real(wp), intent(out) :: fc
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f_center
    type(hbm_settings_type) :: hset
    type(hbm_point_type) :: h1
    if (present(f_center)) then
      fc = f_center
    else
      fc = 0.0_wp
      call hbm_peak(st, element, f_min, f_max, F_E, hset, h1, error)
      if (allocated(error)) return
      fc = h1%f_res
    end if
  end subroutine peak_centre

  !> One run of the single blade.
  subroutine blade_run(self, f, gamma_1, error)
    class(blade_runner_type), intent(inout) :: self
    real(wp), intent(in) :: f
    real(wp), intent(out) :: gamma_1
    type(error_type), allocatable, intent(out) :: error
    type(dti_point_type) :: p
    call integrate(self%st, self%element, 2.0_wp*pi*f, self%F_E, self%settings, p, error)
    gamma_1 = p%gamma_1
    self%points = [self%points, p]
  end subroutine blade_run

  subroutine blade_check(self, error)
    class(blade_runner_type), intent(in) :: self
    type(error_type), allocatable, intent(out) :: error
    call check_inputs(self%st, self%F_E, self%settings, error)
  end subroutine blade_check

  !> The peak search around the centre fc: a bracket (the centre above both ends; widened
  !> towards the higher side if not), then Brent's parabolic/golden maximisation of gamma_1
  !> (Numerical Recipes). `best` is the index of the best run (runs numbered from 1).
  subroutine dti_peak_search(runner, fc, best, runs, error)
    class(dti_runner_type), intent(inout) :: runner
    real(wp), intent(in) :: fc
    integer, intent(out) :: best, runs
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: a, b, c, w, ga, gb, gc, u, fu
    integer :: k, ia, ib, ic, iu
    type(brent_min_type) :: brent
    logical :: more
    best = 0
    runs = 0
    if (.not.(fc > 0.0_wp) .or. fc > huge(1.0_wp)) then
      call fatal_error(error, "dti: the centre frequency must be positive", UDMAP_EINPUT)
      return
    end if
    w = runner%settings%peak_window
    a = fc*(1.0_wp - w); b = fc; c = fc*(1.0_wp + w)
    call run(a, ga, ia); if (allocated(error)) return
    call run(b, gb, ib); if (allocated(error)) return
    call run(c, gc, ic); if (allocated(error)) return
    do k = 1, 20
      if (gb >= ga .and. gb >= gc) exit
      if (ga > gc) then
        c = b; gc = gb; ic = ib; b = a; gb = ga; ib = ia
        a = b - 1.618_wp*(c - b)
        if (a <= 0.0_wp) exit
        call run(a, ga, ia); if (allocated(error)) return
      else
        a = b; ga = gb; ia = ib; b = c; gb = gc; ib = ic
        c = b + 1.618_wp*(b - a)
        call run(c, gc, ic); if (allocated(error)) return
      end if
    end do
    if (.not.(gb >= ga .and. gb >= gc)) then
      call fatal_error(error, "dti: no maximum of gamma_1 found near the single-harmonic peak", &
        & UDMAP_EPHYSICS)
      return
    end if
    ! Brent on [a, c] around b, minimising -gamma_1
    call brent_min_start(brent, min(a, c), max(a, c), b, -gb, runner%settings%peak_rtol, 60)
    best = ib
    do
      call brent_min_next(brent, u, more)
      if (.not. more) exit
      call run(u, fu, iu)
      if (allocated(error)) return
      call brent_min_update(brent, -fu)
      if (brent%better) best = iu
    end do
  contains
    subroutine run(f, g1, idx)
      real(wp), intent(in) :: f
      real(wp), intent(out) :: g1
      integer, intent(out) :: idx
      call runner%run(f, g1, error)
      runs = runs + 1
      idx = runs
    end subroutine run
  end subroutine dti_peak_search

  subroutine check_inputs(st, F_E, settings, error)
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: F_E
    type(dti_settings_type), intent(in) :: settings
    type(error_type), allocatable, intent(out) :: error
    if (st%ndof < 1) then
      call fatal_error(error, "dti: the structure is empty", UDMAP_EINPUT)
    else if (.not.(F_E >= 0.0_wp) .or. F_E > huge(1.0_wp)) then
      call fatal_error(error, "dti: F_E must be finite and >= 0", UDMAP_EINPUT)
    else if (settings%steps_per_period < 8) then
      call fatal_error(error, "dti: steps_per_period must be >= 8", UDMAP_EINPUT)
    else if (.not.(settings%ss_tol > 0.0_wp) .or. settings%min_periods < 3 .or. &
        & settings%max_periods < settings%min_periods) then
      call fatal_error(error, "dti: need ss_tol > 0, min_periods >= 3, max_periods >= "// &
        & "min_periods", UDMAP_EINPUT)
    else if (.not.(settings%peak_rtol > 0.0_wp) .or. .not.(settings%peak_window > 0.0_wp) .or. &
        & .not.(settings%peak_window < 1.0_wp) .or. .not.(settings%gamma_limit > 0.0_wp)) then
      call fatal_error(error, "dti: need peak_rtol > 0, 0 < peak_window < 1, gamma_limit > 0", &
        & UDMAP_EINPUT)
    end if
  end subroutine check_inputs

  !> One time integration from rest at omega [rad/s] to the steady state.
  subroutine integrate(st, element, omega, F_E, set, point, error)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: omega, F_E
    type(dti_settings_type), intent(in) :: set
    type(dti_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    class(hysteretic_element_type), allocatable :: el, trial
    real(wp), allocatable :: xg(:), q(:), v(:), a(:), r(:), qn(:)
    type(newmark_type) :: nm
    type(ss_tracker_type) :: ss
    type(step_trace_type) :: tr
    real(wp) :: c, M_ref, Mr, kt, gam, g_lin
    integer :: n, j, p, good, g

    point%F_E = F_E
    point%f = omega/(2.0_wp*pi)
    n = st%ndof
    g = st%gamma_dof
    call newmark_setup(st, omega, set, nm, error)
    if (allocated(error)) return
    allocate(xg(n), q(n), v(n), a(n), r(n), qn(n))
    xg = 0.0_wp
    xg(g) = 1.0_wp
    call keff_solve(st, nm%Keff, xg, error)
    if (allocated(error)) return
    c = xg(g)
    allocate(el, source=element)
    allocate(trial, source=element)
    call el%load(error)
    if (allocated(error)) return
    M_ref = el%moment()
    kt = el%stuck_stiffness()
    q = 0.0_wp; v = 0.0_wp; a = 0.0_wp   ! at rest; the force F_E sin(omega t) starts at zero
    good = 0
    do p = 1, set%max_periods
      tr = step_trace_type(sq=tr%sq, sv=tr%sv, sa=tr%sa, sma=tr%sma, gmax=q(g))
      call el%clear_flags()
      call trial%clear_flags()
      do j = 0, nm%Ns - 1
        call newmark_load(st, nm, q, v, a, r)
        r(st%exc_dof) = r(st%exc_dof) + F_E*sin(2.0_wp*pi*real(j + 1, wp)/nm%Ns)
        call keff_solve(st, nm%Keff, r, error)
        if (allocated(error)) return
        g_lin = r(g)
        call solve_gamma(g_lin, gam, Mr, kt)
        if (allocated(error)) return
        qn = r - xg*(Mr - M_ref)
        qn(g) = gam
        call newmark_commit(st, nm, j, tr, q, v, a, qn)
        call el%copy_state(trial)
        if (.not.(abs(gam) <= set%gamma_limit)) then
          call fatal_error(error, "dti: |gamma_P| exceeds gamma_limit: the response is "// &
            & "unbounded (F_E at or above the limit force with little damping, or a force far "// &
            & "beyond the model)", UDMAP_EPHYSICS)
          return
        end if
      end do
      tr%G1 = 2.0_wp*tr%G1/nm%T
      tr%S1 = 2.0_wp*tr%S1/nm%T
      call ss_track(ss, tr%G1)
      if (p >= set%min_periods .and. ss%est <= set%ss_tol*abs(tr%G1)) then
        good = good + 1
      else
        good = 0
      end if
      point%periods = p
      if (good >= 3) exit
    end do
    point%gamma_1 = abs(tr%G1)
    point%sigma_1 = abs(tr%S1)
    point%lift_off = el%lifted()
    point%gamma_max = tr%gmax
    point%gamma_0 = tr%gmean/nm%T
    point%ss_error = ss_relative(ss%est, tr%G1)
    if (good < 3) then
      call fatal_error(error, "dti: no steady state within max_periods = "// &
        & itoa(set%max_periods)//" periods (raise max_periods or ss_tol)", UDMAP_ENUMERIC)
      return
    end if
  contains
    !> gamma + c (M_r(gamma) - M_ref) = g_lin along the path from the committed state.
    subroutine solve_gamma(glin, gam_out, M_out, kt_io)
      real(wp), intent(in) :: glin
      real(wp), intent(out) :: gam_out, M_out
      real(wp), intent(inout) :: kt_io
      real(wp) :: x, lo, hi, phi, xn, Mx, ktx, g0, M0, scale
      integer :: it
      logical :: has_lo, has_hi
      g0 = el%gamma()
      M0 = el%moment()
      scale = max(abs(glin), abs(g0), tiny(1.0_wp))
      ! Newton from the committed state with the last tangent
      x = g0 + (glin - g0 - c*(M0 - M_ref))/(1.0_wp + c*max(kt_io, 0.0_wp))
      has_lo = .false.; has_hi = .false.
      lo = 0.0_wp; hi = 0.0_wp
      do it = 1, 200
        call trial%copy_state(el)
        call trial%advance(x, Mx, ktx, error)
        if (allocated(error)) return
        phi = x + c*(Mx - M_ref) - glin
        if (abs(phi) <= 4.0_wp*epsilon(1.0_wp)*scale) exit
        if (phi > 0.0_wp) then
          hi = x; has_hi = .true.
        else
          lo = x; has_lo = .true.
        end if
        xn = x - phi/(1.0_wp + c*max(ktx, 0.0_wp))
        if (has_lo .and. has_hi) then
          if (.not.(xn > lo .and. xn < hi)) xn = 0.5_wp*(lo + hi)
          if (hi - lo <= 2.0_wp*epsilon(1.0_wp)*scale) exit
        end if
        if (xn == x) exit
        x = xn
      end do
      gam_out = x
      M_out = Mx
      kt_io = ktx
    end subroutine solve_gamma
  end subroutine integrate

  !> The scheme at omega [rad/s]: step, coefficients, K_eff = K + a1 C + a0 M factorised
  !> (banded or dense Cholesky), the step's Fourier weights and the stress rows.
  subroutine newmark_setup(st, omega, set, nm, error)
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    type(dti_settings_type), intent(in) :: set
    type(newmark_type), intent(out) :: nm
    type(error_type), allocatable, intent(out) :: error
    integer :: info, j
    nm%Ns = set%steps_per_period
    nm%T = 2.0_wp*pi/omega
    nm%dt = nm%T/nm%Ns
    nm%a0 = 4.0_wp/nm%dt**2
    nm%a1 = 2.0_wp/nm%dt
    nm%a2 = 4.0_wp/nm%dt
    nm%Keff = st%K + nm%a1*st%C + nm%a0*st%M
    if (st%kd >= 0) then
      call dpbtrf('U', st%ndof, st%kd, nm%Keff, st%kd+1, info)
    else
      call dpotrf('U', st%ndof, nm%Keff, st%ndof, info)
    end if
    if (info /= 0) then
      call fatal_error(error, "dti: dpbtrf/dpotrf failed on K + 2/dt C + 4/dt^2 M (info = "// &
        & itoa(info)//"): M, K, C not positive definite", UDMAP_ENUMERIC)
      return
    end if
    call step_integrals(omega, nm%dt, nm%I0, nm%I1, nm%I2)
    allocate(nm%phase(0:nm%Ns-1))
    do j = 0, nm%Ns - 1
      nm%phase(j) = exp(cmplx(0.0_wp, -2.0_wp*pi*j/nm%Ns, wp))
    end do
    if (st%has_stress) then
      nm%sK = st%s_K
      nm%sM = st%s_M
    else
      allocate(nm%sK(st%ndof), nm%sM(st%ndof))
      nm%sK = 0.0_wp; nm%sM = 0.0_wp
    end if
  end subroutine newmark_setup

  !> The effective load at t_{n+1} without the excitation: M (a0 q + a2 v + a) + C (a1 q + v).
  subroutine newmark_load(st, nm, q, v, a, r)
    type(structure_type), intent(in) :: st
    type(newmark_type), intent(in) :: nm
    real(wp), intent(in) :: q(:), v(:), a(:)
    real(wp), intent(out) :: r(:)
    real(wp) :: w1(size(q)), w2(size(q))
    w1 = nm%a0*q + nm%a2*v + a
    w2 = nm%a1*q + v
    call band_matvec(st%kd, st%M, w1, r)
    call band_matvec(st%kd, st%C, w2, w1)
    r = r + w1
  end subroutine newmark_load

  !> Step j done: the acceleration of the new displacement qn, the step's Fourier integrals,
  !> and (q, v, a) moved on.
  subroutine newmark_commit(st, nm, j, tr, q, v, a, qn)
    type(structure_type), intent(in) :: st
    type(newmark_type), intent(in) :: nm
    integer, intent(in) :: j
    type(step_trace_type), intent(inout) :: tr
    real(wp), intent(inout) :: q(:), v(:), a(:)
    real(wp), intent(in) :: qn(:)
    real(wp) :: an(size(q))
    an = nm%a0*(qn - q) - nm%a2*v - a
    call trace_step(tr, st%has_stress, nm%sK, nm%sM, nm%phase(j), nm%I0, nm%I1, nm%I2, nm%dt, &
      & st%gamma_dof, q, v, a, qn, an)
    v = v + 0.5_wp*nm%dt*(a + an)
    q = qn
    a = an
  end subroutine newmark_commit

  !> x := K_eff^-1 x with the factor of newmark_setup.
  subroutine keff_solve(st, Keff, x, error)
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: Keff(:,:)
    real(wp), intent(inout) :: x(:)
    type(error_type), allocatable, intent(out) :: error
    integer :: inf, n
    n = st%ndof
    if (st%kd >= 0) then
      call dpbtrs('U', n, st%kd, 1, Keff, st%kd+1, x, n, inf)
    else
      call dpotrs('U', n, 1, Keff, n, x, n, inf)
    end if
    if (inf /= 0) call fatal_error(error, "dti: dpbtrs/dpotrs failed", UDMAP_ENUMERIC)
  end subroutine keff_solve

  !> y = A x for a symmetric matrix A in the structure's storage (kd >= 0: band 'U').
  pure subroutine band_matvec(kd, A, x, y)
    integer, intent(in) :: kd
    real(wp), intent(in) :: A(:,:)
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: y(:)
    integer :: jj, ii, lo, n
    real(wp) :: s
    if (kd < 0) then
      y = matmul(A, x)
      return
    end if
    n = size(x)
    y = 0.0_wp
    do jj = 1, n
      lo = max(1, jj - kd)
      s = 0.0_wp
      do ii = lo, jj - 1
        y(ii) = y(ii) + A(kd+1+ii-jj, jj)*x(jj)
        s = s + A(kd+1+ii-jj, jj)*x(ii)
      end do
      y(jj) = y(jj) + s + A(kd+1, jj)*x(jj)
    end do
  end subroutine band_matvec

  !> Adds one Newmark step (q, v, a) -> (qn, an) to the period's Fourier integrals of DOF g
  !> (exact for the step's quadratic trajectory), its mean and maximum, and of the stress.
  pure subroutine trace_step(tr, has_stress, sK, sM, ph, I0, I1, I2, dt, g, q, v, a, qn, an)
    type(step_trace_type), intent(inout) :: tr
    logical, intent(in) :: has_stress
    real(wp), intent(in) :: sK(:), sM(:), dt
    complex(wp), intent(in) :: ph, I0, I1, I2
    integer, intent(in) :: g
    real(wp), intent(in) :: q(:), v(:), a(:), qn(:), an(:)
    real(wp) :: aavg, tv, sq_n, sv_n, sa_n, sma_n
    aavg = 0.5_wp*(a(g) + an(g))
    tr%G1 = tr%G1 + ph*(q(g)*I0 + v(g)*I1 + 0.5_wp*aavg*I2)
    tr%gmean = tr%gmean + q(g)*dt + v(g)*dt**2/2.0_wp + aavg*dt**3/6.0_wp
    tr%gmax = max(tr%gmax, qn(g))
    if (v(g) > 0.0_wp .and. aavg < 0.0_wp) then
      tv = -v(g)/aavg
      if (tv < dt) tr%gmax = max(tr%gmax, q(g) + 0.5_wp*v(g)*tv)
    end if
    if (has_stress) then
      sq_n = dot_product(sK, qn)
      sa_n = dot_product(sK, an)
      sma_n = dot_product(sM, an)
      sv_n = dot_product(sK, v + 0.5_wp*dt*(a + an))
      tr%S1 = tr%S1 + ph*((tr%sq + 0.5_wp*(tr%sma + sma_n))*I0 + tr%sv*I1 + &
        & 0.25_wp*(tr%sa + sa_n)*I2)
      tr%sq = sq_n; tr%sv = sv_n; tr%sa = sa_n; tr%sma = sma_n
    end if
  end subroutine trace_step

  !> Steady state: the remaining error of G1 estimated from the contraction of successive
  !> period differences (module header).
  pure subroutine ss_track(t, G1)
    type(ss_tracker_type), intent(inout) :: t
    complex(wp), intent(in) :: G1
    complex(wp) :: d_cur, mu
    if (t%have_prev) then
      d_cur = G1 - t%G1_prev
      if (t%have_d .and. abs(t%d_prev) > 0.0_wp) then
        mu = d_cur/t%d_prev
        if (abs(mu) < 1.0_wp) then
          t%est = abs(d_cur)*abs(mu)/abs(1.0_wp - mu)
        else
          t%est = huge(1.0_wp)
        end if
      end if
      if (abs(d_cur) == 0.0_wp) t%est = 0.0_wp
      t%d_prev = d_cur
      t%have_d = .true.
    end if
    t%G1_prev = G1
    t%have_prev = .true.
  end subroutine ss_track

  !> The estimate relative to |G1|, without overflow when no estimate exists yet.
  pure real(wp) function ss_relative(est, G1) result(r)
    real(wp), intent(in) :: est
    complex(wp), intent(in) :: G1
    if (est < 1.0e-3_wp*huge(1.0_wp)*max(abs(G1), tiny(1.0_wp))) then
      r = est/max(abs(G1), tiny(1.0_wp))
    else
      r = huge(1.0_wp)
    end if
  end function ss_relative

  !> I_k = int_0^dt tau^k e^{-i omega tau} dtau, k = 0, 1, 2 (power series, omega dt < 1).
  pure subroutine step_integrals(omega, dt, I0, I1, I2)
    real(wp), intent(in) :: omega, dt
    complex(wp), intent(out) :: I0, I1, I2
    complex(wp) :: term, z
    integer :: m
    z = cmplx(0.0_wp, -omega*dt, wp)
    I0 = 0; I1 = 0; I2 = 0
    term = (1.0_wp, 0.0_wp)
    do m = 0, 40
      I0 = I0 + term/(m + 1)
      I1 = I1 + term/(m + 2)
      I2 = I2 + term/(m + 3)
      term = term*z/(m + 1)
    end do
    I0 = I0*dt
    I1 = I1*dt**2
    I2 = I2*dt**3
  end subroutine step_integrals
end module udmap_baseline_newmark
