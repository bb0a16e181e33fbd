!> Response curves of a traveling wave (PHYSICS.md 2.6 with section 3): for a force F_E, the
!> points (omega, gamma) where the layer gamma's force is F_E, |F(gamma, omega)| = F_E, on both
!> sides of the layer's peak, for layers from the curve's level at the band's edges up to the
!> peak of F_E (the backbone root). Each layer is solved on its own (udmap_mapping_traveling_layer);
!> the crossings are bracketed outward from the layer's peak and refined by Brent's method.
module udmap_mapping_traveling_curves
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update
  use udmap_mapping_model_data, only: model_type, point_type, curve_type, BRANCH_LOWER, &
    & BRANCH_UPPER, BRANCH_TURNING
  use udmap_mapping_traveling_layer, only: traveling_type, wave_layer_type, wave_peak, &
    & wave_layer_solve
  use udmap_mapping_traveling_backbone, only: new_model_traveling, wave_backbone, wave_response
  implicit none
  private
  public :: wave_curves

  !> Relative tolerance of the crossings in omega.
  real(wp), parameter :: crossing_rtol = 1.0e-10_wp

contains

  !> The response curves for the forces F_E [N] with `layers` amplitude layers each.
  subroutine wave_curves(model, F_E, layers, curves, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    integer, intent(in) :: layers
    type(curve_type), allocatable, intent(out) :: curves(:)
    type(error_type), allocatable, intent(out) :: error
    type(traveling_type) :: tw
    type(wave_layer_type) :: L
    type(point_type), allocatable :: peak(:), edge(:)
    real(wp), allocatable :: g(:), wl(:), wu(:)
    real(wp) :: g_lo, w_peak
    integer :: i, k, n, m
    if (layers < 4) then
      call fatal_error(error, "curves: layers must be at least 4", UDMAP_EINPUT)
      return
    end if
    call new_model_traveling(model, tw, error)
    if (allocated(error)) return
    call wave_backbone(model, F_E, peak, error)
    if (allocated(error)) return
    allocate(curves(size(F_E)))
    do i = 1, size(F_E)
      curves(i)%F_E = F_E(i)
      if (peak(i)%unbounded) then
        allocate(curves(i)%f(0), curves(i)%gamma_P(0), curves(i)%sigma_a(0), &
          & curves(i)%branch(0), curves(i)%part(0))
        cycle
      end if
      ! the lowest layer: the smaller response at the band's edges
      g_lo = peak(i)%gamma_P
      do k = 1, 2
        call wave_response(model, merge(model%analysis%f_min, model%analysis%f_max, k == 1)* &
          & (1 + merge(1e-9_wp, -1e-9_wp, k == 1)), [F_E(i)], edge, error)
        if (allocated(error)) return
        g_lo = min(g_lo, edge(1)%roots(1))
      end do
      n = layers
      allocate(g(n), wl(n), wu(n))
      L = wave_layer_type()
      w_peak = 2*pi*peak(i)%f_res
      do k = n, 1, -1
        ! from the peak down: each layer's crossings start from the layer above's (they move
        ! outward as the layers go down), the first ones from the peak
        g(k) = exp(log(g_lo) + (log(peak(i)%gamma_P) - log(g_lo))*(k - 1)/real(n - 1, wp)* &
          & (1 - 1e-9_wp))
        wl(k) = crossing(g(k), merge(w_peak, wl(min(k + 1, n)), k == n), -1)
        if (allocated(error)) return
        wu(k) = crossing(g(k), merge(w_peak, wu(min(k + 1, n)), k == n), 1)
        if (allocated(error)) return
      end do
      m = 2*n + 1
      allocate(curves(i)%f(m), curves(i)%gamma_P(m), curves(i)%sigma_a(m), &
        & curves(i)%branch(m), curves(i)%part(m))
      curves(i)%part = 1
      ! path order: lower branch upwards, the peak, upper branch downwards
      curves(i)%f(1:n) = wl/(2*pi)
      curves(i)%gamma_P(1:n) = g
      curves(i)%branch(1:n) = BRANCH_LOWER
      curves(i)%f(n+1) = peak(i)%f_res
      curves(i)%gamma_P(n+1) = peak(i)%gamma_P
      curves(i)%sigma_a(n+1) = peak(i)%sigma_a
      curves(i)%branch(n+1) = BRANCH_TURNING
      curves(i)%f(n+2:m) = wu(n:1:-1)/(2*pi)
      curves(i)%gamma_P(n+2:m) = g(n:1:-1)
      curves(i)%branch(n+2:m) = BRANCH_UPPER
      ! the stress of each crossing (layer solved there again: cheap with the warm start)
      do k = 1, m
        if (k == n + 1) cycle
        call wave_layer_solve(tw, curves(i)%gamma_P(k), 2*pi*curves(i)%f(k), L, error)
        if (allocated(error)) return
        curves(i)%sigma_a(k) = F_E(i)*abs(L%sigma(1))/abs(L%F)
      end do
      deallocate(g, wl, wu)
    end do

  contains

    !> The frequency on side `side` (-1 below, +1 above) of the layer's peak w0 where the
    !> layer's force is F_E(i): bracketed outward in steps that double, refined by Brent's
    !> method.
    real(wp) function crossing(gamma, w0, side) result(w)
      real(wp), intent(in) :: gamma, w0
      integer, intent(in) :: side
      type(brent_type) :: bs
      real(wp) :: a, b, fa, fb, d, x, fx, Fbb
      logical :: more
      integer :: it
      w = w0
      a = w0
      L%gamma = gamma
      fa = misfit(a)
      if (allocated(error)) return
      if (fa > 0) then
        ! the start is outside the curve (a layer whose peak moved): from the layer's peak
        call wave_peak(tw, gamma, w0, L, Fbb, error)
        if (allocated(error)) return
        a = L%omega
        fa = misfit(a)
        if (allocated(error)) return
      end if
      d = 1e-4_wp*w0
      b = a
      fb = fa
      do it = 1, 60
        b = a + side*d
        b = min(max(b, model%omega_lo), model%omega_hi)
        fb = misfit(b)
        if (allocated(error)) return
        if (fb >= 0 .or. b == model%omega_lo .or. b == model%omega_hi) exit
        a = b
        fa = fb
        d = 2*d
      end do
      if (fa*fb > 0) then
        ! the curve leaves the band on this side: its point is the band's edge
        w = b
        return
      end if
      call brent_start(bs, min(a, b), merge(fa, fb, a < b), max(a, b), merge(fb, fa, a < b), &
        & crossing_rtol*w0)
      do
        call brent_next(bs, x, more)
        if (.not. more) exit
        fx = misfit(x)
        if (allocated(error)) return
        call brent_update(bs, fx)
      end do
      w = x
    end function crossing

    real(wp) function misfit(w)
      real(wp), intent(in) :: w
      misfit = 0
      call wave_layer_solve(tw, L%gamma, w, L, error)
      if (allocated(error)) return
      misfit = log(abs(L%F)) - log(F_E(i))
    end function misfit
  end subroutine wave_curves
end module udmap_mapping_traveling_curves
