!> Backbone points from the force table (udmap_mapping_harmonic_force_table): the panels on the
!> path to a force built from exact points, a point interpolated where a verified leaf holds
!> its force, and a range of forces covered in advance. The exact points come from the caller's
!> solver (exact_point): the in-phase multi-harmonic layers (udmap_mapping_harmonic_mapping) or
!> the traveling-wave layers (udmap_mapping_traveling_backbone), so that both share one table.
!>
!> A point is packed as the table holds it: its outputs (in ln where positive by nature), the
!> scale each is checked on, and its structure (signature: H, roots, jump, harmonic content
!> and, for a traveling wave, the regime its trace found, which the amplitude alone does not
!> give; in phase the regime follows from gamma_P and is not part of it).
module udmap_mapping_harmonic_table_points
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  use udmap_mapping_model_data, only: model_type, point_type, regime_of, damper_fingerprint, &
    & REGIME_LIMIT
  use udmap_mapping_harmonic_types, only: SIGNATURE_SIZE
  use udmap_mapping_harmonic_force_table, only: table_reset, table_lookup, table_first_visit, &
    & table_panel, table_has_node, table_add_node, table_judge, node_force, &
    & table_panel_harmonics, table_set_panel_harmonics, table_position, table_next_gap, &
    & table_skip_panel, TABLE_VERIFIED, TABLE_MISSING, TABLE_SPLIT, LEVEL_MAX
  implicit none
  private
  public :: exact_point, table_usable, table_backbone_point, cover_table, reset_table

  !> The force table interpolates to harmonic_tol times this, and is not used below
  !> table_tol_min (exact points are then cheaper than a table that fine).
  real(wp), parameter :: table_share = 1.0e-3_wp, table_tol_min = 1.0e-9_wp
  !> At the deepest level (panels 3e-4 wide in ln F_E) the check takes harmonic_tol times this
  !> instead: a panel that still fails there has exact points that scatter by more than
  !> table_share (the automatic H at some 46 harmonics: f_res rough at 1e-5), and
  !> interpolating them is as good as solving them again; panels whose structure changes
  !> (H, roots, jump, regime) stay exact.
  real(wp), parameter :: deepest_share = 1.0e-1_wp

  abstract interface
    !> The exact backbone point at F [N] at the model's harmonics (0: auto, reporting the H it
    !> chose); ok = .false. where there is none (a failed or unbounded point: its panel then
    !> stays exact).
    subroutine exact_point(model, F, q, ok)
      import :: model_type, point_type, wp
      type(model_type), intent(inout) :: model
      real(wp), intent(in) :: F
      type(point_type), intent(out) :: q
      logical, intent(out) :: ok
    end subroutine exact_point
  end interface

