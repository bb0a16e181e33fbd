!> The Fortran test framework: assertion helpers, unit tests and the suites that collect them
!> (the layout of dftd4's test/unit). A unit test is a subroutine that records its checks in a
!> `test_suite` count; each suite module has a `collect_<suite>` routine that returns its unit
!> tests; the driver main.f90 runs suites by name. A unit fails when one of its checks fails or
!> when it made no check at all.
module testing
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  implicit none
  private
  public :: test_suite, check_close, check_true, check_no_error, check_error
  public :: unittest_type, new_unittest, testsuite_type, new_testsuite, run_testsuite

  !> Counts of passed and failed checks of one unit test.
  type :: test_suite
    integer :: passed = 0, failed = 0
  end type test_suite

  abstract interface
    !> A unit test: records its checks in `suite`.
    subroutine test_interface(suite)
      import :: test_suite
      type(test_suite), intent(inout) :: suite
    end subroutine test_interface
  end interface

  !> One named unit test.
  type :: unittest_type
    character(len=:), allocatable :: name
    procedure(test_interface), pointer, nopass :: test => null()
  end type unittest_type

  abstract interface
    !> Returns the unit tests of one suite.
    subroutine collect_interface(testsuite)
      import :: unittest_type
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
    end subroutine collect_interface
  end interface

  !> One named suite: the routine that collects its unit tests.
  type :: testsuite_type
    character(len=:), allocatable :: name
    procedure(collect_interface), pointer, nopass :: collect => null()
  end type testsuite_type

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

  !> A unit test named `name` that runs `test`.
  function new_unittest(name, test) result(unittest)
    character(len=*), intent(in) :: name
    procedure(test_interface) :: test
    type(unittest_type) :: unittest
    unittest%name = name
    unittest%test => test
  end function new_unittest

  !> A suite named `name`; `collect` returns its unit tests.
  function new_testsuite(name, collect) result(testsuite)
    character(len=*), intent(in) :: name
    procedure(collect_interface) :: collect
    type(testsuite_type) :: testsuite
    testsuite = testsuite_type(name, collect)
  end function new_testsuite

  !> Runs every unit test of one suite, prints a count line per unit and for the suite, and
  !> adds the number of failed units to `nfailed`.
  subroutine run_testsuite(testsuite, nfailed)
    type(testsuite_type), intent(in) :: testsuite
    integer, intent(inout) :: nfailed
    type(unittest_type), allocatable :: units(:)
    type(test_suite) :: counts, total
    integer :: i
    call testsuite%collect(units)
    do i = 1, size(units)
      counts = test_suite()
      call units(i)%test(counts)
      write(*, '(a, i0, a, i0, a)') "# "//testsuite%name//": "//units(i)%name//": ", &
        & counts%passed, " passed, ", counts%failed, " failed"
      if (counts%failed > 0 .or. counts%passed == 0) nfailed = nfailed + 1
      total%passed = total%passed + counts%passed
      total%failed = total%failed + counts%failed
    end do
    write(*, '(i0, a, i0, a)') total%passed, " passed, ", total%failed, " failed"
  end subroutine run_testsuite
end module testing
