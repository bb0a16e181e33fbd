!> The core of the damper's event-driven tracer (PHYSICS.md 2.1): the contact states and the
!> geometry, the contact forces of a state, and the exact tracing of the quasi-static path in
!> gamma: stick/slip/open transitions resolved as events (the mode of each contact at an event,
!> the rates of the forces and of the sliders in each mode), with the breakpoints recorded.
module udmap_damper_tracer_core
  use udmap_core_kinds, only: wp
  use udmap_core_arrays, only: put
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  implicit none
  private
  public :: contact_forces, lever_forces, trace_core, solve3, append_vertex, compute_rates, &
    & rates_type, mode_stiffness, &
    & mode_log_type, mode_code, code_modes

  !> Contact states.
  integer, parameter, public :: CONTACT_OPEN = 0, CONTACT_STICK = 1, CONTACT_SLIP_POS = 2, &
    & CONTACT_SLIP_NEG = 3

  !> Classes of a contact at a point, which decide its candidate states.
  integer, parameter :: CLS_FIXED = 0, CLS_CONE = 1, CLS_GAP = 2
  !> Kinds of events.
  integer, parameter :: EV_TARGET = 0
  !> Safety limit on the events of one call (a real path has a handful per reversal).
  integer, parameter :: MAX_EVENTS = 100000
  !> Relative tolerances: forces at a boundary, rates that count as zero.
  real(wp), parameter :: TOL_FORCE = 1e-11_wp, TOL_RATE = 1e-9_wp

  !> Contact kinematics in generalised form. For contact i with point r, normal n (into the
  !> damper), tangent t = (-n_y, n_x) and platform centre P: the normal approach is
  !> g = -bn.q + gamma cn and the tangential relative displacement s = bt.q - gamma ct, with
  !> bn = (n_x, n_y, r x n), bt = (t_x, t_y, r x t), cn = n.a, ct = t.a, a = (-(r_y - P_y), r_x - P_x).
  !> Contacts 1, 2 are the flat points, 3 the curved point.
  type, public :: damper_geometry_type
    !> bn(:,i), bt(:,i): generalised directions of the normal and tangent of contact i.
    real(wp) :: bn(3,3) = 0, bt(3,3) = 0
    !> Lever arms of the platform rotation along the normal and the tangent [m].
    real(wp) :: cn(3) = 0, ct(3) = 0
    !> Normal and tangential stiffnesses [N/m] and the friction coefficient.
    real(wp) :: kn(3) = 0, kt(3) = 0, mu = 0
    !> Face inclinations [deg] (for messages).
    real(wp) :: beta_deg(2) = 0
    !> Force rate per unit gamma (max of kn |cn|, kt |ct|), a scale for tolerances [N/rad].
    real(wp) :: rate_scale = 0
    !> Moment rate per unit gamma (rate_scale times the largest lever arm) [N m/rad].
    real(wp) :: moment_scale = 0
    !> Rigid platform kinematics (PHYSICS.md 2.6): contact i touches platform side(i) (1: the
    !> flat side, blade j; 2: the curved side, blade j + 1) with centre P; a platform motion
    !> (u_P, v_P, gamma_P) moves the contact point by n.(...) = pn(:,i).(u_P, v_P, gamma_P)
    !> along the normal and pt(:,i).(...) along the tangent (pn = (n_x, n_y, cn),
    !> pt = (t_x, t_y, ct)). These are also the generalised directions of the contact force
    !> on the platform's coordinates.
    real(wp) :: pn(3,3) = 0, pt(3,3) = 0
    integer :: side(3) = 0
  end type damper_geometry_type

  !> State of the damper on its loading path: DOFs, sliders, contact states, loads.
  type, public :: damper_state_type
    !> Damper DOFs (x [m], y [m], theta [rad]).
    real(wp) :: q(3) = 0
    !> Slider positions of the Jenkins elements [m].
    real(wp) :: w(3) = 0
    !> Platform rotation [rad] and centrifugal load [N].
    real(wp) :: gamma = 0, CF = 0
    !> Contact states (CONTACT_*).
    integer :: mode(3) = CONTACT_OPEN
    !> Last direction of motion in gamma (+1, -1; 0 before any).
    integer :: direction = 0
    !> Derivatives of q, w, gamma with respect to the path parameter p (loop amplitude);
    !> zero unless the targets depend on p.
    real(wp) :: q_p(3) = 0, w_p(3) = 0, gamma_p = 0
    !> Platform displacement at each contact beyond gamma (cn, ct): off(1,i) along the
    !> normal, off(2,i) along the tangent [m]; zero on in-phase paths (PHYSICS.md 2.6).
    real(wp) :: off(2,3) = 0
    !> Both platforms' coordinates (u_P, v_P, gamma_P of side 1, then of side 2) on a
    !> traveling-wave path (trace_path).
    real(wp) :: X(6) = 0
  end type damper_state_type

  !> Range [lo, hi] of the parameter p around p0 in which the traced event sequence holds.
  type, public :: validity_type
    real(wp) :: p0 = 0, lo = -huge(1.0_wp), hi = huge(1.0_wp)
  end type validity_type

  !> Vertices (gamma, M_r) of a traced path, with their p-derivatives; slope(j) is dM_r/dgamma
  !> on the segment that ends at vertex j (j >= 2). States are kept on request.
  type, public :: branch_record_type
    integer :: n = 0
    real(wp), allocatable :: gamma(:), gamma_p(:), M(:), M_p(:), slope(:)
    logical :: keep_states = .false.
    type(damper_state_type), allocatable :: states(:)
    !> Some contact slipped / was open along a segment of positive length.
    logical :: slipped = .false., opened = .false.
  end type branch_record_type

  !> The contact states of each step of a trace (mode_code) and the value of gamma where the
  !> step ended (trace_path's events; cheaper than a branch record with states).
  type :: mode_log_type
    integer :: n = 0
    real(wp), allocatable :: s(:)
    integer, allocatable :: code(:)
    !> The event that ended each step: 4 contact + its new state, or 0 (the target); the
    !> rate at which that contact's boundary came nearer (what the derivatives of the step
    !> need: udmap_damper_tracer_tangent).
    integer, allocatable :: event(:)
    real(wp), allocatable :: rate(:)
  end type mode_log_type

  !> Rates per unit travel of a set of contact states.
  type :: rates_type
    real(wp) :: dq(3) = 0, dg(3) = 0, ds(3) = 0, dN(3) = 0, dT(3) = 0, dw(3) = 0, dM = 0
  end type rates_type

