!> A traveling-wave peak at a given force in one Newton iteration on the whole point
!> (PHYSICS.md 2.6): the unknowns are the platform's harmonics x (as in a layer), the
!> amplitude gamma and omega; the equations are the layer's balance R = 0, the peak
!> psi = d|F|^2/domega = 0 and |F| = F_E.
!>
!! Why: the nested search (the root in gamma of layer peaks, each a root in omega of layer
!! solves, each a Newton iteration with a Jacobian of its own) traces the damper some 140
!! times per peak. Only the damper's action A(x, gamma) needs a trace, and it does not depend
!! on omega. So A is linearised, A ~ A_b + D (y - y_b), y = (x, gamma), with D the traced
!! action's exact derivatives (wave_aft's forward mode: one trace, whatever the size of y);
!! with the linear action the whole point is solved without a trace: at each omega the
!! balance is linear in y, |F|^2 = F_E^2 is a quadratic in gamma, and psi(omega) = 0 is a
!! scalar root (Brent). The point found is traced and linearised again (Newton) until a step
!! is so small that the linear action's error, O(step^2), is at the rounding floor. The point
!! is then that of the same equations as the layers': the balance holds with the traced
!! action, and psi takes the derivatives at the point, as the layer's solve does. Some 2.5
!! traces per peak, each with its derivatives.
module udmap_mapping_traveling_point
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_core_lapack, only: dgetrf, dgetrs
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update, &
    & outward_type, outward_start, outward_next, outward_update
  use udmap_blade_platform, only: platform_receptances_type, platform_receptances, &
    & platform_count, platform_scales, platform_pack, platform_unpack, platform_balance
  use udmap_contact_element_wave, only: wave_aft, wave_result_type
  use udmap_mapping_traveling_layer, only: traveling_type, wave_layer_type, &
    & wave_layer_solve, wave_balance_omega, wave_peak
  implicit none
  private
  public :: wave_point, wave_jump_point

  !> The Newton step (scaled) that ends the iteration: the linear action's error, O(step^2),
  !> is then at the rounding floor; and the iteration cap.
  real(wp), parameter :: newton_accept = 1.0e-5_wp
  integer, parameter :: max_outer = 30
  !> Relative tolerance of the root of psi in omega (at fixed action: no trace).
  real(wp), parameter :: omega_rtol = 1.0e-13_wp
  !> A jump's one-sided layers: the nearest below and above gamma_c that have a solution,
  !> from jump_gap_min (relative) doubling up to jump_gap_max (beyond: not one jump).
  real(wp), parameter :: jump_gap_min = 1.0e-9_wp, jump_gap_max = 1.0e-6_wp
  !> The widest gap above gamma_c without a layer that is still one jump (relative): there
  !> gamma_P goes across the gap with the blend.
  real(wp), parameter :: jump_gap_wide = 1.0e-3_wp
  !> How far (relative) the lower branch is followed up past the jump's first sign, and the
  !> change of a layer's peak frequency that means another branch.
  real(wp), parameter :: jump_follow_max = 0.1_wp, jump_branch = 1.0e-3_wp

  !> The action linearised about y_b: A(y) = A_b + sum_k dA(:, :, k) (y_k - y_b(k)).
  type :: linear_action_type
    real(wp), allocatable :: yb(:), dA0(:, :)
    real(wp) :: Ab0(3) = 0
    complex(wp), allocatable :: Ab(:, :), dA(:, :, :)
  end type linear_action_type

  !> What the procedures of one point share: the sizes of x and y = (x, gamma), the scales
  !> of y, the force, and whether gamma is held at the linear action's base (a layer at a jump
  !> of the action, wave_jump_point) instead of |F| = F_E.
  type :: point_work_type
    integer :: n = 0, ny = 0
    real(wp) :: F_E = 0
    logical :: fixed_gamma = .false.
    real(wp), allocatable :: sc(:)
  end type point_work_type

