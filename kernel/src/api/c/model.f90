!> C API, mapping and backbone (wrappers/c/udmap.h, section "mapping, backbone").
!> A udmap_model handle points to a c_model_type allocated here: the model (which borrows the
!> blade and damper the handles point to) and the last response curves computed with it.
module udmap_api_c_model
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, &
    & c_loc, c_int, c_double
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input, take_handle, &
    & copy_out
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type
  ! udmap_analysis and its conversions, generated from kernel/parameters.toml
  use udmap_api_c_parameters, only: c_analysis_type, analysis_from_c, analysis_to_c
  use udmap_mapping_model, only: is_traveling, cover_forces
  use udmap_mapping_model, only: model_type, analysis_type, point_type, curve_type, new_model, &
    & set_damper, limit_force, backbone_curve, backbone, response, response_curves, &
    & limit_force_backbone, set_harmonics, set_ibpa, admissible_force
  use udmap_mapping_model_data, only: regime_of, check_forces, REGIME_LIMIT
  use udmap_mapping_harmonic_mapping, only: force_table_count
  implicit none
  private
  public :: c_analysis_type, c_point_type, c_model_type, traced_damper_type, model_from_handle

  !> A damper traced by udmap_model_designs for one parameter block (bit for bit), or the
  !> error its tracing gave; kept in the model handle between calls.
  type :: traced_damper_type
    logical :: used = .false.
    integer(int64) :: key(16) = 0
    type(damper_type) :: damper
    type(error_type), allocatable :: error
  end type traced_damper_type

  !> Largest number of roots a udmap_point carries (UDMAP_MAX_ROOTS).
  integer, parameter :: max_roots = 8

  !> struct udmap_point.
  type, bind(C) :: c_point_type
    real(c_double) :: F_E, gamma_P, f_res, sigma_a, u_E, k_re, k_im
    integer(c_int) :: regime, hcf_ok, unbounded, nroots
    real(c_double) :: roots(max_roots)
    real(c_double) :: gamma_max, sigma_max
    integer(c_int) :: harmonics
  end type c_point_type

  !> What a udmap_model handle points to.
  type :: c_model_type
    type(model_type) :: model
    type(curve_type), allocatable :: curves(:)
    !> Per point of the last udmap_model_backbone call: gamma_P lies at a jump of k.
    logical, allocatable :: jump(:)
    !> The points of the last backbone or response call (for their harmonic content).
    type(point_type), allocatable :: last(:)
    !> Dampers traced by udmap_model_designs (a few, reused round-robin from next_traced); the
    !> array is allocated once, so that the model may point at its elements.
    type(traced_damper_type), allocatable :: traced(:)
    integer :: next_traced = 1
  end type c_model_type

