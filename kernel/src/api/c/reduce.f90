!> C API, reduction section (wrappers/c/udmap.h): the Platform Centred Reduction of a sparse FE
!> blade given by COO arrays (PHYSICS.md 1.3). A udmap_reduction handle points to a
!> reduction_type allocated here and owned by the caller. Every pointer argument is checked.
module udmap_api_c_reduce
  use, intrinsic :: iso_c_binding, only: c_ptr, c_associated, c_f_pointer, c_loc, c_int, &
    & c_double, c_int64_t
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input, take_handle, &
    & handle_slot, put_out, report_error
  use udmap_blade_reduce_craig_bampton, only: reduction_type, platform_centred_reduction
  implicit none
  private

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
    out => handle_slot(reduction)
    call check_handle(reduction, "reduction", err)
    call check_input(n >= 1, "n: the model has no DOF", err)
    call check_input(nnz_k >= 1, "nnz_K: K has no entry", err)
    call check_input(nnz_m >= 1, "nnz_M: M has no entry", err)
    call check_input(nnz_k <= huge(1_c_int) .and. nnz_m <= huge(1_c_int), &
      & "nnz_K/nnz_M: more than 2^31 - 1 entries", err)
    call check_input(n_nodes >= 1, "n_nodes: no node", err)
    call check_input(n_platform >= 1, "platform_nodes: the platform set is empty", err)
    call check_input(n_clamp >= 0 .and. n_stress >= 0, "n_clamp/n_stress: negative", err)
    call check_handle(k_row, "K_row", err)
    call check_handle(k_col, "K_col", err)
    call check_handle(k_val, "K_val", err)
    call check_handle(m_row, "M_row", err)
    call check_handle(m_col, "M_col", err)
    call check_handle(m_val, "M_val", err)
    call check_handle(dof_node, "dof_node", err)
    call check_handle(dof_comp, "dof_comp", err)
    call check_handle(node_ids, "node_ids", err)
    call check_handle(node_xyz, "node_xyz", err)
    call check_handle(platform_nodes, "platform_nodes", err)
    call check_handle(ref_point, "ref_point", err)
    call check_handle(axis, "axis", err)
    call check_handle(exc_direction, "exc_direction", err)
    if (n_clamp > 0) call check_handle(clamp_nodes, "clamp_nodes", err)
    if (n_stress > 0) call check_handle(stress_rows, "stress_rows", err)
    if (report_error(error, err, stat)) return
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
  end function udmap_reduce

  !> void udmap_delete_reduction(udmap_reduction *)
  subroutine udmap_delete_reduction(reduction) bind(C, name="udmap_delete_reduction")
    type(c_ptr), value :: reduction
    type(c_ptr), pointer :: handle
    type(reduction_type), pointer :: red
    if (.not.c_associated(reduction)) return
    call c_f_pointer(reduction, handle)
    if (.not.c_associated(handle)) return
    call c_f_pointer(take_handle(handle), red)
    deallocate(red)
  end subroutine udmap_delete_reduction

  !> int udmap_reduction_sizes(error, reduction, int *r, int *n_modes, int *n_stress,
  !>   int *n_freqs_full, int *gamma_dof, int *exc_dof)
  function udmap_reduction_sizes(error, reduction, r, n_modes, n_stress, n_freqs_full, &
      & gamma_dof, exc_dof) result(stat) bind(C, name="udmap_reduction_sizes")
    type(c_ptr), value :: error, reduction, r, n_modes, n_stress, n_freqs_full, gamma_dof, exc_dof
    integer(c_int) :: stat
    type(reduction_type), pointer :: red
    call reduction_from_handle(error, reduction, red, stat)
    if (stat /= 0) return
    call put_out(r, red%r)
    call put_out(n_modes, red%n_modes)
    call put_out(n_stress, size(red%S, 2))
    call put_out(n_freqs_full, size(red%freqs_full))
    call put_out(gamma_dof, red%gamma_dof)
    call put_out(exc_dof, red%exc_dof)
  end function udmap_reduction_sizes

  !> int udmap_reduction_get(error, reduction, double *M, double *K, double *stress,
  !>   double *freqs_reduced, double *freqs_full): M, K r x r (column-major = row-major, they
  !>   are symmetric), stress n_stress rows of r, freqs_reduced r, freqs_full n_freqs_full.
  !>   Any output may be NULL.
  function udmap_reduction_get(error, reduction, m, k, stress, freqs_reduced, freqs_full) &
      & result(stat) bind(C, name="udmap_reduction_get")
    type(c_ptr), value :: error, reduction, m, k, stress, freqs_reduced, freqs_full
    integer(c_int) :: stat
    type(reduction_type), pointer :: red
    call reduction_from_handle(error, reduction, red, stat)
    if (stat /= 0) return
    call put_out(m, red%M)
    call put_out(k, red%K)
    call put_out(stress, red%S)
    call put_out(freqs_reduced, red%freqs_reduced)
    call put_out(freqs_full, red%freqs_full)
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
    call reduction_from_handle(error, reduction, red, stat)
    if (stat /= 0) return
    call check_handle(info, "info", err)
    if (report_error(error, err, stat)) return
    call put_out(info, [red%f_cut, red%f_check, real(red%cut_count, wp), &
      & real(red%cut_found, wp), real(red%full_count, wp), real(red%full_found, wp), &
      & real(red%n_t, wp), real(red%n_i, wp), real(red%factor_entries, wp), &
      & real(red%n_residual, wp), red%timings])
    stat = 0
  end function udmap_reduction_info

  !> The reduction behind a C handle, clearing the error handle; stat /= 0 with the NULL-handle
  !> error in the error handle when it is NULL.
  subroutine reduction_from_handle(error, reduction, red, stat)
    type(c_ptr), intent(in) :: error, reduction
    type(reduction_type), pointer, intent(out) :: red
    integer(c_int), intent(out) :: stat
    type(error_type), allocatable :: err
    call clear_error(error)
    nullify(red)
    call check_handle(reduction, "reduction", err)
    stat = set_error(error, err)
    if (stat == 0) call c_f_pointer(reduction, red)
  end subroutine reduction_from_handle
end module udmap_api_c_reduce
