!> The umbrella module udmap: the version string agrees with the numeric version that the C API
!> reports (udmap_get_version, 10000 major + 100 minor + patch).
module test_umbrella
  use, intrinsic :: iso_c_binding, only: c_int
  use testing, only: test_suite, check_true, unittest_type, new_unittest
  use udmap, only: udmap_version, udmap_version_major, udmap_version_minor, udmap_version_patch
  implicit none
  private
  public :: collect_umbrella

  interface
    function udmap_get_version() result(version) bind(C, name="udmap_get_version")
      import :: c_int
      integer(c_int) :: version
    end function udmap_get_version
  end interface

contains

  !> The umbrella module udmap.
  subroutine collect_umbrella(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("umbrella", run_umbrella)]
  end subroutine collect_umbrella

  !> The version string of module udmap agrees with the C API's numeric version.
  subroutine run_umbrella(suite)
    type(test_suite), intent(inout) :: suite
    character(len=32) :: expected
    integer :: v

    write(expected, '(i0,".",i0,".",i0)') udmap_version_major, udmap_version_minor, &
      & udmap_version_patch
    call check_true(suite, "udmap_version() is major.minor.patch", &
      & udmap_version() == trim(expected))
    v = udmap_get_version()
    write(expected, '(i0,".",i0,".",i0)') v/10000, mod(v/100, 100), mod(v, 100)
    call check_true(suite, "udmap_version() equals the C API's udmap_get_version()", &
      & udmap_version() == trim(expected))
    call check_true(suite, "version is not 0.0.0", v > 0)
  end subroutine run_umbrella
end module test_umbrella
