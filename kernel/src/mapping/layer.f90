!> One amplitude layer of the force mapping (PHYSICS.md 3): with the damper a complex spring k
!> on the gamma DOF, the blade's response to a unit force at E is, by Sherman-Morrison,
!> g~(omega) = H_gE/(1 + k H_gg); the force that puts the blade on layer gamma* at omega is
!> F(omega) = gamma*/|g~(omega)|.
!>
!> This module holds what is done on one layer: the peak of |g~| over the band (the backbone
!> point of the layer, PHYSICS.md 4) and the frequencies where |g~| equals a level (the
!> crossings of a response curve with the layer).
!>
!> Peak search. |g~| is maximal where P = 1/|g~|^2 is minimal. For one mode with hysteretic
!> or viscous damping P is a quadratic polynomial in s = omega^2, so psi = dP/ds is linear in
!> s; with several modes it is nearly so. The peak is therefore found as the root of psi(s),
!> psi = -(d ln|g~|/d omega)/(omega |g~|^2), by secant steps from the start until a sign change
!> brackets it and Brent's method after that: from an eigenvalue start this takes 3 to 5
!> receptance evaluations to rtol = 1e-12.
module udmap_mapping_layer
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC, UDMAP_EPHYSICS
  use udmap_blade_type, only: blade_type, receptances_type
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update
  use udmap_mapping_caches, only: band_receptances_type, PEAK_OK, PEAK_BELOW_BAND, &
    & PEAK_ABOVE_BAND, bare_type, layer_peak_type
  use udmap_mapping_band_receptances, only: band_eval
  implicit none
  private
  public :: bare_receptances, log_slope, layer_peak, layer_crossing, layer_amplitude, abs2

