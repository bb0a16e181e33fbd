!> The mapping with multi-harmonic layers (PHYSICS.md 4.1): the backbone peaks, the response at
!> a given frequency and the response curves with harmonics 0..H (analysis%harmonics > 1) or
!> an automatic H (analysis%harmonics = 0). With analysis%harmonics = 1 every entry point here
!> is exactly the single-harmonic method (the same code path, the same numbers).
!>
!> Backbone: F_bb(gamma) = min_omega |P(omega; gamma)|; the roots of F_bb = F_E are located by
!> Newton steps in (ln gamma, ln omega) from each single-harmonic root (the multi-harmonic
!> correction is a few percent, so every root has its single-harmonic counterpart to start
!> from), or from the last root with as many harmonics moved by the change of the
!> single-harmonic root; secant steps around full peak searches as the fallback. Every layer on
!> the way is solved on its own (udmap_mapping_harmonic_layer); the previous layer only warm-starts.
!>
!> Automatic H: start at H = 3, raised to every harmonic h <= 6 whose h omega lies within 12 %
!> of a bare-blade mode above mode 1; then compare with the next H of the ladder 3, 5, 7, 9,
!> 13, 17, 25, 33, 49, 64, itself raised to the near-mode harmonics up to twice the current
!> H and to the next near-mode harmonic above it, whatever its order (so no comparison stops
!> short of a harmonic that a bare mode amplifies), until gamma_P,
!> sigma_a, gamma_max, sigma_max and f_res change by less than harmonic_tol (relative); the
!> larger H is reported.
module udmap_mapping_harmonic_mapping
  use udmap_core_kinds, only: wp, pi
  use udmap_core_sorting, only: sort_ascending
  use udmap_core_error, only: error_type, fatal_error, require, UDMAP_EINPUT
  use udmap_damper_type, only: DAMPER_ASYMMETRIC, DAMPER_JENKINS
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_mapping_model_data, only: model_type, point_type, curve_type, limit_force_or_huge, &
    & regime_of, damper_fingerprint, limit_force_backbone, EIGEN_AUTO, EIGEN_MODAL
  use udmap_mapping_backbone, only: backbone_single => backbone, backbone_curve
  use udmap_mapping_response, only: response_single => response
  use udmap_mapping_curves, only: curves_single => response_curves
  use udmap_mapping_harmonic_types, only: harmonic_state_type, harmonic_outputs_type, &
    & HARMONICS_MAX
  use udmap_mapping_harmonic_layer, only: harmonic_setup, harmonic_resize, harmonic_outputs
  use udmap_mapping_harmonic_search, only: harmonic_root, harmonic_peak_root, harmonic_force_root
  use udmap_mapping_harmonic_force_table, only: table_count
  use udmap_mapping_harmonic_table_points, only: table_usable, table_backbone_point, cover_table
  implicit none
  private
  public :: layered, response_curves, harmonics_near_modes, set_harmonics, check_harmonics, &
    & cover_forces, force_table_count

  !> The ladder of H tried by the automatic choice.
  integer, parameter :: ladder(10) = [3, 5, 7, 9, 13, 17, 25, 33, 49, 64]
  !> A harmonic h omega within this relative distance of a bare mode is always included.
  real(wp), parameter :: near_mode = 0.12_wp
  !> Relative tolerance of the layer roots and peaks (far below the 1e-6 agreement asked of
  !> the outputs; the AFT is exact to rounding).
  real(wp), parameter :: rtol_h = 1.0e-10_wp

