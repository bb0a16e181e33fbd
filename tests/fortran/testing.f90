!> Minimal assertion helpers for the Fortran test programs.
module testing
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  implicit none
  private
  public :: test_suite, check_close, check_true, check_no_error, check_error, finish

  !> Counts of passed and failed checks of one test program.
  type :: test_suite
    integer :: passed = 0, failed = 0
  end type test_suite

contains

  !> |actual - expected| <= rtol |expected| (+ atol if given).
  subroutine check_close(suite, name, actual, expected, rtol, atol)
    type(test_suite), intent(inout) :: suite
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: actual, expected, rtol
    real(wp), intent(in), optional :: atol
    real(wp) :: tol
    tol = rtol*abs(expected)
    if (present(atol)) tol = tol + atol
    if (abs(actual - expected) <= tol .and. actual == actual) then
      suite%passed = suite%passed + 1
    else
      suite%failed = suite%failed + 1
      write(*, '(a, a, es24.16, a, es24.16, a, es10.3)') "FAIL ", name//": got ", actual, &
        & " expected ", expected, " rel err ", abs(actual - expected)/max(abs(expected), tiny(1.0_wp))
    end if
  end subroutine check_close

  subroutine check_true(suite, name, condition)
    type(test_suite), intent(inout) :: suite
    character(len=*), intent(in) :: name
    logical, intent(in) :: condition
    if (condition) then
      suite%passed = suite%passed + 1
    else
      suite%failed = suite%failed + 1
      write(*, '(a)') "FAIL "//name
    end if
  end subroutine check_true

  !> Passes when `error` is not allocated; prints its message otherwise.
  subroutine check_no_error(suite, name, error)
    type(test_suite), intent(inout) :: suite
    character(len=*), intent(in) :: name
    type(error_type), allocatable, intent(in) :: error
    if (.not.allocated(error)) then
      suite%passed = suite%passed + 1
    else
      suite%failed = suite%failed + 1
      write(*, '(a)') "FAIL "//name//": unexpected error: "//error%message
    end if
  end subroutine check_no_error

  !> Passes when `error` is allocated with status `stat` and its message contains `needle`.
  subroutine check_error(suite, name, error, stat, needle)
    type(test_suite), intent(inout) :: suite
    character(len=*), intent(in) :: name
    type(error_type), allocatable, intent(in) :: error
    integer, intent(in) :: stat
    character(len=*), intent(in) :: needle
    if (.not.allocated(error)) then
      suite%failed = suite%failed + 1
      write(*, '(a)') "FAIL "//name//": expected an error, got none"
    else if (error%stat /= stat .or. index(error%message, needle) == 0) then
      suite%failed = suite%failed + 1
      write(*, '(a, i0, a)') "FAIL "//name//": got status ", error%stat, " message '"// &
        & error%message//"', expected it to contain '"//needle//"'"
    else
      suite%passed = suite%passed + 1
    end if
  end subroutine check_error

  !> Prints the closing count line and stops with status 1 on any failure.
  subroutine finish(suite)
    type(test_suite), intent(in) :: suite
    write(*, '(i0, a, i0, a)') suite%passed, " passed, ", suite%failed, " failed"
    if (suite%failed > 0 .or. suite%passed == 0) error stop 1
  end subroutine finish
end module testing
