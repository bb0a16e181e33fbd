!> The stiffness table k(gamma) of the asymmetric damper (PHYSICS.md 2.3), built once from the
!> base cycle and the loops below gamma_b, evaluated in tens of nanoseconds.
!>
!> Below gamma_b every amplitude needs its own loop, but the loop's events are affine in the
!> amplitude as long as their order (the topology) does not change, so one traced loop gives
!> k exactly over its whole topology interval, whose ends (the kinks of k, where a contact starts
!> slipping earlier or later in the cycle) the tracer computes exactly. The table marches through
!> these intervals from gamma -> 0 up to gamma_b:
!> - the first interval (stick; k = k_stuck, k_Im = 0 below gamma_s) is a constant;
!> - in each further interval k_Im = E(p)/(pi p^2) with the exact quadratic E(p), and k_Re is
!>   a Chebyshev series in theta, p = a + (b - a) sin^2(theta/2): at an end where a vertex
!>   reaches a reversal k_Re goes like (p - a)^(3/2), smooth in theta, so the series converges
!>   fast; its degree (or a split) is chosen until the tail is below 1e-11 of k_stuck;
!> - above gamma_b the closed form of the elongated base cycle (exact).
!> Geometries whose plateaus are not frozen (an open gap keeps growing) have no exact
!> elongation law; there the march goes on to 1000 gamma_b and the loop of the last topology
!> interval (affine in the amplitude) serves all larger amplitudes.
!> With lift-off the steady loop can change its shape abruptly between two topology intervals
!> (PHYSICS.md 2.5): k then jumps at the common end gamma_c of the two intervals, which the
!> tracer locates exactly (an event coincidence, not a tolerance), and both one-sided values
!> come from the two intervals' loops. Checking each interval end costs one loop evaluation.
module udmap_damper_stiffness_table
  use udmap_core_kinds, only: wp, pi
  use udmap_core_sorting, only: bisect
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC, UDMAP_EPHYSICS
  use udmap_damper_tracer_core, only: damper_geometry_type, validity_type
  use udmap_damper_loops, only: loop_type, ramp_type, base_cycle_type, loop_workspace_type, &
    & steady_loop, trace_base_cycle, loop_stiffness, loop_k_re, loop_energy, &
    & elongated_stiffness
  implicit none
  private
  public :: stiffness_table_type, build_stiffness_table
  public :: table_stiffness, table_stiffness_exact, table_stiffness_derivative
  public :: table_energy_slope

  !> Largest number of topology intervals below gamma_b before giving up.
  integer, parameter :: MAX_INTERVALS = 400
  !> Largest number of jumps of k in a table with extrapolated shakedowns (limit loops): more
  !> mean limits that change from one amplitude to the next (blade A's damper at 10 deg: 242 of
  !> 353 interval ends; at 89 deg 0 of 278, at 5 deg 8 of 17).
  integer, parameter :: MAX_SHAKEN_JUMPS = 50
  !> Chebyshev degrees tried per piece; relative tail accepted.
  integer, parameter :: DEG_START = 16, DEG_MAX = 64
  real(wp), parameter :: CHEB_TOL = 1e-11_wp
  !> A step of k at an interval end larger than this (relative to k_stuck) is a jump; where
  !> k is continuous the two loops agree to rounding (1e-13 and below).
  real(wp), parameter :: JUMP_TOL = 1e-8_wp

  !> k(gamma) of one asymmetric damper at its reference CF.
  type :: stiffness_table_type
    !> Largest amplitude without slip, base-cycle amplitude [rad], stuck stiffness [N m/rad].
    real(wp) :: gamma_s = 0, gamma_b = 0, k_stuck = 0
    !> k on [0, p_const] (the first topology interval, where k is constant).
    complex(wp) :: k_small = 0
    real(wp) :: p_const = 0
    !> End of the Chebyshev pieces; above: elongation law (or the last, unbounded interval).
    real(wp) :: p_end = 0
    logical :: use_elongation = .true.
    !> A contact opens somewhere on a steady loop (base cycle or below gamma_b).
    logical :: lift_off = .false.
    type(base_cycle_type) :: base
    !> Topology intervals: their loops, used ranges [a, b] and energies E0 + E1 d + E2 d^2.
    integer :: n_int = 0
    type(loop_type), allocatable :: loops(:)
    real(wp), allocatable :: int_a(:), int_b(:), E(:,:)
    !> Chebyshev pieces: range, interval, degree, coefficients coef(0:deg, piece).
    integer :: n_piece = 0
    real(wp), allocatable :: piece_a(:), piece_b(:), coef(:,:)
    integer, allocatable :: piece_int(:), piece_deg(:)
    !> Jumps of k (PHYSICS.md 2.5): amplitudes gamma_c (ascending) and the one-sided values
    !> k(gamma_c-), k(gamma_c+) with their derivatives dk/dgamma.
    integer :: n_jump = 0
    !> Intervals whose loops repeat only in the limit (extrapolated shakedown).
    integer :: n_shaken = 0
    real(wp), allocatable :: jump_gamma(:)
    complex(wp), allocatable :: jump_k(:,:), jump_dk(:,:)
  end type stiffness_table_type