contains

  !> Default analysis settings (the band is left 0: it must be set).
  subroutine udmap_analysis_defaults(analysis) bind(C, name="udmap_analysis_defaults")
    type(c_analysis_type), intent(out) :: analysis
    type(analysis_type) :: a
    analysis = analysis_to_c(a)  ! f_min = f_max = 0
  end subroutine udmap_analysis_defaults

  !> int udmap_new_model(error, blade, damper, const udmap_analysis *, udmap_model *): couples the
  !> blade and damper handles (borrowed) over the band.
  function udmap_new_model(errh, bladeh, damperh, analysis, modelh) result(stat) &
      & bind(C, name="udmap_new_model")
    type(c_ptr), value :: errh, bladeh, damperh
    type(c_analysis_type), intent(in) :: analysis
    type(c_ptr), intent(out) :: modelh
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(blade_type), pointer :: blade
    type(damper_type), pointer :: damper
    type(c_model_type), pointer :: m
    type(analysis_type) :: a
    call clear_error(errh)
    modelh = c_null_ptr
    call check_handle(bladeh, "blade", error)
    call check_handle(damperh, "damper", error)
    if (.not.allocated(error)) then
      call c_f_pointer(bladeh, blade)
      call c_f_pointer(damperh, damper)
      a = analysis_from_c(analysis)
      allocate(m)
      call new_model(m%model, blade, damper, a, error)
      if (allocated(error)) then
        deallocate(m)
      else
        modelh = c_loc(m)
      end if
    end if
    stat = set_error(errh, error)
  end function udmap_new_model

  !> void udmap_delete_model(udmap_model *): frees the model (not the blade or damper).
  subroutine udmap_delete_model(modelh) bind(C, name="udmap_delete_model")
    type(c_ptr), intent(inout) :: modelh
    type(c_model_type), pointer :: m
    if (.not.c_associated(modelh)) return
    call c_f_pointer(take_handle(modelh), m)
    deallocate(m)
  end subroutine udmap_delete_model

  !> int udmap_model_set_damper(error, model, damper): couples another damper.
  function udmap_model_set_damper(errh, modelh, damperh) result(stat) &
      & bind(C, name="udmap_model_set_damper")
    type(c_ptr), value :: errh, modelh, damperh
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    type(damper_type), pointer :: damper
    call model_from_handle(errh, modelh, m, error)
    call check_handle(damperh, "damper", error)
    if (.not.allocated(error)) then
      call c_f_pointer(damperh, damper)
      call set_damper(m%model, damper, error)
      if (allocated(m%curves)) deallocate(m%curves)
    end if
    stat = set_error(errh, error)
  end function udmap_model_set_damper

  !> int udmap_model_limit_force(error, model, double *F_lim) [N].
  function udmap_model_limit_force(errh, modelh, F_lim) result(stat) &
      & bind(C, name="udmap_model_limit_force")
    type(c_ptr), value :: errh, modelh
    real(c_double), intent(out) :: F_lim
    integer(c_int) :: stat
    stat = model_limit(errh, modelh, F_lim, backbone_level=.false.)
  end function udmap_model_limit_force

  !> int udmap_model_limit_force_backbone(error, model, double *F_lim_backbone) [N]: the level
  !> F_bb approaches without structural damping (PHYSICS.md 5); equal to F_lim unless lift-off
  !> lowers it. With zeta = 0 the unbounded flag and, always, hcf_ok and the regime are
  !> judged against the smaller of F_lim and F_lim_backbone.
  function udmap_model_limit_force_backbone(errh, modelh, F) result(stat) &
      & bind(C, name="udmap_model_limit_force_backbone")
    type(c_ptr), value :: errh, modelh
    real(c_double), intent(out) :: F
    integer(c_int) :: stat
    stat = model_limit(errh, modelh, F, backbone_level=.true.)
  end function udmap_model_limit_force_backbone

  !> int udmap_model_admissible_force(error, model, F_lim, sigma_all, rtol, double *F_adm):
  !> the largest F_E <= F_lim/2 whose resonant stress (sigma_a; sigma_max with more than one
  !> harmonic) is at most sigma_all [Pa], refined to rtol (udmap_mapping_admissible); F_lim [N] as
  !> the caller takes it (the smaller of F_lim and F_lim_backbone for the DOE).
  function udmap_model_admissible_force(errh, modelh, F_lim, sigma_all, rtol, F_adm) &
      & result(stat) bind(C, name="udmap_model_admissible_force")
    type(c_ptr), value :: errh, modelh
    real(c_double), value :: F_lim, sigma_all, rtol
    real(c_double), intent(out) :: F_adm
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    real(wp) :: value
    F_adm = 0
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) then
      call admissible_force(m%model, real(F_lim, wp), real(sigma_all, wp), real(rtol, wp), &
        & value, error)
      if (.not.allocated(error)) F_adm = value
    end if
    stat = set_error(errh, error)
  end function udmap_model_admissible_force

  !> int udmap_model_classify(error, model, F_lim, n, F_E, gamma_P, sigma, unbounded, regime,
  !> hcf_ok): the regime and HCF admissibility of n points as the backbone gives them, for
  !> points computed elsewhere (e.g. by the standard method): regime_of against the damper's
  !> gamma_s and gamma_b, and hcf_ok = F_E <= F_lim/2 and sigma <= sigma_all of the model's
  !> analysis; an unbounded point (unbounded(i) /= 0) is REGIME_LIMIT and not admissible.
  !> F_lim [N] as the caller takes it (the backbone: the smaller of F_lim and F_lim_backbone;
  !> +inf: no limit known, as for a damper without slip moment range).
  function udmap_model_classify(errh, modelh, F_lim, n, F_E, gamma_P, sigma, unbounded, &
      & regime, hcf_ok) result(stat) bind(C, name="udmap_model_classify")
    type(c_ptr), value :: errh, modelh
    real(c_double), value :: F_lim
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*), gamma_P(*), sigma(*)
    integer(c_int), intent(in) :: unbounded(*)
    integer(c_int), intent(out) :: regime(*), hcf_ok(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    integer :: i
    character(len=12) :: buf
    call model_from_handle(errh, modelh, m, error)
    call check_input(n >= 0, "classify: n must not be negative", error)
    call check_input(F_lim > 0, "classify: F_lim must be positive [N]", error)
    if (.not.allocated(error)) call check_forces(F_E(1:n), "classify", error)
    do i = 1, n
      if (allocated(error)) exit
      if (unbounded(i) /= 0) cycle
      write(buf, "(i0)") i
      call check_input(gamma_P(i) >= 0, "classify: gamma_P("//trim(buf)//") must not be "// &
        & "negative [rad]", error)
      call check_input(sigma(i) >= 0, "classify: sigma("//trim(buf)//") must not be "// &
        & "negative [Pa]", error)
    end do
    if (.not.allocated(error)) then
      do i = 1, n
        if (unbounded(i) /= 0) then
          regime(i) = REGIME_LIMIT
          hcf_ok(i) = 0
        else
          regime(i) = regime_of(m%model%damper, F_E(i), F_lim, gamma_P(i))
          hcf_ok(i) = merge(1, 0, F_E(i) <= 0.5_wp*F_lim .and. &
            & sigma(i) <= m%model%analysis%sigma_all .and. F_lim < huge(1.0_wp))
        end if
      end do
    end if
    stat = set_error(errh, error)
  end function udmap_model_classify

  !> F_lim or, backbone_level, F_lim_backbone (computed after F_lim); the status.
  function model_limit(errh, modelh, F, backbone_level) result(stat)
    type(c_ptr), intent(in) :: errh, modelh
    real(c_double), intent(out) :: F
    logical, intent(in) :: backbone_level
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    real(wp) :: value
    F = 0
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) then
      call limit_force(m%model, value, error)
      if (.not.allocated(error)) then
        F = value
        ! at phi /= 0, F_lim(phi) is the supremum of the backbone itself (PHYSICS.md 2.6)
        if (backbone_level .and. .not. is_traveling(m%model)) F = limit_force_backbone(m%model)
      end if
    end if
    stat = set_error(errh, error)
  end function model_limit

  !> int udmap_model_backbone_jumps(error, model, n, int *jump): per point of the last
  !> udmap_model_backbone call (n of them) 1 if gamma_P is the amplitude gamma_c of a jump of
  !> k(gamma), with k interpolated between its one-sided values (PHYSICS.md 2.5), else 0.
  function udmap_model_backbone_jumps(errh, modelh, n, jump) result(stat) &
      & bind(C, name="udmap_model_backbone_jumps")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: n
    integer(c_int), intent(out) :: jump(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) then
      if (.not.allocated(m%jump)) then
        call fatal_error(error, "backbone_jumps: no udmap_model_backbone call yet", UDMAP_EINPUT)
      else if (n /= size(m%jump)) then
        call fatal_error(error, "backbone_jumps: n must equal the number of points of the "// &
          & "last udmap_model_backbone call", UDMAP_EINPUT)
      else
        jump(1:n) = merge(1_c_int, 0_c_int, m%jump)
      end if
    end if
    stat = set_error(errh, error)
  end function udmap_model_backbone_jumps

  !> int udmap_model_backbone_curve(error, model, n, gamma, F_bb, f_res): F_bb [N] and the
  !> peak frequency [Hz] at n amplitudes [rad].
  function udmap_model_backbone_curve(errh, modelh, n, gamma, F_bb, f_res) result(stat) &
      & bind(C, name="udmap_model_backbone_curve")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: n
    real(c_double), intent(in) :: gamma(*)
    real(c_double), intent(out) :: F_bb(*), f_res(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    real(wp), allocatable :: Fb(:), fr(:)
    call model_from_handle(errh, modelh, m, error)
    call check_input(n >= 0, "backbone_curve: n must not be negative", error)
    if (.not.allocated(error)) then
      allocate(Fb(n), fr(n))
      call backbone_curve(m%model, gamma(1:n), Fb, fr, error)
      if (.not.allocated(error)) then
        F_bb(1:n) = Fb
        f_res(1:n) = fr
      end if
    end if
    stat = set_error(errh, error)
  end function udmap_model_backbone_curve

  !> The C struct of a result point (at most max_roots roots: the largest ones), by a structure
  !> constructor: the compiler checks that every field is set.
  pure function to_c_point(p) result(c)
    type(point_type), intent(in) :: p
    type(c_point_type) :: c
    real(c_double) :: roots(max_roots)
    integer :: nr
    roots = 0
    nr = 0
    if (allocated(p%roots)) nr = min(size(p%roots), max_roots)
    if (nr > 0) roots(1:nr) = p%roots(size(p%roots) - nr + 1:)
    c = c_point_type(F_E=p%F_E, gamma_P=p%gamma_P, f_res=p%f_res, sigma_a=p%sigma_a, &
      & u_E=p%u_E, k_re=real(p%k, wp), k_im=aimag(p%k), regime=p%regime, &
      & hcf_ok=merge(1, 0, p%hcf_ok), unbounded=merge(1, 0, p%unbounded), nroots=nr, &
      & roots=roots, gamma_max=p%gamma_max, sigma_max=p%sigma_max, harmonics=p%harmonics)
  end function to_c_point

  !> int udmap_model_backbone(error, model, n, F_E, udmap_point *): the n resonance peaks.
  function udmap_model_backbone(errh, modelh, n, F_E, points) result(stat) &
      & bind(C, name="udmap_model_backbone")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_point_type), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = model_points(errh, modelh, n, F_E, points)
  end function udmap_model_backbone

  !> int udmap_model_response(error, model, f_exc, n, F_E, udmap_point *): the response at
  !> f_exc [Hz].
  function udmap_model_response(errh, modelh, f_exc, n, F_E, points) result(stat) &
      & bind(C, name="udmap_model_response")
    type(c_ptr), value :: errh, modelh
    real(c_double), value :: f_exc
    integer(c_int), value :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_point_type), intent(out) :: points(*)
    integer(c_int) :: stat
    stat = model_points(errh, modelh, n, F_E, points, f_exc)
  end function udmap_model_response

  !> The backbone points of n forces or, given f_exc, the response at f_exc; kept for
  !> udmap_model_point_harmonics (and the jumps of the backbone for udmap_model_backbone_jumps).
  function model_points(errh, modelh, n, F_E, points, f_exc) result(stat)
    type(c_ptr), intent(in) :: errh, modelh
    integer(c_int), intent(in) :: n
    real(c_double), intent(in) :: F_E(*)
    type(c_point_type), intent(out) :: points(*)
    real(c_double), intent(in), optional :: f_exc
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    type(point_type), allocatable :: p(:)
    integer :: i
    call model_from_handle(errh, modelh, m, error)
    if (present(f_exc)) then
      call check_input(n >= 0, "response: n must not be negative", error)
    else
      call check_input(n >= 0, "backbone: n must not be negative", error)
    end if
    if (.not.allocated(error)) then
      if (present(f_exc)) then
        call response(m%model, f_exc, F_E(1:n), p, error)
      else
        if (allocated(m%jump)) deallocate(m%jump)
        call backbone(m%model, F_E(1:n), p, error)
      end if
      if (.not.allocated(error)) then
        do i = 1, n
          points(i) = to_c_point(p(i))
        end do
        if (.not.present(f_exc)) m%jump = p(1:n)%jump
        call move_alloc(p, m%last)
      end if
    end if
    stat = set_error(errh, error)
  end function model_points

  !> int udmap_model_set_harmonics(error, model, harmonics, harmonic_tol): harmonics of the
  !> platform rotation for the next calls (1: the single-harmonic method; H = 2..64: harmonics
  !> 0..H in multi-harmonic layers; 0: automatic, raised until the outputs change by less than
  !> harmonic_tol, in [1e-10, 0.1]). Keeps everything the model has cached.
  function udmap_model_set_harmonics(errh, modelh, harmonics, harmonic_tol) result(stat) &
      & bind(C, name="udmap_model_set_harmonics")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: harmonics
    real(c_double), value :: harmonic_tol
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) then
      call set_harmonics(m%model, int(harmonics), real(harmonic_tol, wp), error)
    end if
    stat = set_error(errh, error)
  end function udmap_model_set_harmonics

  !> int udmap_model_set_ibpa(error, model, ibpa_deg): the interblade phase angle [deg] of the
  !> next calls (as udmap_analysis.ibpa_deg), keeping everything the model has cached.
  function udmap_model_set_ibpa(errh, modelh, ibpa_deg) result(stat) &
      & bind(C, name="udmap_model_set_ibpa")
    type(c_ptr), value :: errh, modelh
    real(c_double), value :: ibpa_deg
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) call set_ibpa(m%model, real(ibpa_deg, wp), error)
    stat = set_error(errh, error)
  end function udmap_model_set_ibpa

  !> int udmap_model_set_force_table(error, model, on): with on /= 0, backbone points at
  !> harmonics /= 1 come from the force table (udmap_mapping_harmonic_force_table; what the FMU uses
  !> after a change of F_E alone): interpolated to harmonic_tol/1000 where a verified panel of exact
  !> points holds F_E, solved exactly elsewhere. Off (0) by default.
  function udmap_model_set_force_table(errh, modelh, on) result(stat) &
      & bind(C, name="udmap_model_set_force_table")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: on
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) m%model%force_table = on /= 0
    stat = set_error(errh, error)
  end function udmap_model_set_force_table

  !> int udmap_model_cover_forces(error, model, F_min, F_max): prepares the model so that a
  !> later udmap_model_backbone for forces in [F_min, F_max] [N] (0 < F_min <= F_max, finite)
  !> at the current harmonics builds nothing: the single-harmonic backbone table is grown to
  !> F_max and, at harmonics /= 1 with the force table on, the force table gets every panel the
  !> range needs (as visits on demand would build them; the answers agree with those of a table
  !> built on demand to the layer tolerance, far inside harmonic_tol/1000). A traveling-wave
  !> model with the force table on gets its panels at every H, H = 1 included. The cover holds
  !> until the damper, the harmonics or harmonic_tol change.
  function udmap_model_cover_forces(errh, modelh, F_min, F_max) result(stat) &
      & bind(C, name="udmap_model_cover_forces")
    type(c_ptr), value :: errh, modelh
    real(c_double), value :: F_min, F_max
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) call check_input(F_min > 0 .and. F_min <= F_max .and. &
      & F_max < huge(1.0_c_double), "cover_forces: the forces must satisfy 0 < F_min <= "// &
      & "F_max < inf", error)
    if (.not.allocated(error)) &
      & call cover_forces(m%model, real(F_min, wp), real(F_max, wp), error)
    stat = set_error(errh, error)
  end function udmap_model_cover_forces

  !> int udmap_model_force_table_info(error, model, int *points, int *leaves,
  !> int *exact_leaves): what the model's force table holds now: its exact points (each one
  !> layer solve; a count that grows only when panels are built), its leaves, and of these the
  !> ones whose forces are solved exactly at every visit.
  function udmap_model_force_table_info(errh, modelh, points, leaves, exact_leaves) &
      & result(stat) bind(C, name="udmap_model_force_table_info")
    type(c_ptr), value :: errh, modelh
    integer(c_int), intent(out) :: points, leaves, exact_leaves
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    integer :: np, nl, ne
    points = 0
    leaves = 0
    exact_leaves = 0
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) then
      call force_table_count(m%model, np, nl, ne)
      points = np
      leaves = nl
      exact_leaves = ne
    end if
    stat = set_error(errh, error)
  end function udmap_model_force_table_info

  !> int udmap_model_point_harmonics(error, model, i, nmax, gamma_h, sigma_h, int *nh): the
  !> harmonic content of point i (0-based) of the last udmap_model_backbone or
  !> udmap_model_response call: |Gamma_h| [rad] and |sigma_h| [Pa] for h = 0..nh - 1 (at most
  !> nmax values each). nh = 2 (harmonics 0 and 1, harmonic 0 not computed: 0) for a
  !> single-harmonic point.
  function udmap_model_point_harmonics(errh, modelh, i, nmax, gamma_h, sigma_h, nh) &
      & result(stat) bind(C, name="udmap_model_point_harmonics")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: i, nmax
    real(c_double), intent(out) :: gamma_h(*), sigma_h(*)
    integer(c_int), intent(out) :: nh
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    nh = 0
    call model_from_handle(errh, modelh, m, error)
    if (.not.allocated(error)) then
      if (.not.allocated(m%last)) then
        call fatal_error(error, "point_harmonics: no backbone or response computed yet", &
          & UDMAP_EINPUT)
      else if (i < 0 .or. i >= size(m%last)) then
        call fatal_error(error, "point_harmonics: index out of range", UDMAP_EINPUT)
      else if (nmax < 0) then
        call fatal_error(error, "point_harmonics: nmax must not be negative", UDMAP_EINPUT)
      else
        associate(p => m%last(i + 1))
          if (allocated(p%gamma_h)) then
            nh = int(size(p%gamma_h), c_int)
            call copy_out(p%gamma_h, gamma_h, int(nmax))
            call copy_out(p%sigma_h, sigma_h, int(nmax))
          else
            nh = 2
            call copy_out([0.0_wp, p%gamma_P], gamma_h, int(nmax))
            call copy_out([0.0_wp, p%sigma_a], sigma_h, int(nmax))
          end if
        end associate
      end if
    end if
    stat = set_error(errh, error)
  end function udmap_model_point_harmonics

  !> int udmap_model_curves(error, model, n, F_E, layers): computes and keeps the response
  !> curves of n forces.
  function udmap_model_curves(errh, modelh, n, F_E, layers) result(stat) &
      & bind(C, name="udmap_model_curves")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: n, layers
    real(c_double), intent(in) :: F_E(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    call model_from_handle(errh, modelh, m, error)
    call check_input(n >= 0, "curves: n must not be negative", error)
    if (.not.allocated(error)) then
      if (allocated(m%curves)) deallocate(m%curves)
      call response_curves(m%model, F_E(1:n), int(layers), m%curves, error)
      if (allocated(error) .and. allocated(m%curves)) deallocate(m%curves)
    end if
    stat = set_error(errh, error)
  end function udmap_model_curves

  !> The model behind a C handle (clearing the error handle first), or the NULL-handle error.
  subroutine model_from_handle(errh, modelh, m, error)
    type(c_ptr), intent(in) :: errh, modelh
    type(c_model_type), pointer, intent(out) :: m
    type(error_type), allocatable, intent(out) :: error
    call clear_error(errh)
    m => null()
    call check_handle(modelh, "model", error)
    if (.not.allocated(error)) call c_f_pointer(modelh, m)
  end subroutine model_from_handle

  !> The stored curve i (0-based), or an error.
  subroutine get_curve(errh, modelh, i, m, error)
    type(c_ptr), intent(in) :: errh, modelh
    integer(c_int), intent(in) :: i
    type(c_model_type), pointer, intent(out) :: m
    type(error_type), allocatable, intent(out) :: error
    call model_from_handle(errh, modelh, m, error)
    if (allocated(error)) return
    if (.not.allocated(m%curves)) then
      call fatal_error(error, "curves: none computed yet (call udmap_model_curves)", UDMAP_EINPUT)
    else if (i < 0 .or. i >= size(m%curves)) then
      call fatal_error(error, "curves: index out of range", UDMAP_EINPUT)
    end if
  end subroutine get_curve

  !> int udmap_model_curve_size(error, model, i, int *npoints): points of kept curve i (0-based).
  function udmap_model_curve_size(errh, modelh, i, npoints) result(stat) &
      & bind(C, name="udmap_model_curve_size")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: i
    integer(c_int), intent(out) :: npoints
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    npoints = 0
    call get_curve(errh, modelh, i, m, error)
    if (.not.allocated(error)) npoints = int(size(m%curves(i + 1)%f), c_int)
    stat = set_error(errh, error)
  end function udmap_model_curve_size

  !> int udmap_model_curve_get(error, model, i, npoints, f_hz, gamma_P, sigma_a, branch, part):
  !> copies kept curve i (0-based).
  function udmap_model_curve_get(errh, modelh, i, npoints, f_hz, gamma_P, sigma_a, branch, &
      & part) result(stat) bind(C, name="udmap_model_curve_get")
    type(c_ptr), value :: errh, modelh
    integer(c_int), value :: i, npoints
    real(c_double), intent(out) :: f_hz(*), gamma_P(*), sigma_a(*)
    integer(c_int), intent(out) :: branch(*), part(*)
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    integer :: n
    call get_curve(errh, modelh, i, m, error)
    if (.not.allocated(error)) then
      n = size(m%curves(i + 1)%f)
      if (npoints < n) then
        call fatal_error(error, "curves: npoints is smaller than the curve "// &
          & "(udmap_model_curve_size)", UDMAP_EINPUT)
      else
        associate(c => m%curves(i + 1))
          call copy_out(c%f, f_hz, n)
          call copy_out(c%gamma_P, gamma_P, n)
          call copy_out(c%sigma_a, sigma_a, n)
          call copy_out(c%branch, branch, n)
          call copy_out(c%part, part, n)
        end associate
      end if
    end if
    stat = set_error(errh, error)
  end function udmap_model_curve_get
end module udmap_api_c_model