contains

  !> The model's backbone points may come from the force table: it is on, and its tolerance
  !> (harmonic_tol/1000) is not below table_tol_min.
  pure logical function table_usable(model)
    type(model_type), intent(in) :: model
    table_usable = model%force_table .and. &
      & table_share*model%analysis%harmonic_tol >= table_tol_min
  end function table_usable

  !> The backbone point at F [N] from the force table (found), interpolated where a verified
  !> leaf holds F; the panels on the path to F are built on the second visit of its level-0
  !> panel (the first force in it is left to the caller's exact solve). traveling: the
  !> signature keeps the regime; F_lim [N] gives regime 3 and hcf_ok as for an exact point.
  subroutine table_backbone_point(model, F, solve, traveling, F_lim, point, found)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F, F_lim
    procedure(exact_point) :: solve
    logical, intent(in) :: traveling
    type(point_type), intent(out) :: point
    logical, intent(out) :: found
    real(wp), allocatable :: y(:)
    real(wp) :: u
    integer :: status, sig(SIGNATURE_SIZE)
    call reset_table(model)
    u = log(F)
    call table_lookup(model%ftable, u, status, y, sig)
    if (status == TABLE_MISSING) then
      if (.not.table_first_visit(model%ftable, u)) then
        call build_panels(model, u, solve, traveling)
        call table_lookup(model%ftable, u, status, y, sig)
      end if
    end if
    found = status == TABLE_VERIFIED
    if (found) call unpack_point(model, F, y, sig, F_lim, point)
  end subroutine table_backbone_point

  !> Gives every force of [F_lo, F_hi] (0 < F_lo <= F_hi) its leaf, each built by build_panels
  !> as a visit on demand would build it (same panels, same harmonics, same judgement).
  subroutine cover_table(model, F_lo, F_hi, solve, traveling)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_lo, F_hi
    procedure(exact_point) :: solve
    logical, intent(in) :: traveling
    real(wp), allocatable :: y(:)
    real(wp) :: u, x
    integer :: status, sig(SIGNATURE_SIZE)
    logical :: found, first
    call reset_table(model)
    x = table_position(log(F_lo))
    do
      call table_next_gap(model%ftable, x, log(F_hi), u, found)
      if (.not.found) exit
      ! the visit recorded (build_panels needs it), then the building a second visit does
      first = table_first_visit(model%ftable, u)
      call build_panels(model, u, solve, traveling)
      call table_lookup(model%ftable, u, status, y, sig)
      if (status == TABLE_MISSING) x = table_skip_panel(u)
    end do
  end subroutine cover_table

  !> Empties the force table unless it was built for the model's damper, harmonics,
  !> harmonic_tol and interblade phase.
  subroutine reset_table(model)
    type(model_type), intent(inout) :: model
    call table_reset(model%ftable, [real(model%damper%revision, wp), &
      & damper_fingerprint(model%damper), real(model%analysis%harmonics, wp), &
      & model%analysis%harmonic_tol, model%analysis%ibpa_deg])
  end subroutine reset_table

  !> The panels of the force table on the path to u = ln F_E, down to a verified or exact leaf,
  !> with every point at the panel's harmonics (auto: the H chosen at the middle of the
  !> level-0 panel, solved then at that fixed H); u's level-0 panel must have been visited.
  subroutine build_panels(model, u, solve, traveling)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: u
    procedure(exact_point) :: solve
    logical, intent(in) :: traveling
    integer(int64) :: idx(9)
    integer :: H, harmonics, L, j
    real(wp) :: F_mid
    type(point_type) :: q
    logical :: ok
    harmonics = model%analysis%harmonics
    H = harmonics
    if (harmonics == 0) then
      call table_panel_harmonics(model%ftable, u, H, F_mid)
      if (H == 0) then
        call solve(model, F_mid, q, ok)
        H = merge(q%harmonics, -1, ok)
        call table_set_panel_harmonics(model%ftable, u, H)
      end if
      if (H < 0) return
    end if
    model%analysis%harmonics = H
    do L = 0, LEVEL_MAX
      idx = table_panel(u, L)
      do j = 1, 9
        if (.not.table_has_node(model%ftable, idx(j), H)) call add_node(idx(j))
      end do
      if (table_judge(model%ftable, idx, H, merge(deepest_share, table_share, &
        & L == LEVEL_MAX)*model%analysis%harmonic_tol, L == LEVEL_MAX) /= TABLE_SPLIT) exit
    end do
    model%analysis%harmonics = harmonics
  contains
    subroutine add_node(at)
      integer(int64), intent(in) :: at
      real(wp), allocatable :: yn(:), sn(:)
      integer :: sn_sig(SIGNATURE_SIZE)
      call solve(model, node_force(at), q, ok)
      if (ok) call pack_point(q, traveling, yn, sn, sn_sig, ok)
      if (ok) then
        call table_add_node(model%ftable, at, H, .true., sn_sig, yn, sn)
      else
        call table_add_node(model%ftable, at, H, .false., spread(0, 1, SIGNATURE_SIZE), &
          & [real(wp) ::], [real(wp) ::])
      end if
    end subroutine add_node
  end subroutine build_panels

  !> A backbone point as the force table holds it: y the outputs, s the scale each is checked
  !> on (1: relative, in ln), signature its structure. ok = .false. for a point the table
  !> cannot hold (a zero where a logarithm is taken).
  subroutine pack_point(p, traveling, y, s, signature, ok)
    type(point_type), intent(in) :: p
    logical, intent(in) :: traveling
    real(wp), allocatable, intent(out) :: y(:), s(:)
    integer, intent(out) :: signature(SIGNATURE_SIZE)
    logical, intent(out) :: ok
    integer :: nr, nh
    nr = size(p%roots)
    nh = 0
    if (allocated(p%gamma_h)) nh = size(p%gamma_h)
    signature = [p%harmonics, nr, merge(1, 0, p%jump), nh, merge(p%regime + 1, 0, traveling)]
    ok = p%gamma_P > 0 .and. p%f_res > 0 .and. p%u_E > 0 .and. p%gamma_max > 0 .and. &
      & all(p%roots > 0) .and. nr > 0
    if (ok .and. nh > 0) ok = size(p%sigma_h) == nh
    if (.not.ok) return
    y = [log(p%gamma_P), log(p%f_res), p%sigma_a, log(p%u_E), real(p%k, wp), aimag(p%k), &
      & log(p%gamma_max), p%sigma_max, log(p%roots)]
    s = [1.0_wp, 1.0_wp, p%sigma_a, 1.0_wp, abs(p%k), abs(p%k), 1.0_wp, p%sigma_max, &
      & spread(1.0_wp, 1, nr)]
    if (nh > 0) then
      y = [y, p%gamma_h, p%sigma_h]
      s = [s, spread(p%gamma_max, 1, nh), spread(p%sigma_max, 1, nh)]
    end if
  end subroutine pack_point

  !> The point at F_E from the interpolated outputs y (pack_point's order) and their
  !> structure; regime and hcf_ok follow from them and F_lim [N] as for an exact point.
  subroutine unpack_point(model, F_E, y, signature, F_lim, p)
    type(model_type), intent(in) :: model
    real(wp), intent(in) :: F_E, y(:), F_lim
    integer, intent(in) :: signature(SIGNATURE_SIZE)
    type(point_type), intent(out) :: p
    integer :: nr, nh
    nr = signature(2)
    nh = signature(4)
    p%F_E = F_E
    p%gamma_P = exp(y(1))
    p%f_res = exp(y(2))
    p%sigma_a = y(3)
    p%u_E = exp(y(4))
    p%k = cmplx(y(5), y(6), wp)
    p%gamma_max = exp(y(7))
    p%sigma_max = y(8)
    p%roots = exp(y(9:8+nr))
    p%roots(nr) = p%gamma_P
    if (nh > 0) then
      p%gamma_h = y(9+nr:8+nr+nh)
      p%sigma_h = y(9+nr+nh:8+nr+2*nh)
    end if
    p%harmonics = signature(1)
    p%jump = signature(3) == 1
    p%unbounded = .false.
    if (signature(5) > 0) then
      p%regime = signature(5) - 1
      if (F_E >= F_lim) p%regime = REGIME_LIMIT
    else
      p%regime = regime_of(model%damper, F_E, F_lim, p%gamma_P)
    end if
    p%hcf_ok = F_E <= 0.5_wp*F_lim .and. p%sigma_max <= model%analysis%sigma_all .and. &
      & F_lim < huge(1.0_wp)
  end subroutine unpack_point
end module udmap_mapping_harmonic_table_points
