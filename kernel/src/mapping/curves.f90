!> Non-linear response curves by amplitude layered force mapping (PHYSICS.md 3, paper 4.1).
!>
!> For each layer gamma* the force that puts the blade on the layer at omega is
!> F(omega) = gamma*/|g~(omega; gamma*)|; the curve for F_E passes through (omega, gamma*)
!> wherever F(omega) = F_E, i.e. |g~| = gamma*/F_E. On each layer the crossings are bracketed
!> between the samples of one bare-blade sweep of the band (shared by all layers), split at
!> the layer's exact peak so that the two crossings near the top are never lost, and refined
!> by Brent's method with exact receptances. Where a layer just touches F_E (F_bb(gamma) = F_E,
!> a backbone root) the curve turns: those layers are included exactly. The band edges are
!> included exactly too (the response at f_min and f_max). Layers start log-spaced between the
!> lowest band-edge amplitude and the highest backbone root and are then added where the
!> curves bend or leave gaps: a segment longer than 1/layers of the (frequency band,
!> ln-amplitude range) box, or a turn sharper than 10 degrees, gets a layer at its middle.
module udmap_mapping_curves
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_core_arrays, only: put
  use udmap_blade_type, only: receptances_type, layer_response
  use udmap_mapping_layer, only: layer_amplitude, layer_crossing, bare_receptances
  use udmap_mapping_model_data, only: model_type, point_type, curve_type, check_forces, &
    & BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING, backbone_eval_type
  use udmap_mapping_backbone, only: backbone
  use udmap_mapping_backbone_table, only: cover_table, eval_backbone
  use udmap_mapping_response, only: response_roots
  implicit none
  private
  public :: response_curves

  !> Points of one curve while it is being built.
  type :: point_list
    integer :: n = 0
    real(wp), allocatable :: gamma(:), omega(:), sigma(:)
    integer, allocatable :: kind(:)
  end type point_list

  !> Largest turn between consecutive segments before a layer is added [rad].
  real(wp), parameter :: max_turn = 10*pi/180
  !> Passes of refinement at most.
  integer, parameter :: max_passes = 40

