!> Exact event-driven quasi-static tracing of the asymmetric damper (PHYSICS.md 2.1).
!>
!> The damper has three DOFs q = (x, y, theta) and three point contacts (two flat, one curved),
!> each a unilateral normal spring and a Jenkins tangential element. For a fixed set of contact
!> states (open, stick, slip+, slip-) the equilibrium is linear, so q, the contact forces and
!> the restoring moment are affine in the load (gamma or CF) until the next transition. The
!> tracer moves from transition to transition (events), choosing at each one the contact states
!> whose rates are consistent; there is no time step, so loops are exact to rounding.
!>
!> Along a path every quantity is also tracked with its derivative with respect to a parameter
!> p (the loop amplitude when the targets are +-p). Between topology changes all events are affine
!> in p; `validity_type` collects the exact range of p over which the event sequence holds.
module udmap_damper_tracer
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_damper_params, only: asymmetric_params_type, check_asymmetric_params
  implicit none
  private
  public :: new_damper_geometry, virgin_state, ramp_CF, advance, restoring_moment
  public :: contact_forces, full_slip_moment, trace_gamma, trace_to_plateau
  public :: record_start, reset_record, same_forces

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

  !> Rates per unit travel of a set of contact states.
  type :: rates_type
    real(wp) :: dq(3) = 0, dg(3) = 0, ds(3) = 0, dN(3) = 0, dT(3) = 0, dw(3) = 0, dM = 0
  end type rates_type

