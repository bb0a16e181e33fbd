!> Dense LU with partial pivoting and its solve, for the small dense Jacobians of the harmonic
!> balance (a few hundred unknowns at most). The same factors, pivots and solutions as the
!> reference LAPACK's dgetrf and dgetrs, bit for bit: each entry receives its updates
!> a_ij - l_ik u_kj in increasing k, the column is scaled by the reciprocal of its pivot, the
!> first largest |a_ik| is the pivot, and the solve runs dtrsm's column sweeps. Written out so
!> that the updates, independent over a column, are vectorized (the reference BLAS runs them
!> one by one; a dense factorisation was a third of the automatic H's time).
module udmap_core_dense_lu
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: lu_factor, lu_solve

contains

  !> A = P L U in place (L unit lower, U upper) with the row interchanges ipiv; info = 0, or
  !> the first k with U(k, k) = 0 (the factors are then complete but U is singular).
  pure subroutine lu_factor(n, a, ipiv, info)
    integer, intent(in) :: n
    real(wp), intent(inout) :: a(n, n)
    integer, intent(out) :: ipiv(n), info
    integer :: i, j, k, p
    real(wp) :: t, r
    info = 0
    do k = 1, n
      p = k - 1 + maxloc(abs(a(k:n, k)), 1)
      ipiv(k) = p
      if (a(p, k) == 0) then
        if (info == 0) info = k
        cycle
      end if
      if (p /= k) then
        do j = 1, n
          t = a(k, j)
          a(k, j) = a(p, j)
          a(p, j) = t
        end do
      end if
      ! dgetrf2 divides instead below the safe minimum, where 1/pivot would overflow
      if (abs(a(k, k)) >= tiny(1.0_wp)) then
        r = 1/a(k, k)
        do i = k + 1, n
          a(i, k) = a(i, k)*r
        end do
      else
        do i = k + 1, n
          a(i, k) = a(i, k)/a(k, k)
        end do
      end if
      do j = k + 1, n
        t = a(k, j)
        do i = k + 1, n
          a(i, j) = a(i, j) - t*a(i, k)
        end do
      end do
    end do
  end subroutine lu_factor

  !> b = A^-1 b with the factors of lu_factor.
  pure subroutine lu_solve(n, a, ipiv, b)
    integer, intent(in) :: n
    real(wp), intent(in) :: a(n, n)
    integer, intent(in) :: ipiv(n)
    real(wp), intent(inout) :: b(n)
    integer :: i, k
    real(wp) :: t
    do k = 1, n
      if (ipiv(k) /= k) then
        t = b(k)
        b(k) = b(ipiv(k))
        b(ipiv(k)) = t
      end if
    end do
    do k = 1, n
      if (b(k) /= 0) then
        do i = k + 1, n
          b(i) = b(i) - b(k)*a(i, k)
        end do
      end if
    end do
    do k = n, 1, -1
      if (b(k) /= 0) then
        b(k) = b(k)/a(k, k)
        do i = 1, k - 1
          b(i) = b(i) - b(k)*a(i, k)
        end do
      end if
    end do
  end subroutine lu_solve
end module udmap_core_dense_lu
