!> C API, common part: version and the error handle (wrappers/c/udmap.h).
!> Handles are C pointers to Fortran objects allocated here; nothing is kept globally.
module udmap_api
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, &
    & c_loc, c_int, c_char, c_null_char
  use udmap_error, only: error_type, UDMAP_OK, UDMAP_EINPUT
  use udmap_version_info, only: udmap_version_major, udmap_version_minor, udmap_version_patch
  implicit none
  private
  public :: c_error_type, set_error, clear_error, error_from_handle, c_string_to_fortran

  !> What the C error handle points to: the last error, if any.
  type :: c_error_type
    type(error_type), allocatable :: error
  end type c_error_type

contains

  !> Version as 10000 major + 100 minor + patch.
  function udmap_get_version() result(version) bind(C, name="udmap_get_version")
    integer(c_int) :: version
    version = int(10000*udmap_version_major + 100*udmap_version_minor + udmap_version_patch, c_int)
  end function udmap_get_version

  function udmap_new_error() result(handle) bind(C, name="udmap_new_error")
    type(c_ptr) :: handle
    type(c_error_type), pointer :: err
    allocate(err)
    handle = c_loc(err)
  end function udmap_new_error

  subroutine udmap_delete_error(handle) bind(C, name="udmap_delete_error")
    type(c_ptr), intent(inout) :: handle
    type(c_error_type), pointer :: err
    if (c_associated(handle)) then
      call c_f_pointer(handle, err)
      deallocate(err)
      handle = c_null_ptr
    end if
  end subroutine udmap_delete_error

  function udmap_check_error(handle) result(stat) bind(C, name="udmap_check_error")
    type(c_ptr), value :: handle
    integer(c_int) :: stat
    type(c_error_type), pointer :: err
    stat = UDMAP_OK
    if (.not.c_associated(handle)) return
    call c_f_pointer(handle, err)
    if (allocated(err%error)) stat = int(err%error%stat, c_int)
  end function udmap_check_error

  subroutine udmap_get_error(handle, buffer, buflen) bind(C, name="udmap_get_error")
    type(c_ptr), value :: handle
    character(kind=c_char), intent(out) :: buffer(*)
    integer(c_int), value :: buflen
    type(c_error_type), pointer :: err
    integer :: i, n
    if (buflen < 1) return
    buffer(1) = c_null_char
    if (.not.c_associated(handle)) return
    call c_f_pointer(handle, err)
    if (.not.allocated(err%error)) return
    n = min(len(err%error%message), int(buflen) - 1)
    do i = 1, n
      buffer(i) = err%error%message(i:i)
    end do
    buffer(n+1) = c_null_char
  end subroutine udmap_get_error

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

  !> Clears the handle's error before a new call.
  subroutine clear_error(handle)
    type(c_ptr), intent(in) :: handle
    type(c_error_type), pointer :: err
    if (.not.c_associated(handle)) return
    call c_f_pointer(handle, err)
    if (allocated(err%error)) deallocate(err%error)
  end subroutine clear_error

  !> An input error for a NULL handle argument named `name`.
  function error_from_handle(name) result(error)
    character(len=*), intent(in) :: name
    type(error_type), allocatable :: error
    allocate(error)
    error%stat = UDMAP_EINPUT
    error%message = "argument '"//name//"' is a NULL handle"
  end function error_from_handle

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
end module udmap_api