contains

  !> Contact kinematics of the damper `params` (PHYSICS.md 2.1); checks the parameters.
  subroutine new_damper_geometry(geo, params, error)
    type(damper_geometry_type), intent(out) :: geo
    type(asymmetric_params_type), intent(in) :: params
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: bL, bR, n(2), t(2), r(2), P(2), a(2)
    integer :: i

    call check_asymmetric_params(params, error)
    if (allocated(error)) return
    bL = params%beta_L_deg*acos(-1.0_wp)/180
    bR = params%beta_R_deg*acos(-1.0_wp)/180
    do i = 1, 3
      if (i <= 2) then
        r = params%flat(:,i)
        n = [sin(bL), -cos(bL)]
        P = [-params%pitch/2, params%y_P]
        geo%kn(i) = params%kn_flat
        geo%kt(i) = params%kt_flat
      else
        r = params%curved
        n = [-sin(bR), -cos(bR)]
        P = [params%pitch/2, params%y_P]
        geo%kn(i) = params%kn_curved
        geo%kt(i) = params%kt_curved
      end if
      t = [-n(2), n(1)]
      a = [-(r(2) - P(2)), r(1) - P(1)]
      geo%bn(:,i) = [n(1), n(2), r(1)*n(2) - r(2)*n(1)]
      geo%bt(:,i) = [t(1), t(2), r(1)*t(2) - r(2)*t(1)]
      geo%cn(i) = dot_product(n, a)
      geo%ct(i) = dot_product(t, a)
    end do
    geo%mu = params%mu
    geo%beta_deg = [params%beta_L_deg, params%beta_R_deg]
    geo%rate_scale = max(maxval(geo%kn*abs(geo%cn)), maxval(geo%kt*abs(geo%ct)))
    geo%moment_scale = geo%rate_scale*max(maxval(abs(geo%cn)), maxval(abs(geo%ct)))
  end subroutine new_damper_geometry

  !> The virgin state: no contact force, sliders at 0, platforms and load at 0.
  pure subroutine virgin_state(geo, state)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(out) :: state
    ! Every damper starts unloaded; the geometry argument only keeps the calls uniform
    ! (and this test on it keeps -Wunused-dummy-argument quiet).
    if (geo%mu < 0) return
    state = damper_state_type()
  end subroutine virgin_state

  !> Normal approach g, tangential displacement s and forces N, T of the three contacts for
  !> the states `mode` at (q, gamma, w). Linear and homogeneous in (q, gamma, w), so it also
  !> maps p-derivatives to p-derivatives.
  pure subroutine contact_forces(geo, mode, q, gamma, w, g, s, N, T)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: q(3), gamma, w(3)
    real(wp), intent(out) :: g(3), s(3), N(3), T(3)
    integer :: i
    do i = 1, 3
      g(i) = -(geo%bn(1,i)*q(1) + geo%bn(2,i)*q(2) + geo%bn(3,i)*q(3)) + gamma*geo%cn(i)
      s(i) = geo%bt(1,i)*q(1) + geo%bt(2,i)*q(2) + geo%bt(3,i)*q(3) - gamma*geo%ct(i)
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

  !> Restoring moment on the blade M_r = sum (r - P) x F = sum (cn N + ct T) [N m].
  pure function restoring_moment(geo, state) result(M)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: state
    real(wp) :: M
    real(wp) :: g(3), s(3), N(3), T(3)
    call contact_forces(geo, state%mode, state%q, state%gamma, state%w, g, s, N, T)
    M = sum(geo%cn*N + geo%ct*T)
  end function restoring_moment

  !> True if the contact states and forces of a and b agree to a relative 1e-10 of `F_scale`:
  !> the future of the forces then agrees too (it depends on forces and states only).
  pure logical function same_forces(geo, a, b, F_scale)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: a, b
    real(wp), intent(in) :: F_scale
    real(wp) :: g(3), s(3), Na(3), Ta(3), Nb(3), Tb(3)
    call contact_forces(geo, a%mode, a%q, a%gamma, a%w, g, s, Na, Ta)
    call contact_forces(geo, b%mode, b%q, b%gamma, b%w, g, s, Nb, Tb)
    same_forces = all(a%mode == b%mode) .and. all(abs(Na - Nb) <= 1e-10_wp*F_scale) &
      & .and. all(abs(Ta - Tb) <= 1e-10_wp*F_scale)
  end function same_forces

  !> Proportional ramp of the centrifugal load from state%CF to CF at fixed gamma (from the
  !> virgin state this is step 1 of the loading history of PHYSICS.md 2.1).
  subroutine ramp_CF(geo, state, CF, error)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: state
    real(wp), intent(in) :: CF
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: travel, dM
    if (.not. (CF >= 0 .and. CF <= huge(CF))) then
      call fatal_error(error, "ramp_CF: parameter 'CF' must be a finite non-negative number")
      return
    end if
    call trace_core(geo, state, 2, merge(1, -1, CF >= state%CF), CF, 0.0_wp, .true., &
      & travel, dM, error)
    state%direction = 0
  end subroutine ramp_CF

  !> Exact quasi-static path from state%gamma to gamma_target (monotonic in between), every
  !> stick/slip/open transition on the way resolved; M_r is the restoring moment at the target.
  !> Replaying a waveform sample by sample with this routine is exact.
  subroutine advance(geo, state, gamma_target, M_r, error)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: state
    real(wp), intent(in) :: gamma_target
    real(wp), intent(out) :: M_r
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: travel, dM
    M_r = 0
    if (.not. (abs(gamma_target) <= huge(gamma_target))) then
      call fatal_error(error, "advance: parameter 'gamma_target' is not a finite number")
      return
    end if
    if (gamma_target /= state%gamma) then
      call trace_core(geo, state, 1, merge(1, -1, gamma_target > state%gamma), gamma_target, &
        & state%gamma_p, .true., travel, dM, error)
      if (allocated(error)) return
    end if
    M_r = restoring_moment(geo, state)
  end subroutine advance

  !> Traces gamma to `target` (p-derivative `target_p`), appending the vertices to `rec` and
  !> narrowing `val` to the range of p over which the event sequence holds.
  subroutine trace_gamma(geo, state, target, target_p, error, rec, val)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: state
    real(wp), intent(in) :: target, target_p
    type(error_type), allocatable, intent(out) :: error
    type(branch_record_type), intent(inout), optional :: rec
    type(validity_type), intent(inout), optional :: val
    real(wp) :: travel, dM
    if (target == state%gamma) return
    call trace_core(geo, state, 1, merge(1, -1, target > state%gamma), target, target_p, &
      & .true., travel, dM, error, rec, val)
  end subroutine trace_gamma

  !> Traces gamma in `direction` (+1, -1) until no contact changes state any more (a plateau);
  !> `travel` is the gamma travel from the start to the last transition. An endless last stretch
  !> on which the moment keeps changing is a jammed damper (error).
  subroutine trace_to_plateau(geo, state, direction, travel, frozen, error, rec)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: state
    integer, intent(in) :: direction
    real(wp), intent(out) :: travel
    !> On the plateau every force and every open gap stays constant, so what follows a reversal
    !> does not depend on where on the plateau it happens (elongation law of PHYSICS.md 2.3).
    logical, intent(out) :: frozen
    type(error_type), allocatable, intent(out) :: error
    type(branch_record_type), intent(inout), optional :: rec
    real(wp) :: dM
    character(len=40) :: buf
    ! Beyond 1e4 times the rotation that CF deflects the contacts by, the small-displacement
    ! model has long lost its meaning: a path still changing there jams.
    call trace_core(geo, state, 1, direction, 0.0_wp, 0.0_wp, .false., travel, dM, error, rec, &
      & frozen=frozen, max_travel=1e4_wp*state%CF/geo%rate_scale)
    if (allocated(error)) return
    if (abs(dM) > 1e-8_wp*geo%moment_scale) then
      write(buf, '(es12.5)') state%gamma
      call fatal_error(error, "damper jams: beyond gamma = "//trim(adjustl(buf))// &
        & " rad the contacts settle in a state whose moment grows without bound (no plateau)", &
        & UDMAP_EPHYSICS)
    end if
  end subroutine trace_to_plateau

  !> Empties a record (keeps its storage).
  pure subroutine reset_record(rec)
    type(branch_record_type), intent(inout) :: rec
    rec%n = 0
    rec%slipped = .false.
    rec%opened = .false.
  end subroutine reset_record

  !> Appends the current point of `state` as the first vertex of a branch.
  pure subroutine record_start(geo, state, rec)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: state
    type(branch_record_type), intent(inout) :: rec
    call append_vertex(geo, state, 0.0_wp, rec)
  end subroutine record_start

  !> Full-slip statics: with every contact slipping in the direction signs(i) (+1: T = mu N),
  !> the three normal forces follow from equilibrium alone (independent of kn, kt); M is the
  !> restoring moment. `admissible` is false if a normal force is negative.
  pure subroutine full_slip_moment(geo, CF, signs, M, N, admissible, error)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF
    integer, intent(in) :: signs(3)
    real(wp), intent(out) :: M, N(3)
    logical, intent(out) :: admissible
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: A(3,3)
    logical :: ok
    integer :: i
    do i = 1, 3
      A(:,i) = geo%bn(:,i) + signs(i)*geo%mu*geo%bt(:,i)
    end do
    call solve3(A, [0.0_wp, -CF, 0.0_wp], N, ok)
    M = 0
    admissible = .false.
    if (.not. ok) then
      N = 0
      call fatal_error(error, "full_slip_moment: the full-slip equilibrium is singular", &
        & UDMAP_EPHYSICS)
      return
    end if
    M = sum(N*(geo%cn + signs*geo%mu*geo%ct))
    admissible = all(N >= 0)
  end subroutine full_slip_moment

  ! ------------------------------------------------------------------ internals

  !> The tracing engine. var = 1: load parameter gamma, var = 2: CF. With has_target it stops
  !> at `target`, otherwise after the last event (travel = distance to it, dM = moment rate of
  !> the final states per unit travel).
  subroutine trace_core(geo, st, var, dir, target, target_p, has_target, travel, dM, error, &
      & rec, val, frozen, max_travel)
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
    type(rates_type) :: rt
    integer :: pred(3), nev, i, nc, ic, best, ev_contact(10), ev_state(10)
    real(wp) :: dgam, dcf, tc(10), tcp(10), rate_of(10), g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    real(wp) :: f(3), df(3), fp(3), remaining, step, step_p, cur, scale
    character(len=60) :: buf

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
      call snap_sliders(geo, st)
      call resolve_mode(geo, st, dgam, dcf, pred, rt, error)
      if (allocated(error)) return

      call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T)
      call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
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
  pure subroutine snap_sliders(geo, st)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: st
    real(wp) :: g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    integer :: i
    if (all(st%mode == CONTACT_STICK)) return
    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T)
    call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
    do i = 1, 3
      if (st%mode(i) /= CONTACT_STICK) then
        st%w(i) = s(i) + T(i)/geo%kt(i)
        st%w_p(i) = sp(i) + Tp(i)/geo%kt(i)
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

    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T)
    tolF = force_tolerance(geo, st)
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
      call contact_forces(geo, st%mode, st%q, st%gamma, st%w, gg, ss, NN, TT)
      call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, gp, sp, Np, Tp)
      do j = 1, 3
        if ((old(j) == CONTACT_OPEN) .neqv. (st%mode(j) == CONTACT_OPEN)) then
          st%w(j) = ss(j)
          st%w_p(j) = sp(j)
        end if
      end do
    end subroutine snap_new_states
  end subroutine resolve_mode

  !> Forces within this of a boundary count as on it: the resolution of the force sums.
  pure real(wp) function force_tolerance(geo, st)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: st
    real(wp) :: g(3), s(3), N(3), T(3)
    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T)
    force_tolerance = TOL_FORCE*max(abs(st%CF), maxval(abs(N)), maxval(abs(T)))
  end function force_tolerance

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

    K = 0
    h = 0
    do i = 1, 3
      select case (mode(i))
      case (CONTACT_STICK)
        K = K + geo%kn(i)*outer(geo%bn(:,i), geo%bn(:,i)) + geo%kt(i)*outer(geo%bt(:,i), geo%bt(:,i))
        h = h + geo%kn(i)*geo%cn(i)*geo%bn(:,i) + geo%kt(i)*geo%ct(i)*geo%bt(:,i)
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        sg = merge(1, -1, mode(i) == CONTACT_SLIP_POS)
        v = geo%bn(:,i) + sg*geo%mu*geo%bt(:,i)
        K = K + geo%kn(i)*outer(v, geo%bn(:,i))
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

  pure function outer(a, b) result(c)
    real(wp), intent(in) :: a(3), b(3)
    real(wp) :: c(3,3)
    integer :: j
    do j = 1, 3
      c(:,j) = a*b(j)
    end do
  end function outer

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
    integer :: cap
    if (.not. allocated(rec%gamma)) then
      cap = 16
      allocate(rec%gamma(cap), rec%gamma_p(cap), rec%M(cap), rec%M_p(cap), rec%slope(cap))
    end if
    if (rec%n == size(rec%gamma)) call grow(rec)
    if (rec%keep_states) then
      if (.not. allocated(rec%states)) allocate(rec%states(size(rec%gamma)))
      if (size(rec%states) < size(rec%gamma)) call grow_states(rec)
    end if
    rec%n = rec%n + 1
    rec%gamma(rec%n) = st%gamma
    rec%gamma_p(rec%n) = st%gamma_p
    call contact_forces(geo, st%mode, st%q, st%gamma, st%w, g, s, N, T)
    rec%M(rec%n) = sum(geo%cn*N + geo%ct*T)
    call contact_forces(geo, st%mode, st%q_p, st%gamma_p, st%w_p, g, s, N, T)
    rec%M_p(rec%n) = sum(geo%cn*N + geo%ct*T)
    rec%slope(rec%n) = slope
    if (rec%keep_states) rec%states(rec%n) = st
  end subroutine append_vertex

  pure subroutine grow(rec)
    type(branch_record_type), intent(inout) :: rec
    real(wp), allocatable :: tmp(:)
    integer :: n
    n = size(rec%gamma)
    allocate(tmp(2*n)); tmp(1:n) = rec%gamma; call move_alloc(tmp, rec%gamma)
    allocate(tmp(2*n)); tmp(1:n) = rec%gamma_p; call move_alloc(tmp, rec%gamma_p)
    allocate(tmp(2*n)); tmp(1:n) = rec%M; call move_alloc(tmp, rec%M)
    allocate(tmp(2*n)); tmp(1:n) = rec%M_p; call move_alloc(tmp, rec%M_p)
    allocate(tmp(2*n)); tmp(1:n) = rec%slope; call move_alloc(tmp, rec%slope)
  end subroutine grow

  pure subroutine grow_states(rec)
    type(branch_record_type), intent(inout) :: rec
    type(damper_state_type), allocatable :: tmp(:)
    integer :: n
    n = size(rec%states)
    allocate(tmp(size(rec%gamma)))
    tmp(1:n) = rec%states
    call move_alloc(tmp, rec%states)
  end subroutine grow_states
end module udmap_damper_tracer
