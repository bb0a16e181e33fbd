!> Explicit interfaces of the LAPACK and BLAS routines the kernel calls (reference LAPACK
!> names and argument lists), so that -Wimplicit-interface stays quiet and arguments are checked.
!> Add routines here rather than declaring them again elsewhere.
module udmap_core_lapack
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: dsyev, dsygvd, dsygv, dpotrf, dpotrs, dpbtrf, dpbtrs, dsbmv
  public :: zgetrf, zgetrs, zgbtrf, zgbtrs, zggev
  public :: dgesv, dgetrf, dgetrs, dgbtrf, dgbtrs, dgemm, dgemv

  interface
    !> Symmetric eigenproblem A x = lambda x (QR iteration).
    pure subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
      import :: wp
      character(len=1), intent(in) :: jobz, uplo
      integer, intent(in) :: n, lda, lwork
      real(wp), intent(inout) :: a(lda, *)
      real(wp), intent(out) :: w(*), work(*)
      integer, intent(out) :: info
    end subroutine dsyev

    !> Generalized symmetric-definite eigenproblem A x = lambda B x, divide and conquer.
    pure subroutine dsygvd(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, iwork, &
        & liwork, info)
      import :: wp
      integer, intent(in) :: itype, n, lda, ldb, lwork, liwork
      character(len=1), intent(in) :: jobz, uplo
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      real(wp), intent(out) :: w(*), work(*)
      integer, intent(out) :: iwork(*), info
    end subroutine dsygvd

    !> Generalized symmetric-definite eigenproblem A x = lambda B x (QR iteration).
    pure subroutine dsygv(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, info)
      import :: wp
      integer, intent(in) :: itype, n, lda, ldb, lwork
      character(len=1), intent(in) :: jobz, uplo
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      real(wp), intent(out) :: w(*), work(*)
      integer, intent(out) :: info
    end subroutine dsygv

    !> Cholesky factorization of a dense symmetric positive definite matrix.
    pure subroutine dpotrf(uplo, n, a, lda, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: info
    end subroutine dpotrf

    !> Solves with the dense Cholesky factor from dpotrf.
    pure subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dpotrs

    !> Cholesky factorization of a symmetric positive definite band matrix.
    pure subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, kd, ldab
      real(wp), intent(inout) :: ab(ldab, *)
      integer, intent(out) :: info
    end subroutine dpbtrf

    !> Solves with the band Cholesky factor from dpbtrf.
    pure subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, kd, nrhs, ldab, ldb
      real(wp), intent(in) :: ab(ldab, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dpbtrs

    !> y = alpha A x + beta y with A symmetric in band storage (BLAS 2).
    pure subroutine dsbmv(uplo, n, k, alpha, a, lda, x, incx, beta, y, incy)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, k, lda, incx, incy
      real(wp), intent(in) :: alpha, beta, a(lda, *), x(*)
      real(wp), intent(inout) :: y(*)
    end subroutine dsbmv

    !> LU factorization of a general complex matrix with partial pivoting.
    pure subroutine zgetrf(m, n, a, lda, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, lda
      complex(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine zgetrf

    !> Solves with the LU factors from zgetrf.
    pure subroutine zgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, nrhs, lda, ldb, ipiv(*)
      complex(wp), intent(in) :: a(lda, *)
      complex(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine zgetrs

    !> LU factorization of a general complex band matrix (kl sub-, ku super-diagonals;
    !> ab has 2 kl + ku + 1 rows).
    pure subroutine zgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, kl, ku, ldab
      complex(wp), intent(inout) :: ab(ldab, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine zgbtrf

    !> Solves with the band LU factors from zgbtrf.
    pure subroutine zgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb, ipiv(*)
      complex(wp), intent(in) :: ab(ldab, *)
      complex(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine zgbtrs
    !> Dense real LU solve.
    pure subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgesv
    !> Dense real LU factorisation.
    pure subroutine dgetrf(m, n, a, lda, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgetrf
    !> Dense real LU back substitution.
    pure subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, nrhs, lda, ldb, ipiv(*)
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dgetrs
    !> Banded real LU factorisation.
    pure subroutine dgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, kl, ku, ldab
      real(wp), intent(inout) :: ab(ldab, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgbtrf
    !> Banded real LU back substitution.
    pure subroutine dgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb, ipiv(*)
      real(wp), intent(in) :: ab(ldab, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dgbtrs

    !> Generalized non-symmetric eigenproblem A x = lambda B x (QZ), eigenvalues
    !> alpha/beta.
    pure subroutine zggev(jobvl, jobvr, n, a, lda, b, ldb, alpha, beta, vl, ldvl, vr, ldvr, &
        & work, lwork, rwork, info)
      import :: wp
      character(len=1), intent(in) :: jobvl, jobvr
      integer, intent(in) :: n, lda, ldb, ldvl, ldvr, lwork
      complex(wp), intent(inout) :: a(lda, *), b(ldb, *)
      complex(wp), intent(out) :: alpha(*), beta(*), vl(ldvl, *), vr(ldvr, *), work(*)
      real(wp), intent(out) :: rwork(*)
      integer, intent(out) :: info
    end subroutine zggev
    !> BLAS matrix product.
    pure subroutine dgemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
      import :: wp
      character(len=1), intent(in) :: transa, transb
      integer, intent(in) :: m, n, k, lda, ldb, ldc
      real(wp), intent(in) :: alpha, beta, a(lda, *), b(ldb, *)
      real(wp), intent(inout) :: c(ldc, *)
    end subroutine dgemm
    !> BLAS matrix-vector product.
    pure subroutine dgemv(trans, m, n, alpha, a, lda, x, incx, beta, y, incy)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: m, n, lda, incx, incy
      real(wp), intent(in) :: alpha, beta, a(lda, *), x(*)
      real(wp), intent(inout) :: y(*)
    end subroutine dgemv
  end interface
end module udmap_core_lapack
