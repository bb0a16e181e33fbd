!> The non-linear response at a given excitation frequency (PHYSICS.md 4, last paragraph).
!> At a fixed omega the bare receptances are numbers, and the amplitude a solves
!>   q(a) = a |1 + k(a) H_gg| = F_E |H_gE|,
!> a scalar equation in a alone. Its roots are bracketed on the same amplitude grid as the
!> backbone (linear below the stuck amplitude, where k is constant), all of them, and refined
!> by Brent's method in ln(a) to rtol. The scan stops where the lower bound
!> a (1 - |k(a)| |H_gg|) of q exceeds the target with |k| falling. Only damper stiffness
!> evaluations are needed.
module udmap_mapping_response
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_blade_type, only: receptances_type
  use udmap_mapping_layer, only: bare_receptances
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update
  use udmap_mapping_model_data, only: model_type, point_type, limit_force_or_huge, fill_point, &
    & check_forces, check_response_frequency, limit_force_backbone
  use udmap_mapping_backbone_table, only: ensure_table, grid_gamma, max_decades, j_limit, j_rising
  implicit none
  private
  public :: response, response_roots

contains

  !> The response at the excitation frequency f_exc [Hz] (up to 3 f_max) to the forces
  !> F_E [N]: every amplitude root, the largest giving gamma_P and the outputs.
  !> The response at a fixed frequency is finite even above F_lim, so points are never
  !> flagged unbounded here (the regime still says REGIME_LIMIT).
  subroutine response(model, f_exc, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: f_exc
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(receptances_type) :: r
    real(wp), allocatable :: roots(:)
    real(wp) :: F_lim, omega
    integer :: i
    allocate(points(size(F_E)))
    call check_response_frequency(model%analysis, f_exc, error)
    if (allocated(error)) return
    call check_forces(F_E, "response", error)
    if (allocated(error)) return
    if (size(F_E) == 0) return
    call ensure_table(model, error)
    if (allocated(error)) return
    ! the HCF check and the regime against the smaller limit (PHYSICS.md 5)
    F_lim = min(limit_force_or_huge(model), limit_force_backbone(model))
    omega = 2*pi*f_exc
    call bare_receptances(model%bare, omega, r, error, .false.)
    if (allocated(error)) return
    do i = 1, size(F_E)
      call response_roots(model, r, F_E(i), roots, error)
      if (allocated(error)) return
      call fill_point(model, points(i), F_E(i), F_lim, omega, r, &
        & model%damper%stiffness(roots(size(roots))), roots)
    end do
  end subroutine response

  !> Every root a of a |1 + k(a) H_gg| = F_E |H_gE| (ascending) for the bare receptances r
  !> at one frequency. The backbone table must exist (for the grid anchor).
  subroutine response_roots(model, r, F_E, roots, error)
    type(model_type), intent(inout) :: model
    type(receptances_type), intent(in) :: r
    real(wp), intent(in) :: F_E
    real(wp), allocatable, intent(out) :: roots(:)
    type(error_type), allocatable, intent(out) :: error
    type(brent_type) :: brent
    real(wp) :: target, found(256), a0, q0, a1, q1, u, fu, q_lo, a_lo, k0, k1
    logical :: more
    integer :: j, n, gpd, j_cap
    logical :: capped
    target = F_E*abs(r%gE)
    gpd = model%analysis%grid_per_decade
    j_cap = j_limit(model)
    capped = j_cap < max_decades*gpd
    n = 0
    j = model%table%j_lo
    a_lo = grid_gamma(model, j)
    q_lo = q(a_lo)
    if (target <= q_lo) then
      ! stuck: q is linear through the origin below the first node
      n = 1
      found(1) = target*a_lo/q_lo
    end if
    a0 = a_lo
    q0 = q_lo
    k0 = abs(model%damper%stiffness(a_lo))
    do
      j = j + 1
      a1 = grid_gamma(model, j)
      q1 = q(a1)
      ! a root in (a0, a1]: a sign change, or a zero at a1
      if (n < size(found) .and. ((q0 < target .and. q1 >= target) .or. &
          & (q0 > target .and. q1 <= target))) then
        if (q1 == target) then
          n = n + 1
          found(n) = a1
        else
          call brent_start(brent, log(a0), q0/target - 1, log(a1), q1/target - 1, &
            & 2*model%analysis%rtol)
          do
            call brent_next(brent, u, more)
            if (.not.more) exit
            fu = q(exp(u))/target - 1
            call brent_update(brent, fu)
          end do
          n = n + 1
          found(n) = exp(brent%b)
        end if
      end if
      ! No more roots above a1 once q(a) >= a (1 - |k(a)| |H_gg|) exceeds the target there
      ! and |k| no longer grows: the bound then rises with a (above gamma_b |k| falls as the
      ! friction saturates). q itself need not rise: it dips where the layer's resonance passes
      ! this frequency. A measured table without delta_M is scanned to its last row, where q
      ! must be past the target.
      k1 = abs(model%damper%stiffness(a1))
      if (.not.capped .and. j >= j_rising(model) .and. k1 <= k0 .and. &
        & a1*(1 - k1*abs(r%gg)) > target) exit
      if (j >= j_cap .and. capped .and. q1 > target) exit
      k0 = k1
      if (j >= j_cap) then
        if (capped) then
          call fatal_error(error, "response: the amplitude goes beyond the damper's stiffness "// &
            & "range (a measured table without delta_M ends at its last row)", UDMAP_EINPUT)
        else
          call fatal_error(error, "response: the amplitude exceeds 1e12 gamma_b", UDMAP_EPHYSICS)
        end if
        return
      end if
      a0 = a1
      q0 = q1
    end do
    if (n == 0) then
      call fatal_error(error, "response: no amplitude found (internal)", UDMAP_EPHYSICS)
      return
    end if
    roots = found(1:n)
  contains
    !> q(a) = a |1 + k(a) H_gg|.
    real(wp) function q(a)
      real(wp), intent(in) :: a
      q = a*abs(1 + model%damper%stiffness(a)*r%gg)
    end function q
  end subroutine response_roots
end module udmap_mapping_response
