!> Hysteresis loops of the asymmetric damper: the loading history of PHYSICS.md 2.1, the base
!> cycle of 2.3 and the describing function of 2.2 in closed form over piecewise-linear loops.
!>
!> A loop at amplitude p (gamma = p cos tau) is kept as two branches: the descending one from the
!> reversal at +p and the ascending one from -p, each a list of vertices (s, M_r) in the travel
!> s in [0, 2p] from its reversal, with the slope dM_r/ds of every segment. The integrals of 2.2
!> over a linear segment are elementary, so k(p) is exact:
!>   k_Re = 1/(2 pi) [sum_asc m_j (H_j - H_j-1) - sum_desc m_j (H_j - H_j-1)],
!>   H(s) = phi - sin(phi) cos(phi), cos(phi) = 1 - s/p   (by parts from int M cos(tau) dtau),
!>   k_Im = E/(pi p^2),  E = int_asc M ds - int_desc M ds   (trapezoids are exact).
!> Vertices also carry their derivatives with respect to p; within one event topology they are
!> affine in p, so the same loop gives k exactly over its whole validity range.
module udmap_damper_loops
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EPHYSICS
  use udmap_damper_tracer_core, only: damper_geometry_type, damper_state_type, &
    & branch_record_type, validity_type, equilibrium_cache_type, rates_cache_type, &
    & contact_forces, CONTACT_OPEN, CONTACT_STICK
  use udmap_damper_tracer, only: virgin_state, ramp_CF, trace_gamma, trace_to_plateau, &
    & record_start, reset_record, same_forces
  implicit none
  private
  public :: half_loop_type, loop_type, ramp_type, base_cycle_type, loop_workspace_type
  public :: trace_ramp, cf_only_ramp, steady_loop, trace_base_cycle
  public :: loop_stiffness, loop_k_re, loop_energy, elongated_stiffness, loop_moment
  public :: travel_integral

  !> Cycles after which a loop that has not repeated is an error (a ratcheting damper).
  integer, parameter :: MAX_CYCLES = 200
  !> A shakedown whose cycle-to-cycle ratio rho is this close to 1 is not extrapolated (a
  !> neutral wedge: the loop drifts without a limit that 200 cycles could resolve).
  real(wp), parameter :: RHO_MAX = 1 - 1e-6_wp
  !> Successive cycle-to-cycle changes of the state count as geometric (one dominant mode)
  !> when they are parallel to this relative accuracy.
  real(wp), parameter :: PARALLEL_TOL = 1e-7_wp

  !> One branch of a loop: vertices in the travel s from the reversal, with p-derivatives.
  type :: half_loop_type
    integer :: n = 0
    !> s(j), M(j): travel [rad] and restoring moment [N m] of vertex j; *_p: d/dp.
    real(wp), allocatable :: s(:), s_p(:), M(:), M_p(:)
    !> slope(j): dM_r/ds on the segment from vertex j-1 to j (j >= 2) [N m/rad].
    real(wp), allocatable :: slope(:)
  end type half_loop_type

  !> A steady loop traced at amplitude p0.
  type :: loop_type
    real(wp) :: p0 = 0
    type(half_loop_type) :: desc, asc
    !> Some contact slips / is open somewhere on the loop.
    logical :: slipped = .false., opened = .false.
    !> Amplitudes over which the event topology (hence the affine vertices) holds.
    real(wp) :: lo = 0, hi = 0
    !> Cycles traced until the loop repeated.
    integer :: cycles = 0
    !> The shakedown was extrapolated (the loop repeats only in the limit).
    logical :: extrapolated = .false.
  end type loop_type

  !> The monotonic virgin path: CF ramp, then gamma from 0 up to the upward plateau. States at
  !> its events let every amplitude start its ramp from the last event below it (same path).
  type :: ramp_type
    integer :: n = 0
    type(damper_state_type), allocatable :: states(:)
    real(wp), allocatable :: gamma(:)
    real(wp) :: CF = 0
  end type ramp_type

  !> Storage reused by successive loop tracings.
  type :: loop_workspace_type
    type(branch_record_type) :: desc, asc
    !> The equilibrium matrices met by the loops of one damper geometry (the same arithmetic
    !> whichever loop meets a contact state first; kept across the loops of a table).
    type(equilibrium_cache_type) :: eqc
    !> The rates of the contact states met by those loops (the same arithmetic, kept).
    type(rates_cache_type) :: rates
  end type loop_workspace_type

  !> The base cycle (PHYSICS.md 2.3): the branches from a reversal on one plateau until the
  !> last contact transition before the other plateau.
  type :: base_cycle_type
    !> Half the longer travel, the two travels, the plateau moments.
    real(wp) :: gamma_b = 0, s_desc = 0, s_asc = 0, M_max = 0, M_min = 0
    !> Dissipated energy E(p) = E0 + 2 (M_max - M_min) p for p >= gamma_b [J].
    real(wp) :: E0 = 0
    !> Branches (no p-dependence) from their reversals, ending at the last transition.
    type(half_loop_type) :: desc, asc
    !> Vertex travels and coefficients for k_Re(p) = sum c_v H(s_v; p), p >= gamma_b.
    real(wp), allocatable :: s_v(:), c_v(:)
    !> Contact states on the two plateaus.
    integer :: mode_max(3) = 0, mode_min(3) = 0
    !> A contact slips / opens on the base cycle; plateaus frozen (elongation law exact).
    logical :: slipped = .false., opened = .false., frozen = .false.
    !> State at the start of the upward plateau (a reversal point of the base cycle).
    type(damper_state_type) :: top
  end type base_cycle_type

