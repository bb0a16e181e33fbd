!> C API, reduction section (wrappers/c/udmap.h): the Platform Centred Reduction of a sparse FE
!> blade given by COO arrays (PHYSICS.md 1.3). A udmap_reduction handle points to a
!> reduction_type allocated here and owned by the caller. Every pointer argument is checked.
module udmap_api_reduce
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, c_loc, &
    & c_int, c_double, c_int64_t
  use udmap_kinds, only: wp
  use udmap_error, only: error_type, fatal_error
  use udmap_api, only: set_error, clear_error, error_from_handle
  use udmap_craig_bampton, only: reduction_type, platform_centred_reduction
  implicit none
  private

  !> Entries of udmap_reduction_info.
  integer, parameter :: n_info = 15

contains

  !> int udmap_reduce(...): see wrappers/c/udmap.h.
  function udmap_reduce(error, n, nnz_k, k_row, k_col, k_val, nnz_m, m_row, m_col, m_val, &
      & dof_node, dof_comp, n_nodes, node_ids, node_xyz, n_platform, platform_nodes, ref_point, &
      & axis, exc_node, exc_direction, n_clamp, clamp_nodes, n_stress, stress_rows, n_modes, &
      & f_max, n_residual, check_full, reduction) result(stat) bind(C, name="udmap_reduce")
    type(c_ptr), value :: error, k_row, k_col, k_val, m_row, m_col, m_val, dof_node, dof_comp
    type(c_ptr), value :: node_ids, node_xyz, platform_nodes, ref_point, axis, exc_direction
    type(c_ptr), value :: clamp_nodes, stress_rows, reduction
    integer(c_int), value :: n, n_nodes, n_platform, exc_node, n_clamp, n_stress, n_modes
    integer(c_int), value :: n_residual, check_full
    integer(c_int64_t), value :: nnz_k, nnz_m
    real(c_double), value :: f_max
    integer(c_int) :: stat
    type(c_ptr), pointer :: out
    type(error_type), allocatable :: err
    integer(c_int), pointer :: kr(:), kc(:), mr(:), mc(:), dn(:), dc(:), ids(:), pn(:), cn(:)
    real(c_double), pointer :: kv(:), mv(:), xyz(:, :), rp(:), ax(:), ed(:), sr(:, :)
    type(reduction_type), pointer :: red
    integer(c_int), target :: none_i(1)
    call clear_error(error)
    if (c_associated(reduction)) then
      call c_f_pointer(reduction, out)
      out = c_null_ptr
    end if
    if (.not.c_associated(reduction)) then
      err = error_from_handle("reduction")
    else if (n < 1) then
      call fatal_error(err, "n: the model has no DOF")
    else if (nnz_k < 1) then
      call fatal_error(err, "nnz_K: K has no entry")
    else if (nnz_m < 1) then
      call fatal_error(err, "nnz_M: M has no entry")
    else if (nnz_k > huge(1_c_int) .or. nnz_m > huge(1_c_int)) then
      call fatal_error(err, "nnz_K/nnz_M: more than 2^31 - 1 entries")
    else if (n_nodes < 1) then
      call fatal_error(err, "n_nodes: no node")
    else if (n_platform < 1) then
      call fatal_error(err, "platform_nodes: the platform set is empty")
    else if (n_clamp < 0 .or. n_stress < 0) then
      call fatal_error(err, "n_clamp/n_stress: negative")
    else
      call null_check(k_row, "K_row")
      call null_check(k_col, "K_col")
      call null_check(k_val, "K_val")
      call null_check(m_row, "M_row")
      call null_check(m_col, "M_col")
      call null_check(m_val, "M_val")
      call null_check(dof_node, "dof_node")
      call null_check(dof_comp, "dof_comp")
      call null_check(node_ids, "node_ids")
      call null_check(node_xyz, "node_xyz")
      call null_check(platform_nodes, "platform_nodes")
      call null_check(ref_point, "ref_point")
      call null_check(axis, "axis")
      call null_check(exc_direction, "exc_direction")
      if (n_clamp > 0) call null_check(clamp_nodes, "clamp_nodes")
      if (n_stress > 0) call null_check(stress_rows, "stress_rows")
    end if
    if (allocated(err)) then
      stat = set_error(error, err)
      return
    end if
    call c_f_pointer(k_row, kr, [nnz_k])
    call c_f_pointer(k_col, kc, [nnz_k])
    call c_f_pointer(k_val, kv, [nnz_k])
    call c_f_pointer(m_row, mr, [nnz_m])
    call c_f_pointer(m_col, mc, [nnz_m])
    call c_f_pointer(m_val, mv, [nnz_m])
    call c_f_pointer(dof_node, dn, [n])
    call c_f_pointer(dof_comp, dc, [n])
    call c_f_pointer(node_ids, ids, [n_nodes])
    call c_f_pointer(node_xyz, xyz, [3, n_nodes])
    call c_f_pointer(platform_nodes, pn, [n_platform])
    call c_f_pointer(ref_point, rp, [3])
    call c_f_pointer(axis, ax, [3])
    call c_f_pointer(exc_direction, ed, [3])
    if (n_clamp > 0) then
      call c_f_pointer(clamp_nodes, cn, [n_clamp])
    else
      cn => none_i(1:0)
    end if
    if (n_stress > 0) then
      call c_f_pointer(stress_rows, sr, [n, n_stress])
    else
      allocate(sr(n, 0))
    end if
    allocate(red)
    call platform_centred_reduction(int(n), kr, kc, kv, mr, mc, mv, dn, dc, ids, xyz, pn, &
      & rp, ax, int(exc_node), ed, cn, sr, int(n_modes), real(f_max, wp), int(n_residual), &
      & check_full /= 0, red, err)
    if (n_stress == 0) deallocate(sr)
    if (allocated(err)) then
      deallocate(red)
    else
      out = c_loc(red)
    end if
    stat = set_error(error, err)
  contains
    subroutine null_check(p, name)
      type(c_ptr), intent(in) :: p
      character(len=*), intent(in) :: name
      if (allocated(err)) return
      if (.not.c_associated(p)) err = error_from_handle(name)
    end subroutine null_check
  end function udmap_reduce

  !> void udmap_delete_reduction(udmap_reduction *)
  subroutine udmap_delete_reduction(reduction) bind(C, name="udmap_delete_reduction")
    type(c_ptr), value :: reduction
    type(c_ptr), pointer :: handle
    type(reduction_type), pointer :: red
    if (.not.c_associated(reduction)) return
    call c_f_pointer(reduction, handle)
    if (c_associated(handle)) then
      call c_f_pointer(handle, red)
      deallocate(red)
      handle = c_null_ptr
    end if
  end subroutine udmap_delete_reduction

  !> int udmap_reduction_sizes(error, reduction, int *r, int *n_modes, int *n_stress,
  !>   int *n_freqs_full, int *gamma_dof, int *exc_dof)
  function udmap_reduction_sizes(error, reduction, r, n_modes, n_stress, n_freqs_full, &
      & gamma_dof, exc_dof) result(stat) bind(C, name="udmap_reduction_sizes")
    type(c_ptr), value :: error, reduction, r, n_modes, n_stress, n_freqs_full, gamma_dof, exc_dof
    integer(c_int) :: stat
    type(error_type), allocatable :: err
    type(reduction_type), pointer :: red
    integer(c_int), pointer :: p
    call clear_error(error)
    if (.not.c_associated(reduction)) then
      err = error_from_handle("reduction")
      stat = set_error(error, err)
      return
    end if
    call c_f_pointer(reduction, red)
    if (c_associated(r)) then
      call c_f_pointer(r, p)
      p = int(red%r, c_int)
    end if
    if (c_associated(n_modes)) then
      call c_f_pointer(n_modes, p)
      p = int(red%n_modes, c_int)
    end if
    if (c_associated(n_stress)) then
      call c_f_pointer(n_stress, p)
      p = int(size(red%S, 2), c_int)
    end if
    if (c_associated(n_freqs_full)) then
      call c_f_pointer(n_freqs_full, p)
      p = int(size(red%freqs_full), c_int)
    end if
    if (c_associated(gamma_dof)) then
      call c_f_pointer(gamma_dof, p)
      p = int(red%gamma_dof, c_int)
    end if
    if (c_associated(exc_dof)) then
      call c_f_pointer(exc_dof, p)
      p = int(red%exc_dof, c_int)
    end if
    stat = 0
  end function udmap_reduction_sizes

  !> int udmap_reduction_get(error, reduction, double *M, double *K, double *stress,
  !>   double *freqs_reduced, double *freqs_full): M, K r x r (column-major = row-major, they
  !>   are symmetric), stress n_stress rows of r, freqs_reduced r, freqs_full n_freqs_full.
  !>   Any output may be NULL.
  function udmap_reduction_get(error, reduction, m, k, stress, freqs_reduced, freqs_full) &
      & result(stat) bind(C, name="udmap_reduction_get")
    type(c_ptr), value :: error, reduction, m, k, stress, freqs_reduced, freqs_full
    integer(c_int) :: stat
    type(error_type), allocatable :: err
    type(reduction_type), pointer :: red
    real(c_double), pointer :: a(:, :), f(:)
    call clear_error(error)
    if (.not.c_associated(reduction)) then
      err = error_from_handle("reduction")
      stat = set_error(error, err)
      return
    end if
    call c_f_pointer(reduction, red)
    if (c_associated(m)) then
      call c_f_pointer(m, a, [red%r, red%r])
      a = red%M
    end if
    if (c_associated(k)) then
      call c_f_pointer(k, a, [red%r, red%r])
      a = red%K
    end if
    if (c_associated(stress)) then
      call c_f_pointer(stress, a, [red%r, size(red%S, 2)])
      a = red%S
    end if
    if (c_associated(freqs_reduced)) then
      call c_f_pointer(freqs_reduced, f, [red%r])
      f = red%freqs_reduced
    end if
    if (c_associated(freqs_full)) then
      call c_f_pointer(freqs_full, f, [size(red%freqs_full)])
      f = red%freqs_full
    end if
    stat = 0
  end function udmap_reduction_get

  !> int udmap_reduction_info(error, reduction, double info[15]): f_cut, f_check, cut_count,
  !>   cut_found, full_count, full_found, n_t, n_i, factor_entries, n_residual, then the five
  !>   timings (transformation, factorisation and static modes, modes, projection, full check).
  function udmap_reduction_info(error, reduction, info) result(stat) &
      & bind(C, name="udmap_reduction_info")
    type(c_ptr), value :: error, reduction, info
    integer(c_int) :: stat
    type(error_type), allocatable :: err
    type(reduction_type), pointer :: red
    real(c_double), pointer :: o(:)
    call clear_error(error)
    if (.not.c_associated(reduction)) then
      err = error_from_handle("reduction")
    else if (.not.c_associated(info)) then
      err = error_from_handle("info")
    end if
    if (allocated(err)) then
      stat = set_error(error, err)
      return
    end if
    call c_f_pointer(reduction, red)
    call c_f_pointer(info, o, [n_info])
    o = [red%f_cut, red%f_check, real(red%cut_count, wp), real(red%cut_found, wp), &
      & real(red%full_count, wp), real(red%full_found, wp), real(red%n_t, wp), &
      & real(red%n_i, wp), real(red%factor_entries, wp), real(red%n_residual, wp), red%timings]
    stat = 0
  end function udmap_reduction_info
end module udmap_api_reduce
