!> C API, blade section (wrappers/c/udmap.h): the built-in beam and imported blades, their
!> natural frequencies, receptances, Sherman-Morrison layer response and Matrix Market export.
!> A udmap_blade handle points to a blade_type allocated here. Every pointer argument is checked
!> for NULL; every function returns a status and leaves a message in the error handle.
module udmap_api_blade
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, c_loc, &
    & c_int, c_double, c_char, c_size_t
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use udmap_kinds, only: wp, pi
  use udmap_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_api, only: set_error, clear_error, error_from_handle, c_string_to_fortran
  use udmap_beam, only: beam_params_type
  use udmap_blade, only: blade_type, receptances_type, new_beam_blade, read_matrices_blade, &
    & export_blade, layer_response
  implicit none
  private
  public :: c_beam_params

  !> udmap_beam_params: 12 doubles then 2 ints, as in the header.
  type, bind(C) :: c_beam_params
    real(c_double) :: E, rho, zeta
    real(c_double) :: neck_L, neck_h, neck_b
    real(c_double) :: platform_L, platform_m, platform_J
    real(c_double) :: airfoil_L, airfoil_h, airfoil_b
    integer(c_int) :: neck_elements, airfoil_elements
  end type c_beam_params

  interface
    function c_strlen(s) bind(C, name="strlen") result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: n
    end function c_strlen
  end interface

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
    type(beam_params_type) :: p
    call clear_error(error)
    if (.not.c_associated(blade)) then
      err = error_from_handle("blade")
    else if (.not.c_associated(params)) then
      err = error_from_handle("params")
    end if
    if (allocated(err)) then
      stat = set_error(error, err)
      return
    end if
    call c_f_pointer(blade, out)
    out = c_null_ptr
    call c_f_pointer(params, cp)
    p = beam_params_type(E=cp%E, rho=cp%rho, zeta=cp%zeta, neck_L=cp%neck_L, neck_h=cp%neck_h, &
      & neck_b=cp%neck_b, platform_L=cp%platform_L, platform_m=cp%platform_m, &
      & platform_J=cp%platform_J, airfoil_L=cp%airfoil_L, airfoil_h=cp%airfoil_h, &
      & airfoil_b=cp%airfoil_b, neck_elements=int(cp%neck_elements), &
      & airfoil_elements=int(cp%airfoil_elements))
    allocate(b)
    call new_beam_blade(b, p, err)
    if (allocated(err)) then
      deallocate(b)
    else
      out = c_loc(b)
    end if
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
    call clear_error(error)
    if (.not.c_associated(blade)) then
      err = error_from_handle("blade")
    else if (.not.c_associated(M_path)) then
      err = error_from_handle("M_path")
    else if (.not.c_associated(K_path)) then
      err = error_from_handle("K_path")
    end if
    if (allocated(err)) then
      stat = set_error(error, err)
      return
    end if
    call c_f_pointer(blade, out)
    out = c_null_ptr
    allocate(b)
    ! Optional paths: NULL means absent (an absent optional actual argument below).
    if (c_associated(C_path)) then
      if (c_associated(sK_path) .and. c_associated(sM_path)) then
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, C_path=string(C_path), sK_path=string(sK_path), &
          & sM_path=string(sM_path))
      else if (c_associated(sK_path)) then
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, C_path=string(C_path), sK_path=string(sK_path))
      else if (c_associated(sM_path)) then
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, C_path=string(C_path), sM_path=string(sM_path))
      else
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, C_path=string(C_path))
      end if
    else
      if (c_associated(sK_path) .and. c_associated(sM_path)) then
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, sK_path=string(sK_path), sM_path=string(sM_path))
      else if (c_associated(sK_path)) then
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, sK_path=string(sK_path))
      else if (c_associated(sM_path)) then
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err, sM_path=string(sM_path))
      else
        call read_matrices_blade(b, string(M_path), string(K_path), int(gamma_dof), int(exc_dof), &
          & real(zeta, wp), err)
      end if
    end if
    if (allocated(err)) then
      deallocate(b)
    else
      out = c_loc(b)
    end if
    stat = set_error(error, err)
  end function udmap_new_blade_matrices

  !> void udmap_delete_blade(udmap_blade *)
  subroutine udmap_delete_blade(blade) bind(C, name="udmap_delete_blade")
    type(c_ptr), value :: blade
    type(c_ptr), pointer :: handle
    type(blade_type), pointer :: b
    if (.not.c_associated(blade)) return
    call c_f_pointer(blade, handle)
    if (c_associated(handle)) then
      call c_f_pointer(handle, b)
      deallocate(b)
      handle = c_null_ptr
    end if
  end subroutine udmap_delete_blade

  !> int udmap_blade_get_size(udmap_error, udmap_blade, int *ndof, int *has_stress)
  function udmap_blade_get_size(error, blade, ndof, has_stress) result(stat) &
      & bind(C, name="udmap_blade_get_size")
    type(c_ptr), value :: error, blade, ndof, has_stress
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    integer(c_int), pointer :: pn, ps
    type(error_type), allocatable :: err
    call clear_error(error)
    if (.not.c_associated(blade)) then
      err = error_from_handle("blade")
    else if (.not.c_associated(ndof)) then
      err = error_from_handle("ndof")
    else if (.not.c_associated(has_stress)) then
      err = error_from_handle("has_stress")
    else
      call c_f_pointer(blade, b)
      call c_f_pointer(ndof, pn)
      call c_f_pointer(has_stress, ps)
      pn = int(b%ndof, c_int)
      ps = merge(1_c_int, 0_c_int, b%has_stress)
    end if
    stat = set_error(error, err)
  end function udmap_blade_get_size

  !> int udmap_blade_natural_frequencies(udmap_error, udmap_blade, int nmodes, double *f_hz)
  function udmap_blade_natural_frequencies(error, blade, nmodes, f_hz) result(stat) &
      & bind(C, name="udmap_blade_natural_frequencies")
    type(c_ptr), value :: error, blade, f_hz
    integer(c_int), value :: nmodes
    integer(c_int) :: stat
    type(blade_type), pointer :: b
    real(c_double), pointer :: f(:)
    real(wp), allocatable :: fw(:)
    type(error_type), allocatable :: err
    call clear_error(error)
    if (.not.c_associated(blade)) then
      err = error_from_handle("blade")
    else if (.not.c_associated(f_hz)) then
      err = error_from_handle("f_hz")
    else if (nmodes < 1) then
      call fatal_error(err, "nmodes must be at least 1", UDMAP_EINPUT)
    else
      call c_f_pointer(blade, b)
      allocate(fw(nmodes))
      call b%natural_frequencies(fw, err)
      if (.not.allocated(err)) then
        call c_f_pointer(f_hz, f, [nmodes])
        f = real(fw, c_double)
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
          call fatal_error(err, "the layer response is unbounded at f_hz["//itoa(i-1)// &
            & "] (1 + k H_gg = 0: an undamped natural frequency of the blade with the damper)", &
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
    call clear_error(error)
    if (.not.c_associated(blade)) then
      err = error_from_handle("blade")
    else if (.not.c_associated(dir)) then
      err = error_from_handle("dir")
    else
      call c_f_pointer(blade, b)
      call export_blade(b, string(dir), err)
    end if
    stat = set_error(error, err)
  end function udmap_blade_export

  ! ------------------------------------------------------------------ helpers

  subroutine check_arrays(blade, n, f_hz, out, err)
    type(c_ptr), intent(in) :: blade, f_hz, out
    integer(c_int), intent(in) :: n
    type(error_type), allocatable, intent(out) :: err
    if (.not.c_associated(blade)) then
      err = error_from_handle("blade")
    else if (n < 0) then
      call fatal_error(err, "n must not be negative", UDMAP_EINPUT)
    else if (n > 0 .and. .not.c_associated(f_hz)) then
      err = error_from_handle("f_hz")
    else if (n > 0 .and. .not.c_associated(out)) then
      err = error_from_handle("out")
    end if
  end subroutine check_arrays

  subroutine check_frequency(f, i, err)
    real(c_double), intent(in) :: f
    integer, intent(in) :: i
    type(error_type), allocatable, intent(out) :: err
    if (.not.ieee_is_finite(f)) then
      call fatal_error(err, "f_hz["//itoa(i-1)//"] must be a non-negative finite frequency", &
        & UDMAP_EINPUT)
    else if (f < 0.0_c_double) then
      call fatal_error(err, "f_hz["//itoa(i-1)//"] must be a non-negative finite frequency", &
        & UDMAP_EINPUT)
    end if
  end subroutine check_frequency

  !> The Fortran string of a NUL-terminated C string.
  function string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    call c_f_pointer(p, chars, [int(c_strlen(p)) + 1])
    s = c_string_to_fortran(chars)
  end function string

  pure function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write(buf, '(i0)') i
    s = trim(buf)
  end function itoa
end module udmap_api_blade
