!> What every C API module (api*.f90) shares: the error handle's object, the argument checks
!> (NULL handles and pointers, counts and ranges) and the copy-out into caller buffers. The
!> checks keep the first error, so a function lists its checks in the order the header gives
!> them and stops at the first failure. Nothing is kept between calls.
module udmap_api_c_support
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, c_int, &
    & c_double, c_char, c_null_char, c_size_t
  use udmap_core_error, only: error_type, fatal_error, UDMAP_OK, UDMAP_EINPUT
  use udmap_core_strings, only: indexed_name
  implicit none
  private
  public :: c_error_type, set_error, clear_error, error_from_handle, report_error
  public :: check_handle, check_input, take_handle, handle_slot, indexed_name
  public :: c_string_to_fortran, c_string, copy_string, copy_out, put_out

  !> What the C error handle points to: the last error, if any.
  type :: c_error_type
    type(error_type), allocatable :: error
  end type c_error_type

  !> Copies values into a caller's buffer, at most `capacity` of them.
  interface copy_out
    module procedure copy_out_real, copy_out_int
  end interface copy_out

  !> Stores a result through an optional C pointer: nothing when it is NULL.
  interface put_out
    module procedure put_out_int, put_out_real1, put_out_real2
  end interface put_out

  interface
    function c_strlen(s) bind(C, name="strlen") result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: n
    end function c_strlen
  end interface

