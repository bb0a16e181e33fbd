!> Errors travel as values (mctc-lib style): an allocated error_type means failure.
module udmap_core_error
  implicit none
  private
  public :: error_type, fatal_error, require
  public :: UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC

  !> Status codes shared with the C API and the CLI exit codes.
  integer, parameter :: UDMAP_OK = 0        !< success
  integer, parameter :: UDMAP_EINPUT = 2    !< bad input: a parameter, file or argument is invalid
  integer, parameter :: UDMAP_EPHYSICS = 3  !< physics failure: jammed damper, no resonance in band
  integer, parameter :: UDMAP_ENUMERIC = 4  !< numerical failure: a LAPACK/ARPACK routine failed

  !> An error with its status code and a message for the user.
  type :: error_type
    integer :: stat = UDMAP_EINPUT
    character(len=:), allocatable :: message
  end type error_type

contains

  !> Allocates `error` with `message` and status `stat` (default UDMAP_EINPUT).
  pure subroutine fatal_error(error, message, stat)
    type(error_type), allocatable, intent(out) :: error
    character(len=*), intent(in) :: message
    integer, intent(in), optional :: stat
    allocate(error)
    error%message = message
    if (present(stat)) error%stat = stat
  end subroutine fatal_error

  !> One check of a series on the input: sets `error` (UDMAP_EINPUT) with `message` where `ok`
  !> is false and no earlier check of the series failed, so the first failure is the one
  !> reported; the caller tests `error` once after the series.
  pure subroutine require(ok, message, error)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: message
    type(error_type), allocatable, intent(inout) :: error
    if (allocated(error) .or. ok) return
    call fatal_error(error, message, UDMAP_EINPUT)
  end subroutine require
end module udmap_core_error
