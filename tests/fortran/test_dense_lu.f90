!> The dense LU of the harmonic balance (udmap_core_dense_lu) against the reference LAPACK it
!> replaces: the same factors, pivots, info and solutions as dgetrf and dgetrs, bit for bit, on
!> random matrices of 1 to 200 rows (past dgetrf's block of 64), a singular one and one whose
!> pivots lie below the safe minimum.
module test_dense_lu
  use udmap_core_kinds, only: wp
  use udmap_core_lapack, only: dgetrf, dgetrs
  use udmap_core_dense_lu, only: lu_factor, lu_solve
  use fixtures, only: uniform_sequence_type
  use testing, only: test_suite, check_true, unittest_type, new_unittest
  implicit none
  private
  public :: collect_dense_lu

contains

  subroutine collect_dense_lu(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("dense_lu", run_dense_lu)]
  end subroutine collect_dense_lu

  subroutine run_dense_lu(suite)
    type(test_suite), intent(inout) :: suite
    integer, parameter :: sizes(9) = [1, 2, 3, 17, 63, 64, 65, 127, 200]
    real(wp), allocatable :: A(:, :), F(:, :), Fr(:, :), b(:), x(:), xr(:)
    integer, allocatable :: ip(:), ipr(:)
    integer :: c, n, info, infor, k, differ
    type(uniform_sequence_type) :: rng
    character(len=40) :: tag
    rng%state = 7_8
    do c = 1, size(sizes) + 2
      n = merge(sizes(min(c, size(sizes))), 40, c <= size(sizes))
      if (c <= size(sizes)) then
        write(tag, '(a, i0)') "n = ", n
      else
        tag = merge("singular          ", "pivot below tiny()", c == size(sizes) + 1)
      end if
      allocate(A(n, n), b(n), ip(n), ipr(n))
      do k = 1, n
        A(:, k) = [(rng%next() - 0.5_wp, info = 1, n)]
      end do
      b = [(rng%next() - 0.5_wp, info = 1, n)]
      ! zero columns: U(7, 7) = U(12, 12) = 0 exactly (the first and the second of a pair of
      ! columns that lu_factor eliminates together)
      if (c == size(sizes) + 1) then
        A(:, 7) = 0
        A(:, 12) = 0
      end if
      ! subnormal entries (and a right-hand side to match: the solution stays finite)
      if (c == size(sizes) + 2) then
        A = 1.0e-309_wp*A
        b = 1.0e-309_wp*b
      end if
      F = A
      Fr = A
      call lu_factor(n, F, ip, info)
      call dgetrf(n, n, Fr, n, ipr, infor)
      differ = count(F /= Fr) + count(ip /= ipr)
      call check_true(suite, "factors and pivots of dgetrf, "//trim(tag), differ == 0 .and. &
        & info == infor)
      if (c == size(sizes) + 1) call check_true(suite, "singular: info > 0", info > 0)
      if (info == 0) then
        x = b
        xr = b
        call lu_solve(n, F, ip, x)
        call dgetrs('N', n, 1, Fr, n, ipr, xr, n, infor)
        call check_true(suite, "solution of dgetrs, "//trim(tag), all(x == xr))
      end if
      deallocate(A, b, ip, ipr)
    end do
  end subroutine run_dense_lu
end module test_dense_lu
