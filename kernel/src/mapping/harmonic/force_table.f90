!> The force table: reuse of exact multi-harmonic backbone points after a change of F_E alone
!> (the FMU's F_E-only step at H > 1, PHYSICS.md 4.1). A layer solve costs 10^2 us and more, so
!> a point between exact points is interpolated instead, where the interpolation is verified:
!>
!> - Panels in u = ln F_E on a fixed dyadic hierarchy: level 0 has width_0 = ln(10)/8 and is
!>   aligned to multiples of it, level L halves level L - 1. A panel is judged on nine equally
!>   spaced exact points (its eighths; a child shares five with its parent).
!> - A panel is accepted when the quartic through its points 0, 2, 4, 6, 8 predicts points 1, 3,
!>   5 and 7 to tol in every packed output. Its halves then answer, each by the quartic through
!>   its own five points, which is finer than the one just checked. A panel whose points
!>   disagree in structure (H, number of roots, jump, a failed or unbounded point) or fail the
!>   check is halved, down to level LEVEL_MAX, where it is marked exact: points there are
!>   solved exactly.
!> - Only the panels on the path to the asked u are built (lazily), and a level-0 panel is
!>   built only on its second visit: the first force in it is solved exactly.
!> - Every point of a panel has the same harmonics: with the automatic H, the H chosen at the
!>   middle of its level-0 panel (points are keyed by position and H).
!> - A range of forces can be covered in advance (udmap_model_cover_forces, the FMU's
!>   F_E_min..F_E_max): table_next_gap walks the range from left to right and names each
!>   force no leaf holds yet; the caller builds the path to it exactly as on demand (same
!>   panels, same judgement), so that afterwards every force of the range finds its leaf.
!>
!> The table holds numbers only; udmap_mapping_harmonic_mapping packs the points (what is
!> interpolated in ln, what linearly, and on what scale the check is done) and solves them.
module udmap_mapping_harmonic_force_table
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  use udmap_core_arrays, only: put
  use udmap_mapping_harmonic_types, only: table_node_type, force_table_type, SIGNATURE_SIZE
  implicit none
  private
  public :: table_reset, table_lookup, table_first_visit, table_panel, table_has_node, &
    & table_add_node, table_judge, node_force, table_panel_harmonics, table_set_panel_harmonics, &
    & table_position, table_next_gap, table_skip_panel, table_count
  public :: TABLE_MISSING, TABLE_VERIFIED, TABLE_EXACT, TABLE_SPLIT, LEVEL_MAX

  !> Deepest level (width_0/2^10, about 3e-4 in ln F_E).
  integer, parameter :: LEVEL_MAX = 10
  !> Width of a level-0 panel in ln F_E.
  real(wp), parameter :: width_0 = log(10.0_wp)/8
  !> Node positions are integers: multiples of width_0/FINE (an eighth of the deepest panel).
  integer(int64), parameter :: FINE = 2_int64**(LEVEL_MAX + 3)

  integer, parameter :: TABLE_MISSING = 0, TABLE_VERIFIED = 1, TABLE_EXACT = 2, TABLE_SPLIT = 3

contains

  !> Empties the table unless it was built for key.
  subroutine table_reset(t, key)
    type(force_table_type), intent(inout) :: t
    real(wp), intent(in) :: key(:)
    if (allocated(t%key)) then
      if (size(t%key) == size(key)) then
        if (all(t%key == key)) return
      end if
    end if
    t%key = key
    t%F_lim = -1
    t%n_node = 0
    t%n_leaf = 0
    t%n_visit = 0
  end subroutine table_reset

  !> Position (in FINE units) of u rounded down to the grid of level-L panels.
  pure integer(int64) function panel_lo(u, L)
    real(wp), intent(in) :: u
    integer, intent(in) :: L
    integer(int64) :: step
    step = FINE/2_int64**L
    panel_lo = floor(u/width_0*2.0_wp**L, int64)*step
  end function panel_lo

  !> The nine node positions (eighths) of the level-L panel holding u.
  pure function table_panel(u, L) result(idx)
    real(wp), intent(in) :: u
    integer, intent(in) :: L
    integer(int64) :: idx(9)
    integer(int64) :: lo, q
    integer :: j
    lo = panel_lo(u, L)
    q = FINE/2_int64**L/8
    do j = 0, 8
      idx(j + 1) = lo + j*q
    end do
  end function table_panel

  !> The force [N] at node position idx.
  pure real(wp) function node_force(idx)
    integer(int64), intent(in) :: idx
    node_force = exp(real(idx, wp)*(width_0/real(FINE, wp)))
  end function node_force

  !> True on the first visit of u's level-0 panel (which records the visit).
  logical function table_first_visit(t, u)
    type(force_table_type), intent(inout) :: t
    real(wp), intent(in) :: u
    integer(int64) :: k
    k = panel_lo(u, 0)
    if (allocated(t%visited)) then
      if (any(t%visited(1:t%n_visit) == k)) then
        table_first_visit = .false.
        return
      end if
    end if
    t%n_visit = t%n_visit + 1
    call put(t%visited, t%n_visit, k)
    call put(t%visited_h, t%n_visit, 0)
    table_first_visit = .true.
  end function table_first_visit

  !> The harmonics of the points of u's level-0 panel (0: not set; the panel must have been
  !> visited), and the force [N] at its middle.
  subroutine table_panel_harmonics(t, u, h, F_mid)
    type(force_table_type), intent(in) :: t
    real(wp), intent(in) :: u
    integer, intent(out) :: h
    real(wp), intent(out) :: F_mid
    integer :: i
    h = 0
    F_mid = node_force(panel_lo(u, 0) + FINE/2)
    do i = 1, t%n_visit
      if (t%visited(i) == panel_lo(u, 0)) h = t%visited_h(i)
    end do
  end subroutine table_panel_harmonics

  subroutine table_set_panel_harmonics(t, u, h)
    type(force_table_type), intent(inout) :: t
    real(wp), intent(in) :: u
    integer, intent(in) :: h
    integer :: i
    do i = 1, t%n_visit
      if (t%visited(i) == panel_lo(u, 0)) t%visited_h(i) = h
    end do
  end subroutine table_set_panel_harmonics

  !> The leaf holding u: TABLE_MISSING, TABLE_EXACT, or TABLE_VERIFIED with the interpolated
  !> outputs y and the structure of its points.
  subroutine table_lookup(t, u, status, y, signature)
    type(force_table_type), intent(in) :: t
    real(wp), intent(in) :: u
    integer, intent(out) :: status
    real(wp), allocatable, intent(inout) :: y(:)
    integer, intent(out) :: signature(SIGNATURE_SIZE)
    real(wp) :: x, w(5)
    integer :: i, j, m(5)
    status = TABLE_MISSING
    signature = 0
    x = u/width_0*real(FINE, wp)
    do i = 1, t%n_leaf
      if (.not.(x >= real(t%leaf_lo(i), wp) .and. x < real(t%leaf_hi(i), wp))) cycle
      status = t%leaf_status(i)
      if (status /= TABLE_VERIFIED) return
      do j = 1, 5
        m(j) = find_node(t, t%leaf_lo(i) + (j - 1)*(t%leaf_hi(i) - t%leaf_lo(i))/4, t%leaf_h(i))
      end do
      ! the quartic through the five points, x in quarters of the panel
      w = lagrange(4*(x - real(t%leaf_lo(i), wp))/real(t%leaf_hi(i) - t%leaf_lo(i), wp))
      signature = t%node(m(1))%signature
      if (allocated(y)) then
        if (size(y) /= size(t%node(m(1))%y)) deallocate(y)
      end if
      if (.not.allocated(y)) allocate(y(size(t%node(m(1))%y)))
      y = w(1)*t%node(m(1))%y + w(2)*t%node(m(2))%y + w(3)*t%node(m(3))%y + &
        & w(4)*t%node(m(4))%y + w(5)*t%node(m(5))%y
      return
    end do
  end subroutine table_lookup

  !> The position (FINE units, real) of u = ln F_E, as table_lookup computes it.
  pure real(wp) function table_position(u) result(x)
    real(wp), intent(in) :: u
    x = u/width_0*real(FINE, wp)
  end function table_position

  !> The walk of a range [x, position of u_hi] in FINE units (table_cover in the mapping):
  !> from the cursor x on, skipping every leaf, the first u = ln F_E that no leaf holds
  !> (found), or found = .false. once leaves hold everything up to u_hi. Past the first leaf
  !> the cursor sits half a FINE unit inside a cell, so that no rounding of u moves it across
  !> a panel edge (edges are whole FINE units, the finest leaf is 4 of them wide).
  subroutine table_next_gap(t, x, u_hi, u, found)
    type(force_table_type), intent(in) :: t
    real(wp), intent(inout) :: x
    real(wp), intent(in) :: u_hi
    real(wp), intent(out) :: u
    logical, intent(out) :: found
    integer :: i
    logical :: inside
    found = .false.
    u = 0
    do while (x <= table_position(u_hi))
      inside = .false.
      do i = 1, t%n_leaf
        if (x >= real(t%leaf_lo(i), wp) .and. x < real(t%leaf_hi(i), wp)) then
          inside = .true.
          x = real(t%leaf_hi(i), wp) + 0.5_wp
          exit
        end if
      end do
      if (.not.inside) then
        u = x*(width_0/real(FINE, wp))
        found = .true.
        return
      end if
    end do
  end subroutine table_next_gap

  !> The cursor of table_next_gap past the level-0 panel holding u (whose building left u
  !> without a leaf: an automatic H that failed there; its forces stay exact).
  pure real(wp) function table_skip_panel(u) result(x)
    real(wp), intent(in) :: u
    x = real(panel_lo(u, 0) + FINE, wp) + 0.5_wp
  end function table_skip_panel

  !> What the table holds: exact points, leaves, and of these the exact ones (forces solved
  !> exactly at every visit).
  pure subroutine table_count(t, points, leaves, exact_leaves)
    type(force_table_type), intent(in) :: t
    integer, intent(out) :: points, leaves, exact_leaves
    points = t%n_node
    leaves = t%n_leaf
    exact_leaves = 0
    if (t%n_leaf > 0) exact_leaves = count(t%leaf_status(1:t%n_leaf) == TABLE_EXACT)
  end subroutine table_count

  !> Weights of the quartic through the points 0..4 at x.
  pure function lagrange(x) result(w)
    real(wp), intent(in) :: x
    real(wp) :: w(5)
    integer :: j, k
    do j = 0, 4
      w(j + 1) = 1
      do k = 0, 4
        if (k /= j) w(j + 1) = w(j + 1)*(x - k)/real(j - k, wp)
      end do
    end do
  end function lagrange

  !> Index of the node at (idx, h) in t%node (0: none); nodes are sorted by idx, then h.
  pure integer function find_node(t, idx, h) result(m)
    type(force_table_type), intent(in) :: t
    integer(int64), intent(in) :: idx
    integer, intent(in) :: h
    integer :: lo, hi, mid
    m = 0
    lo = 1
    hi = t%n_node
    do while (lo <= hi)
      mid = (lo + hi)/2
      if (t%node(mid)%idx == idx .and. t%node(mid)%h == h) then
        m = mid
        return
      else if (before(t%node(mid), idx, h)) then
        lo = mid + 1
      else
        hi = mid - 1
      end if
    end do
  end function find_node

  !> Whether node a sorts before (idx, h).
  pure logical function before(a, idx, h)
    type(table_node_type), intent(in) :: a
    integer(int64), intent(in) :: idx
    integer, intent(in) :: h
    before = a%idx < idx .or. (a%idx == idx .and. a%h < h)
  end function before

  logical function table_has_node(t, idx, h)
    type(force_table_type), intent(in) :: t
    integer(int64), intent(in) :: idx
    integer, intent(in) :: h
    table_has_node = find_node(t, idx, h) > 0
  end function table_has_node

  !> Adds the exact point at idx with h harmonics: ok (bounded and solved) with its structure,
  !> outputs y and check scales s, or not ok (y, s ignored).
  subroutine table_add_node(t, idx, h, ok, signature, y, s)
    type(force_table_type), intent(inout) :: t
    integer(int64), intent(in) :: idx
    integer, intent(in) :: h
    logical, intent(in) :: ok
    integer, intent(in) :: signature(SIGNATURE_SIZE)
    real(wp), intent(in) :: y(:), s(:)
    type(table_node_type), allocatable :: grown(:)
    integer :: i, pos
    if (find_node(t, idx, h) > 0) return
    if (.not.allocated(t%node)) allocate(t%node(16))
    if (t%n_node == size(t%node)) then
      allocate(grown(2*size(t%node)))
      do i = 1, t%n_node
        call move_node(t%node(i), grown(i))
      end do
      call move_alloc(grown, t%node)
    end if
    pos = t%n_node + 1
    do i = 1, t%n_node
      if (.not.before(t%node(i), idx, h)) then
        pos = i
        exit
      end if
    end do
    do i = t%n_node, pos, -1
      call move_node(t%node(i), t%node(i + 1))
    end do
    t%n_node = t%n_node + 1
    t%node(pos)%idx = idx
    t%node(pos)%h = h
    t%node(pos)%ok = ok
    t%node(pos)%signature = signature
    t%node(pos)%y = y
    t%node(pos)%s = s
  end subroutine table_add_node

  subroutine move_node(a, b)
    type(table_node_type), intent(inout) :: a, b
    b%idx = a%idx
    b%h = a%h
    b%ok = a%ok
    b%signature = a%signature
    if (allocated(b%y)) deallocate(b%y)
    if (allocated(b%s)) deallocate(b%s)
    if (allocated(a%y)) call move_alloc(a%y, b%y)
    if (allocated(a%s)) call move_alloc(a%s, b%s)
  end subroutine move_node

  !> Judges the panel whose nine nodes (idx, all present) are given: TABLE_VERIFIED (its
  !> halves become leaves answering by interpolation), TABLE_SPLIT (to be halved), or, at the
  !> deepest level, TABLE_EXACT (a leaf answering by exact solves).
  integer function table_judge(t, idx, h, tol, deepest) result(verdict)
    type(force_table_type), intent(inout) :: t
    integer(int64), intent(in) :: idx(9)
    integer, intent(in) :: h
    real(wp), intent(in) :: tol
    logical, intent(in) :: deepest
    real(wp), allocatable :: sc(:)
    real(wp) :: w(5)
    integer :: m(9), j
    logical :: good
    do j = 1, 9
      m(j) = find_node(t, idx(j), h)
    end do
    good = all(m > 0)
    if (good) good = all(t%node(m)%ok)
    if (good) then
      do j = 2, 9
        good = good .and. all(t%node(m(j))%signature == t%node(m(1))%signature)
      end do
    end if
    if (good) then
      sc = t%node(m(1))%s
      do j = 2, 9
        sc = max(sc, t%node(m(j))%s)
      end do
      ! the quartic through the even points at the odd ones, against the exact points there
      do j = 2, 8, 2
        w = lagrange(0.5_wp*(j - 1))
        good = good .and. all(abs(w(1)*t%node(m(1))%y + w(2)*t%node(m(3))%y + &
          & w(3)*t%node(m(5))%y + w(4)*t%node(m(7))%y + w(5)*t%node(m(9))%y - &
          & t%node(m(j))%y) <= tol*sc)
      end do
    end if
    if (good) then
      verdict = TABLE_VERIFIED
      call add_leaf(t, idx(1), idx(5), h, verdict)
      call add_leaf(t, idx(5), idx(9), h, verdict)
    else if (deepest) then
      verdict = TABLE_EXACT
      call add_leaf(t, idx(1), idx(9), h, verdict)
    else
      verdict = TABLE_SPLIT
    end if
  end function table_judge

  subroutine add_leaf(t, lo, hi, h, status)
    type(force_table_type), intent(inout) :: t
    integer(int64), intent(in) :: lo, hi
    integer, intent(in) :: h, status
    t%n_leaf = t%n_leaf + 1
    call put(t%leaf_lo, t%n_leaf, lo)
    call put(t%leaf_hi, t%n_leaf, hi)
    call put(t%leaf_status, t%n_leaf, status)
    call put(t%leaf_h, t%n_leaf, h)
  end subroutine add_leaf
end module udmap_mapping_harmonic_force_table
