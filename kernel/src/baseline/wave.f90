!> The standard convergence-based method (PHYSICS.md 6) for a traveling wave (2.6): harmonic
!> balance of blade 0's platform at a given force F_E and frequency, Newton-Raphson on every
!> harmonic of p = (u_P, v_P, gamma_P) (gamma_P's first harmonic included), the damper's action
!> by the same AFT as the layers (udmap_contact_element_wave), Jacobian by finite differences,
!> continuation in frequency, and the peak as the maximum of |Gamma_1| over frequency (Brent's
!> minimiser on -|Gamma_1|, each value a converged balance). The same equations as the layers
!> of udmap_mapping_traveling_layer, reached the other way round: the force is given and the
!> amplitude found, so the two agree to their tolerances.
!>
!>   R_h = p_h + H_pp(h omega) A_h(p) - delta_h1 H_pE(omega) F_E   (h = 1 or 0..H)
module udmap_baseline_wave
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC, &
    & UDMAP_EPHYSICS
  use udmap_core_strings, only: ftoa
  use udmap_core_lapack, only: dgesv
  use udmap_blade_type, only: blade_type
  use udmap_blade_platform, only: platform_receptances_type, platform_receptances, &
    & platform_unknowns_type, platform_count, platform_scales, platform_pack, platform_unpack, &
    & platform_balance
  use udmap_damper_tracer_core, only: damper_geometry_type
  use udmap_contact_element_wave, only: wave_aft, wave_settings_type, wave_static_action, &
    & wave_samples
  use udmap_core_minimise, only: brent_min_type, brent_min_start, brent_min_next, &
    & brent_min_update, golden_section
  implicit none
  private
  public :: wave_hbm_type, wave_hbm_point_type, new_wave_hbm, wave_hbm_peak

  real(wp), parameter :: fd_step = 1.0e-7_wp, newton_tol = 1.0e-13_wp
  integer, parameter :: newton_max = 60

  type :: wave_hbm_type
    type(blade_type), pointer :: blade => null()
    type(damper_geometry_type) :: geo
    real(wp) :: CF = 0, phi = 0, A_ref(3) = 0
    integer :: H = 1
    !> The unknowns: every harmonic of the platform, Gamma_1 included.
    type(platform_unknowns_type) :: u
    type(wave_settings_type) :: settings
    type(platform_receptances_type) :: r0
    !> Statistics: Newton iterations and traces of the last peak.
    integer :: iterations = 0, traces = 0
  end type wave_hbm_type

  !> A converged balance: frequency, harmonics P(:,h) (h = 1..H), static Gamma_0, stress.
  type :: wave_hbm_point_type
    real(wp) :: omega = 0, P0 = 0
    complex(wp), allocatable :: P(:, :)
    complex(wp) :: sigma_1 = 0, u_E1 = 0
  end type wave_hbm_point_type

contains

  subroutine new_wave_hbm(s, blade, geo, CF, phi, H, error)
    type(wave_hbm_type), intent(out) :: s
    type(blade_type), target, intent(in) :: blade
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF, phi
    integer, intent(in) :: H
    type(error_type), allocatable, intent(out) :: error
    if (.not. allocated(blade%platform_uv)) then
      call fatal_error(error, "standard method at phi /= 0: the blade's platform translations "// &
        & "are unknown (blade.u_dof, blade.platform.tangent)", UDMAP_EINPUT)
      return
    end if
    if (H < 1 .or. H > 64) then
      call fatal_error(error, "standard method at phi /= 0: harmonics must lie in 1..64", &
        & UDMAP_EINPUT)
      return
    end if
    s%blade => blade
    s%geo = geo
    s%CF = CF
    s%phi = phi
    s%H = H
    s%settings%samples = wave_samples(H)
    s%u = platform_unknowns_type(H=H, v_free=any(blade%platform_uv(:, 2) /= 0), &
      & gamma1_fixed=.false., lever=max(maxval(abs(geo%cn)), maxval(abs(geo%ct)), tiny(1.0_wp)))
    call wave_static_action(geo, CF, s%A_ref, error)
    if (allocated(error)) return
    if (H > 1) call platform_receptances(blade, 0.0_wp, s%r0, error)
  end subroutine new_wave_hbm

  !> The peak for F_E [N]: continuation in omega from omega_start [rad/s] (above the peak)
  !> downwards until |Gamma_1| falls, then Brent's minimiser on -|Gamma_1| in the last three
  !> steps. Downwards: the friction damper softens the blade, its response curves lean to
  !> lower frequencies, and coming from above follows the upper branch to the peak.
  subroutine wave_hbm_peak(s, F_E, omega_start, omega_lo, pt, error)
    type(wave_hbm_type), intent(inout) :: s
    real(wp), intent(in) :: F_E, omega_start, omega_lo
    type(wave_hbm_point_type), intent(out) :: pt
    type(error_type), allocatable, intent(out) :: error
    type(wave_hbm_point_type) :: p_prev, p_cur
    real(wp) :: w, dw, g_prev2, g_prev, g_cur, w_prev2, w_prev
    integer :: k
    s%iterations = 0
    s%traces = 0
    allocate(p_cur%P(3, s%H))
    p_cur%P = 0
    p_cur%P0 = 0
    w = omega_start
    dw = -2e-4_wp*omega_start
    call solve(s, F_E, w, p_cur, error)
    if (allocated(error)) return
    g_prev2 = -1
    g_prev = -1
    w_prev2 = w
    w_prev = w
    g_cur = abs(p_cur%P(3, 1))
    do k = 1, 100000
      if (g_cur < g_prev .and. g_prev2 >= 0 .and. g_prev > g_prev2) exit
      g_prev2 = g_prev
      g_prev = g_cur
      w_prev2 = w_prev
      w_prev = w
      p_prev = p_cur
      w = w + dw
      if (w <= omega_lo) then
        call fatal_error(error, "standard method at phi /= 0: no peak above f_min for F_E = "// &
          & ftoa(F_E)//" N", UDMAP_EPHYSICS)
        return
      end if
      call solve(s, F_E, w, p_cur, error)
      if (allocated(error)) return
      g_cur = abs(p_cur%P(3, 1))
    end do
    ! the maximum lies in [w, w_prev2]
    call refine(w, w_prev2)
    if (allocated(error)) return
    pt = p_prev

  contains

    !> Brent's minimiser of -|Gamma_1(omega)| on [lo, hi]; p_prev ends as the solution there.
    subroutine refine(lo, hi)
      real(wp), intent(in) :: lo, hi
      type(brent_min_type) :: brent
      real(wp) :: x, fx, u, fu
      logical :: more
      x = lo + golden_section*(hi - lo)
      fx = f(x)
      if (allocated(error)) return
      call brent_min_start(brent, lo, hi, x, fx, 1e-12_wp, 200)
      do
        call brent_min_next(brent, u, more)
        if (.not. more) exit
        fu = f(u)
        if (allocated(error)) return
        call brent_min_update(brent, fu)
      end do
      fx = f(brent%x)
    end subroutine refine

    real(wp) function f(om)
      real(wp), intent(in) :: om
      f = 0
      call solve(s, F_E, om, p_prev, error)
      if (allocated(error)) return
      f = -abs(p_prev%P(3, 1))
    end function f
  end subroutine wave_hbm_peak

  !> The converged balance at (F_E, omega) by Newton from what q holds.
  subroutine solve(s, F_E, omega, q, error)
    type(wave_hbm_type), intent(inout) :: s
    real(wp), intent(in) :: F_E, omega
    type(wave_hbm_point_type), intent(inout) :: q
    type(error_type), allocatable, intent(out) :: error
    type(platform_receptances_type), allocatable :: r(:)
    real(wp), allocatable :: y(:), R0(:), Rt(:), J(:, :), dy(:), yt(:), sc(:)
    integer, allocatable :: ipiv(:)
    complex(wp), allocatable :: A(:, :)
    real(wp) :: A0(3), rn, rnt, t, gs
    integer :: n, h, it, k, info, ls
    logical :: done
    n = platform_count(s%u)
    allocate(r(s%H), y(n), R0(n), Rt(n), J(n, n), dy(n), yt(n), sc(n), ipiv(n), A(3, s%H))
    do h = 1, s%H
      call platform_receptances(s%blade, h*omega, r(h), error)
      if (allocated(error)) return
    end do
    if (all(q%P == 0)) then
      ! the linear start: the blade with the damper's action left out
      q%P(:, 1) = r(1)%pE*F_E
    end if
    q%omega = omega
    gs = max(abs(q%P(3, 1)), tiny(1.0_wp))
    call platform_pack(s%u, q%P0, q%P, y)
    call platform_scales(s%u, gs, sc)
    call residual(y, R0, error)
    if (allocated(error)) return
    rn = norm2(R0/sc)
    done = rn == 0
    do it = 1, newton_max
      if (done) exit
      do k = 1, n
        yt = y
        yt(k) = y(k) + fd_step*sc(k)
        call residual(yt, Rt, error)
        if (allocated(error)) return
        J(:, k) = (Rt - R0)/(fd_step*sc(k))
      end do
      dy = -R0
      call dgesv(n, 1, J, n, ipiv, dy, n, info)
      if (info /= 0) exit
      s%iterations = s%iterations + 1
      if (maxval(abs(dy)/sc) <= newton_tol) then
        y = y + dy
        done = .true.
        exit
      end if
      t = 1
      do ls = 1, 10
        yt = y + t*dy
        call residual(yt, Rt, error)
        if (allocated(error)) return
        rnt = norm2(Rt/sc)
        if (rnt < rn .or. rnt == 0) exit
        t = t/2
      end do
      y = yt
      R0 = Rt
      rn = rnt
      done = maxval(abs(t*dy)/sc) <= newton_tol .or. rn == 0
    end do
    if (.not. done) then
      call fatal_error(error, "standard method at phi /= 0: Newton did not converge at "// &
        & ftoa(omega/(2*pi))//" Hz, F_E = "//ftoa(F_E)//" N", UDMAP_ENUMERIC)
      return
    end if
    call residual(y, R0, error)
    if (allocated(error)) return
    q%sigma_1 = r(1)%sE*F_E - sum(r(1)%sp*A(:, 1))
    q%u_E1 = r(1)%EE*F_E - sum(r(1)%pE*A(:, 1))

  contains

    subroutine residual(yv, Rv, err)
      real(wp), intent(in) :: yv(:)
      real(wp), intent(out) :: Rv(:)
      type(error_type), allocatable, intent(out) :: err
      call platform_unpack(s%u, yv, q%P0, q%P)
      call wave_aft(s%geo, s%CF, s%phi, [0.0_wp, 0.0_wp, q%P0], q%P, s%settings, A0, A, err)
      s%traces = s%traces + 1
      Rv = 0
      if (allocated(err)) return
      call platform_balance(s%u, r, s%r0, q%P0, q%P, A0, A, s%A_ref, &
        & cmplx(F_E, 0.0_wp, wp), Rv)
    end subroutine residual
  end subroutine solve
end module udmap_baseline_wave
