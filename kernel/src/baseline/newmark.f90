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
  implicit none
  private
  public :: dti_settings_type, dti_point_type, dti_response, dti_peak

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

contains

  !> Steady-state response at f [Hz] to F_E sin(2 pi f t) at E, from rest.
  subroutine dti_response(st, element, f, F_E, settings, point, error)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f, F_E
    type(dti_settings_type), intent(in) :: settings
    type(dti_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    integer(8) :: c0, rate
    call system_clock(c0, rate)
    call check_inputs(st, F_E, settings, error)
    if (allocated(error)) return
    if (.not.(f > 0.0_wp) .or. f > huge(1.0_wp)) then
      call fatal_error(error, "dti: the frequency f must be positive and finite", UDMAP_EINPUT)
      return
    end if
    call integrate(st, element, 2.0_wp*pi*f, F_E, settings, point, error)
    point%runs = 1
    point%seconds = seconds_since(c0, rate)
  end subroutine dti_response

  !> The frequency of the largest gamma_1 near the single-harmonic peak: the H = 1 standard
  !> method gives the centre, then Brent's maximisation over time integrations from rest.
  subroutine dti_peak(st, element, f_min, f_max, F_E, settings, point, error, f_center)
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    type(dti_settings_type), intent(in) :: settings
    type(dti_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f_center
    type(hbm_settings_type) :: hset
    type(hbm_point_type) :: h1
    type(dti_point_type) :: pa, pb, pc, pt
    real(wp) :: fc, a, b, c, w
    integer :: runs, k
    integer(8) :: c0, rate
    call system_clock(c0, rate)
    call check_inputs(st, F_E, settings, error)
    if (allocated(error)) return
    if (present(f_center)) then
      fc = f_center
    else
      call hbm_peak(st, element, f_min, f_max, F_E, hset, h1, error)
      if (allocated(error)) return
      fc = h1%f_res
    end if
    if (.not.(fc > 0.0_wp) .or. fc > huge(1.0_wp)) then
      call fatal_error(error, "dti: the centre frequency must be positive", UDMAP_EINPUT)
      return
    end if
    ! bracket: the centre above both ends; widen towards the higher side if not
    w = settings%peak_window
    a = fc*(1.0_wp - w); b = fc; c = fc*(1.0_wp + w)
    runs = 0
    call run(a, pa); if (allocated(error)) return
    call run(b, pb); if (allocated(error)) return
    call run(c, pc); if (allocated(error)) return
    do k = 1, 20
      if (pb%gamma_1 >= pa%gamma_1 .and. pb%gamma_1 >= pc%gamma_1) exit
      if (pa%gamma_1 > pc%gamma_1) then
        c = b; pc = pb; b = a; pb = pa
        a = b - 1.618_wp*(c - b)
        if (a <= 0.0_wp) exit
        call run(a, pa); if (allocated(error)) return
      else
        a = b; pa = pb; b = c; pb = pc
        c = b + 1.618_wp*(b - a)
        call run(c, pc); if (allocated(error)) return
      end if
    end do
    if (.not.(pb%gamma_1 >= pa%gamma_1 .and. pb%gamma_1 >= pc%gamma_1)) then
      call fatal_error(error, "dti: no maximum of gamma_1 found near the single-harmonic peak", &
        & UDMAP_EPHYSICS)
      return
    end if
    call brent_max(a, b, c, pb, pt)
    if (allocated(error)) return
    point = pt
    point%runs = runs
    point%seconds = seconds_since(c0, rate)
  contains
    subroutine run(f, p)
      real(wp), intent(in) :: f
      type(dti_point_type), intent(out) :: p
      call integrate(st, element, 2.0_wp*pi*f, F_E, settings, p, error)
      runs = runs + 1
    end subroutine run
    !> Brent's parabolic/golden maximisation of gamma_1 on [a, c] around b (Numerical Recipes).
    subroutine brent_max(a0, b0, c0_, pbest, best)
      real(wp), intent(in) :: a0, b0, c0_
      type(dti_point_type), intent(in) :: pbest
      type(dti_point_type), intent(out) :: best
      real(wp), parameter :: cgold = 0.3819660112501051_wp
      real(wp) :: lo, hi, x, v, ww, fx, fv, fw, u, fu, d, e, xm, tol1, tol2, r, q, pp, etemp
      type(dti_point_type) :: pu
      integer :: it
      lo = min(a0, c0_); hi = max(a0, c0_)
      x = b0; v = b0; ww = b0
      fx = -pbest%gamma_1; fv = fx; fw = fx
      best = pbest
      d = 0.0_wp; e = 0.0_wp
      do it = 1, 60
        xm = 0.5_wp*(lo + hi)
        tol1 = settings%peak_rtol*abs(x)
        tol2 = 2.0_wp*tol1
        if (abs(x - xm) <= tol2 - 0.5_wp*(hi - lo)) exit
        if (abs(e) > tol1) then
          r = (x - ww)*(fx - fv)
          q = (x - v)*(fx - fw)
          pp = (x - v)*q - (x - ww)*r
          q = 2.0_wp*(q - r)
          if (q > 0.0_wp) pp = -pp
          q = abs(q)
          etemp = e
          e = d
          if (abs(pp) >= abs(0.5_wp*q*etemp) .or. pp <= q*(lo - x) .or. pp >= q*(hi - x)) then
            e = merge(lo - x, hi - x, x >= xm)
            d = cgold*e
          else
            d = pp/q
            u = x + d
            if (u - lo < tol2 .or. hi - u < tol2) d = sign(tol1, xm - x)
          end if
        else
          e = merge(lo - x, hi - x, x >= xm)
          d = cgold*e
        end if
        if (abs(d) >= tol1) then
          u = x + d
        else
          u = x + sign(tol1, d)
        end if
        call run(u, pu)
        if (allocated(error)) return
        fu = -pu%gamma_1
        if (fu <= fx) then
          if (u >= x) then
            lo = x
          else
            hi = x
          end if
          v = ww; fv = fw
          ww = x; fw = fx
          x = u; fx = fu
          best = pu
        else
          if (u < x) then
            lo = u
          else
            hi = u
          end if
          if (fu <= fw .or. ww == x) then
            v = ww; fv = fw
            ww = u; fw = fu
          else if (fu <= fv .or. v == x .or. v == ww) then
            v = u; fv = fu
          end if
        end if
      end do
    end subroutine brent_max
  end subroutine dti_peak

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
    real(wp), allocatable :: Keff(:,:), xg(:), q(:), v(:), a(:), r(:), w1(:), w2(:), qn(:), an(:)
    real(wp), allocatable :: sK(:), sM(:)
    complex(wp), allocatable :: phase(:)
    complex(wp) :: I0, I1, I2, G1, S1, G1_prev, d_prev, d_cur, mu
    real(wp) :: dt, a0, a1, a2, c, M_ref, Mr, kt, T, gam, gmean, est, sq, sv, sa, sma
    real(wp) :: sq_n, sv_n, sa_n, sma_n, aavg, gmax_p, tv, g_lin
    integer :: n, Ns, kd, j, p, info, good, g
    logical :: have_prev, have_d

    point%F_E = F_E
    point%f = omega/(2.0_wp*pi)
    n = st%ndof
    kd = st%kd
    g = st%gamma_dof
    Ns = set%steps_per_period
    T = 2.0_wp*pi/omega
    dt = T/Ns
    a0 = 4.0_wp/dt**2
    a1 = 2.0_wp/dt
    a2 = 4.0_wp/dt
    ! effective stiffness, factorised once
    if (kd >= 0) then
      Keff = st%K + a1*st%C + a0*st%M
      call dpbtrf('U', n, kd, Keff, kd+1, info)
    else
      Keff = st%K + a1*st%C + a0*st%M
      call dpotrf('U', n, Keff, n, info)
    end if
    if (info /= 0) then
      call fatal_error(error, "dti: dpbtrf/dpotrf failed on K + 2/dt C + 4/dt^2 M (info = "// &
        & itoa(info)//"): M, K, C not positive definite", UDMAP_ENUMERIC)
      return
    end if
    allocate(xg(n), q(n), v(n), a(n), r(n), w1(n), w2(n), qn(n), an(n))
    xg = 0.0_wp
    xg(g) = 1.0_wp
    call keff_solve(xg)
    if (allocated(error)) return
    c = xg(g)
    ! Fourier weights of one step: I_k = int_0^dt tau^k e^{-i omega tau} dtau
    call step_integrals(omega, dt, I0, I1, I2)
    allocate(phase(0:Ns-1))
    do j = 0, Ns - 1
      phase(j) = exp(cmplx(0.0_wp, -2.0_wp*pi*j/Ns, wp))
    end do
    if (st%has_stress) then
      sK = st%s_K
      sM = st%s_M
    else
      allocate(sK(n), sM(n))
      sK = 0.0_wp; sM = 0.0_wp
    end if
    allocate(el, source=element)
    allocate(trial, source=element)
    call el%load(error)
    if (allocated(error)) return
    M_ref = el%moment()
    kt = el%stuck_stiffness()
    q = 0.0_wp; v = 0.0_wp; a = 0.0_wp   ! at rest; the force F_E sin(omega t) starts at zero
    sq = 0.0_wp; sv = 0.0_wp; sa = 0.0_wp; sma = 0.0_wp
    have_prev = .false.
    have_d = .false.
    good = 0
    G1_prev = (0.0_wp, 0.0_wp)
    d_prev = (0.0_wp, 0.0_wp)
    est = huge(1.0_wp)
    do p = 1, set%max_periods
      G1 = (0.0_wp, 0.0_wp)
      S1 = (0.0_wp, 0.0_wp)
      gmean = 0.0_wp
      call el%clear_flags()
      call trial%clear_flags()
      gmax_p = q(g)
      do j = 0, Ns - 1
        ! effective load at t_{n+1}
        w1 = a0*q + a2*v + a
        w2 = a1*q + v
        call matvec(st%M, w1, r)
        call matvec(st%C, w2, w1)
        r = r + w1
        r(st%exc_dof) = r(st%exc_dof) + F_E*sin(2.0_wp*pi*real(j + 1, wp)/Ns)
        call keff_solve(r)
        if (allocated(error)) return
        g_lin = r(g)
        call solve_gamma(g_lin, gam, Mr, kt)
        if (allocated(error)) return
        qn = r - xg*(Mr - M_ref)
        qn(g) = gam
        an = a0*(qn - q) - a2*v - a
        ! Fourier integral of the step's quadratic trajectory
        aavg = 0.5_wp*(a(g) + an(g))
        G1 = G1 + phase(j)*(q(g)*I0 + v(g)*I1 + 0.5_wp*aavg*I2)
        gmean = gmean + q(g)*dt + v(g)*dt**2/2.0_wp + aavg*dt**3/6.0_wp
        gmax_p = max(gmax_p, gam)
        if (v(g) > 0.0_wp .and. aavg < 0.0_wp) then
          tv = -v(g)/aavg
          if (tv < dt) gmax_p = max(gmax_p, q(g) + 0.5_wp*v(g)*tv)
        end if
        if (st%has_stress) then
          sq_n = dot_product(sK, qn)
          sa_n = dot_product(sK, an)
          sma_n = dot_product(sM, an)
          sv_n = dot_product(sK, v + 0.5_wp*dt*(a + an))
          S1 = S1 + phase(j)*((sq + 0.5_wp*(sma + sma_n))*I0 + sv*I1 + 0.25_wp*(sa + sa_n)*I2)
          sq = sq_n; sv = sv_n; sa = sa_n; sma = sma_n
        end if
        v = v + 0.5_wp*dt*(a + an)
        q = qn
        a = an
        call el%copy_state(trial)
        if (.not.(abs(gam) <= set%gamma_limit)) then
          call fatal_error(error, "dti: |gamma_P| exceeds gamma_limit: the response is "// &
            & "unbounded (F_E at or above the limit force with little damping, or a force far "// &
            & "beyond the model)", UDMAP_EPHYSICS)
          return
        end if
      end do
      G1 = 2.0_wp*G1/T
      S1 = 2.0_wp*S1/T
      ! steady state: remaining error from the contraction of successive differences
      if (have_prev) then
        d_cur = G1 - G1_prev
        if (have_d .and. abs(d_prev) > 0.0_wp) then
          mu = d_cur/d_prev
          if (abs(mu) < 1.0_wp) then
            est = abs(d_cur)*abs(mu)/abs(1.0_wp - mu)
          else
            est = huge(1.0_wp)
          end if
        end if
        if (abs(d_cur) == 0.0_wp) est = 0.0_wp
        d_prev = d_cur
        have_d = .true.
      end if
      G1_prev = G1
      have_prev = .true.
      if (p >= set%min_periods .and. est <= set%ss_tol*abs(G1)) then
        good = good + 1
      else
        good = 0
      end if
      point%periods = p
      if (good >= 3) exit
    end do
    point%gamma_1 = abs(G1)
    point%sigma_1 = abs(S1)
    point%lift_off = el%lifted()
    point%gamma_max = gmax_p
    point%gamma_0 = gmean/T
    ! relative remaining error, without overflow when no estimate exists yet
    if (est < 1.0e-3_wp*huge(1.0_wp)*max(abs(G1), tiny(1.0_wp))) then
      point%ss_error = est/max(abs(G1), tiny(1.0_wp))
    else
      point%ss_error = huge(1.0_wp)
    end if
    if (good < 3) then
      call fatal_error(error, "dti: no steady state within max_periods = "// &
        & itoa(set%max_periods)//" periods (raise max_periods or ss_tol)", UDMAP_ENUMERIC)
      return
    end if
  contains
    subroutine keff_solve(x)
      real(wp), intent(inout) :: x(:)
      integer :: inf
      if (kd >= 0) then
        call dpbtrs('U', n, kd, 1, Keff, kd+1, x, n, inf)
      else
        call dpotrs('U', n, 1, Keff, n, x, n, inf)
      end if
      if (inf /= 0) call fatal_error(error, "dti: dpbtrs/dpotrs failed", UDMAP_ENUMERIC)
    end subroutine keff_solve

    !> y = A x for the symmetric matrix A (st%M or st%C, in the structure's storage).
    subroutine matvec(A, x, y)
      real(wp), intent(in) :: A(:,:)
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: y(:)
      integer :: jj, ii, lo
      real(wp) :: s
      if (kd < 0) then
        y = matmul(A, x)
        return
      end if
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
    end subroutine matvec

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
