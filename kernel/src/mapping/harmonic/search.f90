!> The searches on multi-harmonic layers (PHYSICS.md 4.1): the peak of one layer (the minimum of
!> |P(omega)|, the root of psi = d|P|^2/domega), the backbone root (the layer whose peak force is
!> F_E, with the jumps of F_bb over F_E where the damper's loop changes shape), the peak root on
!> a given layer and the force root at a given frequency. Each solves layers with
!> udmap_mapping_harmonic_layer and uses its derivatives (dGamma/domega, dGamma/dgamma).
module udmap_mapping_harmonic_search
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC, UDMAP_EPHYSICS
  use udmap_core_root_finding, only: brent_bracket, brent_step
  use udmap_blade_type, only: blade_type
  use udmap_mapping_harmonic_types, only: harmonic_workspace_type, harmonic_state_type
  use udmap_mapping_harmonic_layer, only: harmonic_solve
  implicit none
  private
  public :: harmonic_peak, harmonic_root, harmonic_force_root, harmonic_peak_root

contains

  !> The peak of the layer gamma: the minimum of |P(omega)| over [omega_lo, omega_hi], the root
  !> of psi, by secant steps from s%omega (or omega_start when s holds no frequency) until a
  !> sign change brackets it, then Brent's method. s holds the layer at the peak on return.
  !> The peak frequency is located to rtol.
  subroutine harmonic_peak(ws, blade, gamma, omega_lo, omega_hi, rtol, s, error, omega_start)
    type(harmonic_workspace_type), intent(inout) :: ws
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: gamma, omega_lo, omega_hi, rtol
    type(harmonic_state_type), intent(inout) :: s
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: omega_start
    real(wp) :: w0, w1, p0, p1, wn, a, b, fa, fb, c, fc, d, e, tol, m
    integer :: it
    logical :: bracketed
    character(len=160) :: buf
    w0 = s%omega
    if (present(omega_start)) w0 = omega_start
    if (.not.(w0 > omega_lo .and. w0 < omega_hi)) w0 = 0.5_wp*(omega_lo + omega_hi)
    call harmonic_solve(ws, blade, gamma, w0, s, error)
    if (allocated(error)) return
    p0 = s%psi
    if (p0 == 0) return
    ! first step: 1e-3 of omega against the slope of psi
    w1 = w0*(1 - sign(1.0e-3_wp, p0))
    bracketed = .false.
    do it = 1, 40
      w1 = min(max(w1, omega_lo), omega_hi)
      call harmonic_solve(ws, blade, gamma, w1, s, error)
      if (allocated(error)) return
      p1 = s%psi
      if (p1 == 0) return
      if ((p1 > 0) .neqv. (p0 > 0)) then
        bracketed = .true.
        exit
      end if
      if (abs(w1 - w0) <= rtol*w1) exit
      if ((w1 == omega_lo .and. p1 > 0) .or. (w1 == omega_hi .and. p1 < 0)) then
        write(buf, '(a, es12.5, a)') "harmonic layer gamma = ", gamma, &
          & " rad: |P| still falls at the band edge, no resonance in [f_min, f_max]"
        call fatal_error(error, trim(buf), UDMAP_EPHYSICS)
        return
      end if
      ! secant, at most 10 % of omega per step, always downhill
      wn = w1 - p1*(w1 - w0)/(p1 - p0)
      if (.not.(abs(wn - w1) <= 0.1_wp*w1) .or. ((wn - w1) > 0 .eqv. p1 > 0)) &
        & wn = w1 - sign(min(0.1_wp*w1, 4*abs(w1 - w0)), p1)
      w0 = w1
      p0 = p1
      w1 = wn
    end do
    if (.not.bracketed) then
      if (abs(w1 - w0) <= rtol*w1) return
      write(buf, '(a, es12.5, a)') "harmonic layer gamma = ", gamma, &
        & " rad: the peak search did not converge"
      call fatal_error(error, trim(buf), UDMAP_ENUMERIC)
      return
    end if
    ! Brent on psi in [w0, w1] (s holds w1), with a relative tolerance and its own sign test
    a = w0; fa = p0; b = w1; fb = p1
    c = a; fc = fa; d = b - a; e = d
    do it = 1, 100
      call brent_bracket((fb > 0) .eqv. (fc > 0), a, b, c, fa, fb, fc, d, e)
      tol = 0.5_wp*rtol*abs(b)
      m = 0.5_wp*(c - b)
      if (abs(m) <= tol .or. fb == 0) exit
      call brent_step(a, b, c, fa, fb, fc, d, e, tol, m)
      call harmonic_solve(ws, blade, gamma, b, s, error)
      if (allocated(error)) return
      fb = s%psi
    end do
    if (s%omega /= b) call harmonic_solve(ws, blade, gamma, b, s, error)
  end subroutine harmonic_peak

  !> The backbone root: the layer gamma whose peak force min_omega |P| equals F_E, by secant
  !> steps on ln(F_bb/F_E) against ln gamma from gamma_start (a single-harmonic root) with
  !> the slope d ln F_bb/d ln gamma = slope0 as the first guess, and bisection once the root is
  !> bracketed and the secant stalls. s holds the root's peak. Where F_bb jumps over F_E (a
  !> damper whose loop changes shape abruptly with lift-off, PHYSICS.md 2.5) the bisection
  !> closes on the jump gamma_c: jump is then set, s holds the layer just above it and below
  !> the layer just below.
  subroutine harmonic_root(ws, blade, F_E, gamma_start, slope0, omega_lo, omega_hi, rtol, s, &
      & error, jump, below)
    type(harmonic_workspace_type), intent(inout) :: ws
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: F_E, gamma_start, slope0, omega_lo, omega_hi, rtol
    type(harmonic_state_type), intent(inout) :: s
    type(error_type), allocatable, intent(out) :: error
    logical, intent(out), optional :: jump
    type(harmonic_state_type), intent(out), optional :: below
    type(harmonic_state_type) :: s_neg, s_pos
    real(wp) :: u0, u1, f0, f1, slope, u_neg, u_pos, f_neg, f_pos
    logical :: have_neg, have_pos, converged, moved
    integer :: it
    character(len=160) :: buf
    if (present(jump)) jump = .false.
    u1 = log(gamma_start)
    slope = slope0
    if (.not.(abs(slope) > 0.05_wp .and. abs(slope) < 20)) slope = 1
    have_neg = .false.
    have_pos = .false.
    do it = 1, 20
      call harmonic_peak(ws, blade, exp(u1), omega_lo, omega_hi, rtol, s, error)
      if (allocated(error)) return
      f1 = log(abs(s%P)/F_E)
      call keep_bracket(u1, f1)
      call secant_step(it, rtol, u0, f0, u1, f1, slope, converged, moved)
      if (converged) then
        ! one more exactly at the root
        if (moved) call harmonic_peak(ws, blade, exp(u1), omega_lo, omega_hi, rtol, s, error)
        return
      end if
    end do
    if (.not.(have_neg .and. have_pos)) then
      write(buf, '(a, i0, a, es12.5, a)') "harmonic backbone (H = ", s%H, "): no root found "// &
        & "for F_E = ", F_E, " N"
      call fatal_error(error, trim(buf), UDMAP_ENUMERIC)
      return
    end if
    ! bisection in ln gamma
    do it = 1, 200
      if (abs(u_pos - u_neg) <= rtol) exit
      u1 = 0.5_wp*(u_neg + u_pos)
      s = s_neg
      call harmonic_peak(ws, blade, exp(u1), omega_lo, omega_hi, rtol, s, error)
      if (allocated(error)) return
      f1 = log(abs(s%P)/F_E)
      if (f1 == 0) return
      call keep_bracket(u1, f1)
    end do
    if (min(-f_neg, f_pos) <= 1.0e-8_wp) then
      ! a root where F_bb is continuous: the closer side
      if (-f_neg < f_pos) then
        s = s_neg
      else
        s = s_pos
      end if
      return
    end if
    ! F_bb jumps over F_E at gamma_c
    if (present(jump)) jump = .true.
    if (present(below)) then
      if (u_neg < u_pos) then
        below = s_neg
      else
        below = s_pos
      end if
    end if
    if (u_neg < u_pos) then
      s = s_pos
    else
      s = s_neg
    end if
  contains
    subroutine keep_bracket(u, f)
      real(wp), intent(in) :: u, f
      if (f < 0) then
        have_neg = .true.
        u_neg = u
        f_neg = f
        s_neg = s
      else
        have_pos = .true.
        u_pos = u
        f_pos = f
        s_pos = s
      end if
    end subroutine keep_bracket
  end subroutine harmonic_root

  !> The backbone root and its peak at once: Newton on (ln gamma, ln omega) for
  !> ln(|P|/F_E) = 0 and d ln|P|/d ln omega = 0 (= omega psi/(2 |P|^2)), from gamma_start,
  !> omega_start, with the root Jacobian each layer solve returns (s%Jroot). Each iteration
  !> is one layer solve; the answer is the same root as harmonic_root (which nests a peak
  !> search in a secant on gamma), found with a fraction of the layer solves. ok = .false.
  !> when it does not converge in 30 iterations (then use harmonic_root).
  subroutine harmonic_peak_root(ws, blade, F_E, gamma_start, omega_start, omega_lo, omega_hi, &
      & rtol, s, ok, error)
    type(harmonic_workspace_type), intent(inout) :: ws
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: F_E, gamma_start, omega_start, omega_lo, omega_hi, rtol
    type(harmonic_state_type), intent(inout) :: s
    logical, intent(out) :: ok
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: z(2), f(2), zt(2), ft(2), J(2, 2), dz(2), det, h
    integer :: it
    ok = .false.
    z = [log(gamma_start), log(omega_start)]
    call eval(z, f, error)
    if (allocated(error)) return
    do it = 1, 30
      ! Newton with the root Jacobian of the layer just solved
      J = s%Jroot
      det = J(1,1)*J(2,2) - J(1,2)*J(2,1)
      if (.not.(abs(det) > 0)) return
      dz(1) = -( J(2,2)*f(1) - J(1,2)*f(2))/det
      dz(2) = -(-J(2,1)*f(1) + J(1,1)*f(2))/det
      ! converged when the next step would be below rtol: s holds the root's layer
      if (maxval(abs(dz)) <= rtol) then
        ok = .true.
        return
      end if
      ! steps at most 30 % in gamma and 2 % in omega, inside the band
      h = min(1.0_wp, 0.3_wp/max(abs(dz(1)), tiny(1.0_wp)), 0.02_wp/max(abs(dz(2)), tiny(1.0_wp)))
      dz = h*dz
      zt = z + dz
      if (exp(zt(2)) <= omega_lo .or. exp(zt(2)) >= omega_hi) return
      call eval(zt, ft, error)
      if (allocated(error)) return
      z = zt
      f = ft
    end do
  contains
    subroutine eval(zv, fv, err)
      real(wp), intent(in) :: zv(2)
      real(wp), intent(out) :: fv(2)
      type(error_type), allocatable, intent(out) :: err
      call harmonic_solve(ws, blade, exp(zv(1)), exp(zv(2)), s, err)
      if (allocated(err)) return
      fv(1) = log(abs(s%P)/F_E)
      fv(2) = s%omega*s%psi/(2*abs(s%P)**2)
    end subroutine eval
  end subroutine harmonic_peak_root

  !> The response at a given omega: the layer gamma with |P(omega)| = F_E, by secant steps on
  !> ln(|P|/F_E) against ln gamma from gamma_start. s holds the layer on return.
  subroutine harmonic_force_root(ws, blade, F_E, gamma_start, omega, rtol, s, error)
    type(harmonic_workspace_type), intent(inout) :: ws
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: F_E, gamma_start, omega, rtol
    type(harmonic_state_type), intent(inout) :: s
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: u0, u1, f0, f1, slope
    logical :: converged, moved
    integer :: it
    character(len=160) :: buf
    u1 = log(gamma_start)
    slope = 1
    do it = 1, 60
      call harmonic_solve(ws, blade, exp(u1), omega, s, error)
      if (allocated(error)) return
      f1 = log(abs(s%P)/F_E)
      call secant_step(it, rtol, u0, f0, u1, f1, slope, converged, moved, min_slope=1.0e-3_wp)
      if (converged) then
        if (moved) call harmonic_solve(ws, blade, exp(u1), omega, s, error)
        return
      end if
    end do
    write(buf, '(a, i0, a, es12.5, a, g0.8, a)') "harmonic response (H = ", s%H, &
      & "): no amplitude found for F_E = ", F_E, " N at ", omega/(2*pi), " Hz"
    call fatal_error(error, trim(buf), UDMAP_ENUMERIC)
  end subroutine harmonic_force_root

  !> One secant step on f(u) = 0 in the searches above: f1 at u1 and, from the second step
  !> on (it > 1), f0 at u0 the point before. The slope is updated where the two points differ
  !> (kept at least min_slope in magnitude when given) and the step -f1/slope clamped to 0.5.
  !> converged: the step was below rtol or f1 is zero; u1 then moves by the step (moved: it was
  !> not zero, one more evaluation is due there). Otherwise u1 moves by it and (u0, f0) take
  !> the old point.
  pure subroutine secant_step(it, rtol, u0, f0, u1, f1, slope, converged, moved, min_slope)
    integer, intent(in) :: it
    real(wp), intent(in) :: rtol, f1
    real(wp), intent(inout) :: u0, f0, u1, slope
    logical, intent(out) :: converged, moved
    real(wp), intent(in), optional :: min_slope
    real(wp) :: du
    if (it > 1) then
      if (u1 /= u0 .and. f1 /= f0) slope = (f1 - f0)/(u1 - u0)
    end if
    if (present(min_slope)) then
      if (.not.(abs(slope) > min_slope)) slope = sign(min_slope, slope)
    end if
    du = -f1/slope
    du = max(-0.5_wp, min(0.5_wp, du))
    converged = abs(du) <= rtol .or. f1 == 0
    moved = abs(du) > 0
    if (converged) then
      if (moved) u1 = u1 + du
      return
    end if
    u0 = u1
    f0 = f1
    u1 = u1 + du
  end subroutine secant_step
end module udmap_mapping_harmonic_search