contains

  !> The virgin ramp at centrifugal load CF: from the virgin state, CF from 0 to CF at
  !> gamma = 0, then gamma upwards until the upward plateau, states kept at every event.
  subroutine trace_ramp(geo, CF, ramp, error)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF
    type(ramp_type), intent(out) :: ramp
    type(error_type), allocatable, intent(out) :: error
    type(damper_state_type) :: st
    type(branch_record_type) :: rec
    real(wp) :: travel
    logical :: frozen

    call virgin_state(geo, st)
    call ramp_CF(geo, st, CF, error)
    if (allocated(error)) return
    rec%keep_states = .true.
    call record_start(geo, st, rec)
    call trace_to_plateau(geo, st, 1, travel, frozen, error, rec)
    if (allocated(error)) return
    ramp%n = rec%n
    ramp%states = rec%states(1:rec%n)
    ramp%gamma = rec%gamma(1:rec%n)
    ramp%CF = CF
  end subroutine trace_ramp

  !> A ramp holding only the state after the CF ramp, so that steady_loop traces the whole
  !> history from the virgin state (used to cross-check the shared ramp).
  subroutine cf_only_ramp(geo, CF, ramp, error)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF
    type(ramp_type), intent(out) :: ramp
    type(error_type), allocatable, intent(out) :: error
    type(damper_state_type) :: st
    call virgin_state(geo, st)
    call ramp_CF(geo, st, CF, error)
    if (allocated(error)) return
    ramp%n = 1
    ramp%states = [st]
    ramp%gamma = [0.0_wp]
    ramp%CF = CF
  end subroutine cf_only_ramp

  !> The steady loop at amplitude p > 0 with the history of PHYSICS.md 2.1: the virgin ramp up
  !> to +p, then gamma = p cos(tau) cycle after cycle until the contact forces at tau = 0
  !> repeat; the last cycle is the loop. `val` (if present, val%p0 = p) returns the exact
  !> range of amplitudes with the same event topology. `work` serves one geometry geo.
  !> Without `loop` (a probe of the topology interval: val) the branches are not recorded;
  !> recording does not change the path.
  subroutine steady_loop(geo, ramp, p, loop, work, error, val)
    type(damper_geometry_type), intent(in) :: geo
    type(ramp_type), intent(in) :: ramp
    real(wp), intent(in) :: p
    type(loop_type), intent(inout), optional :: loop
    type(loop_workspace_type), intent(inout) :: work
    type(error_type), allocatable, intent(out) :: error
    type(validity_type), intent(inout), optional :: val
    type(damper_state_type) :: st, start
    real(wp) :: x(12), dx(12), dx_prev(12), rho, room, lambda
    integer :: j, c, n_geo, m
    character(len=40) :: buf, bm, bl, br

    j = ramp%n
    do while (j > 1)
      if (ramp%gamma(j) <= p) exit
      j = j - 1
    end do
    st = ramp%states(j)
    call trace_gamma(geo, st, p, 1.0_wp, error, val=val, cache=work%eqc, rates=work%rates)
    if (allocated(error)) return
    n_geo = 0
    dx_prev = 0
    if (present(loop)) loop%extrapolated = .false.
    do c = 1, MAX_CYCLES
      start = st
      if (present(loop)) then
        call reset_record(work%desc)
        call record_start(geo, st, work%desc)
        call trace_gamma(geo, st, -p, -1.0_wp, error, work%desc, val, work%eqc, work%rates)
        if (allocated(error)) return
        call reset_record(work%asc)
        call record_start(geo, st, work%asc)
        call trace_gamma(geo, st, p, 1.0_wp, error, work%asc, val, work%eqc, work%rates)
      else
        call trace_gamma(geo, st, -p, -1.0_wp, error, val=val, cache=work%eqc, rates=work%rates)
        if (allocated(error)) return
        call trace_gamma(geo, st, p, 1.0_wp, error, val=val, cache=work%eqc, rates=work%rates)
      end if
      if (allocated(error)) return
      if (same_forces(geo, start, st, ramp%CF)) exit
      ! Shakedown: with the event sequence of the cycle fixed, one cycle is an affine map of
      ! the state (q, w at gamma = p, with their p-derivatives), x -> A x + b. When the changes
      ! of successive cycles are parallel, dx_c+1 = rho dx_c (one dominant mode of A), m more
      ! cycles add rho (1 - rho^m)/(1 - rho) dx exactly, and m -> infinity gives the limit
      ! (rho < 1). The jump is taken only as far as the contacts keep their modes with half
      ! of the room to spare (else the sequence would leave this affine piece: an unstable
      ! limit, rho > 1, or one outside it), by a whole number of cycles, so that the state is
      ! one the cycles themselves reach; the next cycle checks it (same_forces). Any affine
      ! combination of equilibria with the same modes is an equilibrium.
      ! (most loops repeat after one or two cycles: nothing to do for the first)
      if (c == 1) cycle
      x = [st%q, st%w, st%q_p, st%w_p]
      dx = x - [start%q, start%w, start%q_p, start%w_p]
      n_geo = n_geo + 1
      if (any(st%mode /= start%mode)) n_geo = 0
      if (n_geo >= 3) then
        rho = dot_product(dx, dx_prev)/max(dot_product(dx_prev, dx_prev), tiny(1.0_wp))
        if (rho > 0 .and. abs(rho - 1) > 1 - RHO_MAX .and. &
          & norm2(dx - rho*dx_prev) <= PARALLEL_TOL*norm2(dx)) then
          room = 0.5_wp*drift_room(st, dx)
          if (rho < 1 .and. rho/(1 - rho) <= room) then
            lambda = rho/(1 - rho)
          else if (room < 1e100_wp) then
            ! whole cycles m with rho (rho^m - 1)/(rho - 1) <= room
            lambda = log(1 + room*(rho - 1)/rho)/log(rho)
            m = 0
            if (lambda >= 2 .and. lambda < 1e6_wp) m = floor(lambda)
            lambda = 0
            if (m >= 2) lambda = rho*(rho**m - 1)/(rho - 1)
          else
            ! a drift that no contact stops: the damper ratchets (an error below)
            lambda = 0
          end if
          if (lambda > 0) then
            if (present(loop)) loop%extrapolated = .true.
            x = x + lambda*dx
            st%q = x(1:3)
            st%w = x(4:6)
            st%q_p = x(7:9)
            st%w_p = x(10:12)
            n_geo = 0
          end if
        end if
      end if
      dx_prev = dx
    end do
    if (c > MAX_CYCLES) then
      write(buf, '(es12.5)') p
      write(bm, '(g0.8)') geo%mu
      write(bl, '(g0.8)') geo%beta_deg(1)
      write(br, '(g0.8)') geo%beta_deg(2)
      call fatal_error(error, "damper loop at amplitude "//trim(adjustl(buf))// &
        & " rad does not repeat after 200 cycles: with mu = "//trim(bm)//", beta_L = "// &
        & trim(bl)//" deg, beta_R = "//trim(br)//" deg the damper ratchets or shakes down "// &
        & "only asymptotically, without a limit loop (mu = tan(beta) is a neutral wedge)", &
        & UDMAP_EPHYSICS)
      return
    end if
    if (.not. present(loop)) return
    loop%p0 = p
    loop%cycles = min(c, MAX_CYCLES)
    call to_half(work%desc, p, -1, loop%desc)
    call to_half(work%asc, p, 1, loop%asc)
    loop%slipped = work%desc%slipped .or. work%asc%slipped
    loop%opened = work%desc%opened .or. work%asc%opened
    if (present(val)) then
      loop%lo = val%lo
      loop%hi = val%hi
    else
      loop%lo = p
      loop%hi = p
    end if

  contains

    !> How many steps dx the state can move before a contact reaches the end of its mode
    !> (N = 0 for a closed contact, |T| = mu N for a stuck one); contact forces are linear in
    !> (q, w) for fixed modes.
    real(wp) function drift_room(s0, d) result(room)
      type(damper_state_type), intent(in) :: s0
      real(wp), intent(in) :: d(12)
      real(wp) :: g(3), sl(3), N(3), T(3), dN(3), dT(3), m, dm
      integer :: i
      call contact_forces(geo, s0%mode, s0%q, s0%gamma, s0%w, g, sl, N, T)
      call contact_forces(geo, s0%mode, d(1:3), 0.0_wp, d(4:6), g, sl, dN, dT)
      room = huge(1.0_wp)
      do i = 1, 3
        if (s0%mode(i) == CONTACT_OPEN) cycle
        if (dN(i) < 0) room = min(room, N(i)/(-dN(i)))
        if (s0%mode(i) == CONTACT_STICK) then
          m = geo%mu*N(i) - sign(1.0_wp, T(i))*T(i)
          dm = geo%mu*dN(i) - sign(1.0_wp, T(i))*dT(i)
          if (dm < 0) room = min(room, m/(-dm))
        end if
      end do
      room = max(room, 0.0_wp)
    end function drift_room
  end subroutine steady_loop

  !> The base cycle: from the upward plateau of the ramp, down to the next plateau and up again,
  !> repeated until the plateau forces repeat.
  subroutine trace_base_cycle(geo, ramp, base, error)
    type(damper_geometry_type), intent(in) :: geo
    type(ramp_type), intent(in) :: ramp
    type(base_cycle_type), intent(out) :: base
    type(error_type), allocatable, intent(out) :: error
    type(branch_record_type) :: desc, asc
    type(damper_state_type) :: st, top
    real(wp) :: sd, sa, A_desc, A_asc
    logical :: frozen_d, frozen_a
    integer :: it, nv, j

    st = ramp%states(ramp%n)
    do it = 1, MAX_CYCLES
      top = st
      call reset_record(desc)
      call record_start(geo, st, desc)
      call trace_to_plateau(geo, st, -1, sd, frozen_d, error, desc)
      if (allocated(error)) return
      base%mode_min = st%mode
      base%opened = any(st%mode == CONTACT_OPEN)
      call reset_record(asc)
      call record_start(geo, st, asc)
      call trace_to_plateau(geo, st, 1, sa, frozen_a, error, asc)
      if (allocated(error)) return
      base%mode_max = st%mode
      base%opened = base%opened .or. any(st%mode == CONTACT_OPEN)
      if (same_forces(geo, top, st, ramp%CF)) exit
    end do
    if (it > MAX_CYCLES) then
      call fatal_error(error, "damper base cycle does not repeat after 200 cycles (the damper "// &
        & "ratchets)", UDMAP_EPHYSICS)
      return
    end if
    base%top = top
    base%frozen = frozen_d .and. frozen_a
    base%slipped = desc%slipped .or. asc%slipped
    base%opened = base%opened .or. desc%opened .or. asc%opened
    ! Branches in the travel from their reversals (no p-dependence).
    call to_half(desc, desc%gamma(1), -1, base%desc)
    call to_half(asc, -asc%gamma(1), 1, base%asc)
    base%desc%s_p = 0
    base%asc%s_p = 0
    base%desc%M_p = 0
    base%asc%M_p = 0
    base%s_desc = sd
    base%s_asc = sa
    base%gamma_b = max(sd, sa)/2
    base%M_max = desc%M(1)
    base%M_min = desc%M(desc%n)
    A_desc = travel_integral(base%desc)
    A_asc = travel_integral(base%asc)
    base%E0 = A_asc - A_desc - base%M_max*sa + base%M_min*sd
    ! k_Re by parts over the vertices: the plateau beyond the last vertex has slope 0.
    nv = (base%desc%n - 1) + (base%asc%n - 1)
    allocate(base%s_v(nv), base%c_v(nv))
    nv = 0
    do j = 2, base%desc%n
      nv = nv + 1
      base%s_v(nv) = base%desc%s(j)
      base%c_v(nv) = -(base%desc%slope(j) - next_slope(base%desc, j))/(2*pi)
    end do
    do j = 2, base%asc%n
      nv = nv + 1
      base%s_v(nv) = base%asc%s(j)
      base%c_v(nv) = (base%asc%slope(j) - next_slope(base%asc, j))/(2*pi)
    end do

  contains

    pure real(wp) function next_slope(h, j)
      type(half_loop_type), intent(in) :: h
      integer, intent(in) :: j
      next_slope = 0
      if (j < h%n) next_slope = h%slope(j+1)
    end function next_slope
  end subroutine trace_base_cycle

  !> k(p) for p >= gamma_b from the base cycle with lengthened plateaus, in closed form, and
  !> dk/dp: k_Im = (E0 + 2 Delta_M p)/(pi p^2), k_Re = sum_v c_v H(s_v; p).
  pure subroutine elongated_stiffness(base, p, k, dk)
    type(base_cycle_type), intent(in) :: base
    real(wp), intent(in) :: p
    complex(wp), intent(out) :: k
    complex(wp), intent(out), optional :: dk
    real(wp) :: k_re, dk_re, H, dH, E, dM2, inv2p, x
    integer :: v
    k_re = 0
    dk_re = 0
    if (present(dk)) then
      do v = 1, size(base%s_v)
        call h_of_travel(base%s_v(v), 0.0_wp, p, H, dH)
        k_re = k_re + base%c_v(v)*H
        dk_re = dk_re + base%c_v(v)*dH
      end do
    else
      ! Here s_v <= 2 gamma_b <= 2p: 1 - x loses nothing that H can feel.
      inv2p = 0.5_wp/p
      do v = 1, size(base%s_v)
        x = min(base%s_v(v)*inv2p, 1.0_wp)
        k_re = k_re + base%c_v(v)*h_value(x, 1 - x)
      end do
    end if
    ! E(p)/(pi p^2) written so that no intermediate overflows at huge p.
    dM2 = 2*(base%M_max - base%M_min)
    E = base%E0/p + dM2
    k = cmplx(k_re, E/(pi*p), wp)
    if (present(dk)) dk = cmplx(dk_re, -((dM2 + 2*base%E0/p)/(pi*p))/p, wp)
  end subroutine elongated_stiffness

  !> k(p) and dk/dp of `loop` at amplitude p, its vertices moved affinely from loop%p0 (exact
  !> within the loop's validity range).
  pure subroutine loop_stiffness(loop, p, k, dk)
    type(loop_type), intent(in) :: loop
    real(wp), intent(in) :: p
    complex(wp), intent(out) :: k
    complex(wp), intent(out), optional :: dk
    real(wp) :: k_re, dk_re, kd, dkd, E0, E1, E2, d, E
    call half_re(loop%desc, loop%p0, p, kd, dkd)
    call half_re(loop%asc, loop%p0, p, k_re, dk_re)
    k_re = k_re - kd
    dk_re = dk_re - dkd
    call loop_energy(loop, E0, E1, E2)
    d = p - loop%p0
    E = E0 + d*(E1 + d*E2)
    if (.not. loop%slipped) E = 0
    k = cmplx(k_re/(2*pi), E/(pi*p**2), wp)
    if (present(dk)) then
      if (loop%slipped) then
        dk = cmplx(dk_re/(2*pi), (E1 + 2*d*E2)/(pi*p**2) - 2*E/(pi*p**3), wp)
      else
        dk = cmplx(dk_re/(2*pi), 0.0_wp, wp)
      end if
    end if
  end subroutine loop_stiffness

  !> k_Re(p) of `loop` alone (no derivative, no energy): the cheap part for fitting.
  pure real(wp) function loop_k_re(loop, p) result(k_re)
    type(loop_type), intent(in) :: loop
    real(wp), intent(in) :: p
    k_re = (half_value(loop%asc) - half_value(loop%desc))/(2*pi)

  contains

    pure real(wp) function half_value(h) result(f)
      type(half_loop_type), intent(in) :: h
      real(wp) :: H0, H1, sj
      integer :: j
      f = 0
      H0 = 0
      do j = 2, h%n
        sj = min(max(h%s(j) + h%s_p(j)*(p - loop%p0), 0.0_wp), 2*p)
        H1 = h_value(sj/(2*p), (2*p - sj)/(2*p))
        f = f + h%slope(j)*(H1 - H0)
        H0 = H1
      end do
    end function half_value
  end function loop_k_re

  !> sum_j slope_j (H_j - H_j-1) over a branch whose vertices move affinely from p0 to p,
  !> and its p-derivative.
  pure subroutine half_re(h, p0, p, f, df)
    type(half_loop_type), intent(in) :: h
    real(wp), intent(in) :: p0, p
    real(wp), intent(out) :: f, df
    real(wp) :: H0, dH0, H1, dH1
    integer :: j
    f = 0
    df = 0
    if (h%n < 2) return
    call h_of_travel(h%s(1) + h%s_p(1)*(p - p0), h%s_p(1), p, H0, dH0)
    do j = 2, h%n
      call h_of_travel(h%s(j) + h%s_p(j)*(p - p0), h%s_p(j), p, H1, dH1)
      f = f + h%slope(j)*(H1 - H0)
      df = df + h%slope(j)*(dH1 - dH0)
      H0 = H1
      dH0 = dH1
    end do
  end subroutine half_re

  !> Dissipated energy of `loop` as E(p) = E0 + E1 d + E2 d^2, d = p - p0 (exact: the loop's
  !> area is quadratic in p within one topology).
  pure subroutine loop_energy(loop, E0, E1, E2)
    type(loop_type), intent(in) :: loop
    real(wp), intent(out) :: E0, E1, E2
    real(wp) :: M_ref, a0, a1, a2, d0, d1, d2
    E0 = 0
    E1 = 0
    E2 = 0
    if (loop%desc%n < 1) return
    ! A constant moment encloses no area: subtracting one keeps the sums small.
    M_ref = loop%desc%M(1)
    call half_area(loop%asc, M_ref, a0, a1, a2)
    call half_area(loop%desc, M_ref, d0, d1, d2)
    E0 = a0 - d0
    E1 = a1 - d1
    E2 = a2 - d2
  end subroutine loop_energy

  !> int (M - M_ref) ds over a branch as a quadratic in d = p - p0.
  pure subroutine half_area(h, M_ref, A0, A1, A2)
    type(half_loop_type), intent(in) :: h
    real(wp), intent(in) :: M_ref
    real(wp), intent(out) :: A0, A1, A2
    real(wp) :: ds, ds_p, S, S_p
    integer :: j
    A0 = 0
    A1 = 0
    A2 = 0
    do j = 2, h%n
      ds = h%s(j) - h%s(j-1)
      ds_p = h%s_p(j) - h%s_p(j-1)
      S = (h%M(j) - M_ref + h%M(j-1) - M_ref)/2
      S_p = (h%M_p(j) + h%M_p(j-1))/2
      A0 = A0 + ds*S
      A1 = A1 + ds_p*S + ds*S_p
      A2 = A2 + ds_p*S_p
    end do
  end subroutine half_area

  !> int M ds over a branch (trapezoids, exact for the piecewise-linear branch).
  pure real(wp) function travel_integral(h) result(A)
    type(half_loop_type), intent(in) :: h
    integer :: j
    A = 0
    do j = 2, h%n
      A = A + (h%s(j) - h%s(j-1))*(h%M(j) + h%M(j-1))/2
    end do
  end function travel_integral

  !> M_r(tau) on `loop` (at its own amplitude p0) for gamma = p0 cos(tau).
  pure real(wp) function loop_moment(loop, tau) result(M)
    type(loop_type), intent(in) :: loop
    real(wp), intent(in) :: tau
    real(wp) :: t
    t = modulo(tau, 2*pi)
    if (t <= pi) then
      M = on_half(loop%desc, 2*loop%p0*sin(t/2)**2)
    else
      M = on_half(loop%asc, 2*loop%p0*cos(t/2)**2)
    end if

  contains

    pure real(wp) function on_half(h, s)
      type(half_loop_type), intent(in) :: h
      real(wp), intent(in) :: s
      integer :: j
      j = 2
      do while (j < h%n)
        if (h%s(j) >= s) exit
        j = j + 1
      end do
      on_half = h%M(j-1) + h%slope(j)*(s - h%s(j-1))
      if (h%n < 2) on_half = h%M(1)
    end function on_half
  end function loop_moment

  ! ------------------------------------------------------------------ internals

  !> Converts a recorded branch (vertices in gamma) to travel from its reversal at `p` (desc,
  !> sgn = -1: s = p - gamma) or at -p (asc, sgn = +1: s = gamma + p).
  pure subroutine to_half(rec, p, sgn, h)
    type(branch_record_type), intent(in) :: rec
    real(wp), intent(in) :: p
    integer, intent(in) :: sgn
    type(half_loop_type), intent(inout) :: h
    integer :: n
    n = rec%n
    h%n = n
    if (allocated(h%s)) then
      if (size(h%s) /= n) deallocate(h%s, h%s_p, h%M, h%M_p, h%slope)
    end if
    if (.not. allocated(h%s)) allocate(h%s(n), h%s_p(n), h%M(n), h%M_p(n), h%slope(n))
    if (sgn < 0) then
      h%s = p - rec%gamma(1:n)
      h%s_p = 1 - rec%gamma_p(1:n)
      h%slope = -rec%slope(1:n)
    else
      h%s = rec%gamma(1:n) + p
      h%s_p = rec%gamma_p(1:n) + 1
      h%slope = rec%slope(1:n)
    end if
    ! The reversal vertex sits at s = 0 exactly.
    h%s(1) = 0
    h%s_p(1) = 0
    h%slope(1) = 0
    h%M = rec%M(1:n)
    h%M_p = rec%M_p(1:n)
  end subroutine to_half

  !> H(s; p) = phi - sin(phi) cos(phi) with cos(phi) = 1 - s/p, and dH/dp along s(p) with
  !> ds/dp = s_p. With x = s/(2p) = sin^2(phi/2): H = 2 asin(sqrt(x)) - 2 sqrt(x (1 - x)) (1 - 2x),
  !> a series at small x, and H(1 - x) = pi - H(x) near s = 2p.
  pure subroutine h_of_travel(s, s_p, p, H, dH)
    real(wp), intent(in) :: s, s_p, p
    real(wp), intent(out) :: H, dH
    real(wp) :: sc, x, xb
    sc = min(max(s, 0.0_wp), 2*p)
    x = sc/(2*p)
    xb = (2*p - sc)/(2*p)
    H = h_value(x, xb)
    dH = 4*sqrt(x*xb)*(s_p - sc/p)/p
  end subroutine h_of_travel

  !> H as a function of x = s/(2p) and xb = 1 - x (both given, for accuracy at either end).
  elemental real(wp) function h_value(x, xb) result(H)
    real(wp), intent(in) :: x, xb
    if (x <= 0.5_wp) then
      H = h_half(x, xb)
    else
      H = pi - h_half(xb, x)
    end if
  end function h_value

  !> H(x) for x <= 1/2, without cancellation at small x.
  elemental real(wp) function h_half(x, xb) result(H)
    real(wp), intent(in) :: x, xb
    real(wp) :: y
    y = sqrt(x)
    if (x < 0.01_wp) then
      H = y*x*(16.0_wp/3 - x*(8.0_wp/5 + x*(2.0_wp/7 + x*(1.0_wp/9 + x*(5.0_wp/88 &
        & + x*(7.0_wp/208 + x*(7.0_wp/320 + x*(33.0_wp/2176))))))))
    else
      H = 2*asin(y) - 2*y*sqrt(xb)*(1 - 2*x)
    end if
  end function h_half
end module udmap_damper_loops
