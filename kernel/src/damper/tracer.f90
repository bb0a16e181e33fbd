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
  use udmap_core_arrays, only: put
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EPHYSICS
  use udmap_damper_params, only: asymmetric_params_type, check_asymmetric_params
  use udmap_damper_tracer_core, only: damper_geometry_type, damper_state_type, validity_type, &
    & equilibrium_cache_type, rates_cache_type, &
    & branch_record_type, mode_log_type, mode_code, &
    & contact_forces, trace_core, solve3, append_vertex
  implicit none
  private
  public :: new_damper_geometry, virgin_state, ramp_CF, advance, restoring_moment, &
    & full_slip_moment, trace_gamma, trace_to_plateau, record_start, reset_record, same_forces, &
    & trace_path, platform_actions, along

  !> The contact events of a straight segment of trace_path: at the fraction s(j) of the
  !> segment (0 <= s < 1, ascending) the contact states change from before(j) to after(j)
  !> (as mode_code gives them).
  type, public :: path_events_type
    integer :: n = 0
    real(wp), allocatable :: s(:)
    integer, allocatable :: before(:), after(:)
    !> The step of `log` that ends at each event (0: the segment's start), and the contact
    !> states as the segment started.
    integer, allocatable :: vertex(:)
    integer :: entry = 0
    type(mode_log_type) :: log
  end type path_events_type

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
      geo%pn(:,i) = [n(1), n(2), geo%cn(i)]
      geo%pt(:,i) = [t(1), t(2), geo%ct(i)]
      geo%side(i) = merge(1, 2, i <= 2)
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

  !> Restoring moment on the blade M_r = sum (r - P) x F = sum (cn N + ct T) [N m].
  pure function restoring_moment(geo, state) result(M)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: state
    real(wp) :: M
    real(wp) :: g(3), s(3), N(3), T(3)
    call contact_forces(geo, state%mode, state%q, state%gamma, state%w, g, s, N, T, state%off)
    M = sum(geo%cn*N + geo%ct*T)
  end function restoring_moment

  !> True if the contact states and forces of a and b agree to a relative 1e-10 of `F_scale`:
  !> the future of the forces then agrees too (it depends on forces and states only).
  pure logical function same_forces(geo, a, b, F_scale)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: a, b
    real(wp), intent(in) :: F_scale
    real(wp) :: g(3), s(3), Na(3), Ta(3), Nb(3), Tb(3)
    call contact_forces(geo, a%mode, a%q, a%gamma, a%w, g, s, Na, Ta, a%off)
    call contact_forces(geo, b%mode, b%q, b%gamma, b%w, g, s, Nb, Tb, b%off)
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

  !> Exact quasi-static path on a straight line from the platforms' coordinates state%X to
  !> X_to (PHYSICS.md 2.6: side 1 the flat-side platform, side 2 the curved-side one), every
  !> transition resolved. A straight line in X moves every contact linearly, so the tracer
  !> runs with a geometry whose lever arms are the contacts' travel along the segment and the
  !> load parameter going from 0 to 1; the start of the segment enters as the offsets.
  !> With `events`, the contact events inside the segment are returned too.
  subroutine trace_path(geo, state, X_to, error, events, cache)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: state
    real(wp), intent(in) :: X_to(6)
    type(error_type), allocatable, intent(out) :: error
    type(path_events_type), intent(inout), optional :: events
    !> The equilibrium matrices of geo's damper met so far (kept by the caller for a whole
    !> trace: every segment shares them).
    type(equilibrium_cache_type), intent(inout), optional :: cache
    type(damper_geometry_type) :: seg
    real(wp) :: dX(6), travel, dM
    integer :: j, entry
    if (.not. all(abs(X_to) <= huge(1.0_wp))) then
      call fatal_error(error, "trace_path: the platform coordinates are not finite numbers")
      return
    end if
    dX = X_to - state%X
    seg = along(geo, dX)
    seg%rate_scale = max(maxval(geo%kn*abs(seg%cn)), maxval(geo%kt*abs(seg%ct)))
    if (present(events)) then
      events%n = 0
      events%log%n = 0
      events%entry = mode_code(state%mode)
    end if
    if (seg%rate_scale > 0) then
      ! state%off holds the offsets of state%X already (set where state%X was: at the end of
      ! the last segment, or zero in the virgin state)
      state%gamma = 0
      state%direction = 1
      if (present(events)) then
        ! a vertex ends each step of the tracer, in the states of that step: an event inside
        ! the segment is a vertex before s = 1, the states after it those of the next vertex
        entry = events%entry
        call trace_core(seg, state, 1, 1, 1.0_wp, 0.0_wp, .true., travel, dM, error, &
          & modes=events%log, cache=cache)
        if (allocated(error)) return
        associate (lg => events%log)
          ! states that change as the segment starts (the other side of an event that ended
          ! the last segment, or a reversal at the instant itself) are an event at s = 0
          if (lg%n >= 1) then
            if (lg%code(1) /= entry) call add_event(0, 0.0_wp, entry, lg%code(1))
          end if
          do j = 1, lg%n - 1
            if (lg%s(j) > 0 .and. lg%s(j) < 1 .and. lg%code(j) /= lg%code(j+1)) &
              & call add_event(j, lg%s(j), lg%code(j), lg%code(j+1))
          end do
        end associate
      else
        call trace_core(seg, state, 1, 1, 1.0_wp, 0.0_wp, .true., travel, dM, error, &
          & cache=cache)
        if (allocated(error)) return
      end if
    end if
    state%X = X_to
    call set_offsets(X_to)
    state%gamma = 0
  contains
    subroutine set_offsets(X)
      real(wp), intent(in) :: X(6)
      integer :: j, m
      do j = 1, 3
        m = 3*(geo%side(j) - 1)
        state%off(1,j) = dot_product(geo%pn(:,j), X(m+1:m+3))
        state%off(2,j) = dot_product(geo%pt(:,j), X(m+1:m+3))
      end do
    end subroutine set_offsets

    subroutine add_event(vertex, s_e, code_before, code_after)
      integer, intent(in) :: vertex
      real(wp), intent(in) :: s_e
      integer, intent(in) :: code_before, code_after
      events%n = events%n + 1
      call put(events%vertex, events%n, vertex)
      call put(events%s, events%n, s_e)
      call put(events%before, events%n, code_before)
      call put(events%after, events%n, code_after)
    end subroutine add_event
  end subroutine trace_path

  !> The geometry whose lever arms are the contacts' travel for the motion dX of both
  !> platforms' coordinates (a segment of trace_path, or a velocity: the rates per unit time).
  pure function along(geo, dX) result(seg)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: dX(6)
    type(damper_geometry_type) :: seg
    integer :: i, k
    seg = geo
    do i = 1, 3
      k = 3*(geo%side(i) - 1)
      seg%cn(i) = dot_product(geo%pn(:,i), dX(k+1:k+3))
      seg%ct(i) = dot_product(geo%pt(:,i), dX(k+1:k+3))
    end do
  end function along

  !> The damper's restoring actions on its two platforms (PHYSICS.md 2.6): A(:,k) = (F_x, F_y,
  !> moment about P) of the contact forces on the damper from side k's contacts; the
  !> platform feels -A. In phase, A(3,1) + A(3,2) is the restoring moment M_r of 2.1.
  pure function platform_actions(geo, state) result(A)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: state
    real(wp) :: A(3,2)
    real(wp) :: g(3), s(3), N(3), T(3)
    integer :: i
    call contact_forces(geo, state%mode, state%q, state%gamma, state%w, g, s, N, T, state%off)
    A = 0
    do i = 1, 3
      A(:, geo%side(i)) = A(:, geo%side(i)) + N(i)*geo%pn(:,i) + T(i)*geo%pt(:,i)
    end do
  end function platform_actions

  !> Traces gamma to `target` (p-derivative `target_p`), appending the vertices to `rec` and
  !> narrowing `val` to the range of p over which the event sequence holds.
  subroutine trace_gamma(geo, state, target, target_p, error, rec, val, cache, rates)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(inout) :: state
    real(wp), intent(in) :: target, target_p
    type(error_type), allocatable, intent(out) :: error
    type(branch_record_type), intent(inout), optional :: rec
    type(validity_type), intent(inout), optional :: val
    !> The equilibrium matrices of geo's damper met so far (trace_core).
    type(equilibrium_cache_type), intent(inout), optional :: cache
    !> The rates of the contact states met so far (trace_core; one geometry).
    type(rates_cache_type), intent(inout), optional :: rates
    real(wp) :: travel, dM
    if (target == state%gamma) return
    call trace_core(geo, state, 1, merge(1, -1, target > state%gamma), target, target_p, &
      & .true., travel, dM, error, rec, val, cache=cache, rates=rates)
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
    real(wp) :: g(3), s(3), N(3), T(3), gp(3), sp(3), Np(3), Tp(3)
    call append_vertex(geo, state, 0.0_wp, rec, g, s, N, T, gp, sp, Np, Tp)
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
end module udmap_damper_tracer