contains

  !> Changes the harmonics of a built model (1, H up to 64, or 0 for auto) and the tolerance
  !> of the automatic choice; nothing else is recomputed.
  subroutine set_harmonics(model, harmonics, harmonic_tol, error)
    type(model_type), intent(inout) :: model
    integer, intent(in) :: harmonics
    real(wp), intent(in) :: harmonic_tol
    type(error_type), allocatable, intent(out) :: error
    call check_harmonics(harmonics, harmonic_tol, error)
    if (allocated(error)) return
    model%analysis%harmonics = harmonics
    model%analysis%harmonic_tol = harmonic_tol
  end subroutine set_harmonics

  !> The checks of analysis%harmonics and harmonic_tol, as a series of `require` (the model's
  !> analysis and set_harmonics).
  pure subroutine check_harmonics(harmonics, harmonic_tol, error)
    integer, intent(in) :: harmonics
    real(wp), intent(in) :: harmonic_tol
    type(error_type), allocatable, intent(inout) :: error
    call require(harmonics >= 0 .and. harmonics <= HARMONICS_MAX, &
      & "analysis.harmonics must be 1, an integer up to 64, or auto (0)", error)
    call require(harmonic_tol >= 1e-10_wp .and. harmonic_tol <= 0.1_wp, &
      & "analysis.harmonic_tol must lie in [1e-10, 0.1]", error)
  end subroutine check_harmonics

  !> The in-phase points for the forces F_E [N] (at_peak: the peaks of the backbone, PHYSICS.md 4
  !> and 4.1, else the response at f_exc [Hz]): the single-harmonic points, each solved again as
  !> a multi-harmonic point when H /= 1: a backbone point from the force table where it is on,
  !> an unbounded one kept as it is.
  subroutine layered(model, at_peak, f_exc, F_E, points, error)
    type(model_type), intent(inout) :: model
    logical, intent(in) :: at_peak
    real(wp), intent(in) :: f_exc
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(point_type), allocatable :: p1(:)
    integer :: i, em
    em = starts_modal(model)
    call run()
    model%analysis%eigen_method = em
  contains
    subroutine run()
      if (at_peak) then
        call backbone_single(model, F_E, p1, error)
      else
        call response_single(model, f_exc, F_E, p1, error)
      end if
      if (model%analysis%harmonics == 1 .or. allocated(error)) then
        call move_alloc(p1, points)
        return
      end if
      call ensure_element(model, error)
      if (allocated(error)) return
      allocate(points(size(F_E)))
      do i = 1, size(F_E)
        if (at_peak .and. p1(i)%unbounded) then
          points(i) = p1(i)
          cycle
        end if
        if (at_peak .and. table_usable(model)) then
          call table_point(model, p1(i), points(i), error)
        else
          call multi_point(model, p1(i), at_peak, points(i), error)
        end if
        if (allocated(error)) return
      end do
    end subroutine run
  end subroutine layered

  !> The single-harmonic pass that starts the layers (H /= 1) needs only starts: with the
  !> default eigenvalue start and no direct eigen-solve done yet, it takes the secular
  !> equation alone (EIGEN_MODAL), skipping the model's one dense eigen-solve, most of a cold
  !> gg10 (the layers converge to the same roots from either start). The backbone table is
  !> tagged with its start, so a later single-harmonic call builds its own table again and
  !> keeps its numbers bit for bit. Returns the eigen_method to restore afterwards.
  integer function starts_modal(model) result(em)
    type(model_type), intent(inout) :: model
    em = model%analysis%eigen_method
    if (model%analysis%harmonics /= 1 .and. em == EIGEN_AUTO .and. .not.model%have_direct) &
      & model%analysis%eigen_method = EIGEN_MODAL
  end function starts_modal

  !> The backbone point at p1%F_E from the force table (udmap_mapping_harmonic_table_points):
  !> interpolated where a verified panel holds F_E, else solved exactly. Building a panel
  !> solves its points exactly; a point that fails there only makes the panel finer (the asked
  !> force then gets its own exact solve, and its own error if any).
  subroutine table_point(model, p1, point, error)
    type(model_type), intent(inout) :: model
    type(point_type), intent(in) :: p1
    type(point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    logical :: found
    call table_backbone_point(model, p1%F_E, inphase_exact, .false., &
      & limit_force_or_huge(model), point, found)
    if (.not.found) call multi_point(model, p1, .true., point, error)
  end subroutine table_point

  !> The exact multi-harmonic backbone point at F [N] (the force table's solver in phase).
  subroutine inphase_exact(model, F, q, ok)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F
    type(point_type), intent(out) :: q
    logical, intent(out) :: ok
    type(point_type), allocatable :: pn(:)
    type(error_type), allocatable :: err
    call backbone_single(model, [F], pn, err)
    ok = .not.allocated(err)
    if (ok) ok = .not.pn(1)%unbounded
    if (ok) then
      call multi_point(model, pn(1), .true., q, err)
      ok = .not.allocated(err)
    end if
  end subroutine inphase_exact

  !> Covers the forces [F_min, F_max] (F_min > 0) in advance, so that no later backbone call
  !> for a force of the range at the model's current harmonics builds anything: the
  !> single-harmonic table is grown to F_max and, at harmonics /= 1 with the force table on,
  !> the force table gets a leaf at every force of the range, each built by build_panels as a
  !> visit on demand would build it (same panels, same harmonics, same judgement; the exact
  !> points are the same solves, started from the last root instead of the visit's, so they
  !> agree to the layer tolerance rtol_h, not bit for bit). Where the automatic H fails at a
  !> level-0 panel's middle its forces stay exact (as on demand); unbounded forces (zeta = 0
  !> at or above the limit force) need no table and are left out.
  subroutine cover_forces(model, F_min, F_max, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_min, F_max
    type(error_type), allocatable, intent(out) :: error
    type(point_type), allocatable :: p1(:)
    real(wp) :: F_hi
    integer :: em
    call require(F_min > 0 .and. F_min <= F_max .and. F_max < huge(1.0_wp), &
      & "cover_forces: the range must satisfy 0 < F_min <= F_max < inf", error)
    if (allocated(error)) return
    em = starts_modal(model)
    call run()
    model%analysis%eigen_method = em
  contains
    subroutine run()
      ! the single-harmonic table up to F_max (the start of every multi-harmonic point)
      call backbone_single(model, [F_max], p1, error)
      if (allocated(error)) return
      if (model%analysis%harmonics == 1 .or. .not.table_usable(model)) return
      F_hi = F_max
      if (model%undamped) F_hi = min(F_hi, limit_force_or_huge(model), &
        & limit_force_backbone(model))
      if (.not.(F_hi >= F_min)) return
      call ensure_element(model, error)
      if (allocated(error)) return
      call cover_table(model, F_min, F_hi, inphase_exact, .false.)
    end subroutine run
  end subroutine cover_forces

  !> What the model's force table holds (udmap_model_force_table_info): exact points, leaves
  !> and exact leaves.
  subroutine force_table_count(model, points, leaves, exact_leaves)
    type(model_type), intent(in) :: model
    integer, intent(out) :: points, leaves, exact_leaves
    call table_count(model%ftable, points, leaves, exact_leaves)
  end subroutine force_table_count

  !> The response curves (PHYSICS.md 3) for the forces F_E [N]. With H > 1 (or auto: the H
  !> of each force's peak) every point of the single-harmonic curve is solved again as a
  !> multi-harmonic layer at its frequency (|P(omega; gamma)| = F_E from its single-harmonic
  !> amplitude, the previous point warm-starting the other harmonics); a point whose layer
  !> has no amplitude at that frequency (beyond the shifted peak) is left out.
  subroutine response_curves(model, F_E, layers, curves, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    integer, intent(in) :: layers
    type(curve_type), allocatable, intent(out) :: curves(:)
    type(error_type), allocatable, intent(out) :: error
    type(point_type), allocatable :: peaks(:)
    type(error_type), allocatable :: err_point
    type(harmonic_state_type) :: s
    type(harmonic_outputs_type) :: out
    logical, allocatable :: keep(:)
    integer :: i, j, H
    call curves_single(model, F_E, layers, curves, error)
    if (model%analysis%harmonics == 1 .or. allocated(error)) return
    call layered(model, .true., 0.0_wp, F_E, peaks, error)
    if (allocated(error)) return
    do i = 1, size(curves)
      if (peaks(i)%unbounded) cycle
      H = peaks(i)%harmonics
      s = harmonic_state_type()
      call harmonic_resize(s, H)
      associate(c => curves(i))
        allocate(keep(size(c%f)))
        keep = .true.
        do j = 1, size(c%f)
          if (.not.(c%gamma_P(j) > 0)) then
            keep(j) = .false.
            cycle
          end if
          call harmonic_force_root(model%harm, model%blade, F_E(i), c%gamma_P(j), 2*pi*c%f(j), &
            & rtol_h, s, err_point)
          if (allocated(err_point)) then
            deallocate(err_point)
            keep(j) = .false.
            s = harmonic_state_type()
            call harmonic_resize(s, H)
            cycle
          end if
          ! another branch reached from this start: not this point
          if (abs(log(s%gamma/c%gamma_P(j))) > 0.3_wp) then
            keep(j) = .false.
            cycle
          end if
          call harmonic_outputs(model%harm, s, model%blade%has_stress, out)
          c%gamma_P(j) = s%gamma
          c%sigma_a(j) = abs(out%S1)
        end do
        c%f = pack(c%f, keep)
        c%gamma_P = pack(c%gamma_P, keep)
        c%sigma_a = pack(c%sigma_a, keep)
        c%branch = pack(c%branch, keep)
        if (allocated(c%part)) c%part = pack(c%part, keep)
        deallocate(keep)
      end associate
    end do
  end subroutine response_curves

  !> The highest harmonic 2 <= h <= h_cap whose h omega [rad/s] lies within 12 % of a bare
  !> mode above mode 1 (0 if none).
  integer function harmonics_near_modes(model, omega, h_cap) result(hmax)
    type(model_type), intent(in) :: model
    real(wp), intent(in) :: omega
    integer, intent(in) :: h_cap
    hmax = near_mode_harmonic(model, omega, 2, min(h_cap, HARMONICS_MAX), .true.)
  end function harmonics_near_modes

  !> The lowest (highest: the highest) harmonic h_lo <= h <= h_hi whose h omega [rad/s] lies
  !> within near_mode of a bare mode above mode 1 (0 if none). The lowest above H is the next
  !> rung of the automatic H, as truncating just below an amplified harmonic can look
  !> converged (blade A at 3.97 N: H = 6 and 7 agree to 7e-4 in gamma_P, and both are 0.8 %
  !> from H = 46 through the 14th harmonic and above).
  integer function near_mode_harmonic(model, omega, h_lo, h_hi, highest) result(h_near)
    type(model_type), intent(in) :: model
    real(wp), intent(in) :: omega
    integer, intent(in) :: h_lo, h_hi
    logical, intent(in) :: highest
    integer :: h, r
    h_near = 0
    do h = h_lo, h_hi
      do r = 2, size(model%blade%omega)
        if (abs(h*omega/model%blade%omega(r) - 1) <= near_mode) then
          h_near = h
          if (.not.highest) return
          exit
        end if
      end do
    end do
  end function near_mode_harmonic

  !> The contact element of the model's damper, rebuilt when the damper changed.
  subroutine ensure_element(model, error)
    type(model_type), intent(inout) :: model
    type(error_type), allocatable, intent(out) :: error
    type(contact_element_type) :: el
    type(jenkins_element_type) :: jen
    real(wp) :: fp(5)
    fp = damper_fingerprint(model%damper)
    if (allocated(model%harm%element) .and. model%harm%revision == model%damper%revision &
      & .and. all(model%harm%fingerprint == fp)) return
    select case (model%damper%kind)
    case (DAMPER_ASYMMETRIC)
      call new_contact_element(el, model%damper%params, error)
      if (allocated(error)) return
      call harmonic_setup(model%harm, el, model%blade, error)
    case (DAMPER_JENKINS)
      call new_jenkins_element(jen, model%damper%kt, model%damper%M_slip, error)
      if (allocated(error)) return
      call harmonic_setup(model%harm, jen, model%blade, error)
    case default
      call fatal_error(error, "analysis.harmonics: more than one harmonic needs a damper with "// &
        & "a contact model (asymmetric or jenkins); a measured table has no loop to trace", &
        & UDMAP_EINPUT)
      return
    end select
    if (allocated(error)) return
    model%harm%revision = model%damper%revision
    model%harm%fingerprint = fp
    ! a new damper: no warm start from the old one's roots
    if (allocated(model%harm%rung)) deallocate(model%harm%rung)
    allocate(model%harm%rung(HARMONICS_MAX))
  end subroutine ensure_element

  !> The multi-harmonic counterpart of the single-harmonic point p1: every root refined, the
  !> largest giving the outputs; at_peak: backbone (omega free), else at p1%f_res.
  subroutine multi_point(model, p1, at_peak, point, error)
    type(model_type), intent(inout) :: model
    type(point_type), intent(in) :: p1
    logical, intent(in) :: at_peak
    type(point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    type(harmonic_state_type) :: s, s_prev, s_below
    type(harmonic_outputs_type) :: out, out_prev, out_below
    real(wp) :: w
    logical :: jump
    real(wp), allocatable :: roots(:)
    real(wp) :: F_lim, omega1, change
    !> Tolerance of the root searches: the automatic H is only defined to harmonic_tol (its
    !> rungs are compared with each other to it), so its rungs, the chosen one included, are
    !> solved to a thousandth of it (a refinement to rtol_h cost 12 to 15 % of auto); fixed H
    !> and the other roots to rtol_h
    real(wp) :: tol_s
    integer :: H, j, nr, n_new
    logical :: auto

    F_lim = limit_force_or_huge(model)
    nr = size(p1%roots)
    allocate(roots(nr))
    auto = model%analysis%harmonics == 0
    omega1 = 2*pi*p1%f_res
    if (auto) then
      H = max(3, harmonics_near_modes(model, omega1, 6))
    else
      H = model%analysis%harmonics
    end if
    tol_s = rtol_h
    if (auto) tol_s = max(rtol_h, 1.0e-3_wp*model%analysis%harmonic_tol)
    ! the largest root first: it gives the outputs (and, with auto, H)
    call solve_root(p1%gamma_P, omega1, H, s, error)
    if (allocated(error)) return
    call harmonic_outputs(model%harm, s, model%blade%has_stress, out)
    if (auto) then
      do
        if (H >= ladder(size(ladder))) exit
        s_prev = s
        out_prev = out
        H = max(ladder(findloc(ladder > H, .true., 1)), &
          & harmonics_near_modes(model, s%omega, 2*H), near_mode_harmonic(model, s%omega, H + 1, HARMONICS_MAX, .false.))
        call solve_root(s_prev%gamma, s_prev%omega, H, s, error, s_prev)
        if (allocated(error)) return
        call harmonic_outputs(model%harm, s, model%blade%has_stress, out)
        change = max(rel(s%gamma, s_prev%gamma), rel(s%omega, s_prev%omega), &
          & rel(out%gamma_max, out_prev%gamma_max), rel(abs(out%S1), abs(out_prev%S1)), &
          & rel(out%sigma_max, out_prev%sigma_max))
        if (change < model%analysis%harmonic_tol) exit
      end do
      tol_s = rtol_h
    end if
    roots(nr) = s%gamma
    point%F_E = p1%F_E
    point%gamma_P = s%gamma
    point%f_res = s%omega/(2*pi)
    point%k = s%M(1)/s%gamma
    point%sigma_a = abs(out%S1)
    point%u_E = abs(out%U1)
    point%gamma_max = out%gamma_max
    point%sigma_max = out%sigma_max
    point%jump = jump
    if (jump) then
      ! F_bb jumps over F_E at gamma_c (PHYSICS.md 2.5): gamma_P = gamma_c, the other outputs
      ! the convex combination of the layers on both sides that peaks at F_E (in ln F)
      call harmonic_outputs(model%harm, s_below, model%blade%has_stress, out_below)
      w = log(p1%F_E/abs(s_below%P))/log(abs(s%P)/abs(s_below%P))
      point%gamma_P = sqrt(s%gamma*s_below%gamma)
      roots(nr) = point%gamma_P
      point%f_res = ((1 - w)*s_below%omega + w*s%omega)/(2*pi)
      point%k = (1 - w)*s_below%M(1)/s_below%gamma + w*s%M(1)/s%gamma
      point%sigma_a = (1 - w)*abs(out_below%S1) + w*abs(out%S1)
      point%u_E = (1 - w)*abs(out_below%U1) + w*abs(out%U1)
      point%gamma_max = (1 - w)*out_below%gamma_max + w*out%gamma_max
      point%sigma_max = (1 - w)*out_below%sigma_max + w*out%sigma_max
    end if
    point%harmonics = H
    point%gamma_h = out%gamma_h
    point%sigma_h = out%sigma_h
    point%regime = regime_of(model%damper, p1%F_E, F_lim, point%gamma_P)
    ! with more than one harmonic the stress criterion takes the largest excursion
    point%hcf_ok = p1%F_E <= 0.5_wp*F_lim .and. point%sigma_max <= model%analysis%sigma_all &
      & .and. F_lim < huge(1.0_wp)
    point%unbounded = .false.
    ! the other roots, same H
    do j = nr - 1, 1, -1
      s = harmonic_state_type()
      call solve_root(p1%roots(j), omega1, H, s, error)
      if (allocated(error)) return
      roots(j) = s%gamma
    end do
    ! roots ascending, without duplicates (two starts may reach the same root)
    call sort_ascending(roots)
    n_new = 0
    do j = 1, nr
      if (n_new > 0) then
        if (abs(roots(j) - roots(n_new)) <= 1.0e-8_wp*roots(j)) cycle
      end if
      n_new = n_new + 1
      roots(n_new) = roots(j)
    end do
    point%roots = roots(1:n_new)
  contains
    pure real(wp) function rel(a, b)
      real(wp), intent(in) :: a, b
      rel = 0
      if (max(abs(a), abs(b)) > 0) rel = abs(a - b)/max(abs(a), abs(b))
    end function rel

    !> The root near gamma0 (peak near omega0, or at omega0) with H harmonics; warm: a solved
    !> state with fewer harmonics to start from (else a cold start).
    subroutine solve_root(gamma0, omega0, Hs, st, err, warm)
      real(wp), intent(in) :: gamma0, omega0
      integer, intent(in) :: Hs
      type(harmonic_state_type), intent(inout) :: st
      type(error_type), allocatable, intent(out) :: err
      type(harmonic_state_type), intent(in), optional :: warm
      real(wp) :: slope, Fb(2), fr(2)
      logical :: ok
      jump = .false.
      if (present(warm)) then
        st = warm
      else
        st = harmonic_state_type()
      end if
      call harmonic_resize(st, Hs)
      st%omega = omega0
      if (at_peak) then
        if (.not.present(warm) .and. nr == 1 .and. model%harm%rung(Hs)%gamma1 > 0) then
          ! from the last root with Hs harmonics (after a change of F_E alone, the previous
          ! force): its layer, moved by the change of the single-harmonic root
          associate(mem => model%harm%rung(Hs))
            st = mem%root
            call harmonic_peak_root(model%harm, model%blade, p1%F_E, &
              & gamma0*(mem%root%gamma/mem%gamma1), omega0*(mem%root%omega/mem%omega1), &
              & model%omega_lo, model%omega_hi, tol_s, st, ok, err)
          end associate
          if (allocated(err)) return
          if (ok) then
            call remember(st)
            return
          end if
          st = harmonic_state_type()
          call harmonic_resize(st, Hs)
          st%omega = omega0
        end if
        ! (the next rung of the automatic H starts from the last rung's root, in warm)
        call harmonic_peak_root(model%harm, model%blade, p1%F_E, gamma0, omega0, &
          & model%omega_lo, model%omega_hi, tol_s, st, ok, err)
        if (allocated(err)) return
        if (ok) then
          if (nr == 1) call remember(st)
          return
        end if
        ! fallback: a secant on gamma around full peak searches, started with the
        ! single-harmonic slope d ln F_bb/d ln gamma
        call backbone_curve(model, [gamma0*(1 - 1.0e-4_wp), gamma0*(1 + 1.0e-4_wp)], Fb, fr, err)
        if (allocated(err)) return
        slope = log(Fb(2)/Fb(1))/log((1 + 1.0e-4_wp)/(1 - 1.0e-4_wp))
        call harmonic_root(model%harm, model%blade, p1%F_E, gamma0, slope, model%omega_lo, &
          & model%omega_hi, rtol_h, st, err, jump, s_below)
      else
        call harmonic_force_root(model%harm, model%blade, p1%F_E, gamma0, omega0, tol_s, st, &
          & err)
      end if
    end subroutine solve_root

    !> Keeps a root for the next root with as many harmonics.
    subroutine remember(st)
      type(harmonic_state_type), intent(in) :: st
      model%harm%rung(st%H)%root = st
      model%harm%rung(st%H)%gamma1 = p1%gamma_P
      model%harm%rung(st%H)%omega1 = omega1
    end subroutine remember
  end subroutine multi_point
end module udmap_mapping_harmonic_mapping
