!> C API, blade section (wrappers/c/udmap.h): the built-in beam and imported blades, their
!> natural frequencies, receptances, Sherman-Morrison layer response and Matrix Market export.
!> A udmap_blade handle points to a blade_type allocated here. Every pointer argument is checked
!> for NULL; every function returns a status and leaves a message in the error handle.
module udmap_api_c_blade
  use, intrinsic :: iso_c_binding, only: c_ptr, c_associated, c_f_pointer, c_loc, c_int, &
    & c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_core_strings, only: itoa
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input, take_handle, &
    & handle_slot, indexed_name, c_string, put_out, report_error
  ! udmap_beam_params and its conversion, generated from kernel/parameters.toml
  use udmap_api_c_parameters, only: c_beam_params, beam_from_c
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade, layer_response
  use udmap_blade_io_matrices, only: read_matrices_blade, export_blade
  use udmap_blade_platform, only: set_platform_translations, platform_translations_known
  implicit none
  private
  public :: c_beam_params, beam_from_c

contains

  !> int udmap_new_blade_beam(udmap_error, const udmap_beam_params *, udmap_blade *)
  function udmap_new_blade_beam(error, params, blade) result(stat) &
      & bind(C, name="udmap_new_blade_beam")
    type(c_ptr), value :: error, params, blade
    integer(c_int) :: stat
    type(c_beam_params), pointer :: cp
    type(c_ptr), pointer :: out
    type(blade_type), pointer :: b
    type(error_type), allocatable :: err
    call clear_error(error)
    call check_handle(blade, "blade", err)
    call check_handle(params, "params", err)
    if (report_error(error, err, stat)) return
    out => handle_slot(blade)
    call c_f_pointer(params, cp)
    allocate(b)
    call new_beam_blade(b, beam_from_c(cp), err)
    call hand_over(b, err, out)
    stat = set_error(error, err)
  end function udmap_new_blade_beam

  !> int udmap_new_blade_matrices(udmap_error, const char *M_path, const char *K_path,
  !>   const char *C_path, int gamma_dof, int exc_dof, const char *sK_path, const char *sM_path,
  !>   double zeta, udmap_blade *)
  function udmap_new_blade_matrices(error, M_path, K_path, C_path, gamma_dof, exc_dof, sK_path, &
      & sM_path, zeta, blade) result(stat) bind(C, name="udmap_new_blade_matrices")
    type(c_ptr), value :: error, M_path, K_path, C_path, sK_path, sM_path, blade
    integer(c_int), value :: gamma_dof, exc_dof
    real(c_double), value :: zeta
    integer(c_int) :: stat
    type(c_ptr), pointer :: out
    type(blade_type), pointer :: b
    type(error_type), allocatable :: err
    ! unallocated: an absent optional argument of read_matrices_blade
    character(len=:), allocatable :: C_file, sK_file, sM_file
    call clear_error(error)
    call check_handle(blade, "blade", err)
    call check_handle(M_path, "M_path", err)
    call check_handle(K_path, "K_path", err)
    if (report_error(error, err, stat)) return
    out => handle_slot(blade)
    ! Optional paths: NULL means absent.
    if (c_associated(C_path)) C_file = c_string(C_path)
    if (c_associated(sK_path)) sK_file = c_string(sK_path)
    if (c_associated(sM_path)) sM_file = c_string(sM_path)
    allocate(b)
    call read_matrices_blade(b, c_string(M_path), c_string(K_path), int(gamma_dof), int(exc_dof), &
      & real(zeta, wp), err, C_path=C_file, sK_path=sK_file, sM_path=sM_file)
    call hand_over(b, err, out)
    stat = set_error(error, err)
  end function udmap_new_blade_matrices

  !> void udmap_delete_blade(udmap_blade *)
  subroutine udmap_delete_blade(blade) bind(C, name="udmap_delete_blade")
    type(c_ptr), value :: blade
    type(c_ptr), pointer :: handle
    type(blade_type), pointer :: b
    if (.not.c_associated(blade)) return
    call c_f_pointer(blade, handle)
    if (.not.c_associated(handle)) return
    call c_f_pointer(take_handle(handle), b)
    deallocate(b)
  end subroutine udmap_delete_blade

  !> int udmap_blade_get_size(udmap_error, udmap_blade, int *ndof, int *has_stress)
  function udmap_blade_get_size(error, blade, ndof, has_stress) result(stat) &
      & bind(C, name="udmap_blade_get_size")
    type(c_ptr), value :: error, blade, ndof, has_stress
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    type(error_type), allocatable :: err
    call blade_from_handle(error, blade, b, err)
    call check_handle(ndof, "ndof", err)
    call check_handle(has_stress, "has_stress", err)
    if (.not.allocated(err)) then
      call put_out(ndof, b%ndof)
      call put_out(has_stress, merge(1, 0, b%has_stress))
    end if
    stat = set_error(error, err)
  end function udmap_blade_get_size

  !> int udmap_blade_set_platform_rows(udmap_error, udmap_blade, int ndof, const double *u_row,
  !>   const double *v_row): the platform translations u_P = u_row.q, v_P = v_row.q
  !>   (PHYSICS.md 2.6); v_row NULL: v_P held.
  function udmap_blade_set_platform_rows(error, blade, ndof, u_row, v_row) result(stat) &
      & bind(C, name="udmap_blade_set_platform_rows")
    type(c_ptr), value :: error, blade, u_row, v_row
    integer(c_int), value :: ndof
    integer(c_int) :: stat
    type(error_type), allocatable :: err
    real(c_double), pointer :: u(:), v(:)
    type(blade_type), pointer :: b
    call rows_from_handles(error, blade, ndof, u_row, v_row, .false., b, u, v, err)
    if (.not.allocated(err)) then
      if (associated(v)) then
        call set_platform_translations(b, real(u, wp), err, real(v, wp))
      else
        call set_platform_translations(b, real(u, wp), err)
      end if
    end if
    stat = set_error(error, err)
  end function udmap_blade_set_platform_rows

  !> int udmap_blade_get_platform_rows(udmap_error, udmap_blade, int ndof, double *u_row,
  !>   double *v_row, int *known): the rows of the platform translations (zeros and known = 0
  !>   when the blade does not know them).
  function udmap_blade_get_platform_rows(error, blade, ndof, u_row, v_row, known) result(stat) &
      & bind(C, name="udmap_blade_get_platform_rows")
    type(c_ptr), value :: error, blade, u_row, v_row, known
    integer(c_int), value :: ndof
    integer(c_int) :: stat
    type(error_type), allocatable :: err
    real(c_double), pointer :: u(:), v(:)
    type(blade_type), pointer :: b
    call rows_from_handles(error, blade, ndof, u_row, v_row, .true., b, u, v, err)
    call check_handle(known, "known", err)
    if (.not.allocated(err)) then
      u = 0
      v = 0
      if (platform_translations_known(b)) then
        u = real(b%platform_uv(:, 1), c_double)
        v = real(b%platform_uv(:, 2), c_double)
      end if
      call put_out(known, merge(1, 0, platform_translations_known(b)))
    end if
    stat = set_error(error, err)
  end function udmap_blade_get_platform_rows

  !> int udmap_blade_natural_frequencies(udmap_error, udmap_blade, int nmodes, double *f_hz)
  function udmap_blade_natural_frequencies(error, blade, nmodes, f_hz) result(stat) &
      & bind(C, name="udmap_blade_natural_frequencies")
    type(c_ptr), value :: error, blade, f_hz
    integer(c_int), value :: nmodes
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    real(wp), allocatable :: fw(:)
    type(error_type), allocatable :: err
    call blade_from_handle(error, blade, b, err)
    call check_handle(f_hz, "f_hz", err)
    call check_input(nmodes >= 1, "nmodes must be at least 1", err)
    if (.not.allocated(err)) then
      allocate(fw(nmodes))
      call b%natural_frequencies(fw, err)
      if (.not.allocated(err)) then
        call put_out(f_hz, real(fw, c_double))
      else
        err%message = "nmodes: "//err%message
      end if
    end if
    stat = set_error(error, err)
  end function udmap_blade_natural_frequencies

  !> int udmap_blade_receptances(udmap_error, udmap_blade, int n, const double *f_hz,
  !>   double *out): per frequency the (re, im) pairs of H_gE, H_gg, H_EE, H_sE, H_sg.
  function udmap_blade_receptances(error, blade, n, f_hz, out) result(stat) &
      & bind(C, name="udmap_blade_receptances")
    type(c_ptr), value :: error, blade, f_hz, out
    integer(c_int), value :: n
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    real(c_double), pointer :: f(:), o(:)
    type(receptances_type) :: r
    type(error_type), allocatable :: err
    integer :: i
    call clear_error(error)
    call check_arrays(blade, n, f_hz, out, err)
    if (.not.allocated(err) .and. n > 0) then
      call c_f_pointer(blade, b)
      call c_f_pointer(f_hz, f, [n])
      call c_f_pointer(out, o, [10*n])
      do i = 1, n
        call check_frequency(f(i), i, err)
        if (allocated(err)) exit
        call b%receptances(2*pi*real(f(i), wp), r, err)
        if (allocated(err)) exit
        o(10*i-9:10*i) = real([r%gE%re, r%gE%im, r%gg%re, r%gg%im, r%EE%re, r%EE%im, &
          & r%sE%re, r%sE%im, r%sg%re, r%sg%im], c_double)
      end do
    end if
    stat = set_error(error, err)
  end function udmap_blade_receptances

  !> int udmap_blade_layer_response(udmap_error, udmap_blade, int n, const double *f_hz,
  !>   double k_re, double k_im, double *out): per frequency the (re, im) pairs of g~, s~, u~_E.
  function udmap_blade_layer_response(error, blade, n, f_hz, k_re, k_im, out) result(stat) &
      & bind(C, name="udmap_blade_layer_response")
    type(c_ptr), value :: error, blade, f_hz, out
    integer(c_int), value :: n
    real(c_double), value :: k_re, k_im
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    real(c_double), pointer :: f(:), o(:)
    type(receptances_type) :: r
    type(error_type), allocatable :: err
    complex(wp) :: k, g, s, ue
    integer :: i
    call clear_error(error)
    call check_arrays(blade, n, f_hz, out, err)
    if (.not.allocated(err) .and. .not.(ieee_is_finite(k_re) .and. ieee_is_finite(k_im))) &
      & call fatal_error(err, "the damper stiffness k_re + i k_im must be finite", UDMAP_EINPUT)
    if (.not.allocated(err) .and. n > 0) then
      call c_f_pointer(blade, b)
      call c_f_pointer(f_hz, f, [n])
      call c_f_pointer(out, o, [6*n])
      k = cmplx(k_re, k_im, wp)
      do i = 1, n
        call check_frequency(f(i), i, err)
        if (allocated(err)) exit
        call b%receptances(2*pi*real(f(i), wp), r, err)
        if (allocated(err)) exit
        call layer_response(r, k, g, s, ue)
        if (.not.all(ieee_is_finite([g%re, g%im, s%re, s%im, ue%re, ue%im]))) then
          call fatal_error(err, "the layer response is unbounded at "//indexed_name("f_hz", i)// &
            & " (1 + k H_gg = 0: an undamped natural frequency of the blade with the damper)", &
            & UDMAP_EPHYSICS)
          exit
        end if
        o(6*i-5:6*i) = real([g%re, g%im, s%re, s%im, ue%re, ue%im], c_double)
      end do
    end if
    stat = set_error(error, err)
  end function udmap_blade_layer_response

  !> int udmap_blade_export(udmap_error, udmap_blade, const char *dir)
  function udmap_blade_export(error, blade, dir) result(stat) bind(C, name="udmap_blade_export")
    type(c_ptr), value :: error, blade, dir
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    type(error_type), allocatable :: err
    call blade_from_handle(error, blade, b, err)
    call check_handle(dir, "dir", err)
    if (.not.allocated(err)) call export_blade(b, c_string(dir), err)
    stat = set_error(error, err)
  end function udmap_blade_export

  ! ------------------------------------------------------------------ helpers

  !> Clears the error handle and points b at the blade of the handle `blade`, or sets err
  !> (the first check of the arguments) if it is NULL.
  subroutine blade_from_handle(error, blade, b, err)
    type(c_ptr), intent(in) :: error, blade
    type(blade_type), pointer, intent(out) :: b
    type(error_type), allocatable, intent(out) :: err
    call clear_error(error)
    call check_handle(blade, "blade", err)
    b => null()
    if (.not.allocated(err)) call c_f_pointer(blade, b)
  end subroutine blade_from_handle

  !> The checks of the platform rows' arguments (blade, u_row, v_row unless it may be NULL,
  !> ndof the blade's) and the rows as arrays (v null when v_row is NULL).
  subroutine rows_from_handles(error, blade, ndof, u_row, v_row, v_needed, b, u, v, err)
    type(c_ptr), intent(in) :: error, blade, u_row, v_row
    integer(c_int), intent(in) :: ndof
    logical, intent(in) :: v_needed
    type(blade_type), pointer, intent(out) :: b
    real(c_double), pointer, intent(out) :: u(:), v(:)
    type(error_type), allocatable, intent(out) :: err
    u => null()
    v => null()
    call blade_from_handle(error, blade, b, err)
    call check_handle(u_row, "u_row", err)
    if (v_needed) call check_handle(v_row, "v_row", err)
    if (allocated(err)) return
    call check_input(ndof == b%ndof, "ndof must be the blade's number of DOFs, "// &
      & itoa(b%ndof)//", got "//itoa(int(ndof)), err)
    if (allocated(err)) return
    call c_f_pointer(u_row, u, [ndof])
    if (c_associated(v_row)) call c_f_pointer(v_row, v, [ndof])
  end subroutine rows_from_handles

  !> Gives a new blade to the caller's handle, or frees it on error.
  subroutine hand_over(b, err, out)
    type(blade_type), pointer, intent(inout) :: b
    type(error_type), allocatable, intent(in) :: err
    type(c_ptr), intent(inout) :: out
    if (allocated(err)) then
      deallocate(b)
    else
      out = c_loc(b)
    end if
  end subroutine hand_over

  subroutine check_arrays(blade, n, f_hz, out, err)
    type(c_ptr), intent(in) :: blade, f_hz, out
    integer(c_int), intent(in) :: n
    type(error_type), allocatable, intent(out) :: err
    call check_handle(blade, "blade", err)
    call check_input(n >= 0, "n must not be negative", err)
    if (n <= 0) return
    call check_handle(f_hz, "f_hz", err)
    call check_handle(out, "out", err)
  end subroutine check_arrays

  subroutine check_frequency(f, i, err)
    real(c_double), intent(in) :: f
    integer, intent(in) :: i
    type(error_type), allocatable, intent(out) :: err
    if (ieee_is_finite(f)) then
      if (f >= 0.0_c_double) return
    end if
    call fatal_error(err, indexed_name("f_hz", i)//" must be a non-negative finite frequency", &
      & UDMAP_EINPUT)
  end subroutine check_frequency
end module udmap_api_c_blade
