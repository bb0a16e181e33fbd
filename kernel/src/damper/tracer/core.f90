!> The core of the damper's event-driven tracer (PHYSICS.md 2.1): the exact tracing of the
!> quasi-static path in gamma, stick/slip/open transitions resolved as events (the mode of each
!> contact at an event, chosen by the rates of udmap_damper_tracer_contacts), with the
!> breakpoints recorded. Re-exports the contacts' types and laws, which its users share.
module udmap_damper_tracer_core
  use udmap_core_kinds, only: wp
  use udmap_core_arrays, only: put
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_damper_tracer_contacts, only: damper_geometry_type, damper_state_type, &
    & validity_type, branch_record_type, mode_log_type, rates_type, equilibrium_cache_type, &
    & rates_cache_type, contact_forces, contact_force, compute_rates, mode_stiffness, solve3, &
    & cofactors3, mode_code, code_modes, CONTACT_OPEN, CONTACT_STICK, CONTACT_SLIP_POS, &
    & CONTACT_SLIP_NEG
  implicit none
  private
  public :: trace_core, append_vertex
  public :: damper_geometry_type, damper_state_type, validity_type, branch_record_type, &
    & mode_log_type, rates_type, equilibrium_cache_type, rates_cache_type, contact_forces, &
    & cofactors3, compute_rates, mode_stiffness, solve3, mode_code, code_modes, CONTACT_OPEN, &
    & CONTACT_STICK, CONTACT_SLIP_POS, CONTACT_SLIP_NEG

  !> Classes of a contact at a point, which decide its candidate states.
  integer, parameter :: CLS_FIXED = 0, CLS_CONE = 1, CLS_GAP = 2
  !> Kinds of events.
  integer, parameter :: EV_TARGET = 0
  !> Safety limit on the events of one call (a real path has a handful per reversal).
  integer, parameter :: MAX_EVENTS = 100000
  !> Relative tolerances: forces at a boundary, rates that count as zero.
  real(wp), parameter :: TOL_FORCE = 1e-11_wp, TOL_RATE = 1e-9_wp