contains

  !> The peak of force F_E [N], started from gamma0 [rad], omega0 [rad/s] and the platform's
  !> harmonics in L (scaled to gamma0; none: a cold start). On success (ok) L holds the point
  !> as wave_peak leaves it. ok = .false. when the iteration does not converge (the caller
  !> then takes the nested search, which names the reason).
  subroutine wave_point(tw, F_E, gamma0, omega0, L, ok)
    type(traveling_type), intent(inout) :: tw
    real(wp), intent(in) :: F_E, gamma0, omega0
    type(wave_layer_type), intent(inout) :: L
    logical, intent(out) :: ok
    type(linear_action_type) :: lin
    type(wave_result_type) :: res
    type(point_work_type) :: pw
    type(error_type), allocatable :: err
    real(wp), allocatable :: y(:), y1(:)
    real(wp) :: w, w1, step, bracket
    integer :: n, ny, it

    ok = .false.
    call new_work(tw, F_E, pw)
    n = pw%n
    ny = pw%ny
    w = omega0
    if (.not. (w > tw%omega_lo .and. w < tw%omega_hi)) w = 0.5_wp*(tw%omega_lo + tw%omega_hi)
    if (L%gamma > 0) then
      L%P = L%P*(gamma0/L%gamma)
      L%P0 = L%P0*(gamma0/L%gamma)
    else
      ! a cold start: the platform's harmonics of the layer gamma0 at omega0, roughly (the
      ! linear action about zero translations can be far off)
      call wave_layer_solve(tw, gamma0, w, L, err, rough=.true.)
      if (allocated(err)) return
    end if
    allocate(y(ny), y1(ny))
    call new_linear_action(tw, ny, lin)
    L%P(3, 1) = gamma0
    call platform_pack(tw%u, L%P0(3), L%P, y(1:n))
    y(ny) = gamma0
    bracket = 1e-3_wp*w
    do it = 1, max_outer
      call set_scales(tw, pw, y(ny))
      call linearise_exact(tw, pw, y, lin, res, ok)
      if (.not. ok) return
      call peak(tw, pw, lin, w, bracket, w1, y1, L, ok)
      if (.not. ok) return
      ok = .false.
      step = maxval(abs(y1 - y)/pw%sc)
      bracket = max(4*abs(w1 - w), 1e-9_wp*w1)
      y = y1
      w = w1
      ! converged: a Newton step so small that the linear action's error, O(step^2), is at
      ! the rounding floor
      if (step <= newton_accept) then
        ok = .true.
        exit
      end if
    end do
    if (.not. ok) return
    L%trace = res
    L%gamma = y(ny)
    L%solved = .true.
    L%J_valid = .false.
    L%bracket = bracket

  end subroutine wave_point

  !> The peak of force F_E [N] at a jump of the traveling wave's backbone (PHYSICS.md 2.5 at
  !> phi): F_bb(gamma) jumps at gamma_c (from below F_E to above it), where a contact starts
  !> to lift off in the steady cycle. There the action is set-valued, every
  !> A_s = (1 - s) A- + s A+, with A- and A+ the one-sided actions as linear functions of the
  !> platform's harmonics: their values and derivatives at the one-sided layer peaks nearest
  !> to gamma0 (the differences pointing away from the jump); gamma_c lies between them, at
  !> most 2 jump_gap_max apart. gamma_P = gamma_c,
  !> and s in [0, 1] is the root of F_bb(s) = F_E, the peak of the layer gamma_c with A_s. At
  !> s = 0 and 1 this is the one-sided layer's peak; at phi = 0 the actions depend on gamma
  !> alone and it is 2.5's interpolation of k. Where no layer has a solution over a gap above
  !> gamma_c (wider than jump_gap_max, at most jump_gap_wide: the translations widen the jump
  !> as phi grows), the upper side is the first layer above the gap, and gamma_P goes across
  !> the gap with the blend, gamma_c + s (gamma_+ - gamma_c): the backbone stays continuous.
  !> ok = .false. when F_E is not inside the jump or no one-sided layer is found near gamma0.
  subroutine wave_jump_point(tw, F_E, gamma0, below, above, L, ok)
    type(traveling_type), intent(inout) :: tw
    real(wp), intent(in) :: F_E, gamma0
    !> Solved layers below and above the jump (their peaks: each side starts from its own, a
    !> layer next to the jump can peak on either branch); L: the point.
    type(wave_layer_type), intent(in) :: below, above
    type(wave_layer_type), intent(inout) :: L
    logical, intent(out) :: ok
    type(point_work_type) :: pw
    type(wave_layer_type) :: Lk, Ls(2)
    type(linear_action_type) :: side(2), lin
    type(wave_result_type) :: res(2)
    type(error_type), allocatable :: err
    type(brent_type) :: bs
    real(wp), allocatable :: y(:), yb(:), y1(:)
    real(wp) :: gk, F_bb, w, w1, s, g0, g1, gs, gap, edge(2), gamma_c, ghi, g_up, glo_gap
    integer :: k
    logical :: more

    ok = .false.
    call new_work(tw, F_E, pw)
    allocate(y(pw%ny), yb(pw%ny), y1(pw%ny))
    ! the one-sided layers' peaks nearest to gamma0 (a layer below it may peak on the upper
    ! branch: the lower side is sought down to jump_follow_max)
    if (.not. one_side(1, gamma0, below, jump_follow_max)) return
    if (.not. one_side(2, gamma0, above, jump_gap_wide)) return
    ! the branches below and above may overlap (the upper one already solves where the lower
    ! one still does): F_bb is the least of them, so the jump is where the lower branch ends.
    ! It is followed upwards in steps that double, then the end is bisected to jump_gap_min.
    ghi = 0
    gap = jump_gap_min
    do while (gap <= jump_follow_max)
      gk = edge(1)*(1 + gap)
      Lk = Ls(1)
      call wave_peak(tw, gk, Lk%omega, Lk, F_bb, err)
      if (.not. lower_branch()) then
        ghi = gk
        exit
      end if
      edge(1) = gk
      Ls(1) = Lk
      gap = 2*gap
    end do
    if (ghi == 0) return
    do while (ghi/edge(1) - 1 > jump_gap_min)
      gk = sqrt(edge(1)*ghi)
      Lk = Ls(1)
      call wave_peak(tw, gk, Lk%omega, Lk, F_bb, err)
      if (lower_branch()) then
        edge(1) = gk
        Ls(1) = Lk
      else
        ghi = gk
      end if
    end do
    gamma_c = sqrt(edge(1)*ghi)
    ! the upper side at or above gamma_c (beyond a gap without layers, if need be)
    if (edge(2) < gamma_c*(1 + jump_gap_min)) then
      if (.not. one_side(2, gamma_c, Ls(2), jump_gap_wide)) return
    end if
    g_up = gamma_c
    if (edge(2) > gamma_c*(1 + 2*jump_gap_max)) then
      ! a gap without layers: its upper end, bisected to jump_gap_min like gamma_c (the
      ! same for every force inside the jump)
      glo_gap = gamma_c
      do while (edge(2)/glo_gap - 1 > jump_gap_min)
        gk = sqrt(glo_gap*edge(2))
        Lk = Ls(2)
        call wave_peak(tw, gk, Lk%omega, Lk, F_bb, err)
        if (allocated(err)) then
          deallocate(err)
          glo_gap = gk
        else if (F_bb < F_E) then
          glo_gap = gk
        else
          edge(2) = gk
          Ls(2) = Lk
        end if
      end do
      g_up = edge(2)
    end if
    do k = 1, 2
      L = Ls(k)
      w = L%omega
      call set_scales(tw, pw, edge(k))
      call platform_pack(tw%u, L%P0(3), L%P, y(1:pw%n))
      y(pw%ny) = edge(k)
      call new_linear_action(tw, pw%ny, side(k))
      call linearise(tw, pw, y, 0.1_wp*abs(edge(k)/gamma_c - 1), merge(-1.0_wp, 1.0_wp, &
        & k == 1), side(k), res(k), ok)
      if (.not. ok) return
      if (k == 1) yb = y
    end do
    ! the layer gamma_c, from the lower side's harmonics
    yb(pw%ny) = gamma_c
    call set_scales(tw, pw, gamma_c)
    pw%fixed_gamma = .true.
    call new_linear_action(tw, pw%ny, lin)
    ok = .false.
    g0 = excess(0.0_wp)
    if (.not. ok) return
    g1 = excess(1.0_wp)
    if (.not. ok) return
    ok = g0 <= 0 .and. g1 >= 0
    if (.not. ok) return
    call brent_start(bs, 0.0_wp, g0, 1.0_wp, g1, 1e-13_wp)
    do
      call brent_next(bs, s, more)
      if (.not. more) exit
      gs = excess(s)
      if (.not. ok) return
      call brent_update(bs, gs)
    end do
    gs = excess(s)
    if (.not. ok) return
    L%trace = res(merge(1, 2, s < 0.5_wp))
    L%gamma = gamma_c + s*(g_up - gamma_c)
    L%solved = .true.
    L%J_valid = .false.

  contains

    !> The one-sided layer's peak nearest to g_ref on side k (1: below it and below F_E; 2:
    !> above both), from the layer `start`: next to the jump a layer's balance may have no
    !> solution, so the gap doubles from jump_gap_min up to gap_max until one does on that
    !> side. Sets edge(k) and Ls(k).
    logical function one_side(k, g_ref, start, gap_max)
      integer, intent(in) :: k
      real(wp), intent(in) :: g_ref, gap_max
      type(wave_layer_type), intent(in) :: start
      real(wp) :: gp
      one_side = .false.
      gp = jump_gap_min
      do while (gp <= gap_max)
        gk = g_ref*(1 + merge(-gp, gp, k == 1))
        Lk = start
        call wave_peak(tw, gk, Lk%omega, Lk, F_bb, err)
        if (.not. allocated(err)) then
          one_side = (F_bb < F_E) .eqv. (k == 1)
          if (one_side .or. k == 2) exit
        else
          deallocate(err)
        end if
        gp = 2*gp
      end do
      if (.not. one_side) return
      edge(k) = gk
      Ls(k) = Lk
    end function one_side

    !> Whether the layer just solved (Lk, error err, dropped) continues the lower branch Ls(1):
    !> solved, below F_E, at a nearby frequency.
    logical function lower_branch()
      lower_branch = .not. allocated(err)
      if (allocated(err)) deallocate(err)
      if (lower_branch) lower_branch = F_bb < F_E .and. &
        & abs(Lk%omega/Ls(1)%omega - 1) < jump_branch
    end function lower_branch

    !> ln F_bb(s) - ln F_E: the peak of the layer gamma_c with the blend s (L left there).
    real(wp) function excess(sv)
      real(wp), intent(in) :: sv
      real(wp) :: A0a(3), A0b(3)
      complex(wp) :: Aa(3, tw%H), Ab(3, tw%H)
      yb(pw%ny) = gamma_c + sv*(g_up - gamma_c)
      call action(side(1), yb, A0a, Aa)
      call action(side(2), yb, A0b, Ab)
      lin%yb = yb
      lin%Ab0 = (1 - sv)*A0a + sv*A0b
      lin%Ab = (1 - sv)*Aa + sv*Ab
      lin%dA0 = (1 - sv)*side(1)%dA0 + sv*side(2)%dA0
      lin%dA = (1 - sv)*side(1)%dA + sv*side(2)%dA
      call peak(tw, pw, lin, w, 1e-4_wp*w, w1, y1, L, ok)
      if (ok) w = w1
      excess = 0
      if (ok) excess = log(abs(L%F)) - log(F_E)
    end function excess
  end subroutine wave_jump_point

  !> The work of a point at the force F_E [N].
  subroutine new_work(tw, F_E, pw)
    type(traveling_type), intent(in) :: tw
    real(wp), intent(in) :: F_E
    type(point_work_type), intent(out) :: pw
    pw%n = platform_count(tw%u)
    pw%ny = pw%n + 1
    pw%F_E = F_E
    allocate(pw%sc(pw%ny))
  end subroutine new_work

  subroutine new_linear_action(tw, ny, la)
    type(traveling_type), intent(in) :: tw
    integer, intent(in) :: ny
    type(linear_action_type), intent(out) :: la
    allocate(la%yb(ny), la%dA0(3, ny), la%Ab(3, tw%H), la%dA(3, tw%H, ny))
  end subroutine new_linear_action

  !> Scales of y at the amplitude g: the layer's, and g itself for gamma.
  subroutine set_scales(tw, pw, g)
    type(traveling_type), intent(in) :: tw
    type(point_work_type), intent(inout) :: pw
    real(wp), intent(in) :: g
    call platform_scales(tw%u, g, pw%sc(1:pw%n))
    pw%sc(pw%ny) = g
  end subroutine set_scales

  !> The action linearised at y: a trace there and forward differences of relative step h
  !> (the gamma column's step times gamma_side: -1 keeps it below y's gamma).
  subroutine linearise(tw, pw, y, h, gamma_side, la, res, ok)
    type(traveling_type), intent(inout) :: tw
    type(point_work_type), intent(in) :: pw
    real(wp), intent(in) :: y(:), h, gamma_side
    type(linear_action_type), intent(inout) :: la
    type(wave_result_type), intent(out) :: res
    logical, intent(out) :: ok
    real(wp) :: s(size(y)), A0p(3), dk
    complex(wp) :: Ap(3, tw%H)
    integer :: k
    ok = trace(tw, pw, y, la%Ab0, la%Ab, res)
    if (.not. ok) return
    la%yb = y
    do k = 1, pw%ny
      dk = h*pw%sc(k)
      if (k == pw%ny) dk = dk*gamma_side
      s = y
      s(k) = y(k) + dk
      ok = trace(tw, pw, s, A0p, Ap)
      if (.not. ok) return
      la%dA0(:, k) = (A0p - la%Ab0)/dk
      la%dA(:, :, k) = (Ap - la%Ab)/dk
    end do
  end subroutine linearise

  !> The action linearised at y: one trace with its exact derivatives (wave_aft's forward
  !> mode; gamma, y's last entry, must be positive).
  subroutine linearise_exact(tw, pw, y, la, res, ok)
    type(traveling_type), intent(inout) :: tw
    type(point_work_type), intent(in) :: pw
    real(wp), intent(in) :: y(:)
    type(linear_action_type), intent(inout) :: la
    type(wave_result_type), intent(out) :: res
    logical, intent(out) :: ok
    type(error_type), allocatable :: err
    real(wp) :: P0(3), dP0(3, pw%ny), u(pw%ny)
    complex(wp) :: P(3, tw%H), dP(3, tw%H, pw%ny)
    integer :: k
    ok = y(pw%ny) > 0
    if (.not. ok) return
    ! y -> (P0, P) is linear: the derivatives are the images of the unit vectors
    do k = 1, pw%ny
      u = 0
      u(k) = 1
      call unpack_y(tw, pw, u, dP0(:, k), dP(:, :, k))
    end do
    call unpack_y(tw, pw, y, P0, P)
    call wave_aft(tw%geo, tw%CF, tw%phi, P0, P, tw%settings, la%Ab0, la%Ab, err, res, dP0, dP, &
      & la%dA0, la%dA)
    tw%traces = tw%traces + 1
    ok = .not. allocated(err)
    la%yb = y
  end subroutine linearise_exact

  !> The damper's action at y (a trace); .false. when the trace fails.
  logical function trace(tw, pw, yv, A0v, Av, r)
    type(traveling_type), intent(inout) :: tw
    type(point_work_type), intent(in) :: pw
    real(wp), intent(in) :: yv(:)
    real(wp), intent(out) :: A0v(3)
    complex(wp), intent(out) :: Av(:, :)
    type(wave_result_type), intent(out), optional :: r
    type(error_type), allocatable :: err
    real(wp) :: P0(3)
    complex(wp) :: P(3, tw%H)
    call unpack_y(tw, pw, yv, P0, P)
    call wave_aft(tw%geo, tw%CF, tw%phi, P0, P, tw%settings, A0v, Av, err, r)
    tw%traces = tw%traces + 1
    trace = .not. allocated(err)
  end function trace

  subroutine unpack_y(tw, pw, yv, P0, P)
    type(traveling_type), intent(in) :: tw
    type(point_work_type), intent(in) :: pw
    real(wp), intent(in) :: yv(:)
    real(wp), intent(out) :: P0(3)
    complex(wp), intent(out) :: P(:, :)
    P = 0
    P0 = 0
    call platform_unpack(tw%u, yv(1:pw%n), P0(3), P)
    P(3, 1) = cmplx(yv(pw%ny), 0.0_wp, wp)
  end subroutine unpack_y

  !> The peak of the linear action: the root of psi(omega) on |F| = F_E (or at the base's
  !> gamma, pw%fixed_gamma), bracketed outward from w0 by steps from d0 and refined by
  !> Brent's method; y_out and Lo at the root.
  subroutine peak(tw, pw, la, w0, d0, w_out, y_out, Lo, good)
    type(traveling_type), intent(in) :: tw
    type(point_work_type), intent(in) :: pw
    type(linear_action_type), intent(in) :: la
    real(wp), intent(in) :: w0, d0
    real(wp), intent(out) :: w_out, y_out(:)
    type(wave_layer_type), intent(inout) :: Lo
    logical, intent(out) :: good
    type(brent_type) :: bs
    type(outward_type) :: out
    real(wp) :: fa, x, fx
    logical :: more
    w_out = w0
    call at_omega(tw, pw, la, w0, y_out, Lo, fa, good)
    if (.not. good) return
    call outward_start(out, w0, fa, d0, tw%omega_lo, tw%omega_hi)
    do
      call outward_next(out, x, more)
      if (.not. more) exit
      call at_omega(tw, pw, la, x, y_out, Lo, fx, good)
      if (.not. good) return
      call outward_update(out, fx)
    end do
    good = out%found
    if (.not. good) return
    call brent_start(bs, out%a, out%fa, out%b, out%fb, omega_rtol*out%a)
    do
      call brent_next(bs, x, more)
      if (.not. more) exit
      call at_omega(tw, pw, la, x, y_out, Lo, fx, good)
      if (.not. good) return
      call brent_update(bs, fx)
    end do
    if (Lo%omega /= x) call at_omega(tw, pw, la, x, y_out, Lo, fx, good)
    w_out = x
  end subroutine peak

  !> At omega wv with the linear action la: y_out on |F| = F_E (the balance is linear in y,
  !> |F|^2 a quadratic in gamma: its larger root), or at the base's gamma (pw%fixed_gamma);
  !> psi there, and Lo filled as the layer's solve fills it. good = .false. when |F| does not
  !> reach F_E at wv.
  subroutine at_omega(tw, pw, la, wv, y_out, Lo, psi, good)
    type(traveling_type), intent(in) :: tw
    type(point_work_type), intent(in) :: pw
    type(linear_action_type), intent(in) :: la
    real(wp), intent(in) :: wv
    real(wp), intent(out) :: y_out(:), psi
    type(wave_layer_type), intent(inout) :: Lo
    logical, intent(out) :: good
    type(platform_receptances_type) :: r(tw%H)
    type(error_type), allocatable :: err
    real(wp) :: Jy(pw%n, pw%ny), Rb(pw%n), Rk(pw%n), ax(pw%n), bx(pw%n), Rw(pw%n), xw(pw%n)
    real(wp) :: yk(pw%ny), A0v(3), sk, qa, qb, qc, disc, q, t
    complex(wp) :: Fy(pw%ny), Fb_, Fk, Fa_, Fg, F, Fw
    complex(wp) :: Av(3, tw%H)
    integer :: ipiv(pw%n), info, h, kk, n, ny
    n = pw%n
    ny = pw%ny
    psi = 0
    good = .false.
    do h = 1, tw%H
      call platform_receptances(tw%blade, h*wv, r(h), err, derivatives=.true., &
        & modal=tw%modal)
      if (allocated(err)) return
    end do
    ! the balance and the force are affine in y: their columns by unit differences
    call balance_at(tw, pw, r, la, la%yb, Rb, Fb_)
    do kk = 1, ny
      sk = max(abs(la%yb(kk)), pw%sc(kk))
      yk = la%yb
      yk(kk) = la%yb(kk) + sk
      call balance_at(tw, pw, r, la, yk, Rk, Fk)
      Jy(:, kk) = (Rk - Rb)/sk
      Fy(kk) = (Fk - Fb_)/sk
    end do
    call dgetrf(n, n, Jy, n, ipiv, info)
    if (info /= 0) return
    ax = -Rb
    bx = -Jy(:, ny)
    call dgetrs('N', n, 1, Jy, n, ipiv, ax, n, info)
    call dgetrs('N', n, 1, Jy, n, ipiv, bx, n, info)
    ! F(t) = Fa + t Fg along the layers gamma = gamma_b + t; |F(t)|^2 = F_E^2
    Fa_ = Fb_ + sum(Fy(1:n)*ax)
    Fg = sum(Fy(1:n)*bx) + Fy(ny)
    if (pw%fixed_gamma) then
      t = 0
    else
      qa = abs(Fg)**2
      qb = real(conjg(Fa_)*Fg, wp)
      qc = abs(Fa_)**2 - pw%F_E**2
      disc = qb*qb - qa*qc
      if (.not. (qa > 0)) return
      if (disc >= 0) then
        q = -(qb + sign(sqrt(disc), qb))
        if (q == 0) return
        t = max(q/qa, qc/q)
      else
        ! the line F(t) passes F_E's circle by (a start far from the point): its closest
        ! approach; the next linearisation, nearer, crosses the circle
        t = -qb/qa
      end if
    end if
    y_out(1:n) = la%yb(1:n) + ax + t*bx
    y_out(ny) = la%yb(ny) + t
    if (.not. (y_out(ny) > 0)) return
    ! psi at fixed gamma: the platform's harmonics follow omega through the balance
    call action(la, y_out, A0v, Av)
    F = Fa_ + t*Fg
    call wave_balance_omega(tw%u, r, tw%H, y_out(ny), Av, Rw, Fw)
    xw = -Rw
    call dgetrs('N', n, 1, Jy, n, ipiv, xw, n, info)
    Fw = Fw + sum(Fy(1:n)*xw)
    psi = 2*real(conjg(F)*Fw, wp)
    Lo%omega = wv
    Lo%F = F
    Lo%psi = psi
    Lo%A = Av
    Lo%A0 = A0v
    call unpack_y(tw, pw, y_out, Lo%P0, Lo%P)
    do h = 1, tw%H
      Lo%sigma(h) = -sum(r(h)%sp*Av(:, h))
      Lo%uE(h) = -sum(r(h)%pE*Av(:, h))
    end do
    Lo%sigma(1) = Lo%sigma(1) + r(1)%sE*F
    Lo%uE(1) = Lo%uE(1) + r(1)%EE*F
    good = psi == psi .and. abs(psi) <= huge(psi)
  end subroutine at_omega

  !> The residual of the balance and the force at yv with the linear action lb and the
  !> receptances rr.
  subroutine balance_at(tw, pw, rr, lb, yv, Rv, Fv)
    type(traveling_type), intent(in) :: tw
    type(point_work_type), intent(in) :: pw
    type(platform_receptances_type), intent(in) :: rr(:)
    type(linear_action_type), intent(in) :: lb
    real(wp), intent(in) :: yv(:)
    real(wp), intent(out) :: Rv(:)
    complex(wp), intent(out) :: Fv
    real(wp) :: P0(3), A0l(3)
    complex(wp) :: P(3, tw%H), Al(3, tw%H)
    call unpack_y(tw, pw, yv, P0, P)
    call action(lb, yv, A0l, Al)
    Fv = (yv(pw%ny) + sum(rr(1)%pp(3, :)*Al(:, 1)))/rr(1)%pE(3)
    call platform_balance(tw%u, rr, tw%r0, P0(3), P, A0l, Al, tw%A_ref, Fv, Rv)
  end subroutine balance_at

  !> The linear action at y.
  pure subroutine action(la, y, A0, A)
    type(linear_action_type), intent(in) :: la
    real(wp), intent(in) :: y(:)
    real(wp), intent(out) :: A0(3)
    complex(wp), intent(out) :: A(:, :)
    integer :: k
    A0 = la%Ab0
    A = la%Ab
    do k = 1, size(y)
      if (y(k) == la%yb(k)) cycle
      A0 = A0 + la%dA0(:, k)*(y(k) - la%yb(k))
      A = A + la%dA(:, :, k)*(y(k) - la%yb(k))
    end do
  end subroutine action
end module udmap_mapping_traveling_point
