!> C API, common part: version and the error handle (wrappers/c/udmap.h).
!> Handles are C pointers to Fortran objects allocated here; nothing is kept globally.
module udmap_api_c_common
  use, intrinsic :: iso_c_binding, only: c_ptr, c_associated, c_f_pointer, c_loc, c_int, &
    & c_char, c_null_char
  use udmap_core_error, only: UDMAP_OK
  use udmap_core_version, only: udmap_version_major, udmap_version_minor, udmap_version_patch
  use udmap_api_c_support, only: c_error_type, take_handle, copy_string
  implicit none
  private

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
    if (.not.c_associated(handle)) return
    call c_f_pointer(take_handle(handle), err)
    deallocate(err)
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
    if (buflen < 1) return
    buffer(1) = c_null_char
    if (.not.c_associated(handle)) return
    call c_f_pointer(handle, err)
    if (allocated(err%error)) call copy_string(err%error%message, buffer, buflen)
  end subroutine udmap_get_error

end module udmap_api_c_common
