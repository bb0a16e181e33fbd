!> One amplitude layer of a traveling wave (PHYSICS.md 2.6). The first harmonic of gamma_P is
!> fixed (gamma, real: the phase reference) and so is omega; the blade is condensed onto its
!> platform p = (u_P, v_P, gamma_P) through the platform receptances at each harmonic, and
!> every other harmonic of p is solved for:
!>
!>   p_h + H_pp(h omega) A_h(p) = delta_h1 H_pE(omega) P,
!>
!> A_h the harmonics of the damper's restoring action on blade 0 (udmap_contact_element_wave).
!> The gamma row at h = 1 gives the force explicitly, P = (gamma + [H_pp A_1]_g)/H_gE; the
!> others are a small Newton problem (unknowns: u_1, v_1 at H = 1; with H > 1 also Gamma_0,
!> u_h, v_h, Gamma_h for h = 2..H). The static translations drop out: both platforms of a
!> damper share them. Jacobian by finite differences, Newton with a backtracking line search.
!> The layer's peak is the minimum of |P| over omega (Brent's minimiser); F_bb = that minimum.
module udmap_mapping_traveling_layer
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC, UDMAP_EPHYSICS
  use udmap_core_strings, only: ftoa
  use udmap_core_lapack, only: dgetrf, dgetrs
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update, &
    & outward_type, outward_start, outward_next, outward_update
  use udmap_blade_type, only: blade_type
  use udmap_blade_platform, only: platform_receptances_type, platform_receptances, &
    & platform_modal_type, platform_modal, &
    & platform_unknowns_type, platform_count, platform_scales, platform_pack, &
    & platform_unpack, platform_balance
  use udmap_damper_tracer_core, only: damper_geometry_type
  use udmap_contact_element_wave, only: wave_aft, wave_settings_type, wave_result_type, &
    & wave_static_action, wave_samples
  implicit none
  private
  public :: traveling_type, wave_layer_type, new_traveling, wave_layer_solve, wave_peak, &
    & wave_layer_slope, wave_balance_omega

  !> Newton tolerance (to the layer's scale) and cap; the tolerance of a rough solve.
  real(wp), parameter :: newton_tol = 1.0e-13_wp, rough_tol = 1.0e-2_wp
  !> The residual's rounding floor: at tiny amplitudes the action's harmonics are the small
  !> difference of samples of the preloaded contact forces, noisy to some 1e-12 of the layer's
  !> scale. A Newton step below this that no longer descends ends the solve.
  real(wp), parameter :: floor_tol = 1.0e-9_wp
  integer, parameter :: newton_max = 40
  !> Relative frequency tolerance of the peak.
  real(wp), parameter :: peak_rtol = 1.0e-11_wp

  !> The coupled blade and damper at one interblade phase.
  type :: traveling_type
    type(blade_type), pointer :: blade => null()
    type(damper_geometry_type) :: geo
    real(wp) :: CF = 0, phi = 0
    !> Harmonics: 1 (harmonic 1 only) or H > 1 (0..H).
    integer :: H = 1
    !> The unknowns of a layer: the platform's harmonics but Gamma_1.
    type(platform_unknowns_type) :: u
    !> Static action of the loaded damper on blade 0 (the blade's reference state).
    real(wp) :: A_ref(3) = 0
    !> Static platform receptances (for Gamma_0); the modal form of the receptances.
    type(platform_receptances_type) :: r0
    type(platform_modal_type) :: modal
    type(wave_settings_type) :: settings
    !> Band [rad/s].
    real(wp) :: omega_lo = 0, omega_hi = 0
    !> Statistics: traces run.
    integer :: traces = 0
  end type traveling_type

  !> A solved layer (gamma, omega) and what follows from it.
  type :: wave_layer_type
    real(wp) :: gamma = 0, omega = 0
    !> Platform harmonics P(:,h), h = 1..H, static Gamma_0, damper action harmonics.
    complex(wp), allocatable :: P(:, :), A(:, :)
    real(wp) :: P0(3) = 0, A0(3) = 0
    !> Force amplitude (complex: phase against gamma) that puts the blade on the layer [N].
    complex(wp) :: F = 0
    !> Harmonics of the stress and of u_E (h = 1..H), static stress change.
    complex(wp), allocatable :: sigma(:), uE(:)
    type(wave_result_type) :: trace
    logical :: solved = .false.
    !> d|F|^2/domega at the solution [N^2 s/rad].
    real(wp) :: psi = 0
    !> The Jacobian of the balance, its LU factors and dF/dx (kept for the next solve).
    real(wp), allocatable :: J(:, :), LU(:, :)
    complex(wp), allocatable :: Fx(:)
    integer, allocatable :: ipiv(:)
    logical :: J_valid = .false.
    !> The damper action's derivatives by the unknowns of a whole point (x, gamma) at its
    !> solution (udmap_mapping_traveling_point), which start the next force's point.
    real(wp), allocatable :: dA0(:, :)
    complex(wp), allocatable :: dA(:, :, :)
    !> Where the Jacobian was taken; the bracket width of the last peak search [rad/s].
    real(wp), allocatable :: x_J(:)
    real(wp) :: bracket = 0
  end type wave_layer_type

contains

  !> Couples `blade` (borrowed) and the asymmetric damper geometry at phi [rad].
  subroutine new_traveling(tw, blade, geo, CF, phi, H, omega_lo, omega_hi, error)
    type(traveling_type), intent(out) :: tw
    type(blade_type), target, intent(in) :: blade
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF, phi, omega_lo, omega_hi
    integer, intent(in) :: H
    type(error_type), allocatable, intent(out) :: error
    tw%blade => blade
    tw%geo = geo
    tw%CF = CF
    tw%phi = phi
    tw%H = H
    tw%omega_lo = omega_lo
    tw%omega_hi = omega_hi
    tw%settings%samples = wave_samples(H)
    if (.not. allocated(blade%platform_uv)) then
      call fatal_error(error, "traveling wave (phi /= 0): the blade's platform translations "// &
        & "are unknown: give blade.u_dof (matrices) or blade.platform.tangent (fe)", UDMAP_EINPUT)
      return
    end if
    tw%u = platform_unknowns_type(H=H, v_free=any(blade%platform_uv(:, 2) /= 0), &
      & gamma1_fixed=.true., lever=max(maxval(abs(geo%cn)), maxval(abs(geo%ct)), tiny(1.0_wp)))
    call wave_static_action(geo, CF, tw%A_ref, error)
    if (allocated(error)) return
    call platform_modal(blade, tw%modal)
    if (H > 1) call platform_receptances(blade, 0.0_wp, tw%r0, error, modal=tw%modal)
  end subroutine new_traveling

  !> Solves the layer (gamma, omega), starting from what L holds (a neighbouring solution;
  !> zeros for a cold start). Sets L%F, the harmonics, the stress and psi = d|F|^2/domega
  !> (total: the platform's harmonics follow omega, dx/domega = -J^-1 dR/domega; the damper's
  !> action does not depend on omega, so this needs no trace beyond the Jacobian's). With
  !> `rough`, only the platform's harmonics, to rough_tol: a start for a whole point
  !> (udmap_mapping_traveling_point), whose own iteration solves them exactly.
  subroutine wave_layer_solve(tw, gamma, omega, L, error, rough)
    type(traveling_type), intent(inout) :: tw
    real(wp), intent(in) :: gamma, omega
    type(wave_layer_type), intent(inout) :: L
    type(error_type), allocatable, intent(out) :: error
    logical, intent(in), optional :: rough
    type(platform_receptances_type), allocatable :: r(:)
    real(wp), allocatable :: x(:), R0(:), Rt(:), dx(:), xt(:), sc(:), Rw(:)
    integer, allocatable :: ipiv(:)
    integer :: n, it, h, info, ls, attempt
    real(wp) :: rn, rnt, t, rn_prev
    complex(wp) :: F0, dF
    complex(wp), allocatable :: A_x(:, :)
    real(wp) :: A0_x(3), tol
    logical :: done, fresh

    if (.not. (gamma > 0 .and. gamma < huge(1.0_wp)) .or. .not. (omega > 0)) then
      call fatal_error(error, "traveling layer: gamma and omega must be positive", UDMAP_EINPUT)
      return
    end if
    n = platform_count(tw%u)
    if (.not. allocated(L%P)) then
      allocate(L%P(3, tw%H), L%A(3, tw%H), L%sigma(tw%H), L%uE(tw%H))
      L%P = 0
    end if
    if (.not. allocated(L%J)) allocate(L%J(n, n), L%LU(n, n), L%Fx(n), L%ipiv(n), L%x_J(n))
    if (L%gamma > 0 .and. L%gamma /= gamma) then
      L%P = L%P*(gamma/L%gamma)
      L%P0 = L%P0*(gamma/L%gamma)
      L%J_valid = .false.
    end if
    L%gamma = gamma
    L%omega = omega
    allocate(r(tw%H))
    do h = 1, tw%H
      call platform_receptances(tw%blade, h*omega, r(h), error, derivatives=.true., &
        & modal=tw%modal)
      if (allocated(error)) return
    end do
    allocate(x(n), R0(n), Rt(n), dx(n), xt(n), sc(n), ipiv(n), Rw(n))
    tol = newton_tol
    if (present(rough)) then
      if (rough) tol = rough_tol
    end if
    call platform_scales(tw%u, gamma, sc)
    do attempt = 1, 2
      if (attempt == 2) then
        ! a warm start that led Newton astray: the cold start decides
        L%P = 0
        L%P0 = 0
        L%J_valid = .false.
      end if
      call platform_pack(tw%u, L%P0(3), L%P, x)
      call residual(x, R0, F0, error)
      if (allocated(error)) return
      rn = wnorm(R0)
      done = rn == 0
      rn_prev = huge(1.0_wp)
      ! chord Newton: the Jacobian of a neighbouring solve while it contracts, renewed when not
      do it = 1, newton_max
        if (done) exit
        fresh = .false.
        if (.not. L%J_valid .or. rn > 0.25_wp*rn_prev) then
          call jacobian(x, R0, F0, error)
          if (allocated(error)) return
          fresh = .true.
        end if
        dx = -R0
        call dgetrs('N', n, 1, L%LU, n, L%ipiv, dx, n, info)
        if (maxval(abs(dx)/sc) <= tol) then
          ! at the rounding floor of the residual: the step is the last correction
          x = x + dx
          call residual(x, R0, F0, error)
          if (allocated(error)) return
          done = .true.
          exit
        end if
        t = 1
        do ls = 1, 8
          xt = x + t*dx
          call residual(xt, Rt, F0, error)
          if (allocated(error)) return
          rnt = wnorm(Rt)
          if (rnt < rn .or. rnt == 0) exit
          t = t/2
        end do
        if (.not. (rnt < rn .or. rnt == 0)) then
          ! no descent along a stale Jacobian: renew it; along a fresh one: at the rounding
          ! floor (a step below floor_tol) the solve is done, else it fails
          if (fresh) then
            done = maxval(abs(dx)/sc) <= floor_tol
            exit
          end if
          L%J_valid = .false.
          call residual(x, R0, F0, error)
          if (allocated(error)) return
          cycle
        end if
        rn_prev = rn
        x = xt
        R0 = Rt
        rn = rnt
        done = maxval(abs(t*dx)/sc) <= tol .or. rn == 0
      end do
      if (done) exit
    end do
    if (.not. done) then
      call fatal_error(error, "traveling layer gamma = "//ftoa(gamma)//" rad at "// &
        & ftoa(omega/(2*pi))//" Hz, phi = "//ftoa(tw%phi)//" rad: the harmonic balance of "// &
        & "the platform did not converge", UDMAP_ENUMERIC)
      return
    end if
    if (tol > newton_tol) return
    ! psi needs the Jacobian near the solution: renew one taken far from it (and restore the
    ! action at x, which the differences overwrite)
    if (.not. L%J_valid .or. maxval(abs(x - L%x_J)/sc) > 1e-4_wp) then
      A_x = L%A
      A0_x = L%A0
      call jacobian(x, R0, F0, error)
      if (allocated(error)) return
      L%A = A_x
      L%A0 = A0_x
    end if
    ! psi: the receptances' part at fixed x (no trace), from their exact derivatives
    call balance(r, x, R0, F0)
    call wave_balance_omega(tw%u, r, tw%H, gamma, L%A, Rw, dF)
    dx = -Rw
    call dgetrs('N', n, 1, L%LU, n, L%ipiv, dx, n, info)
    dF = dF + sum(L%Fx*dx)
    L%F = F0
    L%psi = 2*real(conjg(F0)*dF, wp)
    do h = 1, tw%H
      L%sigma(h) = -sum(r(h)%sp*L%A(:, h))
      L%uE(h) = -sum(r(h)%pE*L%A(:, h))
    end do
    L%sigma(1) = L%sigma(1) + r(1)%sE*L%F
    L%uE(1) = L%uE(1) + r(1)%EE*L%F
    L%solved = .true.

  contains

    !> The Jacobian of R (and dF/dx) at x, factorised into L%LU: one trace with the action's
    !> exact derivatives (wave_aft's forward mode); R and F are affine in x and the action, so
    !> a column is their change along x_k with the action's change along it.
    subroutine jacobian(xv, Rv, Fv, err)
      real(wp), intent(in) :: xv(:), Rv(:)
      complex(wp), intent(in) :: Fv
      type(error_type), allocatable, intent(out) :: err
      real(wp) :: xk(size(xv)), Rk(size(xv)), u(size(xv)), dP0(3, size(xv)), dA0(3, size(xv))
      real(wp) :: A0v(3), t
      complex(wp) :: dP(3, tw%H, size(xv)), dA(3, tw%H, size(xv)), Av(3, tw%H), Fk
      integer :: k, inf
      dP0 = 0
      dP = 0
      do k = 1, size(xv)
        u = 0
        u(k) = 1
        call platform_unpack(tw%u, u, dP0(3, k), dP(:, :, k))
      end do
      call unpack_x(xv)
      call wave_aft(tw%geo, tw%CF, tw%phi, L%P0, L%P, tw%settings, A0v, Av, err, &
        & dP0=dP0, dP=dP, dA0=dA0, dA=dA)
      tw%traces = tw%traces + 1
      if (allocated(err)) return
      do k = 1, size(xv)
        t = sc(k)
        xk = xv
        xk(k) = xv(k) + t
        L%A0 = A0v + t*dA0(:, k)
        L%A = Av + t*dA(:, :, k)
        call balance(r, xk, Rk, Fk)
        L%J(:, k) = (Rk - Rv)/t
        L%Fx(k) = (Fk - Fv)/t
      end do
      L%A0 = A0v
      L%A = Av
      call unpack_x(xv)
      L%x_J = xv
      L%LU = L%J
      call dgetrf(size(xv), size(xv), L%LU, size(xv), L%ipiv, inf)
      L%J_valid = inf == 0
      if (inf /= 0) call fatal_error(err, "traveling layer gamma = "//ftoa(gamma)// &
        & " rad: the Jacobian of the platform's harmonic balance is singular", UDMAP_ENUMERIC)
    end subroutine jacobian

    !> Residual of the condensed harmonic balance at x and the force F (leaves A of x in L).
    subroutine residual(xv, Rv, Fv, err)
      real(wp), intent(in) :: xv(:)
      real(wp), intent(out) :: Rv(:)
      complex(wp), intent(out) :: Fv
      type(error_type), allocatable, intent(out) :: err
      call unpack_x(xv)
      call wave_aft(tw%geo, tw%CF, tw%phi, L%P0, L%P, tw%settings, L%A0, L%A, err, L%trace)
      tw%traces = tw%traces + 1
      Rv = 0
      Fv = 0
      if (allocated(err)) then
        err%message = "traveling layer gamma = "//ftoa(gamma)//" rad at "// &
          & ftoa(omega/(2*pi))//" Hz, phi = "//ftoa(tw%phi)//" rad: "//err%message
        return
      end if
      call balance(r, xv, Rv, Fv)
    end subroutine residual

    !> The balance with the receptances rr and the damper action in L (at x); the force F
    !> from the gamma row at h = 1, which Gamma_1 = gamma fixes.
    subroutine balance(rr, xv, Rv, Fv)
      type(platform_receptances_type), intent(in) :: rr(:)
      real(wp), intent(in) :: xv(:)
      real(wp), intent(out) :: Rv(:)
      complex(wp), intent(out) :: Fv
      call unpack_x(xv)
      Fv = (gamma + sum(rr(1)%pp(3, :)*L%A(:, 1)))/rr(1)%pE(3)
      call platform_balance(tw%u, rr, tw%r0, L%P0(3), L%P, L%A0, L%A, tw%A_ref, Fv, Rv)
    end subroutine balance

    !> Gamma_0 and the harmonics of x into L, Gamma_1 = gamma.
    subroutine unpack_x(xv)
      real(wp), intent(in) :: xv(:)
      L%P0 = 0
      call platform_unpack(tw%u, xv, L%P0(3), L%P)
      L%P(3, 1) = cmplx(gamma, 0.0_wp, wp)
    end subroutine unpack_x


    pure real(wp) function wnorm(Rv)
      real(wp), intent(in) :: Rv(:)
      wnorm = norm2(Rv/sc)
    end function wnorm
  end subroutine wave_layer_solve

  !> d/domega at fixed platform harmonics of the balance (Rw) and of the force (Fw), the
  !> layer gamma with the damper's action A, from the receptances rr and their derivatives
  !> (harmonic h: h H'(h omega)).
  pure subroutine wave_balance_omega(u, rr, H, gamma, A, Rw, Fw)
    type(platform_unknowns_type), intent(in) :: u
    type(platform_receptances_type), intent(in) :: rr(:)
    integer, intent(in) :: H
    real(wp), intent(in) :: gamma
    complex(wp), intent(in) :: A(:, :)
    real(wp), intent(out) :: Rw(:)
    complex(wp), intent(out) :: Fw
    complex(wp) :: dR(3, H), Fv
    integer :: hh
    Fv = (gamma + sum(rr(1)%pp(3, :)*A(:, 1)))/rr(1)%pE(3)
    Fw = (sum(rr(1)%dpp(3, :)*A(:, 1)) - Fv*rr(1)%dpE(3))/rr(1)%pE(3)
    do hh = 1, H
      dR(:, hh) = hh*matmul(rr(hh)%dpp, A(:, hh))
    end do
    dR(:, 1) = dR(:, 1) - rr(1)%dpE*Fv - rr(1)%pE*Fw
    ! the active rows as the balance packs them (platform_pack); R_0 does not depend on omega
    call platform_pack(u, 0.0_wp, dR, Rw)
  end subroutine wave_balance_omega

  !> The peak of the layer gamma: the minimum of |F(omega)| over the band, the root of
  !> psi = d|F|^2/domega bracketed outward from omega_guess (0: the band's middle) and refined by
  !> Brent's method. F_bb = |F| there; L is left solved at the peak.
  subroutine wave_peak(tw, gamma, omega_guess, L, F_bb, error)
    type(traveling_type), intent(inout) :: tw
    real(wp), intent(in) :: gamma, omega_guess
    type(wave_layer_type), intent(inout) :: L
    real(wp), intent(out) :: F_bb
    type(error_type), allocatable, intent(out) :: error
    type(brent_type) :: bs
    type(outward_type) :: out
    real(wp) :: a, fa, d, x, fx
    logical :: more
    F_bb = 0
    a = omega_guess
    if (.not. (a > tw%omega_lo .and. a < tw%omega_hi)) a = 0.5_wp*(tw%omega_lo + tw%omega_hi)
    fa = psi(a)
    if (allocated(error)) return
    d = 1e-3_wp*a
    if (L%bracket > 0) d = min(d, L%bracket)
    call outward_start(out, a, fa, d, tw%omega_lo, tw%omega_hi)
    do
      call outward_next(out, x, more)
      if (.not. more) exit
      fx = psi(x)
      if (allocated(error)) return
      call outward_update(out, fx)
    end do
    if (out%left) then
      call fatal_error(error, "traveling wave: the layer gamma = "//ftoa(gamma)// &
        & " rad peaks at the band's edge (no resonance in [f_min, f_max] at phi = "// &
        & ftoa(tw%phi)//" rad)", UDMAP_EPHYSICS)
      return
    end if
    L%bracket = max(abs(out%b - out%a), 1e-6_wp*out%a)
    call brent_start(bs, out%a, out%fa, out%b, out%fb, peak_rtol*out%a)
    do
      call brent_next(bs, x, more)
      if (.not. more) exit
      fx = psi(x)
      if (allocated(error)) return
      call brent_update(bs, fx)
    end do
    if (L%omega /= x) then
      fx = psi(x)
      if (allocated(error)) return
    end if
    F_bb = abs(L%F)

  contains

    real(wp) function psi(w)
      real(wp), intent(in) :: w
      psi = 0
      call wave_layer_solve(tw, gamma, w, L, error)
      if (allocated(error)) return
      psi = L%psi
    end function psi
  end subroutine wave_peak

  !> d ln|F| / d ln gamma of the layer L solved at (gamma, omega), the platform's harmonics
  !> following gamma (dx/dgamma = -J^-1 dR/dgamma, the Jacobian of the solve): one more trace,
  !> with Gamma_1 moved by a relative 1e-7. At a layer's peak this is d ln F_bb / d ln gamma
  !> (psi = 0 there, so the peak's move in omega does not enter).
  subroutine wave_layer_slope(tw, L, slope, error)
    type(traveling_type), intent(inout) :: tw
    type(wave_layer_type), intent(inout) :: L
    real(wp), intent(out) :: slope
    type(error_type), allocatable, intent(out) :: error
    type(platform_receptances_type), allocatable :: r(:)
    real(wp), allocatable :: x(:), R0(:), Rp(:), dx(:)
    complex(wp), allocatable :: Pp(:, :), Ap(:, :)
    real(wp) :: A0p(3), dg, g
    complex(wp) :: F0, Fp, dF
    integer :: n, h, info
    slope = 1
    if (.not. (L%solved .and. L%J_valid)) then
      call fatal_error(error, "wave_layer_slope: the layer is not solved", UDMAP_ENUMERIC)
      return
    end if
    g = L%gamma
    n = platform_count(tw%u)
    allocate(r(tw%H), x(n), R0(n), Rp(n), dx(n), Ap(3, tw%H))
    do h = 1, tw%H
      call platform_receptances(tw%blade, h*L%omega, r(h), error, modal=tw%modal)
      if (allocated(error)) return
    end do
    call platform_pack(tw%u, L%P0(3), L%P, x)
    F0 = (g + sum(r(1)%pp(3, :)*L%A(:, 1)))/r(1)%pE(3)
    call platform_balance(tw%u, r, tw%r0, L%P0(3), L%P, L%A0, L%A, tw%A_ref, F0, R0)
    dg = 1e-7_wp*g
    Pp = L%P
    Pp(3, 1) = cmplx(g + dg, 0.0_wp, wp)
    call wave_aft(tw%geo, tw%CF, tw%phi, L%P0, Pp, tw%settings, A0p, Ap, error)
    tw%traces = tw%traces + 1
    if (allocated(error)) return
    Fp = (g + dg + sum(r(1)%pp(3, :)*Ap(:, 1)))/r(1)%pE(3)
    call platform_balance(tw%u, r, tw%r0, L%P0(3), Pp, A0p, Ap, tw%A_ref, Fp, Rp)
    dx = -(Rp - R0)/dg
    call dgetrs('N', n, 1, L%LU, n, L%ipiv, dx, n, info)
    dF = (Fp - F0)/dg + sum(L%Fx*dx)
    slope = g*real(conjg(F0)*dF, wp)/abs(F0)**2
  end subroutine wave_layer_slope
end module udmap_mapping_traveling_layer
