!> Explicit interfaces of the LAPACK routines used by the standard method and the time
!> integration (keeps -Wimplicit-interface quiet and the calls checked).
module udmap_hbm_lapack
  use udmap_kinds, only: wp
  implicit none
  private
  public :: dgesv, dgetrf, dgetrs, dgbtrf, dgbtrs, dpbtrf, dpbtrs, dpotrf, dpotrs
  public :: zgbtrf, zgbtrs, zgetrf, zgetrs

  interface
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
    !> Banded symmetric positive definite Cholesky factorisation.
    pure subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, kd, ldab
      real(wp), intent(inout) :: ab(ldab, *)
      integer, intent(out) :: info
    end subroutine dpbtrf
    !> Banded symmetric positive definite back substitution.
    pure subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, kd, nrhs, ldab, ldb
      real(wp), intent(in) :: ab(ldab, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dpbtrs
    !> Dense symmetric positive definite Cholesky factorisation.
    pure subroutine dpotrf(uplo, n, a, lda, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: info
    end subroutine dpotrf
    !> Dense symmetric positive definite back substitution.
    pure subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dpotrs
    !> Banded complex LU factorisation.
    pure subroutine zgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, kl, ku, ldab
      complex(wp), intent(inout) :: ab(ldab, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine zgbtrf
    !> Banded complex LU back substitution.
    pure subroutine zgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb, ipiv(*)
      complex(wp), intent(in) :: ab(ldab, *)
      complex(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine zgbtrs
    !> Dense complex LU factorisation.
    pure subroutine zgetrf(m, n, a, lda, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, lda
      complex(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine zgetrf
    !> Dense complex LU back substitution.
    pure subroutine zgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, nrhs, lda, ldb, ipiv(*)
      complex(wp), intent(in) :: a(lda, *)
      complex(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine zgetrs
  end interface
end module udmap_hbm_lapack
