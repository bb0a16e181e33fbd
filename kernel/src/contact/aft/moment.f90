!> The damper moment along a given periodic gamma(t): contact tracing with the loading history
!> and Fourier projection. Shared by the standard method's alternating frequency-time
!> evaluation (PHYSICS.md 6) and the multi-harmonic layers of the mapping (PHYSICS.md 4.1).
!>
!> gamma(tau) = Gamma_0 + Re(sum_h Gamma_h e^{i h tau}), tau = omega t. The element is driven
!> along gamma(tau) with the loading history of PHYSICS.md 2.1 (virgin state, CF ramp, ramp to
!> the waveform's maximum, then periods until the state repeats) and the Fourier coefficients of
!> the steady M_r(tau) are returned: M_r = M_0 + Re(sum_h M_h e^{i h tau}).
!>
!> Two integrations of the last period:
!> - exact (samples = 0): the path is split at the extrema of gamma(tau) (found as roots of
!>   gamma'), every monotone stretch is traced in one call with its events; M_r is linear in
!>   gamma between events, so the Fourier integral is done in closed form. No time step, no
!>   sampling error: the result is exact to rounding for any H.
!> - sampled (samples = N > 0): the classical AFT, N equally spaced instants, the element
!>   advanced from sample to sample and a discrete Fourier transform (error O(1/N^2)).
module udmap_contact_aft_moment
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_contact_element, only: hysteretic_element_type, event_list_type
  use udmap_contact_aft_waveform, only: two_pi, waveform_value, waveform_slope, waveform_extrema, &
    & solve_time, powers
  implicit none
  private
  public :: aft_workspace_type, aft_moment, aft_moment_jacobian

  !> Scratch storage reused between calls (one per caller; not shared between threads).
  type :: aft_workspace_type
    type(event_list_type) :: events
    type(event_list_type) :: bp                     !< breakpoints of the current period
    integer, allocatable :: bp_seg(:)               !< segment of each breakpoint
    real(wp), allocatable :: bp_tau(:)              !< instant of each breakpoint (integration)
    class(hysteretic_element_type), allocatable :: start   !< state at the start of a period
    integer :: calls = 0                            !< number of aft_moment calls (statistics)
    logical :: lift_off = .false.                   !< a contact opened in the last call
  end type aft_workspace_type

contains


  !> The Fourier coefficients of the steady damper moment for gamma(tau) with coefficients
  !> G0, G(1:H): M0 (static) and M(1:H). samples = 0: exact event-driven integration;
  !> samples > 0: classical sampled AFT. The loop is repeated until the element state at the
  !> start of successive periods agrees within loop_rtol (at least min_periods, at most
  !> max_periods periods). gamma_max: the largest value of gamma(tau); periods: periods used.
  subroutine aft_moment(element, ws, G0, G, samples, min_periods, max_periods, loop_rtol, &
      & M0, M, error, gamma_max, periods)
    class(hysteretic_element_type), intent(inout) :: element
    type(aft_workspace_type), intent(inout) :: ws
    real(wp), intent(in) :: G0
    complex(wp), intent(in) :: G(:)
    integer, intent(in) :: samples, min_periods, max_periods
    real(wp), intent(in) :: loop_rtol
    real(wp), intent(out) :: M0
    complex(wp), intent(out) :: M(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: gamma_max
    integer, intent(out), optional :: periods
    real(wp), allocatable :: tau(:), gam(:), Ms(:)
    integer :: n, H, p, k, j, np
    real(wp) :: Mr, kt, gmax
    logical :: closed

    H = size(G)
    if (present(periods)) periods = 0
    call begin_call(element, ws, G0, G, M0, M, tau, n, error)
    if (allocated(error)) return

    ws%lift_off = .false.
    call element%load(error)
    if (allocated(error)) return
    if (n == 0) then
      ! constant gamma: the static moment only
      call element%advance(G0, Mr, kt, error)
      M0 = Mr
      if (present(gamma_max)) gamma_max = G0
      if (present(periods)) periods = 1
      return
    end if
    gmax = G0 + waveform_value(0.0_wp, G, tau(1))
    if (present(gamma_max)) gamma_max = gmax
    ! history: ramp from 0 to the waveform's maximum
    call element%advance(gmax, Mr, kt, error)
    if (allocated(error)) return

    if (samples > 0) then
      ! classical AFT: N equally spaced instants from the maximum on
      np = samples
      allocate(gam(np), Ms(np))
      do j = 1, np
        gam(j) = G0 + waveform_value(0.0_wp, G, tau(1) + two_pi*j/np)
      end do
      do p = 1, max(1, max_periods)
        call ws%start%copy_state(element)
        do j = 1, np
          call element%advance(gam(j), Ms(j), kt, error)
          if (allocated(error)) return
        end do
        closed = element%same_state(ws%start, loop_rtol)
        if (present(periods)) periods = p
        if (p >= min_periods .and. closed) exit
      end do
      ws%lift_off = element%lifted()
      M0 = sum(Ms)/np
      do k = 1, H
        M(k) = (0.0_wp, 0.0_wp)
        do j = 1, np
          M(k) = M(k) + Ms(j)*exp(cmplx(0.0_wp, -k*(tau(1) + two_pi*j/np), wp))
        end do
        M(k) = 2.0_wp*M(k)/np
      end do
      return
    end if

    ! exact: trace each monotone stretch between extrema, keeping the events
    gam = extremum_values(G0, G, tau, n)
    call trace_periods(element, ws, gam, n, min_periods, max_periods, loop_rtol, error, periods)
    if (allocated(error)) return
    ws%lift_off = element%lifted()
    call integrate_period(ws, G0, G, tau, gam, M0, M)
  end subroutine aft_moment

  !> The start of aft_moment and aft_moment_jacobian: the call counted, M0 and M zero, the
  !> waveform checked, the start state ready and the extrema tau(1..n+1) of gamma(tau).
  subroutine begin_call(element, ws, G0, G, M0, M, tau, n, error)
    class(hysteretic_element_type), intent(in) :: element
    type(aft_workspace_type), intent(inout) :: ws
    real(wp), intent(in) :: G0
    complex(wp), intent(in) :: G(:)
    real(wp), intent(out) :: M0
    complex(wp), intent(out) :: M(:)
    real(wp), allocatable, intent(out) :: tau(:)
    integer, intent(out) :: n
    type(error_type), allocatable, intent(out) :: error
    ws%calls = ws%calls + 1
    M = (0.0_wp, 0.0_wp)
    M0 = 0.0_wp
    n = 0
    if (.not.(abs(G0) <= huge(1.0_wp)) .or. .not.all(abs(G) <= huge(1.0_wp))) then
      call fatal_error(error, "aft: the waveform of gamma is not finite", UDMAP_EINPUT)
      return
    end if
    call ensure_start(ws, element)
    call waveform_extrema(G, tau, n)
  end subroutine begin_call

  !> The values of gamma at the extrema tau(1..n+1), the last equal to the first (a period).
  pure function extremum_values(G0, G, tau, n) result(gam)
    real(wp), intent(in) :: G0, tau(:)
    complex(wp), intent(in) :: G(:)
    integer, intent(in) :: n
    real(wp) :: gam(n+1)
    integer :: k
    do k = 1, n + 1
      gam(k) = G0 + waveform_value(0.0_wp, G, tau(k))
    end do
    gam(n+1) = gam(1)
  end function extremum_values

  !> The element state kept at the start of a period: of the element's type.
  subroutine ensure_start(ws, element)
    type(aft_workspace_type), intent(inout) :: ws
    class(hysteretic_element_type), intent(in) :: element
    if (.not.allocated(ws%start)) then
      allocate(ws%start, mold=element)
    else if (.not.same_type_as(ws%start, element)) then
      deallocate(ws%start)
      allocate(ws%start, mold=element)
    end if
  end subroutine ensure_start

  !> Periods through the extremum values gam(1..n+1) (gam(n+1) = gam(1), the element already
  !> at gam(1)) until the state repeats; the breakpoints of the last period in ws.
  subroutine trace_periods(element, ws, gam, n, min_periods, max_periods, loop_rtol, error, &
      & periods)
    class(hysteretic_element_type), intent(inout) :: element
    type(aft_workspace_type), intent(inout) :: ws
    real(wp), intent(in) :: gam(:), loop_rtol
    integer, intent(in) :: n, min_periods, max_periods
    type(error_type), allocatable, intent(out) :: error
    integer, intent(out), optional :: periods
    integer :: p, k, j
    real(wp) :: Mr, kt
    logical :: closed
    do p = 1, max(1, max_periods)
      call ws%start%copy_state(element)
      ws%bp%n = 0
      call push_bp(ws, gam(1), element%moment(), 1)
      do k = 1, n
        ws%events%n = 0
        call element%advance(gam(k+1), Mr, kt, error, ws%events)
        if (allocated(error)) return
        do j = 1, ws%events%n
          call push_bp(ws, ws%events%gamma(j), ws%events%M(j), k)
        end do
        call push_bp(ws, gam(k+1), Mr, k)
      end do
      closed = element%same_state(ws%start, loop_rtol)
      if (present(periods)) periods = p
      if (p >= min_periods .and. closed) exit
    end do
  end subroutine trace_periods

  !> aft_moment's exact integration (samples = 0) and, in closed form, its Jacobian
  !> JM = d(M0, Re M_1, Im M_1, .., Re M_H, Im M_H)/d(G0, Re G_1, Im G_1, .., Re G_H, Im G_H).
  !>
  !> Between events M_r = c0 + slope gamma(tau), and the events (their gamma and M_r) depend
  !> only on the extremum values g_e of the waveform (the element is rate-independent and
  !> driven from extremum to extremum). So, with M_r continuous in tau (the moving piece
  !> boundaries then cancel),
  !>   dM_h = int slope(tau) dgamma(tau) e^{-i h tau} + sum_e dg_e int (dc0/dg_e
  !>          + dslope/dg_e gamma(tau)) e^{-i h tau},   dg_e = dgamma(tau_e),
  !> the first term a convolution with the Fourier coefficients of the piecewise-constant
  !> slope, the second from one cheap element re-trace per extremum (no integration): exact
  !> while the sequence of events does not change (M_r is linear in the g_e there). ok is
  !> .false. when a re-trace changes that sequence (then use finite differences).
  subroutine aft_moment_jacobian(element, ws, G0, G, min_periods, max_periods, loop_rtol, &
      & M0, M, JM, ok, error)
    class(hysteretic_element_type), intent(inout) :: element
    type(aft_workspace_type), intent(inout) :: ws
    real(wp), intent(in) :: G0
    complex(wp), intent(in) :: G(:)
    integer, intent(in) :: min_periods, max_periods
    real(wp), intent(in) :: loop_rtol
    real(wp), intent(out) :: M0
    complex(wp), intent(out) :: M(:)
    real(wp), intent(out) :: JM(:,:)
    logical, intent(out) :: ok
    type(error_type), allocatable, intent(out) :: error
    !> Relative size of the extremum perturbations (M_r is linear in them: no truncation
    !> error, only the sequence of events must stay).
    real(wp), parameter :: dg_rel = 1.0e-7_wp
    real(wp), allocatable :: tau(:), gam(:), gp(:), bg(:), bM(:), c0(:), sl(:), Ac(:,:), &
      & As(:,:)
    integer, allocatable :: bseg(:)
    complex(wp), allocatable :: Qc(:,:), Bs(:,:)
    complex(wp) :: B(-2*size(G):size(G)), Pa(-2*size(G):size(G)), Pb(-2*size(G):size(G))
    complex(wp) :: dC(0:size(G), 2*size(G)+1), Q(0:size(G)), acc_h(0:size(G))
    real(wp) :: d, Mr, kt, slp, cc
    integer :: H, n, nb, i, e, k, h1, mm, c
    logical :: lift, any_s

    H = size(G)
    ok = .false.
    JM = 0.0_wp
    call begin_call(element, ws, G0, G, M0, M, tau, n, error)
    if (allocated(error)) return
    ! a constant waveform has no extrema to differentiate at: finite differences
    if (n == 0) return
    gam = extremum_values(G0, G, tau, n)
    call run(gam)
    if (allocated(error)) return
    lift = element%lifted()
    ws%lift_off = lift
    call integrate_period(ws, G0, G, tau, gam, M0, M, B)
    nb = ws%bp%n
    bg = ws%bp%gamma(1:nb)
    bM = ws%bp%M(1:nb)
    bseg = ws%bp_seg(1:nb)
    allocate(c0(nb), sl(nb), Ac(nb, n), As(nb, n))
    call affine(bg, bM, c0, sl)
    ! the events against each extremum value
    d = dg_rel*max(maxval(gam) - minval(gam), tiny(1.0_wp))
    allocate(gp(n+1))
    do e = 1, n
      gp = gam
      gp(e) = gam(e) + d
      if (e == 1) gp(n+1) = gp(1)
      call run(gp)
      if (allocated(error)) return
      if (ws%bp%n /= nb) exit
      if (any(ws%bp_seg(1:nb) /= bseg)) exit
      call affine(ws%bp%gamma(1:nb), ws%bp%M(1:nb), Ac(:, e), As(:, e))
      Ac(:, e) = (Ac(:, e) - c0)/d
      As(:, e) = (As(:, e) - sl)/d
      ok = e == n
    end do
    ! ws as the base trace left it (breakpoints and flags)
    ws%bp%n = nb
    ws%bp%gamma(1:nb) = bg
    ws%bp%M(1:nb) = bM
    ws%bp_seg(1:nb) = bseg
    ws%lift_off = lift
    if (.not.ok) return

    ! slope term: columns G0 (dgamma = 1), Re G_k (cos k tau), Im G_k (-sin k tau)
    do h1 = 0, H
      dC(h1, 1) = B(-h1)
      do k = 1, H
        dC(h1, 2*k) = 0.5_wp*(B(k - h1) + B(-k - h1))
        dC(h1, 2*k+1) = cmplx(0.0_wp, 0.5_wp, wp)*(B(k - h1) - B(-k - h1))
      end do
    end do
    ! history term: Qc_e(m) = sum_i dc0_i/dg_e (P(tb) - P(ta))(m), Bs_e likewise with dslope
    allocate(Qc(-H:0, n), Bs(-2*H:H, n))
    Qc = (0.0_wp, 0.0_wp)
    Bs = (0.0_wp, 0.0_wp)
    any_s = .false.
    call powers(ws%bp_tau(1), H, Pa)
    do i = 2, nb
      call powers(ws%bp_tau(i), H, Pb)
      do e = 1, n
        cc = Ac(i, e)
        if (cc /= 0.0_wp) then
          Qc(-H:-1, e) = Qc(-H:-1, e) + cc*(Pb(-H:-1) - Pa(-H:-1))
          Qc(0, e) = Qc(0, e) + cc*(ws%bp_tau(i) - ws%bp_tau(i-1))
        end if
        slp = As(i, e)
        if (slp /= 0.0_wp) then
          any_s = .true.
          Bs(:, e) = Bs(:, e) + slp*(Pb - Pa)
          Bs(0, e) = Bs(0, e) + slp*(ws%bp_tau(i) - ws%bp_tau(i-1))   ! P(0) = 1: the time
        end if
      end do
      Pa = Pb
    end do
    do e = 1, n
      do mm = -H, -1
        Qc(mm, e) = Qc(mm, e)/cmplx(0.0_wp, real(mm, wp), wp)
      end do
      if (any_s) then
        do mm = -2*H, H
          if (mm /= 0) Bs(mm, e) = Bs(mm, e)/cmplx(0.0_wp, real(mm, wp), wp)
        end do
      end if
      ! Q_e(h) = int (dc0/dg_e + dslope/dg_e gamma) e^{-i h tau}
      do h1 = 0, H
        Q(h1) = Qc(-h1, e)
      end do
      if (any_s) then
        ! the sums over k as integrate_period's, all h1 a step in k
        acc_h = (0.0_wp, 0.0_wp)
        do k = 1, H
          do h1 = 0, H
            acc_h(h1) = acc_h(h1) + G(k)*Bs(k - h1, e) + conjg(G(k))*Bs(-k - h1, e)
          end do
        end do
        do h1 = 0, H
          Q(h1) = Q(h1) + G0*Bs(-h1, e) + 0.5_wp*acc_h(h1)
        end do
      end if
      ! dg_e = dG0 + sum_k (cos(k tau_e) dRe G_k - sin(k tau_e) dIm G_k)
      dC(:, 1) = dC(:, 1) + Q
      do k = 1, H
        dC(:, 2*k) = dC(:, 2*k) + cos(k*tau(e))*Q
        dC(:, 2*k+1) = dC(:, 2*k+1) - sin(k*tau(e))*Q
      end do
    end do
    do c = 1, 2*H + 1
      JM(1, c) = real(dC(0, c), wp)/(2.0_wp*pi)
      do h1 = 1, H
        JM(2*h1, c) = real(dC(h1, c), wp)/pi
        JM(2*h1+1, c) = aimag(dC(h1, c))/pi
      end do
    end do
  contains
    !> Load, ramp to the maximum and the periods through the extremum values g.
    subroutine run(g)
      real(wp), intent(in) :: g(:)
      call element%load(error)
      if (allocated(error)) return
      call element%advance(g(1), Mr, kt, error)
      if (allocated(error)) return
      call trace_periods(element, ws, g, n, min_periods, max_periods, loop_rtol, error)
    end subroutine run

    !> M_r = c0 + slope gamma on the piece ending at each breakpoint (the first: unused).
    pure subroutine affine(g, Mb, c0v, slv)
      real(wp), intent(in) :: g(:), Mb(:)
      real(wp), intent(out) :: c0v(:), slv(:)
      integer :: j
      c0v(1) = 0.0_wp
      slv(1) = 0.0_wp
      do j = 2, size(g)
        if (g(j) /= g(j-1)) then
          slv(j) = (Mb(j) - Mb(j-1))/(g(j) - g(j-1))
        else
          slv(j) = 0.0_wp
        end if
        c0v(j) = Mb(j-1) - slv(j)*g(j-1)
      end do
    end subroutine affine
  end subroutine aft_moment_jacobian

  !> Appends a breakpoint (gamma, M_r) on segment seg (the events' storage, the segments
  !> alongside at the same capacity).
  pure subroutine push_bp(ws, g, Mr, seg)
    type(aft_workspace_type), intent(inout) :: ws
    real(wp), intent(in) :: g, Mr
    integer, intent(in) :: seg
    integer, allocatable :: t(:)
    call ws%bp%push(g, Mr)
    if (.not.allocated(ws%bp_seg)) then
      allocate(ws%bp_seg(size(ws%bp%gamma)))
    else if (size(ws%bp_seg) < ws%bp%n) then
      allocate(t(size(ws%bp%gamma)))
      t(1:size(ws%bp_seg)) = ws%bp_seg
      call move_alloc(t, ws%bp_seg)
    end if
    ws%bp_seg(ws%bp%n) = seg
  end subroutine push_bp

  !> Closed-form Fourier integral of the piecewise-linear-in-gamma moment over the period. On
  !> the piece [ta, tb], M_r = c0 + slope gamma(tau), so
  !>   int M_r e^{-i h tau} = (c0 + slope G0) E(-h) + slope/2 sum_k (G_k E(k-h) + conj(G_k) E(-k-h)),
  !> E(m) = int_ta^tb e^{i m tau}; the sums over the pieces of c0 E and slope E are accumulated
  !> first, then combined with the G_k once (O(pieces H + H^2) instead of O(pieces H^2)).
  pure subroutine integrate_period(ws, G0, G, tau, gam, M0, M, Bout)
    type(aft_workspace_type), intent(inout) :: ws
    real(wp), intent(in) :: G0, tau(:), gam(:)
    complex(wp), intent(in) :: G(:)
    real(wp), intent(out) :: M0
    complex(wp), intent(out) :: M(:)
    !> sum over the pieces of slope int e^{i m tau}, m = -2H..H (the Jacobian's slope term)
    complex(wp), intent(out), optional :: Bout(-2*size(G):)
    integer :: H, i, k, seg, h1, mm
    real(wp) :: ta, tb, ga, gb, Ma, Mb, slope, c0, G_abs
    complex(wp) :: Pa(-2*size(G):size(G)), Pb(-2*size(G):size(G)), C(0:size(G))
    ! A(mm) = sum (c0 + slope G0) (P(tb) - P(ta)), B(m) = sum slope (P(tb) - P(ta)); mm = 0: times
    complex(wp) :: A(-size(G):0), B(-2*size(G):size(G)), acc_h(0:size(G))
    H = size(G)
    G_abs = sum(abs(G))
    A = (0.0_wp, 0.0_wp)
    B = (0.0_wp, 0.0_wp)
    ta = tau(1)
    call powers(ta, H, Pa)
    if (.not.allocated(ws%bp_tau)) then
      allocate(ws%bp_tau(size(ws%bp%gamma)))
    else if (size(ws%bp_tau) < ws%bp%n) then
      deallocate(ws%bp_tau)
      allocate(ws%bp_tau(size(ws%bp%gamma)))
    end if
    ws%bp_tau(1) = ta
    do i = 2, ws%bp%n
      seg = ws%bp_seg(i)
      ga = ws%bp%gamma(i-1); gb = ws%bp%gamma(i)
      Ma = ws%bp%M(i-1); Mb = ws%bp%M(i)
      if (i == ws%bp%n .or. ws%bp_seg(min(i+1, ws%bp%n)) /= seg) then
        tb = tau(seg+1)   ! the extremum closing the segment
      else
        tb = solve_time(G0, G, G_abs, gb, ta, tau(seg+1), gam(seg+1))
      end if
      ws%bp_tau(i) = tb
      call powers(tb, H, Pb)
      if (gb /= ga) then
        slope = (Mb - Ma)/(gb - ga)
      else
        slope = 0.0_wp
      end if
      c0 = Ma - slope*ga
      A(-H:-1) = A(-H:-1) + (c0 + slope*G0)*(Pb(-H:-1) - Pa(-H:-1))
      A(0) = A(0) + (c0 + slope*G0)*(tb - ta)
      if (slope /= 0.0_wp) then
        B(-2*H:-1) = B(-2*H:-1) + slope*(Pb(-2*H:-1) - Pa(-2*H:-1))
        B(1:H) = B(1:H) + slope*(Pb(1:H) - Pa(1:H))
        B(0) = B(0) + slope*(tb - ta)
      end if
      ta = tb
      Pa = Pb
    end do
    ! E(m) = (P(tb) - P(ta))/(i m), m /= 0
    do mm = -H, -1
      A(mm) = A(mm)/cmplx(0.0_wp, real(mm, wp), wp)
    end do
    do mm = -2*H, H
      if (mm /= 0) B(mm) = B(mm)/cmplx(0.0_wp, real(mm, wp), wp)
    end do
    ! C_h1 = A_-h1 + (sum_k G_k B_k-h1 + conj(G_k) B_-k-h1)/2, each sum in increasing k; all
    ! h1 a step in k (the inner loop runs over independent sums)
    acc_h = (0.0_wp, 0.0_wp)
    do k = 1, H
      do h1 = 0, H
        acc_h(h1) = acc_h(h1) + G(k)*B(k - h1) + conjg(G(k))*B(-k - h1)
      end do
    end do
    do h1 = 0, H
      C(h1) = A(-h1) + 0.5_wp*acc_h(h1)
    end do
    M0 = real(C(0), wp)/(2.0_wp*pi)
    M = C(1:H)/pi
    if (present(Bout)) Bout(-2*H:H) = B
  end subroutine integrate_period
end module udmap_contact_aft_moment