contains

  !> Traces the base cycle and the topology intervals below gamma_b, then fits the pieces.
  subroutine build_stiffness_table(geo, ramp, tab, error)
    type(damper_geometry_type), intent(in) :: geo
    type(ramp_type), intent(in) :: ramp
    type(stiffness_table_type), intent(out) :: tab
    type(error_type), allocatable, intent(out) :: error
    type(loop_workspace_type) :: work
    type(loop_type), allocatable :: loops(:), tmp(:)
    type(validity_type) :: val
    real(wp) :: p, lo, hi, hi_prev, p_stop
    integer :: n, i, n_shaken
    logical :: slip_free_run
    character(len=32) :: bm, bl, br

    call trace_base_cycle(geo, ramp, tab%base, error)
    if (allocated(error)) return
    tab%gamma_b = tab%base%gamma_b
    tab%use_elongation = tab%base%frozen
    tab%lift_off = tab%base%opened
    ! Without an exact elongation law the march goes on to 1000 gamma_b; the last interval's
    ! loop then serves every larger amplitude (exact as far as its topology holds).
    p_stop = merge(tab%gamma_b, 1e3_wp*tab%gamma_b, tab%use_elongation)

    allocate(loops(16))
    n = 0
    n_shaken = 0
    ! First interval from a tiny amplitude (every vertex proportional to it: k constant).
    ! Start at 1e-3 gamma_b, where the loop's forces stand well above the resolution of the
    ! preload forces (a tiny loop cannot tell a contact on its cone from one near it), and
    ! step down past any kink below until the interval reaches down to zero.
    p = 1e-3_wp*tab%gamma_b
    do i = 1, 12
      call probe(p, lo, hi)
      if (allocated(error)) return
      if (lo <= 1e-3_wp*p) exit
      p = lo/4
    end do
    ! Trace the first interval again in its middle.
    call next_loop(min(hi, p_stop)/2)
    if (allocated(error)) return
    hi_prev = max(min(loops(1)%hi, p_stop), loops(1)%p0)
    do while (hi_prev < p_stop*(1 - 1e-12_wp))
      if (n >= MAX_INTERVALS) then
        if (n_shaken > 0) then
          call shakedown_error()
        else
          call fatal_error(error, "stiffness table: more than 400 changes of the loop "// &
            & "topology below gamma_b", UDMAP_ENUMERIC)
        end if
        return
      end if
      ! Probe just past the kink, then trace again in the middle of the interval found, far
      ! from both kinks, where the event order is unambiguous. A probe beyond a gap (an
      ! interval narrower than the step) is moved into the gap.
      p = min(hi_prev*(1 + 1e-6_wp), (hi_prev + p_stop)/2)
      do
        call probe(p, lo, hi)
        if (allocated(error)) return
        if (lo <= hi_prev*(1 + 1e-9_wp) .or. p - hi_prev <= 1e-12_wp*p) exit
        p = (hi_prev + lo)/2
      end do
      ! The interval holds the probe; rounding may put its ends a hair inside.
      lo = max(min(lo, p), hi_prev)
      hi = min(max(hi, p), p_stop)
      call next_loop((lo + hi)/2)
      if (allocated(error)) return
      hi_prev = max(min(loops(n)%hi, p_stop), hi, hi_prev*(1 + 1e-12_wp))
    end do

    tab%n_int = n
    allocate(tab%loops(n), tab%int_a(n), tab%int_b(n), tab%E(3,n))
    do i = 1, n
      tab%loops(i) = loops(i)
      tab%int_a(i) = 0
      if (i > 1) tab%int_a(i) = tab%int_b(i-1)
      tab%int_b(i) = min(max(loops(i)%hi, loops(i)%p0), p_stop)
      call loop_energy(loops(i), tab%E(1,i), tab%E(2,i), tab%E(3,i))
    end do
    if (n == 1) tab%int_b(1) = p_stop

    ! First interval: k constant (every vertex proportional to the amplitude).
    tab%k_small = constant_k(tab%loops(1))
    tab%k_stuck = real(tab%k_small, wp)
    tab%p_const = tab%int_b(1)
    tab%gamma_s = 0
    slip_free_run = .true.
    do i = 1, n
      slip_free_run = slip_free_run .and. .not. tab%loops(i)%slipped
      if (slip_free_run) tab%gamma_s = tab%int_b(i)
    end do

    ! Chebyshev pieces over the finite intervals above the first.
    tab%p_end = tab%p_const
    allocate(tab%piece_a(8), tab%piece_b(8), tab%piece_int(8), tab%piece_deg(8))
    allocate(tab%coef(0:DEG_MAX, 8))
    do i = 2, n
      if (i == n .and. .not. tab%use_elongation) exit
      if (tab%int_b(i) > tab%int_a(i)) call fit_interval(tab, i)
      tab%p_end = tab%int_b(i)
    end do
    if (.not. tab%use_elongation) tab%p_end = max(tab%p_end, tab%int_a(n))
    call find_jumps(tab)
    ! Limit loops that jump from one amplitude to the next define no function k(gamma).
    if (n_shaken > 0 .and. tab%n_jump > MAX_SHAKEN_JUMPS) call shakedown_error()

  contains

    !> Loops that shake down only asymptotically, to limits whose topology changes from one
    !> amplitude to the next (hundreds of intervals, most of their ends jumps of k).
    subroutine shakedown_error()
      write(bm, '(g0.8)') geo%mu
      write(bl, '(g0.8)') geo%beta_deg(1)
      write(br, '(g0.8)') geo%beta_deg(2)
      call fatal_error(error, "stiffness table: with mu = "//trim(bm)//", beta_L = "// &
        & trim(bl)//" deg, beta_R = "//trim(br)//" deg the damper loops shake down only "// &
        & "asymptotically over a range of amplitudes, to limit loops that change their "// &
        & "topology from one amplitude to the next: k(gamma) cannot be tabulated", &
        & UDMAP_EPHYSICS)
    end subroutine shakedown_error

    !> Traces the loop at amplitude pp as the next topology interval.
    subroutine next_loop(pp)
      real(wp), intent(in) :: pp
      if (n == size(loops)) then
        allocate(tmp(2*n))
        tmp(1:n) = loops
        call move_alloc(tmp, loops)
      end if
      n = n + 1
      val = validity_type(p0=pp, lo=0.0_wp)
      call steady_loop(geo, ramp, pp, loops(n), work, error, val)
      if (allocated(error)) return
      tab%lift_off = tab%lift_off .or. loops(n)%opened
      if (loops(n)%extrapolated) n_shaken = n_shaken + 1
      tab%n_shaken = n_shaken
    end subroutine next_loop

    !> The topology interval [plo, phi] that contains pp.
    subroutine probe(pp, plo, phi)
      real(wp), intent(in) :: pp
      real(wp), intent(out) :: plo, phi
      val = validity_type(p0=pp, lo=0.0_wp)
      call steady_loop(geo, ramp, pp, work=work, error=error, val=val)
      plo = val%lo
      phi = val%hi
    end subroutine probe
  end subroutine build_stiffness_table

  !> k(gamma) from the table (gamma > 0 at the reference CF).
  pure function table_stiffness(tab, gamma) result(k)
    type(stiffness_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    complex(wp) :: k
    integer :: ip, j
    real(wp) :: d, E, k_re
    if (gamma <= tab%p_const) then
      k = tab%k_small
    else if (gamma > tab%p_end) then
      ! (at p_end itself the piece below: k(gamma_c-) if k jumps there)
      if (tab%use_elongation) then
        call elongated_stiffness(tab%base, gamma, k)
      else
        call loop_stiffness(tab%loops(tab%n_int), gamma, k)
      end if
    else
      ip = find_piece(tab, gamma)
      k_re = chebyshev_value(tab, ip, gamma)
      j = tab%piece_int(ip)
      E = 0
      if (tab%loops(j)%slipped) then
        d = gamma - tab%loops(j)%p0
        E = tab%E(1,j) + d*(tab%E(2,j) + d*tab%E(3,j))
      end if
      k = cmplx(k_re, E/(pi*gamma**2), wp)
    end if
  end function table_stiffness

  !> k(gamma) from the exact topology-interval loops (no interpolation; slower).
  pure function table_stiffness_exact(tab, gamma) result(k)
    type(stiffness_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    complex(wp) :: k
    if (gamma <= tab%p_const) then
      k = tab%k_small
    else if (tab%use_elongation .and. gamma >= tab%gamma_b) then
      call elongated_stiffness(tab%base, gamma, k)
    else
      call loop_stiffness(tab%loops(find_interval(tab, gamma)), gamma, k)
    end if
  end function table_stiffness_exact

  !> dk/dgamma, exact (closed forms of the elongated base cycle or of the interval's loop).
  pure function table_stiffness_derivative(tab, gamma) result(dk)
    type(stiffness_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    complex(wp) :: dk
    complex(wp) :: k
    if (gamma <= tab%p_const) then
      dk = 0
    else if (tab%use_elongation .and. gamma >= tab%gamma_b) then
      call elongated_stiffness(tab%base, gamma, k, dk)
    else
      call loop_stiffness(tab%loops(find_interval(tab, gamma)), gamma, k, dk)
    end if
  end function table_stiffness_derivative

  !> lim E(gamma)/gamma for gamma -> infinity [N m]: the energy dissipated per cycle and unit
  !> amplitude at large amplitude (2 Delta_M with frozen plateaus; with an open gap that keeps
  !> growing, from the last interval's loop; huge when its energy grows faster than linearly).
  pure real(wp) function table_energy_slope(tab) result(dEdp)
    type(stiffness_table_type), intent(in) :: tab
    real(wp) :: E0, E1, E2
    if (tab%use_elongation) then
      dEdp = 2*(tab%base%M_max - tab%base%M_min)
    else
      call loop_energy(tab%loops(tab%n_int), E0, E1, E2)
      if (.not. tab%loops(tab%n_int)%slipped) then
        dEdp = 0
      else if (E2*tab%loops(tab%n_int)%p0 > 1e-9_wp*abs(E1)) then
        dEdp = huge(1.0_wp)
      else
        dEdp = E1
      end if
    end if
  end function table_energy_slope

  ! ------------------------------------------------------------------ internals

  !> Records the jumps of k at the interval ends (and where the elongation law takes over).
  subroutine find_jumps(tab)
    type(stiffness_table_type), intent(inout) :: tab
    real(wp) :: g(tab%n_int), scale
    complex(wp) :: km(tab%n_int), kp(tab%n_int), dkm(tab%n_int), dkp(tab%n_int)
    integer :: i, m
    scale = JUMP_TOL*max(abs(tab%k_stuck), tiny(1.0_wp))
    m = 0
    ! the loop changes its shape abruptly only where a contact opens (or the loops shake down
    ! to a limit): dampers without either pay nothing here
    if (.not. (tab%lift_off .or. tab%n_shaken > 0)) then
      tab%n_jump = 0
      allocate(tab%jump_gamma(0), tab%jump_k(2, 0), tab%jump_dk(2, 0))
      return
    end if
    do i = 1, tab%n_int
      if (i == tab%n_int .and. .not. tab%use_elongation) exit
      if (tab%int_b(i) <= tab%p_const .and. i > 1) cycle
      m = m + 1
      g(m) = tab%int_b(i)
      call loop_stiffness(tab%loops(i), g(m), km(m), dkm(m))
      if (i == 1) then
        km(m) = tab%k_small
        dkm(m) = 0
      end if
      if (i < tab%n_int) then
        call loop_stiffness(tab%loops(i+1), g(m), kp(m), dkp(m))
      else
        call elongated_stiffness(tab%base, g(m), kp(m), dkp(m))
      end if
      if (abs(kp(m) - km(m)) <= scale) m = m - 1
    end do
    tab%n_jump = m
    tab%jump_gamma = g(1:m)
    allocate(tab%jump_k(2, m), tab%jump_dk(2, m))
    tab%jump_k(1,:) = km(1:m)
    tab%jump_k(2,:) = kp(1:m)
    tab%jump_dk(1,:) = dkm(1:m)
    tab%jump_dk(2,:) = dkp(1:m)
  end subroutine find_jumps


  !> The constant k of the first topology interval.
  pure complex(wp) function constant_k(loop) result(k)
    type(loop_type), intent(in) :: loop
    call loop_stiffness(loop, loop%p0, k)
  end function constant_k

  pure integer function find_interval(tab, gamma) result(i)
    type(stiffness_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    i = bisect(tab%int_b(1:tab%n_int - 1), gamma) + 1
  end function find_interval

  pure integer function find_piece(tab, gamma) result(i)
    type(stiffness_table_type), intent(in) :: tab
    real(wp), intent(in) :: gamma
    i = bisect(tab%piece_b(1:tab%n_piece - 1), gamma) + 1
  end function find_piece

  !> Chebyshev series of piece ip in x = 2 theta/pi - 1, p = a + (b - a) sin^2(theta/2).
  pure real(wp) function chebyshev_value(tab, ip, p) result(f)
    type(stiffness_table_type), intent(in) :: tab
    integer, intent(in) :: ip
    real(wp), intent(in) :: p
    real(wp) :: u, x, b0, b1, b2
    integer :: j
    u = (p - tab%piece_a(ip))/(tab%piece_b(ip) - tab%piece_a(ip))
    u = min(max(u, 0.0_wp), 1.0_wp)
    x = (4/pi)*asin(sqrt(u)) - 1
    b1 = 0
    b2 = 0
    do j = tab%piece_deg(ip), 1, -1
      b0 = 2*x*b1 - b2 + tab%coef(j, ip)
      b2 = b1
      b1 = b0
    end do
    f = x*b1 - b2 + tab%coef(0, ip)
  end function chebyshev_value

  !> Fits k_Re over interval i, splitting it until each piece's series converges.
  subroutine fit_interval(tab, i)
    type(stiffness_table_type), intent(inout) :: tab
    integer, intent(in) :: i
    real(wp) :: stack_a(64), stack_b(64), a, b, c(0:DEG_MAX), f(0:DEG_MAX), scale
    integer :: top, deg
    logical :: ok

    scale = max(abs(tab%k_stuck), tiny(1.0_wp))
    top = 1
    stack_a(1) = tab%int_a(i)
    stack_b(1) = tab%int_b(i)
    do while (top > 0)
      a = stack_a(top)
      b = stack_b(top)
      top = top - 1
      deg = DEG_START
      call sample(tab%loops(i), a, b, deg, 1, f)
      do
        call chebyshev_coefficients(deg, f, c)
        ok = max(abs(c(deg)), abs(c(deg-1)), abs(c(deg-2))) <= CHEB_TOL*scale
        if (ok .or. deg >= DEG_MAX) exit
        ! The Lobatto points of degree 2 deg contain those of deg: sample the new ones only.
        f(0:2*deg:2) = f(0:deg)
        deg = 2*deg
        call sample(tab%loops(i), a, b, deg, 2, f)
      end do
      if (.not. ok .and. top < size(stack_a) - 1 .and. b - a > 1e-9_wp*b) then
        ! Second half first on the stack so that the pieces come out in order.
        stack_a(top+1) = (a + b)/2
        stack_b(top+1) = b
        stack_a(top+2) = a
        stack_b(top+2) = (a + b)/2
        top = top + 2
        cycle
      end if
      do while (deg > 2)
        if (abs(c(deg)) > 1e-3_wp*CHEB_TOL*scale) exit
        deg = deg - 1
      end do
      call add_piece(tab, i, a, b, deg, c)
    end do
  end subroutine fit_interval

  !> k_Re(p(theta)) at the Chebyshev-Lobatto points m = 1, 1 + step, ... of degree deg
  !> (m = 0 only with step 1), p = a + (b - a) sin^2(theta/2), theta = pi (x_m + 1)/2.
  pure subroutine sample(loop, a, b, deg, step, f)
    type(loop_type), intent(in) :: loop
    real(wp), intent(in) :: a, b
    integer, intent(in) :: deg, step
    real(wp), intent(inout) :: f(0:DEG_MAX)
    real(wp) :: p
    integer :: m
    if (step == 1) f(0) = loop_k_re(loop, b)
    do m = 1, deg, step
      p = a + (b - a)*sin(pi*(cos(pi*m/deg) + 1)/4)**2
      if (m == deg) p = a
      f(m) = loop_k_re(loop, p)
    end do
  end subroutine sample

  !> Chebyshev coefficients from the values at the Lobatto points (DCT-I).
  pure subroutine chebyshev_coefficients(deg, f, c)
    integer, intent(in) :: deg
    real(wp), intent(in) :: f(0:DEG_MAX)
    real(wp), intent(out) :: c(0:DEG_MAX)
    real(wp) :: cosines(0:2*DEG_MAX-1), wf(0:DEG_MAX)
    integer :: j, m, jm
    do m = 0, 2*deg - 1
      cosines(m) = cos(pi*m/deg)
    end do
    ! the end points weigh half
    wf(0) = 0.5_wp*f(0)
    wf(1:deg-1) = f(1:deg-1)
    wf(deg) = 0.5_wp*f(deg)
    c = 0
    do j = 0, deg
      ! jm = j m modulo 2 deg, stepped
      jm = 0
      do m = 0, deg
        c(j) = c(j) + wf(m)*cosines(jm)
        jm = jm + j
        if (jm >= 2*deg) jm = jm - 2*deg
      end do
      c(j) = 2*c(j)/deg
    end do
    c(0) = c(0)/2
    c(deg) = c(deg)/2
  end subroutine chebyshev_coefficients

  subroutine add_piece(tab, i, a, b, deg, c)
    type(stiffness_table_type), intent(inout) :: tab
    integer, intent(in) :: i, deg
    real(wp), intent(in) :: a, b, c(0:DEG_MAX)
    real(wp), allocatable :: ra(:), cc(:,:)
    integer, allocatable :: ia(:)
    integer :: n
    n = tab%n_piece
    if (n == size(tab%piece_a)) then
      allocate(ra(2*n)); ra(1:n) = tab%piece_a; call move_alloc(ra, tab%piece_a)
      allocate(ra(2*n)); ra(1:n) = tab%piece_b; call move_alloc(ra, tab%piece_b)
      allocate(ia(2*n)); ia(1:n) = tab%piece_int; call move_alloc(ia, tab%piece_int)
      allocate(ia(2*n)); ia(1:n) = tab%piece_deg; call move_alloc(ia, tab%piece_deg)
      allocate(cc(0:DEG_MAX, 2*n)); cc(:,1:n) = tab%coef; call move_alloc(cc, tab%coef)
    end if
    n = n + 1
    tab%n_piece = n
    tab%piece_a(n) = a
    tab%piece_b(n) = b
    tab%piece_int(n) = i
    tab%piece_deg(n) = deg
    tab%coef(:,n) = c
  end subroutine add_piece
end module udmap_damper_stiffness_table
