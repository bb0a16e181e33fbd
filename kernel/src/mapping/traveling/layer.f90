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
  use udmap_core_lapack, only: dgesv
  use udmap_blade_type, only: blade_type
  use udmap_blade_platform, only: platform_receptances_type, platform_receptances
  use udmap_damper_tracer_core, only: damper_geometry_type
  use udmap_contact_element_wave, only: wave_aft, wave_settings_type, wave_result_type, &
    & wave_static_action
  implicit none
  private
  public :: traveling_type, wave_layer_type, new_traveling, wave_layer_solve, wave_peak

  !> Relative finite-difference step, Newton tolerance (to the layer's scale) and cap.
  real(wp), parameter :: fd_step = 1.0e-7_wp, newton_tol = 1.0e-11_wp
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
    !> The radial translation is a DOF of the blade (else held).
    logical :: v_free = .false.
    !> Length that scales translations to rotations (largest lever arm of a contact) [m].
    real(wp) :: lever = 1
    !> Static action of the loaded damper on blade 0 (the blade's reference state).
    real(wp) :: A_ref(3) = 0
    !> Static platform receptances (for Gamma_0).
    type(platform_receptances_type) :: r0
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
    tw%settings%samples = max(128, 8*H)
    if (.not. allocated(blade%platform_uv)) then
      call fatal_error(error, "traveling wave (phi /= 0): the blade's platform translations "// &
        & "are unknown: give blade.u_dof (matrices) or blade.platform.tangent (fe)", UDMAP_EINPUT)
      return
    end if
    tw%v_free = any(blade%platform_uv(:, 2) /= 0)
    tw%lever = max(maxval(abs(geo%cn)), maxval(abs(geo%ct)), tiny(1.0_wp))
    call wave_static_action(geo, CF, tw%A_ref, error)
    if (allocated(error)) return
    if (H > 1) call platform_receptances(blade, 0.0_wp, tw%r0, error)
  end subroutine new_traveling

  !> Number of real unknowns of a layer.
  pure integer function n_unknowns(tw)
    type(traveling_type), intent(in) :: tw
    integer :: nt
    nt = merge(2, 1, tw%v_free)
    if (tw%H == 1) then
      n_unknowns = 2*nt
    else
      n_unknowns = 1 + 2*nt + (tw%H - 1)*2*(nt + 1)
    end if
  end function n_unknowns

  !> Solves the layer (gamma, omega), starting from what L holds (a neighbouring solution;
  !> zeros for a cold start). Sets L%F, the harmonics and the stress.
  subroutine wave_layer_solve(tw, gamma, omega, L, error)
    type(traveling_type), intent(inout) :: tw
    real(wp), intent(in) :: gamma, omega
    type(wave_layer_type), intent(inout) :: L
    type(error_type), allocatable, intent(out) :: error
    type(platform_receptances_type), allocatable :: r(:)
    real(wp), allocatable :: x(:), R0(:), Rt(:), J(:, :), dx(:), xt(:), sc(:)
    integer, allocatable :: ipiv(:)
    integer :: n, it, k, h, info, ls, attempt
    real(wp) :: rn, rnt, t
    logical :: done

    if (.not. (gamma > 0 .and. gamma < huge(1.0_wp)) .or. .not. (omega > 0)) then
      call fatal_error(error, "traveling layer: gamma and omega must be positive", UDMAP_EINPUT)
      return
    end if
    n = n_unknowns(tw)
    if (.not. allocated(L%P)) then
      allocate(L%P(3, tw%H), L%A(3, tw%H), L%sigma(tw%H), L%uE(tw%H))
      L%P = 0
    end if
    if (L%gamma > 0 .and. L%gamma /= gamma) then
      L%P = L%P*(gamma/L%gamma)
      L%P0 = L%P0*(gamma/L%gamma)
    end if
    L%gamma = gamma
    L%omega = omega
    allocate(r(tw%H))
    do h = 1, tw%H
      call platform_receptances(tw%blade, h*omega, r(h), error)
      if (allocated(error)) return
    end do
    allocate(x(n), R0(n), Rt(n), J(n, n), dx(n), xt(n), sc(n), ipiv(n))
    call scales(sc)
    do attempt = 1, 2
      if (attempt == 2) then
        ! a warm start that led Newton astray: the cold start decides
        L%P = 0
        L%P0 = 0
      end if
      call pack(x)
      call residual(x, R0, error)
      if (allocated(error)) return
      rn = wnorm(R0)
      done = .false.
      do it = 1, newton_max
        do k = 1, n
          xt = x
          xt(k) = x(k) + fd_step*sc(k)
          call residual(xt, Rt, error)
          if (allocated(error)) return
          J(:, k) = (Rt - R0)/(fd_step*sc(k))
        end do
        dx = -R0
        call dgesv(n, 1, J, n, ipiv, dx, n, info)
        if (info /= 0) exit
        t = 1
        do ls = 1, 8
          xt = x + t*dx
          call residual(xt, Rt, error)
          if (allocated(error)) return
          rnt = wnorm(Rt)
          if (rnt < rn .or. rnt == 0) exit
          t = t/2
        end do
        x = xt
        R0 = Rt
        rn = rnt
        if (maxval(abs(t*dx)/sc) <= newton_tol .or. rn == 0) then
          done = .true.
          exit
        end if
      end do
      if (done) exit
    end do
    if (.not. done) then
      call fatal_error(error, "traveling layer gamma = "//ftoa(gamma)//" rad at "// &
        & ftoa(omega/(2*pi))//" Hz, phi = "//ftoa(tw%phi)//" rad: the harmonic balance of "// &
        & "the platform did not converge", UDMAP_ENUMERIC)
      return
    end if
    ! the last residual call left A and F at x; the stress and u_E per harmonic
    call residual(x, R0, error)
    if (allocated(error)) return
    do h = 1, tw%H
      L%sigma(h) = -sum(r(h)%sp*L%A(:, h))
      L%uE(h) = -sum(r(h)%pE*L%A(:, h))
    end do
    L%sigma(1) = L%sigma(1) + r(1)%sE*L%F
    L%uE(1) = L%uE(1) + r(1)%EE*L%F
    L%solved = .true.

  contains

    !> Unknown scales: translations by gamma times the lever arm, rotations by gamma.
    subroutine scales(s)
      real(wp), intent(out) :: s(:)
      integer :: i, hh, c
      i = 0
      do hh = merge(1, 0, tw%H == 1), tw%H
        do c = 1, 3
          if (.not. active(hh, c)) cycle
          i = i + 1
          s(i) = gamma*merge(tw%lever, 1.0_wp, c < 3)
          if (hh > 0) then
            i = i + 1
            s(i) = s(i-1)
          end if
        end do
      end do
    end subroutine scales

    pure logical function active(hh, c)
      integer, intent(in) :: hh, c
      if (hh == 0) then
        active = c == 3
      else if (c == 2) then
        active = tw%v_free
      else
        active = .not. (hh == 1 .and. c == 3)
      end if
    end function active

    subroutine pack(xv)
      real(wp), intent(out) :: xv(:)
      integer :: i, hh, c
      i = 0
      do hh = merge(1, 0, tw%H == 1), tw%H
        do c = 1, 3
          if (.not. active(hh, c)) cycle
          i = i + 1
          if (hh == 0) then
            xv(i) = L%P0(3)
          else
            xv(i) = real(L%P(c, hh), wp)
            i = i + 1
            xv(i) = aimag(L%P(c, hh))
          end if
        end do
      end do
    end subroutine pack

    subroutine unpack(xv)
      real(wp), intent(in) :: xv(:)
      integer :: i, hh, c
      i = 0
      L%P0 = 0
      do hh = merge(1, 0, tw%H == 1), tw%H
        do c = 1, 3
          if (.not. active(hh, c)) then
            if (hh > 0) L%P(c, hh) = 0
            cycle
          end if
          i = i + 1
          if (hh == 0) then
            L%P0(3) = xv(i)
          else
            L%P(c, hh) = cmplx(xv(i), xv(i+1), wp)
            i = i + 1
          end if
        end do
      end do
      L%P(3, 1) = cmplx(gamma, 0.0_wp, wp)
    end subroutine unpack

    !> Residual of the condensed harmonic balance at x (leaves A, F of x in L).
    subroutine residual(xv, Rv, err)
      real(wp), intent(in) :: xv(:)
      real(wp), intent(out) :: Rv(:)
      type(error_type), allocatable, intent(out) :: err
      complex(wp) :: z, HA(3)
      real(wp) :: HA0(3)
      integer :: i, hh, c
      call unpack(xv)
      call wave_aft(tw%geo, tw%CF, tw%phi, L%P0, L%P, tw%settings, L%A0, L%A, err, L%trace)
      tw%traces = tw%traces + 1
      if (allocated(err)) return
      HA = matmul(r(1)%pp, L%A(:, 1))
      L%F = (gamma + HA(3))/r(1)%pE(3)
      i = 0
      do hh = merge(1, 0, tw%H == 1), tw%H
        if (hh > 0) HA = matmul(r(hh)%pp, L%A(:, hh))
        if (hh == 0) HA0 = real(matmul(tw%r0%pp, cmplx(L%A0 - tw%A_ref, 0.0_wp, wp)), wp)
        do c = 1, 3
          if (.not. active(hh, c)) cycle
          i = i + 1
          if (hh == 0) then
            Rv(i) = L%P0(3) + HA0(3)
          else
            z = L%P(c, hh) + HA(c)
            if (hh == 1) z = z - r(1)%pE(c)*L%F
            Rv(i) = real(z, wp)
            i = i + 1
            Rv(i) = aimag(z)
          end if
        end do
      end do
    end subroutine residual

    pure real(wp) function wnorm(Rv)
      real(wp), intent(in) :: Rv(:)
      wnorm = norm2(Rv/sc)
    end function wnorm
  end subroutine wave_layer_solve

  !> The peak of the layer gamma: the minimum of |P(omega)| over the band (Brent's minimiser
  !> on a bracket found from omega_guess, 0: the whole band). F_bb = |P| there.
  subroutine wave_peak(tw, gamma, omega_guess, L, F_bb, error)
    type(traveling_type), intent(inout) :: tw
    real(wp), intent(in) :: gamma, omega_guess
    type(wave_layer_type), intent(inout) :: L
    real(wp), intent(out) :: F_bb
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: a, b, c, fa, fb, fc, d
    integer :: k
    F_bb = 0
    if (omega_guess > tw%omega_lo .and. omega_guess < tw%omega_hi) then
      ! bracket a < b < c with f(b) below both, widening from the guess
      b = omega_guess
      fb = f(b)
      if (allocated(error)) return
      d = 2e-3_wp*b
      do k = 1, 60
        a = max(b - d, tw%omega_lo)
        c = min(b + d, tw%omega_hi)
        fa = f(a)
        if (allocated(error)) return
        fc = f(c)
        if (allocated(error)) return
        if (fa > fb .and. fc > fb) exit
        if (fa < fb .and. a > tw%omega_lo) then
          c = b
          b = a
          fb = fa
        else if (fc < fb .and. c < tw%omega_hi) then
          a = b
          b = c
          fb = fc
        end if
        if ((a <= tw%omega_lo .and. fa <= fb) .or. (c >= tw%omega_hi .and. fc <= fb)) exit
        d = 2*d
      end do
      a = max(b - d, tw%omega_lo)
      c = min(b + d, tw%omega_hi)
    else
      a = tw%omega_lo
      c = tw%omega_hi
    end if
    call brent_min(a, c, b, F_bb)
    if (allocated(error)) return
    if (b <= tw%omega_lo*(1 + 1e-6_wp) .or. b >= tw%omega_hi*(1 - 1e-6_wp)) then
      call fatal_error(error, "traveling wave: the layer gamma = "//ftoa(gamma)// &
        & " rad peaks at the band's edge (no resonance in [f_min, f_max] at phi = "// &
        & ftoa(tw%phi)//" rad)", UDMAP_EPHYSICS)
      return
    end if
    ! leave L solved at the peak
    fb = f(b)
    F_bb = sqrt(fb)

  contains

    real(wp) function f(w)
      real(wp), intent(in) :: w
      f = huge(1.0_wp)
      call wave_layer_solve(tw, gamma, w, L, error)
      if (allocated(error)) return
      f = abs(L%F)**2
    end function f

    !> Brent's minimiser (golden section with parabolic steps) of f on [lo, hi]: xmin, sqrt(f).
    subroutine brent_min(lo, hi, xmin, fmin)
      real(wp), intent(in) :: lo, hi
      real(wp), intent(out) :: xmin, fmin
      real(wp), parameter :: cg = 0.3819660112501051_wp
      real(wp) :: aa, bb, v, w, x, fv, fw, fx, e, dd, u, fu, xm, tol1, tol2, p, q, rr
      integer :: iter
      aa = lo
      bb = hi
      x = aa + cg*(bb - aa)
      if (b > aa .and. b < bb) x = b
      w = x
      v = x
      fx = f(x)
      if (allocated(error)) return
      fv = fx
      fw = fx
      e = 0
      dd = 0
      do iter = 1, 200
        xm = 0.5_wp*(aa + bb)
        tol1 = peak_rtol*abs(x) + 1e-300_wp
        tol2 = 2*tol1
        if (abs(x - xm) <= tol2 - 0.5_wp*(bb - aa)) exit
        if (abs(e) > tol1) then
          rr = (x - w)*(fx - fv)
          q = (x - v)*(fx - fw)
          p = (x - v)*q - (x - w)*rr
          q = 2*(q - rr)
          if (q > 0) p = -p
          q = abs(q)
          if (abs(p) >= abs(0.5_wp*q*e) .or. p <= q*(aa - x) .or. p >= q*(bb - x)) then
            e = merge(aa - x, bb - x, x >= xm)
            dd = cg*e
          else
            e = dd
            dd = p/q
            u = x + dd
            if (u - aa < tol2 .or. bb - u < tol2) dd = sign(tol1, xm - x)
          end if
        else
          e = merge(aa - x, bb - x, x >= xm)
          dd = cg*e
        end if
        u = x + merge(dd, sign(tol1, dd), abs(dd) >= tol1)
        fu = f(u)
        if (allocated(error)) return
        if (fu <= fx) then
          if (u >= x) then
            aa = x
          else
            bb = x
          end if
          v = w
          fv = fw
          w = x
          fw = fx
          x = u
          fx = fu
        else
          if (u < x) then
            aa = u
          else
            bb = u
          end if
          if (fu <= fw .or. w == x) then
            v = w
            fv = fw
            w = u
            fw = fu
          else if (fu <= fv .or. v == x .or. v == w) then
            v = u
            fv = fu
          end if
        end if
      end do
      xmin = x
      fmin = sqrt(fx)
    end subroutine brent_min
  end subroutine wave_peak
end module udmap_mapping_traveling_layer