contains

  !> Bare receptances at omega [rad/s] (with d/d omega when derivatives), counted.
  subroutine bare_receptances(bare, omega, r, error, derivatives)
    type(bare_type), intent(inout) :: bare
    real(wp), intent(in) :: omega
    type(receptances_type), intent(out) :: r
    type(error_type), allocatable, intent(out) :: error
    logical, intent(in) :: derivatives
    bare%evaluations = bare%evaluations + 1
    if (bare%band%active .and. omega >= bare%band%omega_lo .and. omega <= bare%band%omega_hi) then
      call band_eval(bare%band, omega, derivatives, r)
      ! exactly on an undamped natural frequency the receptances are unbounded
      if (.not.(abs(r%gE) <= huge(1.0_wp) .and. abs(r%gg) <= huge(1.0_wp) .and. &
          & abs(r%dgE) <= huge(1.0_wp) .and. abs(r%dgg) <= huge(1.0_wp))) then
        call fatal_error(error, "the receptances are unbounded at an undamped natural "// &
          & "frequency", UDMAP_EPHYSICS)
      end if
    else
      call bare%blade%receptances(omega, r, error, derivatives=derivatives)
    end if
  end subroutine bare_receptances

  !> |z|^2 without the overflow guard of abs (hypot): the values here are far from overflow.
  elemental real(wp) function abs2(z)
    complex(wp), intent(in) :: z
    abs2 = real(z, wp)**2 + aimag(z)**2
  end function abs2

  !> |g~| of the layer with stiffness k, from the bare receptances.
  pure real(wp) function layer_amplitude(r, k) result(amp)
    type(receptances_type), intent(in) :: r
    complex(wp), intent(in) :: k
    amp = sqrt(abs2(r%gE)/abs2(1 + k*r%gg))
  end function layer_amplitude

  !> d ln|g~| / d omega of the layer with stiffness k (needs the receptance derivatives).
  pure real(wp) function log_slope(r, k) result(slope)
    type(receptances_type), intent(in) :: r
    complex(wp), intent(in) :: k
    complex(wp) :: den
    den = 1 + k*r%gg
    slope = real(r%dgE*conjg(r%gE), wp)/abs2(r%gE) - real(k*r%dgg*conjg(den), wp)/abs2(den)
  end function log_slope

  !> psi = dP/ds with P = 1/|g~|^2 and s = omega^2: the function whose root is the peak.
  pure real(wp) function peak_function(r, k, omega) result(psi)
    type(receptances_type), intent(in) :: r
    complex(wp), intent(in) :: k
    real(wp), intent(in) :: omega
    psi = -log_slope(r, k)/(omega*layer_amplitude(r, k)**2)
  end function peak_function

  !> Maximum of |g~(omega)| for the layer stiffness k over [omega_lo, omega_hi] [rad/s],
  !> started at omega0; width estimates the half-power half-width of the peak in s = omega^2
  !> (e.g. |Im lambda| of the eigenvalue start; any positive value works, a good one saves
  !> evaluations). dpsi, when given, is the slope d psi/ds expected at the peak (that of a
  !> neighbouring layer): the first step is then a Newton step with it.
  !>
  !> Termination: after each evaluation the secant estimate s* of the root of psi is formed
  !> from the last two points; its error is about |s* - s1| |s* - s0| |psi''/(2 psi')|, and
  !> |psi''/psi'| <= 1/width for a resonance, so s* is accepted when that bound (or the step
  !> itself) is below the tolerance. The estimate is not evaluated: the receptances are carried
  !> there to first order with their derivatives (error O(step^2)), and the amplitude follows
  !> from the quadratic model of P, so the returned frequency is accurate well beyond rtol at
  !> no extra cost. With `predict`, a single evaluation suffices when the Newton step with the
  !> given slope is small enough that its error (taken as 5 % of the step) is below the
  !> tolerance (used for the grid nodes, which only bracket roots). A maximum at a band edge is
  !> reported in peak%status, not as an error.
  subroutine layer_peak(bare, k, omega0, width, omega_lo, omega_hi, rtol, peak, error, dpsi, &
      & predict)
    type(bare_type), intent(inout) :: bare
    complex(wp), intent(in) :: k
    real(wp), intent(in) :: omega0, width, omega_lo, omega_hi, rtol
    type(layer_peak_type), intent(out) :: peak
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: dpsi
    logical, intent(in), optional :: predict
    integer, parameter :: max_secant = 40, ncache = 4
    type(receptances_type) :: r, rc(ncache)
    real(wp) :: xc(ncache), s_lo, s_hi, s0, s1, p0, p1, step, d, q, amp, tol, x, w, est, slope
    type(brent_type) :: brent
    logical :: more, may_predict, done
    integer :: it, nc, i

    s_lo = omega_lo**2
    s_hi = omega_hi**2
    s0 = min(max(omega0, omega_lo), omega_hi)**2
    tol = 2*rtol*s0
    ! |psi''/psi'| is at most about 1/width (and 1/(0.1 s) where modes are far apart)
    w = min(max(width, 1.0e-9_wp*s0), 0.1_wp*s0)
    may_predict = .false.
    if (present(predict)) may_predict = predict .and. present(dpsi)
    nc = 0
    call evaluate_or_finish(s0, p0, done)
    if (done) return
    amp = layer_amplitude(r, k)
    if (present(dpsi)) then
      slope = dpsi
    else
      slope = 0
    end if
    if (slope > 0) then
      ! Newton step with the slope of a neighbouring layer
      step = -p0/slope
      if (may_predict .and. abs(step) <= 0.01_wp*w .and. 0.05_wp*abs(step) <= tol) then
        call finish(s0, r, s0 + step, p0)
        peak%dpsi = slope
        return
      end if
    else
      ! First step from the single-mode model P = ((s - s*)^2 + W^2)/A^2: with |g~| and psi at
      ! s0 and W = width, s0 - s* solves q d^2 - 2 d + q W^2 = 0 with q = psi |g~|^2.
      q = p0*amp**2
      if (abs(q*w) < 1) then
        d = (1 - sqrt(1 - (q*w)**2))/q
      else
        d = sign(w, q)
      end if
      step = -d
      slope = 2/(amp**2*w**2)
    end if
    if (abs(step) > 4*w) step = sign(4*w, step)
    if (abs(step) < tol) step = sign(tol, step)
    do it = 1, max_secant
      s1 = min(max(s0 + step, s_lo), s_hi)
      if (s1 == s0) then
        ! pushed against the band edge with P still decreasing outwards
        call finish(s0, r)
        if (s0 <= s_lo) peak%status = PEAK_BELOW_BAND
        if (s0 >= s_hi) peak%status = PEAK_ABOVE_BAND
        return
      end if
      call evaluate_or_finish(s1, p1, done)
      if (done) return
      ! secant estimate from the last two points, and its error bound
      if (p1 /= p0) then
        slope = (p1 - p0)/(s1 - s0)
        est = s1 - p1/slope
        if (slope > 0 .and. (abs(est - s1) <= tol .or. &
            & abs(est - s1)*abs(est - s0) <= tol*w)) then
          call finish(s1, r, est, p1)
          peak%dpsi = slope
          return
        end if
      end if
      if ((p0 > 0) .neqv. (p1 > 0)) exit
      ! same side: secant step (backwards too, if |psi| grew), at most four times the last
      if (p1 /= p0) then
        step = est - s1
      else
        step = 4*(s1 - s0)
      end if
      if (abs(step) > 4*abs(s1 - s0)) step = sign(4*abs(s1 - s0), step)
      if (abs(step) < tol) step = sign(tol, step)
      s0 = s1
      p0 = p1
    end do
    if (it > max_secant) then
      call fatal_error(error, "layer_peak: no peak of the layer response found from the "// &
        & "start frequency (secant steps exhausted)", UDMAP_ENUMERIC)
      return
    end if
    call brent_start(brent, s0, p0, s1, p1, tol)
    do
      call brent_next(brent, x, more)
      if (.not.more) exit
      call evaluate(x, p1, r)
      if (allocated(error)) return
      call brent_update(brent, p1)
    end do
    ! the root is the secant estimate within the final bracket [b, c]; b is one of the
    ! recently evaluated abscissae
    x = brent%b
    slope = 0
    if (brent%fc /= brent%fb) then
      slope = (brent%fc - brent%fb)/(brent%c - brent%b)
      x = brent%b - brent%fb/slope
    end if
    if (.not.(x >= min(brent%b, brent%c) .and. x <= max(brent%b, brent%c))) x = brent%b
    do i = 1, min(nc, ncache)
      if (xc(i) == brent%b) then
        call finish(brent%b, rc(i), x, brent%fb)
        peak%dpsi = slope
        return
      end if
    end do
    call evaluate(brent%b, p1, r)
    if (allocated(error)) return
    call finish(brent%b, r, x, p1)
    peak%dpsi = slope

  contains

    !> evaluate at s into r; done on an error, or where psi is zero (the peak, finished there).
    subroutine evaluate_or_finish(s, psi, done)
      real(wp), intent(in) :: s
      real(wp), intent(out) :: psi
      logical, intent(out) :: done
      call evaluate(s, psi, r)
      done = allocated(error)
      if (done .or. psi /= 0) return
      call finish(s, r)
      done = .true.
    end subroutine evaluate_or_finish

    !> psi and the receptances at s = omega^2 (kept in a small cache of recent points).
    subroutine evaluate(s, psi, rs)
      real(wp), intent(in) :: s
      real(wp), intent(out) :: psi
      type(receptances_type), intent(out) :: rs
      call bare_receptances(bare, sqrt(s), rs, error, .true.)
      if (allocated(error)) return
      psi = peak_function(rs, k, sqrt(s))
      nc = nc + 1
      xc(mod(nc - 1, ncache) + 1) = s
      rc(mod(nc - 1, ncache) + 1) = rs
    end subroutine evaluate

    !> The peak at s_star (default s): the receptances carried there from s to first order,
    !> the amplitude from the quadratic model of P = 1/|g~|^2 (P* = P(s) + psi (s* - s)/2,
    !> exact to O((s* - s)^3)).
    subroutine finish(s, rs, s_star, psi)
      real(wp), intent(in) :: s
      type(receptances_type), intent(in) :: rs
      real(wp), intent(in), optional :: s_star, psi
      real(wp) :: dw
      peak%omega = sqrt(s)
      peak%r = rs
      peak%amplitude = layer_amplitude(rs, k)
      if (present(s_star)) then
        peak%omega = sqrt(s_star)
        dw = peak%omega - sqrt(s)
        peak%r%gE = rs%gE + rs%dgE*dw
        peak%r%gg = rs%gg + rs%dgg*dw
        peak%r%EE = rs%EE + rs%dEE*dw
        peak%r%sE = rs%sE + rs%dsE*dw
        peak%r%sg = rs%sg + rs%dsg*dw
        peak%amplitude = 1/sqrt(1/peak%amplitude**2 + 0.5_wp*psi*(s_star - s))
      end if
      peak%status = PEAK_OK
    end subroutine finish
  end subroutine layer_peak

  !> The frequency omega in the bracket [omega_a, omega_b] where |g~(omega)| = level, given
  !> that (|g~| - level) changes sign over the bracket; located to rtol in omega. Returns
  !> the receptances there.
  subroutine layer_crossing(bare, k, level, omega_a, omega_b, rtol, omega, r, error)
    type(bare_type), intent(inout) :: bare
    complex(wp), intent(in) :: k
    real(wp), intent(in) :: level, omega_a, omega_b, rtol
    real(wp), intent(out) :: omega
    type(receptances_type), intent(out) :: r
    type(error_type), allocatable, intent(out) :: error
    type(brent_type) :: brent
    real(wp) :: fa, fb, x, fx
    logical :: more
    call bare_receptances(bare, omega_a, r, error, .false.)
    if (allocated(error)) return
    fa = (level/layer_amplitude(r, k))**2 - 1
    call bare_receptances(bare, omega_b, r, error, .false.)
    if (allocated(error)) return
    fb = (level/layer_amplitude(r, k))**2 - 1
    call brent_start(brent, omega_a, fa, omega_b, fb, rtol*max(abs(omega_a), abs(omega_b)))
    do
      call brent_next(brent, x, more)
      if (.not.more) exit
      call bare_receptances(bare, x, r, error, .false.)
      if (allocated(error)) return
      fx = (level/layer_amplitude(r, k))**2 - 1
      call brent_update(brent, fx)
    end do
    omega = brent%b
    call bare_receptances(bare, omega, r, error, .false.)
  end subroutine layer_crossing
end module udmap_mapping_layer
