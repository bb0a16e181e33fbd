!> The standard method's peak (PHYSICS.md 6): the maximum of |Gamma_1| refined on the continued
!> curve, the peak of the stuck-damper linear response, the outputs at a converged point and the
!> curve they are collected on.
module udmap_baseline_peak
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC
  use udmap_baseline_linear_structure, only: structure_type, structure_receptances_type, &
    & structure_receptances
  use udmap_baseline_types, only: hbm_point_type, hbm_curve_type, HBM_CONDENSED, amplitude, &
    & scaled_dot, problem_type, curve_point_type
  use udmap_baseline_residual, only: evaluate
  use udmap_baseline_continuation, only: newton_arclength, tangent
  implicit none
  private
  public :: refine_peak, stuck_peak, fill_point, curve_push, sort_pairs

contains

  !> The local maximum of gamma_1 between a (dA > 0) and b (dA <= 0): Illinois root finding on
  !> dA/ds along the family of hyperplanes orthogonal to a's tangent.
  subroutine refine_peak(p, st, a, b, pk, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: a, b
    type(curve_point_type), intent(out) :: pk
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: s_lo, s_hi, g_lo, g_hi, s, g, w_lo, w_hi
    real(wp), allocatable :: x_lo(:), x_hi(:), xp(:)
    real(wp) :: wp_
    integer :: iter, side, it, retry
    logical :: ok
    type(curve_point_type) :: trial
    s_lo = 0.0_wp
    s_hi = scaled_dot(p, a%tx, a%tw, b%x - a%x, b%omega - a%omega, a%A_s)
    g_lo = a%dA
    g_hi = b%dA
    allocate(x_lo(p%nx), x_hi(p%nx))
    x_lo = a%x; w_lo = a%omega
    x_hi = b%x; w_hi = b%omega
    pk = b
    if (g_hi == 0.0_wp .or. s_hi <= 0.0_wp) return
    side = 0
    allocate(trial%tx(p%nx))
    do iter = 1, 200
      s = s_lo - g_lo*(s_hi - s_lo)/(g_hi - g_lo)
      if (.not.(s > s_lo .and. s < s_hi)) s = 0.5_wp*(s_lo + s_hi)
      ! predictor on the hyperplane at s: interpolate the bracket
      trial%x = x_lo + (s - s_lo)/(s_hi - s_lo)*(x_hi - x_lo)
      trial%omega = w_lo + (s - s_lo)/(s_hi - s_lo)*(w_hi - w_lo)
      xp = a%x + s*a%tx
      wp_ = a%omega + s*a%tw
      call newton_arclength(p, st, trial%x, trial%omega, a, xp, wp_, p%set%tol, ok, it, error)
      if (allocated(error)) return
      ! retry from the bracket ends (a kink of the damper law between them can defeat the
      ! interpolated guess)
      do retry = 1, 2
        if (ok) exit
        if (retry == 1) then
          trial%x = x_lo; trial%omega = w_lo
        else
          trial%x = x_hi; trial%omega = w_hi
        end if
        call newton_arclength(p, st, trial%x, trial%omega, a, xp, wp_, p%set%tol, ok, it, error)
        if (allocated(error)) return
      end do
      if (.not.ok) then
        ! at the rounding floor: the bracket already pins the peak, keep the best end
        if (s_hi - s_lo <= 1.0e-6_wp*max(1.0_wp, s_hi)) exit
        call fatal_error(error, "hbm: Newton did not converge while refining the peak", &
          & UDMAP_ENUMERIC)
        return
      end if
      trial%A_s = a%A_s
      call tangent(p, st, trial, a%tx, a%tw, error, a%A_s, central=.true.)
      if (allocated(error)) return
      g = trial%dA
      if (g > 0.0_wp) then
        s_lo = s; g_lo = g; x_lo = trial%x; w_lo = trial%omega
        if (side == -1) g_hi = 0.5_wp*g_hi
        side = -1
      else
        s_hi = s; g_hi = g; x_hi = trial%x; w_hi = trial%omega
        if (side == 1) g_lo = 0.5_wp*g_lo
        side = 1
      end if
      pk = trial
      if (g == 0.0_wp .or. s_hi - s_lo <= p%set%peak_tol*max(1.0_wp, s_hi)) exit
    end do
  end subroutine refine_peak

  !> The frequency of the largest linear response |H_gE/(1 + k_stuck H_gg)| with the stuck
  !> damper on [omega_a, omega_b]: the best of a grid, refined by golden-section search.
  subroutine stuck_peak(p, st, omega_a, omega_b, omega, error)
    type(problem_type), intent(in) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega_a, omega_b
    real(wp), intent(out) :: omega
    type(error_type), allocatable, intent(out) :: error
    integer, parameter :: ngrid = 64
    real(wp), parameter :: golden = 0.6180339887498949_wp
    real(wp) :: a, b, c, d, fc, fd, v, best
    integer :: i, ibest
    best = -1.0_wp
    ibest = 0
    do i = 0, ngrid
      v = response(omega_a + (omega_b - omega_a)*i/ngrid)
      if (allocated(error)) return
      if (v > best) then
        best = v
        ibest = i
      end if
    end do
    a = omega_a + (omega_b - omega_a)*max(ibest - 1, 0)/ngrid
    b = omega_a + (omega_b - omega_a)*min(ibest + 1, ngrid)/ngrid
    c = b - golden*(b - a)
    d = a + golden*(b - a)
    fc = response(c)
    fd = response(d)
    do i = 1, 40
      if (allocated(error)) return
      if (fc >= fd) then
        b = d; d = c; fd = fc
        c = b - golden*(b - a)
        fc = response(c)
      else
        a = c; c = d; fc = fd
        d = a + golden*(b - a)
        fd = response(d)
      end if
      if (b - a <= 1.0e-10_wp*b) exit
    end do
    omega = 0.5_wp*(a + b)
  contains
    real(wp) function response(w)
      real(wp), intent(in) :: w
      type(structure_receptances_type) :: r
      response = 0.0_wp
      call structure_receptances(st, w, r, error)
      if (allocated(error)) return
      response = abs(r%gE/(1.0_wp + p%k_stuck*r%gg))
    end function response
  end subroutine stuck_peak

  !> The outputs at a converged point.
  subroutine fill_point(p, st, pt, point, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: pt
    type(hbm_point_type), intent(inout) :: point
    type(error_type), allocatable, intent(out) :: error
    complex(wp) :: G1, S1, U1
    real(wp), allocatable :: R(:)
    type(structure_receptances_type) :: r1
    integer :: h
    allocate(R(p%nx))
    call evaluate(p, st, pt%x, pt%omega, R, error)
    if (allocated(error)) return
    G1 = cmplx(pt%x(p%goff+p%h0+1), pt%x(p%goff+p%h0+2), wp)
    point%gamma_P = abs(G1)
    point%f_res = pt%omega/(2.0_wp*pi)
    point%gamma_max = p%gmax
    point%lift_off = p%ws%lift_off
    if (abs(G1) > 0.0_wp) then
      point%k_re = real(p%Mh(1)/G1, wp)
      point%k_im = aimag(p%Mh(1)/G1)
    end if
    allocate(point%gamma_h(p%H))
    do h = 1, p%H
      point%gamma_h(h) = hypot(pt%x(p%goff+p%h0+2*h-1), pt%x(p%goff+p%h0+2*h))
    end do
    if (p%set%variant == HBM_CONDENSED) then
      call structure_receptances(st, pt%omega, r1, error)
      if (allocated(error)) return
      S1 = r1%sE*p%F - r1%sg*p%Mh(1)
      U1 = r1%EE*p%F - r1%gE*p%Mh(1)
    else
      U1 = cmplx(pt%x((st%exc_dof-1)*p%b+p%h0+1), pt%x((st%exc_dof-1)*p%b+p%h0+2), wp)
      S1 = (0.0_wp, 0.0_wp)
      if (st%has_stress) then
        do h = 1, p%n
          S1 = S1 + (st%s_K(h) - pt%omega**2*st%s_M(h))* &
            & cmplx(pt%x((h-1)*p%b+p%h0+1), pt%x((h-1)*p%b+p%h0+2), wp)
        end do
      end if
    end if
    point%sigma_a = 0.0_wp
    if (st%has_stress) point%sigma_a = abs(S1)
    point%u_E = abs(U1)
  end subroutine fill_point

  subroutine curve_push(p, st, curve, pt)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(hbm_curve_type), intent(inout) :: curve
    type(curve_point_type), intent(in) :: pt
    type(hbm_point_type) :: tmp
    type(error_type), allocatable :: error
    real(wp), allocatable :: t(:)
    integer :: cap
    if (.not.allocated(curve%f)) then
      allocate(curve%f(64), curve%gamma_1(64), curve%sigma_1(64), curve%gamma_max(64))
    else if (curve%n >= size(curve%f)) then
      cap = 2*size(curve%f)
      allocate(t(cap)); t(1:curve%n) = curve%f(1:curve%n); call move_alloc(t, curve%f)
      allocate(t(cap)); t(1:curve%n) = curve%gamma_1(1:curve%n); call move_alloc(t, curve%gamma_1)
      allocate(t(cap)); t(1:curve%n) = curve%sigma_1(1:curve%n); call move_alloc(t, curve%sigma_1)
      allocate(t(cap)); t(1:curve%n) = curve%gamma_max(1:curve%n)
      call move_alloc(t, curve%gamma_max)
    end if
    call fill_point(p, st, pt, tmp, error)
    curve%n = curve%n + 1
    curve%f(curve%n) = pt%omega/(2.0_wp*pi)
    curve%gamma_1(curve%n) = amplitude(p, pt%x)
    curve%sigma_1(curve%n) = tmp%sigma_a
    curve%gamma_max(curve%n) = tmp%gamma_max
  end subroutine curve_push

  pure subroutine sort_pairs(a, b)
    real(wp), intent(inout) :: a(:), b(:)
    integer :: i, j
    real(wp) :: ta, tb
    do i = 2, size(a)
      ta = a(i); tb = b(i)
      j = i - 1
      do while (j >= 1)
        if (a(j) <= ta) exit
        a(j+1) = a(j); b(j+1) = b(j)
        j = j - 1
      end do
      a(j+1) = ta; b(j+1) = tb
    end do
  end subroutine sort_pairs
end module udmap_baseline_peak