contains

  !> Normal approach g, tangential displacement s and forces N, T of the three contacts for
  !> the states `mode` at (q, gamma, w). Linear and homogeneous in (q, gamma, w), so it also
  !> maps p-derivatives to p-derivatives.
  pure subroutine contact_forces(geo, mode, q, gamma, w, g, s, N, T, off)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: q(3), gamma, w(3)
    real(wp), intent(out) :: g(3), s(3), N(3), T(3)
    !> The state's platform offsets (damper_state_type%off); absent: none.
    real(wp), intent(in), optional :: off(2,3)
    integer :: i
    ! lever_forces with the geometry's levers, written out: the tracer's most frequent call
    do i = 1, 3
      g(i) = -(geo%bn(1,i)*q(1) + geo%bn(2,i)*q(2) + geo%bn(3,i)*q(3)) + gamma*geo%cn(i)
      s(i) = geo%bt(1,i)*q(1) + geo%bt(2,i)*q(2) + geo%bt(3,i)*q(3) - gamma*geo%ct(i)
      if (present(off)) then
        g(i) = g(i) + off(1,i)
        s(i) = s(i) - off(2,i)
      end if
      select case (mode(i))
      case (CONTACT_STICK)
        N(i) = geo%kn(i)*g(i)
        T(i) = -geo%kt(i)*(s(i) - w(i))
      case (CONTACT_SLIP_POS)
        N(i) = geo%kn(i)*g(i)
        T(i) = geo%mu*N(i)
      case (CONTACT_SLIP_NEG)
        N(i) = geo%kn(i)*g(i)
        T(i) = -geo%mu*N(i)
      case default
        N(i) = 0
        T(i) = 0
      end select
    end do
  end subroutine contact_forces

  !> contact_forces with the lever arms (cn, ct) given: a segment's, or a derivative's
  !> (udmap_damper_tracer_tangent); with q the rates of the damper's DOFs, gamma = 1 and w = 0,
  !> the rates of the forces.
  pure subroutine lever_forces(geo, mode, cn, ct, q, gamma, w, g, s, N, T, off)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: cn(3), ct(3), q(3), gamma, w(3)
    real(wp), intent(out) :: g(3), s(3), N(3), T(3)
    real(wp), intent(in), optional :: off(2,3)
    integer :: i
    do i = 1, 3
      g(i) = -(geo%bn(1,i)*q(1) + geo%bn(2,i)*q(2) + geo%bn(3,i)*q(3)) + gamma*cn(i)
      s(i) = geo%bt(1,i)*q(1) + geo%bt(2,i)*q(2) + geo%bt(3,i)*q(3) - gamma*ct(i)
      if (present(off)) then
        g(i) = g(i) + off(1,i)
        s(i) = s(i) - off(2,i)
      end if
      select case (mode(i))
      case (CONTACT_STICK)
        N(i) = geo%kn(i)*g(i)
        T(i) = -geo%kt(i)*(s(i) - w(i))
      case (CONTACT_SLIP_POS)
        N(i) = geo%kn(i)*g(i)
        T(i) = geo%mu*N(i)
      case (CONTACT_SLIP_NEG)
        N(i) = geo%kn(i)*g(i)
        T(i) = -geo%mu*N(i)
      case default
        N(i) = 0
        T(i) = 0
      end select
    end do
  end subroutine lever_forces

  ! ------------------------------------------------------------------ internals

  !> The tracing engine. var = 1: load parameter gamma, var = 2: CF. With has_target it stops
  !> at `target`, otherwise after the last event (travel = distance to it, dM = moment rate of
  !> the final states per unit travel).
  subroutine trace_core(geo, st, var, dir, target, target_p, has_target, travel, dM, error, &
      & rec, val, frozen, max_travel, modes)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: st
    integer, intent(in) :: var, dir
    real(wp), intent(in) :: target, target_p
    logical, intent(in) :: has_target
    real(wp), intent(out) :: travel, dM
    type(error_type), allocatable, intent(out) :: error
    type(branch_record_type), intent(inout), optional :: rec
    type(validity_type), intent(inout), optional :: val
    logical, intent(out), optional :: frozen
    real(wp), intent(in), optional :: max_travel
    type(mode_log_type), intent(inout), optional :: modes
    type(rates_type) :: rt
    integer :: pred(3), nev, i, nc, ic, best, ev_contact(10), ev_state(10)
    real(wp) :: dgam, dcf, tc(10), tcp(10), rate_of(10), g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    real(wp) :: f(3), df(3), fp(3), remaining, step, step_p, cur, scale
    character(len=60) :: buf
    logical :: with_p

    travel = 0
    dM = 0
    if (present(frozen)) frozen = .false.
    if (var == 1) then
      dgam = real(dir, wp)
      dcf = 0
    else
      dgam = 0
      dcf = real(dir, wp)
    end if
    ! p-derivatives that start at zero with a target independent of p stay zero: not computed
    with_p = target_p /= 0 .or. st%gamma_p /= 0 .or. any(st%q_p /= 0) .or. any(st%w_p /= 0)
    pred = st%mode
    if (var == 1 .and. st%direction /= dir) then
      where (pred == CONTACT_SLIP_POS .or. pred == CONTACT_SLIP_NEG) pred = CONTACT_STICK
    end if

    do nev = 1, MAX_EVENTS
      cur = merge(st%gamma, st%CF, var == 1)
      remaining = dir*(target - cur)
      if (has_target .and. remaining <= 0) then
        if (var == 1) st%direction = dir
        return
      end if
      call snap_sliders(geo, st, with_p)
      call resolve_mode(geo, st, dgam, dcf, pred, rt, error)
      if (allocated(error)) return

      call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T, st%off)
      if (with_p) then
        call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
      else
        gp = 0
        sp = 0
        Np = 0
        Tp = 0
      end if
      ! Candidate events: travel to each boundary the states move towards.
      nc = 0
      do i = 1, 3
        select case (st%mode(i))
        case (CONTACT_STICK)
          f = [geo%mu*N(i) - T(i), geo%mu*N(i) + T(i), N(i)]
          df = [geo%mu*rt%dN(i) - rt%dT(i), geo%mu*rt%dN(i) + rt%dT(i), rt%dN(i)]
          fp = [geo%mu*Np(i) - Tp(i), geo%mu*Np(i) + Tp(i), Np(i)]
          call add_candidates(3, [CONTACT_SLIP_POS, CONTACT_SLIP_NEG, CONTACT_OPEN])
        case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
          f(1) = N(i)
          df(1) = rt%dN(i)
          fp(1) = Np(i)
          call add_candidates(1, [CONTACT_OPEN, 0, 0])
        case default
          f(1) = -geo%kn(i)*g(i)
          df(1) = -geo%kn(i)*rt%dg(i)
          fp(1) = -geo%kn(i)*gp(i)
          call add_candidates(1, [CONTACT_STICK, 0, 0])
        end select
      end do
      if (has_target) then
        nc = nc + 1
        tc(nc) = remaining
        tcp(nc) = dir*(target_p - merge(st%gamma_p, 0.0_wp, var == 1))
        ev_contact(nc) = 0
        ev_state(nc) = EV_TARGET
      end if

      if (nc == 0) then
        ! Nothing changes any more in this direction: the end of the path.
        dM = rt%dM
        if (present(frozen)) then
          frozen = all(abs(rt%dN) <= TOL_RATE*geo%rate_scale) .and. &
            & all(abs(rt%dT) <= TOL_RATE*geo%rate_scale) .and. &
            & all(abs(geo%kn*rt%dg) <= TOL_RATE*geo%rate_scale .or. st%mode /= CONTACT_OPEN)
        end if
        if (var == 1) st%direction = dir
        return
      end if
      best = 1
      do ic = 2, nc
        if (tc(ic) < tc(best)) best = ic
      end do
      ! An event that coincides with the target to rounding (often identically in p, e.g. a
      ! contact that returns to its cone exactly at the reversal) is left to the next call:
      ! the target ends this one without a zero-length segment.
      ! Coincidence is judged in gamma and in force (stopping at the target instead leaves
      ! the contact past its boundary by less than the force tolerance of the classification),
      ! but never beyond 1e-10 of the amplitude.
      if (has_target .and. ev_contact(best) /= 0) then
        scale = max(abs(target), abs(cur))
        if (tc(best) >= remaining - max(1e-13_wp*scale, &
          & min(TOL_FORCE*max(abs(st%CF), maxval(abs(N)), maxval(abs(T)))/rate_of(best), &
          & 1e-10_wp*scale))) best = nc
      end if
      step = tc(best)
      step_p = tcp(best)
      if (present(val)) then
        call restrict(val, step, step_p)
        do ic = 1, nc
          if (ic /= best) call restrict(val, tc(ic) - step, tcp(ic) - step_p)
        end do
      end if

      ! Move to the event.
      st%q = st%q + step*rt%dq
      st%q_p = st%q_p + step_p*rt%dq
      if (var == 1) then
        st%gamma = st%gamma + step*dgam
        st%gamma_p = st%gamma_p + step_p*dgam
      else
        st%CF = st%CF + step*dcf
      end if
      if (ev_contact(best) == 0) then
        if (var == 1) then
          st%gamma = target
          st%gamma_p = target_p
        else
          st%CF = target
        end if
      end if
      travel = travel + step
      if (present(rec)) then
        if (step > 1e-12_wp*max(abs(st%gamma), abs(travel))) then
          rec%slipped = rec%slipped .or. any(st%mode == CONTACT_SLIP_POS .or. &
            & st%mode == CONTACT_SLIP_NEG)
          rec%opened = rec%opened .or. any(st%mode == CONTACT_OPEN)
        end if
        call append_vertex(geo, st, rt%dM*dir, rec)
      end if
      if (present(modes)) then
        modes%n = modes%n + 1
        call put(modes%s, modes%n, st%gamma)
        call put(modes%code, modes%n, mode_code(st%mode))
        call put(modes%event, modes%n, 4*ev_contact(best) + ev_state(best))
        call put(modes%rate, modes%n, merge(rate_of(best), 0.0_wp, ev_contact(best) /= 0))
      end if
      if (ev_contact(best) == 0) then
        if (var == 1) st%direction = dir
        return
      end if
      if (present(max_travel)) then
        if (travel > max_travel) then
          write(buf, '(es12.5)') st%gamma
          call fatal_error(error, "damper jams: the contacts keep changing state up to gamma = "// &
            & trim(adjustl(buf))//" rad without reaching a plateau (moment unbounded)", &
            & UDMAP_EPHYSICS)
          return
        end if
      end if
      pred = st%mode
      pred(ev_contact(best)) = ev_state(best)
    end do
    write(buf, '(a, es12.5)') "at gamma = ", st%gamma
    call fatal_error(error, "damper tracer: more than 100000 contact events in one step "// &
      & trim(buf)//" (chattering between contact states)", UDMAP_ENUMERIC)

  contains

    subroutine add_candidates(m, states)
      integer, intent(in) :: m, states(3)
      real(wp) :: tolR
      integer :: k
      tolR = TOL_RATE*(geo%rate_scale*abs(dgam) + abs(dcf))
      do k = 1, m
        if (df(k) < -tolR) then
          nc = nc + 1
          tc(nc) = max(f(k), 0.0_wp)/(-df(k))
          tcp(nc) = fp(k)/(-df(k))
          rate_of(nc) = -df(k)
          ev_contact(nc) = i
          ev_state(nc) = states(k)
        end if
      end do
    end subroutine add_candidates

    !> Requires d + d_p (p - p0) >= 0. Gaps below the tie tolerance are ties at p0 (mostly
    !> structural ones that hold for every p, e.g. a contact back on its cone at a reversal):
    !> their p-derivatives are rounding noise and bound nothing.
    subroutine restrict(v, d, d_p)
      type(validity_type), intent(inout) :: v
      real(wp), intent(in) :: d, d_p
      if (abs(d) <= 1e-10_wp*max(abs(v%p0), abs(travel), abs(cur))) return
      if (d_p < 0) then
        v%hi = min(v%hi, v%p0 + d/(-d_p))
      else if (d_p > 0) then
        v%lo = max(v%lo, v%p0 - d/d_p)
      end if
    end subroutine restrict
  end subroutine trace_core

  !> Keeps the sliders of slipping and open contacts on their forces (T = -kt (s - w)),
  !> with their p-derivatives, so that a change to stick continues the force.
  pure subroutine snap_sliders(geo, st, with_p)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: st
    !> The p-derivatives are not all zero.
    logical, intent(in) :: with_p
    real(wp) :: g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    integer :: i
    if (all(st%mode == CONTACT_STICK)) return
    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T, st%off)
    if (with_p) call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
    do i = 1, 3
      if (st%mode(i) /= CONTACT_STICK) then
        st%w(i) = s(i) + T(i)/geo%kt(i)
        if (with_p) st%w_p(i) = sp(i) + Tp(i)/geo%kt(i)
      end if
    end do
  end subroutine snap_sliders

  !> Chooses the contact states for moving on with load rates (dgam, dcf): contacts inside
  !> their stick cone or clearly open keep their state; contacts on the cone (stick or slip)
  !> or at zero gap (open, stick, slip+-) take the combination whose rates are consistent.
  !> `pred` is tried first.
  subroutine resolve_mode(geo, st, dgam, dcf, pred, rt, error)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: st
    real(wp), intent(in) :: dgam, dcf
    integer, intent(in) :: pred(3)
    type(rates_type), intent(out) :: rt
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: g(3), s(3), N(3), T(3), tolF, tolR
    integer :: ncand(3), cand(4,3), cls(3), sig0(3), i, i1, i2, i3, trial(3), old(3)
    logical :: ok, any_regular
    character(len=120) :: buf

    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T, st%off)
    ! forces within this of a boundary count as on it: the resolution of the force sums
    tolF = TOL_FORCE*max(abs(st%CF), maxval(abs(N)), maxval(abs(T)))
    tolR = TOL_RATE*(geo%rate_scale*abs(dgam) + abs(dcf))
    sig0 = 0
    do i = 1, 3
      if (st%mode(i) /= CONTACT_OPEN .and. N(i) > tolF) then
        if (abs(T(i)) >= geo%mu*N(i) - tolF) then
          cls(i) = CLS_CONE
          sig0(i) = merge(1, -1, T(i) > 0)
          ncand(i) = 2
          cand(1:2,i) = [CONTACT_STICK, merge(CONTACT_SLIP_POS, CONTACT_SLIP_NEG, sig0(i) > 0)]
        else
          cls(i) = CLS_FIXED
          ncand(i) = 1
          cand(1,i) = CONTACT_STICK
        end if
      else if (st%mode(i) == CONTACT_OPEN .and. geo%kn(i)*g(i) < -tolF) then
        cls(i) = CLS_FIXED
        ncand(i) = 1
        cand(1,i) = CONTACT_OPEN
      else
        cls(i) = CLS_GAP
        ncand(i) = 4
        cand(:,i) = [CONTACT_STICK, CONTACT_SLIP_POS, CONTACT_SLIP_NEG, CONTACT_OPEN]
      end if
      call put_first(cand(1:ncand(i),i), pred(i))
    end do

    any_regular = .false.
    do i1 = 1, ncand(1)
      do i2 = 1, ncand(2)
        do i3 = 1, ncand(3)
          trial = [cand(i1,1), cand(i2,2), cand(i3,3)]
          call compute_rates(geo, trial, dgam, dcf, rt, ok)
          if (.not. ok) cycle
          any_regular = .true.
          if (consistent()) then
            old = st%mode
            st%mode = trial
            call snap_new_states(old)
            return
          end if
        end do
      end do
    end do
    write(buf, '(a, es12.5, a, es12.5, a, 3i2, a)') "at gamma = ", st%gamma, " rad, CF = ", &
      & st%CF, " N (contact states", st%mode, ")"
    if (.not. any_regular) then
      call fatal_error(error, "singular damper equilibrium "//trim(buf)//": the contacts "// &
        & "left closed do not hold the damper", UDMAP_EPHYSICS)
    else
      call fatal_error(error, "damper jams "//trim(buf)//": no combination of stick, slip "// &
        & "and open contacts is consistent", UDMAP_EPHYSICS)
    end if

  contains

    logical function consistent()
      integer :: j, sg
      consistent = .true.
      do j = 1, 3
        select case (cls(j))
        case (CLS_CONE)
          if (trial(j) == CONTACT_STICK) then
            consistent = sig0(j)*rt%dT(j) - geo%mu*rt%dN(j) <= tolR
          else
            consistent = sig0(j)*geo%kt(j)*rt%dw(j) <= tolR
          end if
        case (CLS_GAP)
          select case (trial(j))
          case (CONTACT_OPEN)
            consistent = geo%kn(j)*rt%dg(j) <= tolR
          case (CONTACT_STICK)
            consistent = rt%dN(j) >= -tolR .and. abs(rt%dT(j)) <= geo%mu*rt%dN(j) + tolR
          case default
            sg = merge(1, -1, trial(j) == CONTACT_SLIP_POS)
            consistent = rt%dN(j) >= -tolR .and. sg*geo%kt(j)*rt%dw(j) <= tolR
          end select
        end select
        if (.not. consistent) return
      end do
    end function consistent

    !> A contact that opens or closes starts with its spring unloaded: w = s.
    subroutine snap_new_states(old)
      integer, intent(in) :: old(3)
      real(wp) :: gg(3), ss(3), NN(3), TT(3), gp(3), sp(3), Np(3), Tp(3)
      integer :: j
      if (all(old == st%mode)) return
      call contact_forces(geo, st%mode, st%q, st%gamma, st%w, gg, ss, NN, TT, st%off)
      call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
      do j = 1, 3
        if ((old(j) == CONTACT_OPEN) .neqv. (st%mode(j) == CONTACT_OPEN)) then
          st%w(j) = ss(j)
          st%w_p(j) = sp(j)
        end if
      end do
    end subroutine snap_new_states
  end subroutine resolve_mode

  !> Moves `first` to the front of the candidate list (if it is in it).
  pure subroutine put_first(list, first)
    integer, intent(inout) :: list(:)
    integer, intent(in) :: first
    integer :: k
    do k = 2, size(list)
      if (list(k) == first) then
        list(k) = list(1)
        list(1) = first
        return
      end if
    end do
  end subroutine put_first

  !> Rates of q, gaps, forces, sliders and moment per unit travel for the contact states
  !> `mode` under load rates (dgam, dcf); ok is false for a singular equilibrium.
  pure subroutine compute_rates(geo, mode, dgam, dcf, rt, ok)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: dgam, dcf
    type(rates_type), intent(out) :: rt
    logical, intent(out) :: ok
    real(wp) :: K(3,3), h(3), v(3)
    integer :: i, sg

    call mode_stiffness(geo, mode, K)
    h = 0
    do i = 1, 3
      select case (mode(i))
      case (CONTACT_STICK)
        h = h + geo%kn(i)*geo%cn(i)*geo%bn(:,i) + geo%kt(i)*geo%ct(i)*geo%bt(:,i)
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        sg = merge(1, -1, mode(i) == CONTACT_SLIP_POS)
        v = geo%bn(:,i) + sg*geo%mu*geo%bt(:,i)
        h = h + geo%kn(i)*geo%cn(i)*v
      end select
    end do
    call solve3(K, dgam*h + [0.0_wp, dcf, 0.0_wp], rt%dq, ok)
    if (.not. ok) return
    do i = 1, 3
      rt%dg(i) = -dot_product(geo%bn(:,i), rt%dq) + dgam*geo%cn(i)
      rt%ds(i) = dot_product(geo%bt(:,i), rt%dq) - dgam*geo%ct(i)
      select case (mode(i))
      case (CONTACT_STICK)
        rt%dN(i) = geo%kn(i)*rt%dg(i)
        rt%dT(i) = -geo%kt(i)*rt%ds(i)
        rt%dw(i) = 0
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        sg = merge(1, -1, mode(i) == CONTACT_SLIP_POS)
        rt%dN(i) = geo%kn(i)*rt%dg(i)
        rt%dT(i) = sg*geo%mu*rt%dN(i)
        rt%dw(i) = rt%ds(i) + rt%dT(i)/geo%kt(i)
      case default
        rt%dN(i) = 0
        rt%dT(i) = 0
        rt%dw(i) = rt%ds(i)
      end select
    end do
    rt%dM = sum(geo%cn*rt%dN + geo%ct*rt%dT)
  end subroutine compute_rates

  !> The damper's equilibrium matrix K in the contact states `mode` (K dq = h, compute_rates):
  !> kn bn bn^T + kt bt bt^T a contact that sticks, kn v bn^T one that slips (v = bn +- mu bt),
  !> element by element (the tracer's most frequent work, without whole-array temporaries).
  pure subroutine mode_stiffness(geo, mode, K)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(out) :: K(3,3)
    real(wp) :: v(3)
    integer :: i, r, c
    K = 0
    do i = 1, 3
      select case (mode(i))
      case (CONTACT_STICK)
        do c = 1, 3
          do r = 1, 3
            K(r,c) = K(r,c) + geo%kn(i)*(geo%bn(r,i)*geo%bn(c,i)) + &
              & geo%kt(i)*(geo%bt(r,i)*geo%bt(c,i))
          end do
        end do
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        v = geo%bn(:,i) + merge(1, -1, mode(i) == CONTACT_SLIP_POS)*geo%mu*geo%bt(:,i)
        do c = 1, 3
          do r = 1, 3
            K(r,c) = K(r,c) + geo%kn(i)*(v(r)*geo%bn(c,i))
          end do
        end do
      end select
    end do
  end subroutine mode_stiffness

  !> Solves the 3x3 system A x = b by cofactors; ok is false if A is numerically singular.
  pure subroutine solve3(A, b, x, ok)
    real(wp), intent(in) :: A(3,3), b(3)
    real(wp), intent(out) :: x(3)
    logical, intent(out) :: ok
    real(wp) :: C(3,3), det, scale
    C(1,1) = A(2,2)*A(3,3) - A(2,3)*A(3,2)
    C(1,2) = A(2,3)*A(3,1) - A(2,1)*A(3,3)
    C(1,3) = A(2,1)*A(3,2) - A(2,2)*A(3,1)
    C(2,1) = A(1,3)*A(3,2) - A(1,2)*A(3,3)
    C(2,2) = A(1,1)*A(3,3) - A(1,3)*A(3,1)
    C(2,3) = A(1,2)*A(3,1) - A(1,1)*A(3,2)
    C(3,1) = A(1,2)*A(2,3) - A(1,3)*A(2,2)
    C(3,2) = A(1,3)*A(2,1) - A(1,1)*A(2,3)
    C(3,3) = A(1,1)*A(2,2) - A(1,2)*A(2,1)
    det = A(1,1)*C(1,1) + A(1,2)*C(1,2) + A(1,3)*C(1,3)
    scale = norm2(A(:,1))*norm2(A(:,2))*norm2(A(:,3))
    ok = abs(det) > 1e-12_wp*scale
    x = 0
    if (.not. ok) return
    ! x = adj(A) b / det, adj(A) = transpose(C)
    x(1) = (C(1,1)*b(1) + C(2,1)*b(2) + C(3,1)*b(3))/det
    x(2) = (C(1,2)*b(1) + C(2,2)*b(2) + C(3,2)*b(3))/det
    x(3) = (C(1,3)*b(1) + C(2,3)*b(2) + C(3,3)*b(3))/det
  end subroutine solve3

  !> Appends the current point as a vertex; `slope` is dM/dgamma of the segment ending there.
  pure subroutine append_vertex(geo, st, slope, rec)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: st
    real(wp), intent(in) :: slope
    type(branch_record_type), intent(inout) :: rec
    real(wp) :: g(3), s(3), N(3), T(3)
    rec%n = rec%n + 1
    call put(rec%gamma, rec%n, st%gamma)
    call put(rec%gamma_p, rec%n, st%gamma_p)
    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T, st%off)
    call put(rec%M, rec%n, sum(geo%cn*N + geo%ct*T))
    call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, g, s, N, T)
    call put(rec%M_p, rec%n, sum(geo%cn*N + geo%ct*T))
    call put(rec%slope, rec%n, slope)
    if (rec%keep_states) then
      if (.not. allocated(rec%states)) allocate(rec%states(size(rec%gamma)))
      if (size(rec%states) < size(rec%gamma)) call grow_states(rec)
      rec%states(rec%n) = st
    end if
  end subroutine append_vertex

  !> The three contacts' states as one integer (base 4), and back.
  pure integer function mode_code(mode)
    integer, intent(in) :: mode(3)
    mode_code = mode(1) + 4*mode(2) + 16*mode(3)
  end function mode_code

  pure function code_modes(code) result(mode)
    integer, intent(in) :: code
    integer :: mode(3)
    mode = [modulo(code, 4), modulo(code/4, 4), code/16]
  end function code_modes

  pure subroutine grow_states(rec)
    type(branch_record_type), intent(inout) :: rec
    type(damper_state_type), allocatable :: tmp(:)
    integer :: n
    n = size(rec%states)
    allocate(tmp(size(rec%gamma)))
    tmp(1:n) = rec%states
    call move_alloc(tmp, rec%states)
  end subroutine grow_states
end module udmap_damper_tracer_core