contains

  ! ------------------------------------------------------------------ internals

  !> The tracing engine. var = 1: load parameter gamma, var = 2: CF. With has_target it stops
  !> at `target`, otherwise after the last event (travel = distance to it, dM = moment rate of
  !> the final states per unit travel).
  subroutine trace_core(geo, st, var, dir, target, target_p, has_target, travel, dM, error, &
      & rec, val, frozen, max_travel, modes, cache, rates)
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
    !> The equilibrium matrices of geo's damper met so far (see compute_rates).
    type(equilibrium_cache_type), intent(inout), optional :: cache
    !> The rates of the contact states met so far (one geometry, gamma traces: see its type).
    type(rates_cache_type), intent(inout), optional :: rates
    type(rates_type) :: rt
    integer :: pred(3), nev, i, nc, ic, best, ev_contact(10), ev_state(10)
    real(wp) :: dgam, dcf, tc(10), tcp(10), rate_of(10), g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    real(wp) :: remaining, step, step_p, cur, scale, tie, tolR
    character(len=60) :: buf
    logical :: with_p, known

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
    known = .false.
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
      ! The forces at the state: the last vertex's when it was recorded (the same state).
      if (.not. known) then
        call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T, st%off)
        if (with_p) call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
      end if
      call snap_sliders(geo, st, with_p, s, T, sp, Tp)
      call resolve_mode(geo, st, dgam, dcf, pred, rt, error, cache, g, s, N, T, gp, sp, Np, Tp, &
        & known .or. with_p, rates)
      known = .false.
      if (allocated(error)) return
      if (.not. with_p) then
        gp = 0
        sp = 0
        Np = 0
        Tp = 0
      end if
      ! Candidate events: travel to each boundary the states move towards.
      tolR = TOL_RATE*(geo%rate_scale*abs(dgam) + abs(dcf))
      nc = 0
      do i = 1, 3
        select case (st%mode(i))
        case (CONTACT_STICK)
          call candidate(geo%mu*N(i) - T(i), geo%mu*rt%dN(i) - rt%dT(i), &
            & geo%mu*Np(i) - Tp(i), CONTACT_SLIP_POS)
          call candidate(geo%mu*N(i) + T(i), geo%mu*rt%dN(i) + rt%dT(i), &
            & geo%mu*Np(i) + Tp(i), CONTACT_SLIP_NEG)
          call candidate(N(i), rt%dN(i), Np(i), CONTACT_OPEN)
        case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
          call candidate(N(i), rt%dN(i), Np(i), CONTACT_OPEN)
        case default
          call candidate(-geo%kn(i)*g(i), -geo%kn(i)*rt%dg(i), -geo%kn(i)*gp(i), CONTACT_STICK)
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
        tie = 1e-10_wp*max(abs(val%p0), abs(travel), abs(cur))
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
        call append_vertex(geo, st, rt%dM*dir, rec, g, s, N, T, gp, sp, Np, Tp)
        known = .true.
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

    !> Contact i reaches the boundary of the value f (rate df, p-derivative fp) into `state`
    !> after the travel f/(-df) when it moves towards it.
    subroutine candidate(f, df, fp, state)
      real(wp), intent(in) :: f, df, fp
      integer, intent(in) :: state
      if (df < -tolR) then
        nc = nc + 1
        tc(nc) = max(f, 0.0_wp)/(-df)
        tcp(nc) = fp/(-df)
        rate_of(nc) = -df
        ev_contact(nc) = i
        ev_state(nc) = state
      end if
    end subroutine candidate

    !> Requires d + d_p (p - p0) >= 0. Gaps below the tie tolerance (tie) are ties at p0 (mostly
    !> structural ones that hold for every p, e.g. a contact back on its cone at a reversal):
    !> their p-derivatives are rounding noise and bound nothing.
    subroutine restrict(v, d, d_p)
      type(validity_type), intent(inout) :: v
      real(wp), intent(in) :: d, d_p
      if (abs(d) <= tie) return
      if (d_p < 0) then
        v%hi = min(v%hi, v%p0 + d/(-d_p))
      else if (d_p > 0) then
        v%lo = max(v%lo, v%p0 - d/d_p)
      end if
    end subroutine restrict
  end subroutine trace_core

  !> Keeps the sliders of slipping and open contacts on their forces (T = -kt (s - w)),
  !> with their p-derivatives, so that a change to stick continues the force. s, T (sp, Tp)
  !> are the state's; a slipping or open contact's forces do not depend on its slider, so
  !> they stay the state's forces.
  pure subroutine snap_sliders(geo, st, with_p, s, T, sp, Tp)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: st
    !> The p-derivatives are not all zero.
    logical, intent(in) :: with_p
    real(wp), intent(in) :: s(3), T(3), sp(3), Tp(3)
    integer :: i
    if (all(st%mode == CONTACT_STICK)) return
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
  !> `pred` is tried first. g, s, N, T (gp, sp, Np, Tp: their p-derivatives, given when
  !> p_known) are the state's on entry and on return.
  subroutine resolve_mode(geo, st, dgam, dcf, pred, rt, error, cache, g, s, N, T, gp, sp, Np, &
      & Tp, p_known, rates)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: st
    real(wp), intent(in) :: dgam, dcf
    integer, intent(in) :: pred(3)
    type(rates_type), intent(out) :: rt
    type(error_type), allocatable, intent(out) :: error
    type(equilibrium_cache_type), intent(inout), optional :: cache
    real(wp), intent(inout) :: g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    logical, intent(in) :: p_known
    type(rates_cache_type), intent(inout), optional :: rates
    real(wp) :: tolF, tolR
    integer :: ncand(3), cand(4,3), cls(3), sig0(3), i, i1, i2, i3, trial(3), old(3)
    logical :: ok, any_regular, cached
    character(len=120) :: buf

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
    cached = .false.
    if (present(rates)) cached = dcf == 0 .and. abs(dgam) == 1
    do i1 = 1, ncand(1)
      do i2 = 1, ncand(2)
        do i3 = 1, ncand(3)
          trial = [cand(i1,1), cand(i2,2), cand(i3,3)]
          call trial_rates()
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

    !> rt and ok of the trial states: from the rates cache where it serves (a gamma trace).
    subroutine trial_rates()
      integer :: code, k
      if (cached) then
        code = mode_code(trial)
        k = merge(2, 1, dgam > 0)
        if (.not. rates%known(code, k)) then
          call compute_rates(geo, trial, dgam, dcf, rates%rt(code, k), rates%ok(code, k), cache)
          rates%known(code, k) = .true.
        end if
        rt = rates%rt(code, k)
        ok = rates%ok(code, k)
      else
        call compute_rates(geo, trial, dgam, dcf, rt, ok, cache)
      end if
    end subroutine trial_rates

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

    !> A contact that opens or closes starts with its spring unloaded: w = s. The forces of
    !> the contacts that change state (gaps and travels stay: the same q, gamma).
    subroutine snap_new_states(old)
      integer, intent(in) :: old(3)
      integer :: j
      if (all(old == st%mode)) return
      if (.not. p_known) &
        & call contact_forces(geo, old, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
      do j = 1, 3
        if (st%mode(j) == old(j)) cycle
        if ((old(j) == CONTACT_OPEN) .neqv. (st%mode(j) == CONTACT_OPEN)) then
          st%w(j) = s(j)
          st%w_p(j) = sp(j)
        end if
        call contact_force(geo, j, st%mode(j), g(j), s(j), st%w(j), N(j), T(j))
        call contact_force(geo, j, st%mode(j), gp(j), sp(j), st%w_p(j), Np(j), Tp(j))
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

  !> Appends the current point as a vertex; `slope` is dM/dgamma of the segment ending there.
  !> Returns the state's forces g, s, N, T and their p-derivatives gp, sp, Np, Tp.
  pure subroutine append_vertex(geo, st, slope, rec, g, s, N, T, gp, sp, Np, Tp)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: st
    real(wp), intent(in) :: slope
    type(branch_record_type), intent(inout) :: rec
    real(wp), intent(out) :: g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    rec%n = rec%n + 1
    call put(rec%gamma, rec%n, st%gamma)
    call put(rec%gamma_p, rec%n, st%gamma_p)
    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T, st%off)
    call put(rec%M, rec%n, sum(geo%cn*N + geo%ct*T))
    call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
    call put(rec%M_p, rec%n, sum(geo%cn*Np + geo%ct*Tp))
    call put(rec%slope, rec%n, slope)
    if (rec%keep_states) then
      if (.not. allocated(rec%states)) allocate(rec%states(size(rec%gamma)))
      if (size(rec%states) < size(rec%gamma)) call grow_states(rec)
      rec%states(rec%n) = st
    end if
  end subroutine append_vertex

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
