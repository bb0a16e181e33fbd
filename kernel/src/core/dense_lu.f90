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
  !> the first k with U(k, k) = 0 (the factors are then complete but U is singular). Two
  !> columns at a time: column k + 1 is brought up to date and pivoted first, then the trailing
  !> columns receive both updates in one pass, (a_ij - l_ik u_kj) - l_i,k+1 u_k+1,j, the order
  !> of two single steps (row k + 1's interchange commutes with step k's update, which moves
  !> the rows' l_ik with them).
  pure subroutine lu_factor(n, a, ipiv, info)
    integer, intent(in) :: n
    real(wp), intent(inout) :: a(n, n)
    integer, intent(out) :: ipiv(n), info
    integer :: i, j, k
    real(wp) :: t1, t2
    logical :: ok1, ok2
    info = 0
    k = 1
    do while (k <= n)
      call pivot_column(n, a, k, ipiv, info, ok1)
      if (k == n) exit
      if (ok1) then
        t1 = a(k, k+1)
        do i = k + 1, n
          a(i, k+1) = a(i, k+1) - t1*a(i, k)
        end do
      end if
      call pivot_column(n, a, k + 1, ipiv, info, ok2)
      do j = k + 2, n
        t1 = a(k, j)
        if (ok1) a(k+1, j) = a(k+1, j) - t1*a(k+1, k)
        t2 = a(k+1, j)
        if (ok1 .and. ok2) then
          do i = k + 2, n
            a(i, j) = (a(i, j) - t1*a(i, k)) - t2*a(i, k+1)
          end do
        else if (ok1) then
          do i = k + 2, n
            a(i, j) = a(i, j) - t1*a(i, k)
          end do
        else if (ok2) then
          do i = k + 2, n
            a(i, j) = a(i, j) - t2*a(i, k+1)
          end do
        end if
      end do
      k = k + 2
    end do
  end subroutine lu_factor

  !> Column k's pivot (the first largest |a_ik|, i >= k), its rows interchanged and the column
  !> below it scaled; ok = .false. (and info set if it is the first) for a zero pivot.
  pure subroutine pivot_column(n, a, k, ipiv, info, ok)
    integer, intent(in) :: n, k
    real(wp), intent(inout) :: a(n, n)
    integer, intent(inout) :: ipiv(n), info
    logical, intent(out) :: ok
    integer :: i, j, p
    real(wp) :: t, r
    p = k - 1 + maxloc(abs(a(k:n, k)), 1)
    ipiv(k) = p
    ok = a(p, k) /= 0
    if (.not. ok) then
      if (info == 0) info = k
      return
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
  end subroutine pivot_column

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