contains

  ! ------------------------------------------------------------------ the error handle

  !> Stores `error` (moved) in the handle and returns its status; UDMAP_OK and a cleared
  !> handle when `error` is not allocated. A NULL handle only loses the message.
  function set_error(handle, error) result(stat)
    type(c_ptr), intent(in) :: handle
    type(error_type), allocatable, intent(inout) :: error
    integer(c_int) :: stat
    type(c_error_type), pointer :: err
    stat = UDMAP_OK
    if (allocated(error)) stat = int(error%stat, c_int)
    if (.not.c_associated(handle)) return
    call c_f_pointer(handle, err)
    if (allocated(err%error)) deallocate(err%error)
    if (allocated(error)) call move_alloc(error, err%error)
  end function set_error

  !> Whether `error` is allocated; if so, it is moved into the handle and stat is its status
  !> (for an early return: `if (report_error(handle, error, stat)) return`).
  logical function report_error(handle, error, stat) result(reported)
    type(c_ptr), intent(in) :: handle
    type(error_type), allocatable, intent(inout) :: error
    integer(c_int), intent(out) :: stat
    reported = allocated(error)
    if (reported) stat = set_error(handle, error)
  end function report_error

  !> Clears the handle's error before a new call.
  subroutine clear_error(handle)
    type(c_ptr), intent(in) :: handle
    type(c_error_type), pointer :: err
    if (.not.c_associated(handle)) return
    call c_f_pointer(handle, err)
    if (allocated(err%error)) deallocate(err%error)
  end subroutine clear_error

  ! ------------------------------------------------------------------ argument checks

  !> An input error for a NULL handle argument named `name`.
  function error_from_handle(name) result(error)
    character(len=*), intent(in) :: name
    type(error_type), allocatable :: error
    allocate(error)
    error%stat = UDMAP_EINPUT
    error%message = "argument '"//name//"' is a NULL handle"
  end function error_from_handle

  !> The NULL-handle error naming `name` when `handle` is NULL; an earlier error is kept.
  subroutine check_handle(handle, name, error)
    type(c_ptr), intent(in) :: handle
    character(len=*), intent(in) :: name
    type(error_type), allocatable, intent(inout) :: error
    if (allocated(error)) return
    if (.not.c_associated(handle)) error = error_from_handle(name)
  end subroutine check_handle

  !> An input error with `message` unless `ok`; an earlier error is kept.
  subroutine check_input(ok, message, error)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: message
    type(error_type), allocatable, intent(inout) :: error
    if (allocated(error)) return
    if (.not.ok) call fatal_error(error, message, UDMAP_EINPUT)
  end subroutine check_input

  ! ------------------------------------------------------------------ handles

  !> The handle's value, leaving NULL in the handle (a delete function frees what it gets).
  function take_handle(handle) result(object)
    type(c_ptr), intent(inout) :: handle
    type(c_ptr) :: object
    object = handle
    handle = c_null_ptr
  end function take_handle

  !> The handle variable a `udmap_x *` argument points to, set to NULL (a constructor's
  !> output before it succeeds); not associated when the argument is NULL.
  function handle_slot(where) result(slot)
    type(c_ptr), intent(in) :: where
    type(c_ptr), pointer :: slot
    nullify(slot)
    if (.not.c_associated(where)) return
    call c_f_pointer(where, slot)
    slot = c_null_ptr
  end function handle_slot

  ! ------------------------------------------------------------------ strings

  !> Copies a NUL-terminated C string into a Fortran string.
  function c_string_to_fortran(cstr) result(str)
    character(kind=c_char), intent(in) :: cstr(*)
    character(len=:), allocatable :: str
    integer :: n, i
    n = 0
    do while (cstr(n+1) /= c_null_char)
      n = n + 1
    end do
    allocate(character(len=n) :: str)
    do i = 1, n
      str(i:i) = cstr(i)
    end do
  end function c_string_to_fortran

  !> The Fortran string of a NUL-terminated C string given by its (non-NULL) address.
  function c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    call c_f_pointer(p, chars, [int(c_strlen(p)) + 1])
    s = c_string_to_fortran(chars)
  end function c_string

  !> Copies `str` into a caller's buffer of `buflen` characters, NUL-terminated and cut to
  !> fit; nothing for buflen < 1.
  subroutine copy_string(str, buffer, buflen)
    character(len=*), intent(in) :: str
    character(kind=c_char), intent(inout) :: buffer(*)
    integer(c_int), intent(in) :: buflen
    integer :: i, n
    if (buflen < 1) return
    n = min(len(str), int(buflen) - 1)
    do i = 1, n
      buffer(i) = str(i:i)
    end do
    buffer(n+1) = c_null_char
  end subroutine copy_string

  ! ------------------------------------------------------------------ copy-out

  subroutine copy_out_real(values, buffer, capacity)
    real(c_double), intent(in) :: values(:)
    real(c_double), intent(inout) :: buffer(*)
    integer, intent(in) :: capacity
    integer :: m
    m = max(0, min(size(values), capacity))
    buffer(1:m) = values(1:m)
  end subroutine copy_out_real

  subroutine copy_out_int(values, buffer, capacity)
    integer, intent(in) :: values(:)
    integer(c_int), intent(inout) :: buffer(*)
    integer, intent(in) :: capacity
    integer :: m
    m = max(0, min(size(values), capacity))
    buffer(1:m) = int(values(1:m), c_int)
  end subroutine copy_out_int

  subroutine put_out_int(where, value)
    type(c_ptr), intent(in) :: where
    integer, intent(in) :: value
    integer(c_int), pointer :: p
    if (.not.c_associated(where)) return
    call c_f_pointer(where, p)
    p = int(value, c_int)
  end subroutine put_out_int

  subroutine put_out_real1(where, values)
    type(c_ptr), intent(in) :: where
    real(c_double), intent(in) :: values(:)
    real(c_double), pointer :: p(:)
    if (.not.c_associated(where)) return
    call c_f_pointer(where, p, [size(values)])
    p = values
  end subroutine put_out_real1

  !> A matrix goes out column-major, as it is stored.
  subroutine put_out_real2(where, values)
    type(c_ptr), intent(in) :: where
    real(c_double), intent(in) :: values(:, :)
    real(c_double), pointer :: p(:, :)
    if (.not.c_associated(where)) return
    call c_f_pointer(where, p, shape(values))
    p = values
  end subroutine put_out_real2
end module udmap_api_c_support
