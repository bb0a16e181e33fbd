!> C API, many designs in one call (wrappers/c/udmap.h, section "many designs"): what a design of
!> experiments asks of every design (the damper's summary, F_lim, F_lim_backbone, the peaks at
!> a set of forces with their jump flags, F_adm), for arrays of asymmetric damper parameter
!> blocks on one model, computing only the stages asked for.
!>
!> Each design goes through the kernel calls a single design makes through the other entry
!> points (set_damper, limit_force, limit_force_backbone, backbone, admissible_force), in that
!> order, so its numbers are those of the single calls bit for bit. A design with a reference
!> block (equal to its own but for CF and a common factor kappa of kn_flat, kt_flat,
!> kn_curved, kt_curved) takes the damper traced for the reference, rescaled exactly
!> (PHYSICS.md 2.3; damper_type%set_scale); a design that is its own reference is the traced
!> damper itself. Traced dampers are kept in the model handle (a few, the latest), so designs
!> that share a reference share one tracing across calls too.
module udmap_api_c_designs
  use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_char, c_null_char, &
    & c_associated, c_f_pointer, c_null_ptr
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_api_c_support, only: set_error, check_input
  use udmap_api_c_parameters, only: udmap_asymmetric_params, asymmetric_from_c
  use udmap_api_c_model, only: c_model_type, model_from_handle
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_mapping_model_data, only: check_forces
  use udmap_mapping_model, only: point_type, set_damper, limit_force, limit_force_backbone, &
    & backbone, admissible_force, is_traveling
  use udmap_mapping_plausibility, only: warning_type, model_warnings
  implicit none
  private
  public :: udmap_design_outputs, udmap_model_designs_warnings

  !> Stages (bit flags of `stages`): UDMAP_DESIGN_LIMIT, _LIMIT_BACKBONE, _PEAKS, _JUMPS,
  !> _ADMISSIBLE.
  integer, parameter :: S_LIMIT = 1, S_LIMIT_BACKBONE = 2, S_PEAKS = 4, S_JUMPS = 8, &
    & S_ADMISSIBLE = 16
  !> Where a design failed (the `stage` output): the damper, the coupling or F_lim, the peaks,
  !> F_adm (0: no failure).
  integer, parameter :: F_DAMPER = 1, F_LIMIT = 2, F_PEAKS = 3, F_ADMISSIBLE = 4
  !> Traced dampers kept per model handle.
  integer, parameter :: n_cache = 4
  !> The four stiffness ratios of a design to its reference agree to this (relative).
  real(wp), parameter :: ratio_tol = 1e-12_wp

  !> struct udmap_design_outputs: where the results go (NULL: not written).
  type, bind(C) :: udmap_design_outputs
    type(c_ptr) :: F_lim, F_lim_backbone, gamma_b, M_max, M_min, lift_off
    type(c_ptr) :: gamma_P, f_res, sigma_a, unbounded, hcf_ok, jump
    type(c_ptr) :: F_adm, status, stage, message
    integer(c_int) :: message_len
    integer(c_int) :: traces
  end type udmap_design_outputs

