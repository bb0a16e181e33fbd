!> Symmetric sparse matrices in coordinate form, lower triangle (row >= col), 1-based, as
!> MUMPS (SYM=2) takes them; duplicate entries add up. Products are formed entry by entry,
!> so no sorting or compression is needed.
module udmap_blade_reduce_sparse_coo
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: coo_type, sym_matvec, sym_matmul

  !> A symmetric n x n matrix by its lower-triangle entries.
  type :: coo_type
    integer :: n = 0
    integer(8) :: nnz = 0
    integer, allocatable :: row(:), col(:)
    real(wp), allocatable :: val(:)
  end type coo_type

contains

  !> y = A x for the symmetric A stored by its lower triangle (sym_matmul with one row).
  pure subroutine sym_matvec(a, x, y)
    type(coo_type), intent(in) :: a
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: y(:)
    real(wp), allocatable :: x1(:, :), y1(:, :)
    x1 = reshape(x, [1, size(x)])
    allocate(y1(1, size(y)))
    call sym_matmul(a, x1, y1)
    y = y1(1, :)
  end subroutine sym_matvec

  !> Y = X A for row blocks: X(r, n) holds r row vectors (so each entry touches contiguous
  !> memory), Y(r, n) = X A = (A X^T)^T.
  pure subroutine sym_matmul(a, x, y)
    type(coo_type), intent(in) :: a
    real(wp), intent(in) :: x(:, :)
    real(wp), intent(out) :: y(:, :)
    integer(8) :: k
    integer :: i, j
    y = 0
    do k = 1, a%nnz
      i = a%row(k)
      j = a%col(k)
      y(:, i) = y(:, i) + a%val(k)*x(:, j)
      if (i /= j) y(:, j) = y(:, j) + a%val(k)*x(:, i)
    end do
  end subroutine sym_matmul
end module udmap_blade_reduce_sparse_coo
