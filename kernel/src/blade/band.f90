!> Storage helpers for the symmetric blade matrices: LAPACK symmetric band storage
!> (uplo = 'U': ab(kd+1+i-j, j) = a(i,j) for max(1, j-kd) <= i <= j) and dense copies,
!> and the matrix-vector product used by the solvers (udmap_blade_dd has the double-double one).
!>
!> Routines that accept a matrix take both its dense form `a` and its band form `ab` as
!> allocatable arguments and use whichever is allocated (the band form if both are).
module udmap_blade_band
  use udmap_core_kinds, only: wp
  use udmap_core_lapack, only: dsbmv
  implicit none
  private
  public :: dense_to_band, band_to_dense, dense_bandwidth, sym_matvec
  public :: sym_entry

contains

  !> Upper band storage (kd+1, n) of the symmetric matrix `a` (its upper triangle is read).
  pure subroutine dense_to_band(a, kd, ab)
    real(wp), intent(in) :: a(:, :)
    integer, intent(in) :: kd
    real(wp), allocatable, intent(out) :: ab(:, :)
    integer :: i, j, n
    n = size(a, 2)
    allocate(ab(kd+1, n), source=0.0_wp)
    do j = 1, n
      do i = max(1, j-kd), j
        ab(kd+1+i-j, j) = a(i, j)
      end do
    end do
  end subroutine dense_to_band

  !> Dense symmetric copy (n, n) of the upper band storage `ab` (kd+1, n).
  pure subroutine band_to_dense(ab, kd, a)
    real(wp), intent(in) :: ab(:, :)
    integer, intent(in) :: kd
    real(wp), allocatable, intent(out) :: a(:, :)
    integer :: i, j, n
    n = size(ab, 2)
    allocate(a(n, n), source=0.0_wp)
    do j = 1, n
      do i = max(1, j-kd), j
        a(i, j) = ab(kd+1+i-j, j)
        a(j, i) = ab(kd+1+i-j, j)
      end do
    end do
  end subroutine band_to_dense

  !> The half-bandwidth of the dense matrix `a`: the largest |i - j| with a(i,j) /= 0.
  pure function dense_bandwidth(a) result(kd)
    real(wp), intent(in) :: a(:, :)
    integer :: kd
    integer :: i, j
    kd = 0
    do j = 1, size(a, 2)
      do i = 1, size(a, 1)
        if (a(i, j) /= 0.0_wp) kd = max(kd, abs(i - j))
      end do
    end do
  end function dense_bandwidth

  !> Entry (i, j) of a symmetric matrix given densely or in band storage.
  pure function sym_entry(a, ab, kd, i, j) result(v)
    real(wp), allocatable, intent(in) :: a(:, :), ab(:, :)
    integer, intent(in) :: kd, i, j
    real(wp) :: v
    if (allocated(ab)) then
      if (abs(i - j) > kd) then
        v = 0.0_wp
      else
        v = ab(kd+1+min(i, j)-max(i, j), max(i, j))
      end if
    else
      v = a(i, j)
    end if
  end function sym_entry

  !> y = A x for the symmetric matrix A (dense `a` or band `ab` with half-bandwidth kd).
  pure subroutine sym_matvec(a, ab, kd, x, y)
    real(wp), allocatable, intent(in) :: a(:, :), ab(:, :)
    integer, intent(in) :: kd
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: y(:)
    integer :: n
    n = size(x)
    if (allocated(ab)) then
      call dsbmv('U', n, kd, 1.0_wp, ab, kd+1, x, 1, 0.0_wp, y, 1)
    else
      y = matmul(a, x)
    end if
  end subroutine sym_matvec
end module udmap_blade_band