contains

  !> int udmap_model_designs(error, model, n, params, reference, nforces, F_E, stages, out):
  !> n designs on the model (see the module and wrappers/c/udmap.h).
  function udmap_model_designs(errh, modelh, n, params, reference, nforces, F_E, stages, out) &
      & result(stat) bind(C, name="udmap_model_designs")
    type(c_ptr), value :: errh, modelh, params, reference, F_E
    integer(c_int), value :: n, nforces, stages
    type(udmap_design_outputs), intent(inout) :: out
    integer(c_int) :: stat
    stat = designs(errh, modelh, n, params, reference, nforces, F_E, stages, out, c_null_ptr)
  end function udmap_model_designs

  !> int udmap_model_designs_warnings(error, model, n, params, reference, nforces, F_E, stages,
  !> out, kinds): udmap_model_designs, and per design the plausibility warnings that
  !> udmap_model_warnings gives on the model coupled to the design's damper, after its stages
  !> (so that they are those of udmap_model_designs bit for bit), as the bit set kinds[i] = sum
  !> of 2^(kind - 1) over them; -1 where the design's damper fails.
  function udmap_model_designs_warnings(errh, modelh, n, params, reference, nforces, F_E, &
      & stages, out, kinds) result(stat) bind(C, name="udmap_model_designs_warnings")
    type(c_ptr), value :: errh, modelh, params, reference, F_E, kinds
    integer(c_int), value :: n, nforces, stages
    type(udmap_design_outputs), intent(inout) :: out
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    call check_input(c_associated(kinds), "designs: kinds must not be NULL", error)
    if (allocated(error)) then
      stat = set_error(errh, error)
      return
    end if
    stat = designs(errh, modelh, n, params, reference, nforces, F_E, stages, out, kinds)
  end function udmap_model_designs_warnings

  !> Both entries: kinds null or the caller's n ints.
  integer(c_int) function designs(errh, modelh, n, params, reference, nforces, F_E, stages, &
      & out, kinds) result(stat)
    type(c_ptr), value :: errh, modelh, params, reference, F_E, kinds
    integer(c_int), value :: n, nforces, stages
    type(udmap_design_outputs), intent(inout) :: out
    type(warning_type), allocatable :: warnings(:)
    integer(c_int), pointer :: o_k(:)
    logical :: coupled
    integer :: j
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    type(damper_type), pointer :: original
    type(udmap_asymmetric_params), pointer :: pp(:), rr(:)
    real(c_double), pointer :: forces(:)
    real(c_double), pointer :: o_lim(:), o_lbb(:), o_gb(:), o_mx(:), o_mn(:), o_gp(:), &
      & o_fr(:), o_sa(:), o_adm(:)
    integer(c_int), pointer :: o_lo(:), o_ub(:), o_ok(:), o_jp(:), o_st(:), o_sg(:)
    character(kind=c_char), pointer :: o_msg(:)
    integer :: i, nf, ml
    call model_from_handle(errh, modelh, m, error)
    call check_input(n >= 0, "designs: n must not be negative", error)
    call check_input(nforces >= 0, "designs: nforces must not be negative", error)
    call check_input(stages >= 0 .and. stages < 32, "designs: stages must be a combination "// &
      & "of the UDMAP_DESIGN_* flags", error)
    call check_input(c_associated(out%status), "designs: out->status must not be NULL", error)
    call check_input(out%message_len >= 0, "designs: out->message_len must not be negative", &
      & error)
    call check_input(.not.c_associated(reference) .or. c_associated(params), &
      & "designs: reference blocks need params blocks", error)
    call check_input(nforces == 0 .or. c_associated(F_E), "designs: F_E must not be NULL", error)
    nf = 0
    if (.not.allocated(error)) then
      nf = nforces
      if (nf > 0) then
        call c_f_pointer(F_E, forces, [nf])
        call check_forces(real(forces, wp), "designs", error)
      end if
    end if
    if (allocated(error)) then
      stat = set_error(errh, error)
      return
    end if
    ml = out%message_len
    if (.not.c_associated(out%message)) ml = 0
    call real_out(out%F_lim, n, o_lim)
    call real_out(out%F_lim_backbone, n, o_lbb)
    call real_out(out%gamma_b, n, o_gb)
    call real_out(out%M_max, n, o_mx)
    call real_out(out%M_min, n, o_mn)
    call int_out(out%lift_off, n, o_lo)
    call real_out(out%gamma_P, n*nf, o_gp)
    call real_out(out%f_res, n*nf, o_fr)
    call real_out(out%sigma_a, n*nf, o_sa)
    call int_out(out%unbounded, n*nf, o_ub)
    call int_out(out%hcf_ok, n*nf, o_ok)
    call int_out(out%jump, n*nf, o_jp)
    call real_out(out%F_adm, n, o_adm)
    call int_out(out%status, n, o_st)
    call int_out(out%stage, n, o_sg)
    o_msg => null()
    if (ml > 0) call c_f_pointer(out%message, o_msg, [n*ml])
    pp => null()
    rr => null()
    if (c_associated(params)) call c_f_pointer(params, pp, [n])
    if (c_associated(reference)) call c_f_pointer(reference, rr, [n])
    out%traces = 0
    if (.not.allocated(m%traced)) allocate(m%traced(n_cache))
    original => m%model%damper
    o_k => null()
    if (c_associated(kinds)) call c_f_pointer(kinds, o_k, [n])
    do i = 1, n
      coupled = .false.
      call one_design(i)
      if (.not. associated(o_k)) cycle
      o_k(i) = -1
      if (.not. coupled) cycle
      call model_warnings(m%model, warnings)
      o_k(i) = 0
      do j = 1, size(warnings)
        o_k(i) = ior(o_k(i), int(ishft(1, warnings(j)%kind - 1), c_int))
      end do
    end do
    if (associated(original)) call set_damper(m%model, original, error)
    stat = set_error(errh, error)

  contains

    !> Design i: its damper, its stages, its outputs; a failure is recorded and the loop goes on.
    subroutine one_design(i)
      integer, intent(in) :: i
      type(damper_type), pointer :: d
      type(error_type), allocatable :: err
      type(point_type), allocatable :: p(:)
      real(wp) :: F_lim, F_lbb, F_adm
      integer :: k, base
      o_st(i) = 0
      if (associated(o_sg)) o_sg(i) = 0
      if (ml > 0) o_msg((i - 1)*ml + 1) = c_null_char
      call design_damper(m, original, pp, rr, i, d, out%traces, err)
      if (allocated(err)) then
        call fail(i, err, F_DAMPER)
        return
      end if
      if (associated(o_gb)) o_gb(i) = d%gamma_b
      if (associated(o_mx)) o_mx(i) = d%M_max
      if (associated(o_mn)) o_mn(i) = d%M_min
      if (associated(o_lo)) o_lo(i) = merge(1_c_int, 0_c_int, d%lift_off)
      call set_damper(m%model, d, err)
      if (allocated(err)) then
        call fail(i, err, F_LIMIT)
        return
      end if
      coupled = .true.
      F_lim = huge(1.0_wp)
      F_lbb = huge(1.0_wp)
      if (iand(int(stages), S_LIMIT + S_LIMIT_BACKBONE + S_ADMISSIBLE) /= 0) then
        call limit_force(m%model, F_lim, err)
        if (allocated(err)) then
          call fail(i, err, F_LIMIT)
          return
        end if
        if (associated(o_lim)) o_lim(i) = F_lim
        ! at phi /= 0, F_lim(phi) is the supremum of the backbone itself (PHYSICS.md 2.6)
        F_lbb = merge(F_lim, limit_force_backbone(m%model), is_traveling(m%model))
        if (associated(o_lbb)) o_lbb(i) = F_lbb
      end if
      if (iand(int(stages), S_PEAKS + S_JUMPS) /= 0 .and. nf > 0) then
        call backbone(m%model, real(forces, wp), p, err)
        if (allocated(err)) then
          call fail(i, err, F_PEAKS)
          return
        end if
        base = (i - 1)*nf
        do k = 1, nf
          if (associated(o_gp)) o_gp(base + k) = p(k)%gamma_P
          if (associated(o_fr)) o_fr(base + k) = p(k)%f_res
          if (associated(o_sa)) o_sa(base + k) = p(k)%sigma_a
          if (associated(o_ub)) o_ub(base + k) = merge(1_c_int, 0_c_int, p(k)%unbounded)
          if (associated(o_ok)) o_ok(base + k) = merge(1_c_int, 0_c_int, p(k)%hcf_ok)
          if (associated(o_jp)) o_jp(base + k) = merge(1_c_int, 0_c_int, p(k)%jump)
        end do
      end if
      if (iand(int(stages), S_ADMISSIBLE) /= 0) then
        F_lim = min(F_lim, F_lbb)
        if (m%model%blade%has_stress) then
          call admissible_force(m%model, F_lim, m%model%analysis%sigma_all, &
            & m%model%analysis%rtol, F_adm, err)
          if (allocated(err)) then
            call fail(i, err, F_ADMISSIBLE)
            return
          end if
        else
          F_adm = 0.5_wp*F_lim
        end if
        if (associated(o_adm)) o_adm(i) = F_adm
      end if
    end subroutine one_design

    !> Records err as design i's failure at stage `at`.
    subroutine fail(i, err, at)
      integer, intent(in) :: i, at
      type(error_type), intent(in) :: err
      integer :: k, nm
      o_st(i) = int(err%stat, c_int)
      if (associated(o_sg)) o_sg(i) = int(at, c_int)
      if (ml > 0) then
        nm = min(len(err%message), ml - 1)
        do k = 1, nm
          o_msg((i - 1)*ml + k) = err%message(k:k)
        end do
        o_msg((i - 1)*ml + nm + 1) = c_null_char
      end if
    end subroutine fail

  end function designs

  !> Design i's damper: the model's own (params null()), or the traced damper of its block or
  !> of its reference block (tracing it now if no slot holds it; traces counts the tracings),
  !> rescaled to the design's CF and stiffness factor.
  subroutine design_damper(m, original, pp, rr, i, d, traces, err)
    type(c_model_type), pointer, intent(in) :: m
    type(damper_type), pointer, intent(in) :: original
    type(udmap_asymmetric_params), pointer, intent(in) :: pp(:), rr(:)
    integer, intent(in) :: i
    type(damper_type), pointer, intent(out) :: d
    integer(c_int), intent(inout) :: traces
    type(error_type), allocatable, intent(out) :: err
    real(wp) :: kappa
    integer :: slot
    d => original
    if (.not. associated(pp)) return
    kappa = 1
    if (associated(rr)) then
      call stiffness_factor(pp(i), rr(i), i, kappa, err)
      if (allocated(err)) return
      slot = traced_slot(m, rr(i), traces)
    else
      slot = traced_slot(m, pp(i), traces)
    end if
    if (allocated(m%traced(slot)%error)) then
      err = m%traced(slot)%error
      return
    end if
    d => m%traced(slot)%damper
    call d%set_scale(real(pp(i)%CF, wp), kappa, err)
  end subroutine design_damper

  !> The slot of the traced damper for the block (tracing it now if no slot holds it).
  integer function traced_slot(m, block, traces) result(slot)
    type(c_model_type), intent(inout) :: m
    type(udmap_asymmetric_params), intent(in) :: block
    integer(c_int), intent(inout) :: traces
    integer(int64) :: key(16)
    integer :: k
    key = transfer(block, key)
    do k = 1, n_cache
      if (m%traced(k)%used) then
        if (all(m%traced(k)%key == key)) then
          slot = k
          return
        end if
      end if
    end do
    slot = m%next_traced
    m%next_traced = mod(slot, n_cache) + 1
    associate(t => m%traced(slot))
      t%used = .true.
      t%key = key
      if (allocated(t%error)) deallocate(t%error)
      call new_asymmetric_damper(t%damper, asymmetric_from_c(block), t%error)
    end associate
    traces = traces + 1
  end function traced_slot

  !> kappa = the design's kn_flat over the reference's, checked: every other field but CF
  !> equal bit for bit, the other three stiffness ratios equal to ratio_tol.
  subroutine stiffness_factor(a, r, i, kappa, err)
    type(udmap_asymmetric_params), intent(in) :: a, r
    integer, intent(in) :: i
    real(wp), intent(out) :: kappa
    type(error_type), allocatable, intent(out) :: err
    integer(int64) :: ka(16), kr(16)
    real(c_double) :: va(16), vr(16)
    character(len=16) :: buf
    ka = transfer(a, ka)
    kr = transfer(r, kr)
    va = transfer(a, va)
    vr = transfer(r, vr)
    kappa = va(13)/vr(13)
    if (any(ka(2:12) /= kr(2:12)) .or. &
      & any(abs(va(14:16)/vr(14:16) - kappa) > ratio_tol*kappa)) then
      write(buf, '(i0)') i - 1
      call fatal_error(err, "designs: design "//trim(buf)//" differs from its reference "// &
        & "block in more than CF and a common factor of kn_flat, kt_flat, kn_curved, "// &
        & "kt_curved", UDMAP_EINPUT)
    end if
  end subroutine stiffness_factor

  !> A caller's array of doubles (or null()).
  subroutine real_out(ptr, n, a)
    type(c_ptr), intent(in) :: ptr
    integer, intent(in) :: n
    real(c_double), pointer, intent(out) :: a(:)
    a => null()
    if (c_associated(ptr)) call c_f_pointer(ptr, a, [n])
  end subroutine real_out

  !> A caller's array of ints (or null()).
  subroutine int_out(ptr, n, a)
    type(c_ptr), intent(in) :: ptr
    integer, intent(in) :: n
    integer(c_int), pointer, intent(out) :: a(:)
    a => null()
    if (c_associated(ptr)) call c_f_pointer(ptr, a, [n])
  end subroutine int_out
end module udmap_api_c_designs