contains

  !> Response curves for the forces F_E [N] with about `layers` initial layers (more are
  !> added where the curves bend). curves(i) holds the points of F_E(i) in path order.
  subroutine response_curves(model, F_E, layers, curves, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    integer, intent(in) :: layers
    type(curve_type), allocatable, intent(out) :: curves(:)
    type(error_type), allocatable, intent(out) :: error
    type(point_type), allocatable :: bb(:)
    type(point_list), allocatable :: lists(:)
    real(wp), allocatable :: roots(:), new_layers(:), gammas(:)
    real(wp) :: gamma_min, gamma_max, ln_range, ds_max
    integer :: i, n, pass, nf, max_layers, n_layers
    character(len=12) :: buf

    allocate(curves(size(F_E)))
    if (layers < 4 .or. layers > 100000) then
      call fatal_error(error, "response_curves: layers must lie in [4, 100000]", UDMAP_EINPUT)
      return
    end if
    call check_forces(F_E, "response_curves", error)
    if (allocated(error)) return
    nf = size(F_E)
    if (nf == 0) return
    call backbone(model, F_E, bb, error)
    if (allocated(error)) return
    call ensure_sweep(model, error)
    if (allocated(error)) return
    allocate(lists(nf))

    ! band-edge points and the amplitude range
    gamma_min = huge(1.0_wp)
    gamma_max = 0
    n = size(model%sweep_omega)
    do i = 1, nf
      call edge_points(model, F_E(i), 1, BRANCH_LOWER, lists(i), roots, error)
      if (allocated(error)) return
      gamma_min = min(gamma_min, minval(roots))
      gamma_max = max(gamma_max, maxval(roots))
      call edge_points(model, F_E(i), n, BRANCH_UPPER, lists(i), roots, error)
      if (allocated(error)) return
      gamma_min = min(gamma_min, minval(roots))
      gamma_max = max(gamma_max, maxval(roots))
    end do
    if (all(bb%unbounded)) then
      gamma_max = 10*max(gamma_max, model%damper%gamma_b)
    else
      gamma_max = 0
      do i = 1, nf
        if (.not.bb(i)%unbounded) gamma_max = max(gamma_max, bb(i)%gamma_P)
      end do
      if (any(bb%unbounded)) gamma_max = 10*gamma_max
    end if
    gamma_max = max(gamma_max, 1.01_wp*gamma_min)
    ln_range = log(gamma_max/gamma_min)
    call cover_table(model, 0.0_wp, gamma_max, error)
    if (allocated(error)) return

    ! initial layers: log-spaced inside the range, and every backbone root exactly
    allocate(gammas(layers))
    do i = 1, layers
      gammas(i) = gamma_min*exp(ln_range*i/(layers + 1))
    end do
    do i = 1, nf
      if (.not.bb(i)%unbounded) gammas = [gammas, bb(i)%roots]
    end do
    n_layers = 0
    max_layers = 20*layers + size(gammas)
    ds_max = 1.0_wp/layers
    new_layers = gammas
    do pass = 1, max_passes
      do i = 1, size(new_layers)
        call add_layer(model, new_layers(i), F_E, bb, lists, error)
        if (allocated(error)) return
      end do
      n_layers = n_layers + size(new_layers)
      if (n_layers >= max_layers) exit
      call refine(model, F_E, bb, lists, gamma_min, ln_range, ds_max, new_layers)
      if (size(new_layers) == 0) exit
      if (n_layers + size(new_layers) > max_layers) &
        & new_layers = new_layers(1:max_layers - n_layers)
    end do

    do i = 1, nf
      call assemble(lists(i), bb(i), curves(i))
      curves(i)%F_E = F_E(i)
      if (size(curves(i)%f) == 0) then
        write(buf, '(i0)') i
        call fatal_error(error, "response_curves: no point found for F_E("//trim(buf)//")", &
          & UDMAP_EINPUT)
        return
      end if
    end do
  end subroutine response_curves

  !> The bare-blade sweep of the band, once per model.
  subroutine ensure_sweep(model, error)
    type(model_type), intent(inout) :: model
    type(error_type), allocatable, intent(out) :: error
    integer :: i, n
    n = model%analysis%sweep_points
    if (allocated(model%sweep_omega)) then
      if (size(model%sweep_omega) == n) return
      deallocate(model%sweep_omega, model%sweep_r)
    end if
    allocate(model%sweep_omega(n), model%sweep_r(n))
    do i = 1, n
      model%sweep_omega(i) = model%omega_lo + (model%omega_hi - model%omega_lo)*(i - 1)/(n - 1)
    end do
    model%sweep_omega(n) = model%omega_hi
    do i = 1, n
      call bare_receptances(model%bare, model%sweep_omega(i), model%sweep_r(i), error, .false.)
      if (allocated(error)) return
    end do
  end subroutine ensure_sweep

  !> Appends a point.
  pure subroutine push(list, gamma, omega, sigma, kind)
    type(point_list), intent(inout) :: list
    real(wp), intent(in) :: gamma, omega, sigma
    integer, intent(in) :: kind
    list%n = list%n + 1
    call put(list%gamma, list%n, gamma)
    call put(list%omega, list%n, omega)
    call put(list%sigma, list%n, sigma)
    call put(list%kind, list%n, kind)
  end subroutine push

  !> Stress amplitude F_E |s~| at a point.
  pure real(wp) function stress(model, r, k, F_E) result(sigma)
    type(model_type), intent(in) :: model
    type(receptances_type), intent(in) :: r
    complex(wp), intent(in) :: k
    real(wp), intent(in) :: F_E
    complex(wp) :: g, s, uE
    sigma = 0
    if (.not.model%blade%has_stress) return
    call layer_response(r, k, g, s, uE)
    sigma = F_E*abs(s)
  end function stress

  !> The points of the curve F_E on the band edge sweep sample i (all amplitude roots).
  subroutine edge_points(model, F_E, i, kind, list, roots, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E
    integer, intent(in) :: i, kind
    type(point_list), intent(inout) :: list
    real(wp), allocatable, intent(out) :: roots(:)
    type(error_type), allocatable, intent(out) :: error
    integer :: j
    call response_roots(model, model%sweep_r(i), F_E, roots, error)
    if (allocated(error)) return
    do j = 1, size(roots)
      call push(list, roots(j), model%sweep_omega(i), &
        & stress(model, model%sweep_r(i), model%damper%stiffness(roots(j)), F_E), kind)
    end do
  end subroutine edge_points

  !> One layer: its peak, then for every force the crossings on both sides (or the turning
  !> point when the layer is a backbone root of that force).
  subroutine add_layer(model, gamma, F_E, bb, lists, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: gamma, F_E(:)
    type(point_type), intent(in) :: bb(:)
    type(point_list), intent(inout) :: lists(:)
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type) :: e
    type(receptances_type) :: r
    real(wp), allocatable :: amp(:)
    real(wp) :: level, omega, x0, x1, a0, a1
    integer :: i, n, j, ipk, side
    logical :: turning
    call eval_backbone(model, gamma, e, error)
    if (allocated(error)) return
    associate(peak => e%peak, k => e%k, F_bb => e%F_bb)
    n = size(model%sweep_omega)
    allocate(amp(n))
    do j = 1, n
      amp(j) = layer_amplitude(model%sweep_r(j), k)
    end do
    ! last sample below the peak
    ipk = count(model%sweep_omega < peak%omega)
    do i = 1, size(F_E)
      turning = .false.
      if (.not.bb(i)%unbounded) turning = any(abs(bb(i)%roots/gamma - 1) <= 1e-13_wp)
      if (turning) then
        call push(lists(i), gamma, peak%omega, stress(model, peak%r, k, F_E(i)), BRANCH_TURNING)
        cycle
      end if
      if (F_bb >= F_E(i)) cycle
      level = gamma/F_E(i)
      ! abscissae: the samples with the exact peak inserted between ipk and ipk + 1
      do j = 1, n
        if (j < n) then
          x0 = model%sweep_omega(j); a0 = amp(j)
          x1 = model%sweep_omega(j + 1); a1 = amp(j + 1)
        else
          cycle
        end if
        if (j == ipk) then
          call try(x0, a0, peak%omega, peak%amplitude, BRANCH_LOWER)
          if (allocated(error)) return
          call try(peak%omega, peak%amplitude, x1, a1, BRANCH_UPPER)
          if (allocated(error)) return
        else
          side = merge(BRANCH_LOWER, BRANCH_UPPER, j < ipk)
          call try(x0, a0, x1, a1, side)
          if (allocated(error)) return
        end if
      end do
    end do
    end associate
  contains
    !> A crossing of the level between (xa, aa) and (xb, ab), refined and pushed.
    subroutine try(xa, aa, xb, ab, kind)
      real(wp), intent(in) :: xa, aa, xb, ab
      integer, intent(in) :: kind
      ! a crossing in (xa, xb]; the band edges themselves are edge points
      if (xa >= xb) return
      if (.not.((aa < level .and. ab >= level) .or. (aa > level .and. ab <= level))) return
      if (xb >= model%omega_hi .and. ab == level) return
      call layer_crossing(model%bare, e%k, level, xa, xb, model%analysis%rtol, omega, r, error)
      if (allocated(error)) return
      if (omega <= model%omega_lo .or. omega >= model%omega_hi) return
      call push(lists(i), gamma, omega, stress(model, r, e%k, F_E(i)), kind)
    end subroutine try
  end subroutine add_layer

  !> Part (1 = main curve, 2, ... = detached) of a point at gamma on the curve whose
  !> backbone roots are `roots`: each pair of roots above the first bounds one more part.
  pure integer function part_of(roots, gamma) result(part)
    real(wp), intent(in) :: roots(:), gamma
    integer :: c
    c = count(roots < gamma*(1 - 1e-13_wp))
    part = 1 + (c + 1)/2
  end function part_of

  !> Layers to add: the middle (in ln gamma) of every segment that is too long or turns too
  !> sharply, over every curve, part and branch.
  subroutine refine(model, F_E, bb, lists, gamma_min, ln_range, ds_max, new_layers)
    type(model_type), intent(in) :: model
    real(wp), intent(in) :: F_E(:), gamma_min, ln_range, ds_max
    type(point_type), intent(in) :: bb(:)
    type(point_list), intent(in) :: lists(:)
    real(wp), allocatable, intent(out) :: new_layers(:)
    real(wp), allocatable :: cand(:), g(:), x(:), y(:)
    integer, allocatable :: idx(:), sel(:)
    real(wp), allocatable :: roots(:)
    real(wp) :: band, d1, d2, c
    integer :: i, p, side, m, j, nparts, nc
    band = model%omega_hi - model%omega_lo
    allocate(cand(0))
    nc = 0
    do i = 1, size(F_E)
      associate(L => lists(i))
        if (L%n < 2) cycle
        if (bb(i)%unbounded) then
          allocate(roots(0))
        else
          roots = bb(i)%roots
        end if
        nparts = (size(roots) + 2)/2
        do p = 1, nparts
          do side = BRANCH_LOWER, BRANCH_UPPER
            sel = pack([(j, j = 1, L%n)], (L%kind(1:L%n) == side .or. &
              & L%kind(1:L%n) == BRANCH_TURNING))
            if (size(sel) < 2) cycle
            sel = pack(sel, [(part_of(roots, L%gamma(sel(j))) == p, j = 1, size(sel))])
            m = size(sel)
            if (m < 2) cycle
            g = L%gamma(sel)
            call sort_index(g, idx)
            g = g(idx)
            x = (L%omega(sel(idx)) - model%omega_lo)/band
            y = log(g/gamma_min)/ln_range
            do j = 1, m - 1
              if (g(j + 1) <= g(j)*(1 + 1e-10_wp)) cycle
              d1 = hypot(x(j + 1) - x(j), y(j + 1) - y(j))
              if (d1 > ds_max) then
                cand = [cand, sqrt(g(j)*g(j + 1))]
              else if (j < m - 1) then
                d2 = hypot(x(j + 2) - x(j + 1), y(j + 2) - y(j + 1))
                if (d1 > 1e-4_wp*ds_max .and. d2 > 1e-4_wp*ds_max .and. &
                    & g(j + 2) > g(j + 1)*(1 + 1e-10_wp)) then
                  c = ((x(j + 1) - x(j))*(x(j + 2) - x(j + 1)) + &
                    & (y(j + 1) - y(j))*(y(j + 2) - y(j + 1)))/(d1*d2)
                  if (c < cos(max_turn)) cand = [cand, sqrt(g(j)*g(j + 1)), &
                    & sqrt(g(j + 1)*g(j + 2))]
                end if
              end if
            end do
          end do
        end do
        deallocate(roots)
      end associate
    end do
    ! unique candidates
    if (size(cand) == 0) then
      allocate(new_layers(0))
      return
    end if
    call sort_index(cand, idx)
    cand = cand(idx)
    nc = 1
    do j = 2, size(cand)
      if (cand(j) > cand(nc)*(1 + 1e-12_wp)) then
        nc = nc + 1
        cand(nc) = cand(j)
      end if
    end do
    new_layers = cand(1:nc)
  end subroutine refine

  !> The curve in path order: per part, the bottom turning point (detached parts), the lower
  !> branch by rising gamma, the top turning point, the upper branch by falling gamma, and the
  !> bottom turning point again to close a detached part.
  subroutine assemble(L, bb, curve)
    type(point_list), intent(in) :: L
    type(point_type), intent(in) :: bb
    type(curve_type), intent(out) :: curve
    real(wp), allocatable :: roots(:), f(:), g(:), s(:)
    integer, allocatable :: br(:), pt(:), idx(:), order(:), parts(:)
    integer :: p, nparts, j, n
    if (bb%unbounded) then
      allocate(roots(0))
    else
      roots = bb%roots
    end if
    nparts = (size(roots) + 2)/2
    n = L%n
    allocate(f(0), g(0), s(0), br(0), pt(0))
    if (n == 0) then
      call move(); return
    end if
    parts = [(part_of(roots, L%gamma(j)), j = 1, n)]
    call sort_index(L%gamma(1:n), idx)
    do p = 1, nparts
      ! bottom turning point of a detached part
      if (p >= 2) call take(pack(idx, L%kind(idx) == BRANCH_TURNING .and. parts(idx) == p .and. &
        & abs(L%gamma(idx)/roots(2*p - 2) - 1) <= 1e-12_wp), p)
      call take(pack(idx, L%kind(idx) == BRANCH_LOWER .and. parts(idx) == p), p)
      if (2*p - 1 <= size(roots)) call take(pack(idx, L%kind(idx) == BRANCH_TURNING .and. &
        & parts(idx) == p .and. abs(L%gamma(idx)/roots(2*p - 1) - 1) <= 1e-12_wp), p)
      order = pack(idx, L%kind(idx) == BRANCH_UPPER .and. parts(idx) == p)
      call take(order(size(order):1:-1), p)
      if (p >= 2) call take(pack(idx, L%kind(idx) == BRANCH_TURNING .and. parts(idx) == p .and. &
        & abs(L%gamma(idx)/roots(2*p - 2) - 1) <= 1e-12_wp), p)
    end do
    call move()
  contains
    !> Appends the points `which` of the list to the curve, tagged with their part.
    subroutine take(which, part)
      integer, intent(in) :: which(:), part
      f = [f, L%omega(which)/(2*pi)]
      g = [g, L%gamma(which)]
      s = [s, L%sigma(which)]
      br = [br, L%kind(which)]
      pt = [pt, spread(part, 1, size(which))]
    end subroutine take
    !> Moves the assembled arrays into the curve.
    subroutine move()
      call move_alloc(f, curve%f)
      call move_alloc(g, curve%gamma_P)
      call move_alloc(s, curve%sigma_a)
      call move_alloc(br, curve%branch)
      call move_alloc(pt, curve%part)
    end subroutine move
  end subroutine assemble

  !> Indices that sort x ascending (stable merge sort).
  pure subroutine sort_index(x, idx)
    real(wp), intent(in) :: x(:)
    integer, allocatable, intent(out) :: idx(:)
    integer, allocatable :: tmp(:)
    integer :: n, width, lo, mid, hi, i, j, k
    n = size(x)
    allocate(idx(n), tmp(n))
    idx = [(i, i = 1, n)]
    width = 1
    do while (width < n)
      lo = 1
      do while (lo <= n)
        mid = min(lo + width - 1, n)
        hi = min(lo + 2*width - 1, n)
        i = lo; j = mid + 1; k = lo
        do while (k <= hi)
          if (j > hi .or. (i <= mid .and. x(idx(min(i, n))) <= x(idx(min(j, n))))) then
            tmp(k) = idx(i); i = i + 1
          else
            tmp(k) = idx(j); j = j + 1
          end if
          k = k + 1
        end do
        lo = lo + 2*width
      end do
      idx = tmp
      width = 2*width
    end do
  end subroutine sort_index
end module udmap_mapping_curves
