!> Linear solves for the blade: Cholesky of a symmetric positive definite matrix (dense or band)
!> and the complex dynamic stiffness D(omega) = K - omega^2 M + i omega C, both with iterative
!> refinement whose residuals are computed in double-double arithmetic (udmap_blade_dd).
!>
!> Why refinement: finely meshed beams are very ill-conditioned (the stiffness of a 2048-element
!> airfoil has kappa eps ~ 1e-3), so a plain double-precision solve loses most digits. With the
!> residual in double-double and the solution accumulated there, refinement converges to the
!> exact solution of the stored (double) data whenever eps kappa < 1, at the price of a
!> matrix-vector product per step.
module udmap_blade_linear_solve
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_core_lapack, only: dpotrf, dpotrs, dpbtrf, dpbtrs, zgetrf, zgetrs, zgbtrf, zgbtrs
  use udmap_blade_band, only: sym_entry
  use udmap_blade_dd, only: dd_add, dd_add_d, dd_mul_d, sym_matvec_dd
  implicit none
  private
  public :: spd_factor_type, spd_factor, spd_solve, dynamic_solve

  !> Maximum number of refinement steps of one solve.
  integer, parameter :: max_refine = 30
  !> Refinement stops when the correction is below this fraction of the largest entry: far
  !> below rounding, so that entries 1e6 times smaller than the largest are still exact.
  real(wp), parameter :: refine_tol = 1.0e-6_wp*epsilon(1.0_wp)

  !> Cholesky factor (uplo = 'U') of a symmetric positive definite matrix: dense (kd < 0)
  !> or in band storage with half-bandwidth kd.
  type :: spd_factor_type
    integer :: n = 0
    integer :: kd = -1
    real(wp), allocatable :: u(:, :)
  end type spd_factor_type

  character(len=*), parameter :: fmt_i = '(i0)'

contains

  !> Factors the symmetric matrix (dense `a` or band `ab`); an error naming `name` when it is
  !> not positive definite.
  subroutine spd_factor(a, ab, kd, name, f, error)
    real(wp), allocatable, intent(in) :: a(:, :), ab(:, :)
    integer, intent(in) :: kd
    character(len=*), intent(in) :: name
    type(spd_factor_type), intent(out) :: f
    type(error_type), allocatable, intent(out) :: error
    integer :: info
    character(len=24) :: buf
    if (allocated(ab)) then
      f%n = size(ab, 2)
      f%kd = kd
      f%u = ab
      call dpbtrf('U', f%n, kd, f%u, kd+1, info)
    else
      f%n = size(a, 2)
      f%kd = -1
      f%u = a
      call dpotrf('U', f%n, f%u, f%n, info)
    end if
    if (info > 0) then
      write(buf, fmt_i) info
      call fatal_error(error, name//" is not positive definite (Cholesky factorization failed "// &
        & "at row "//trim(buf)//")", UDMAP_EINPUT)
    else if (info < 0) then
      write(buf, fmt_i) info
      call fatal_error(error, "Cholesky factorization of "//name//" failed (dpotrf/dpbtrf info = "// &
        & trim(buf)//")", UDMAP_ENUMERIC)
    end if
  end subroutine spd_factor

  !> Solves A x = b for the columns of b with the factor `f` of A (dense `a` or band `ab`).
  !> With `refine`, iterative refinement with extended-precision residuals (see the module
  !> documentation); otherwise one plain solve.
  subroutine spd_solve(f, a, ab, b, x, refine)
    type(spd_factor_type), intent(in) :: f
    real(wp), allocatable, intent(in) :: a(:, :), ab(:, :)
    real(wp), intent(in) :: b(:, :)
    real(wp), intent(out) :: x(:, :)
    logical, intent(in) :: refine
    real(wp), allocatable :: xh(:), xl(:), yh(:), yl(:), d(:)
    real(wp) :: dnorm, dprev
    integer :: j, it, n, kd
    n = f%n
    kd = max(f%kd, 0)
    x = b
    call plain_solve(f, x)
    if (.not.refine) return
    allocate(xh(n), xl(n), yh(n), yl(n), d(n))
    do j = 1, size(b, 2)
      xh = x(:, j)
      xl = 0.0_wp
      dprev = huge(1.0_wp)
      do it = 1, max_refine
        ! d = b - A x in double-double, rounded; then x += A^-1 d kept in double-double.
        call sym_matvec_dd(a, ab, kd, xh, xl, yh, yl)
        call dd_add_d(-yh, -yl, b(:, j), d, yl)
        call plain_solve_1(f, d)
        call dd_add_d(xh, xl, d, yh, yl)
        xh = yh
        xl = yl
        dnorm = maxval(abs(d))
        ! Converged (well below rounding of the largest entry, so that small entries are
        ! accurate too), or stalled (at the floor, or eps kappa >= 1).
        if (dnorm <= refine_tol*maxval(abs(xh)) .or. dnorm > 0.5_wp*dprev) exit
        dprev = dnorm
      end do
      x(:, j) = xh
    end do
  end subroutine spd_solve

  subroutine plain_solve(f, x)
    type(spd_factor_type), intent(in) :: f
    real(wp), intent(inout) :: x(:, :)
    integer :: info
    if (f%kd >= 0) then
      call dpbtrs('U', f%n, f%kd, size(x, 2), f%u, f%kd+1, x, f%n, info)
    else
      call dpotrs('U', f%n, size(x, 2), f%u, f%n, x, f%n, info)
    end if
  end subroutine plain_solve

  subroutine plain_solve_1(f, x)
    type(spd_factor_type), intent(in) :: f
    real(wp), intent(inout) :: x(:)
    integer :: info
    if (f%kd >= 0) then
      call dpbtrs('U', f%n, f%kd, 1, f%u, f%kd+1, x, f%n, info)
    else
      call dpotrs('U', f%n, 1, f%u, f%n, x, f%n, info)
    end if
  end subroutine plain_solve_1

  !> Solves D(omega) q = b for the columns of b, D = K - omega^2 M + i omega C with C the explicit
  !> damping (`c`/`cb` allocated) or beta K, by complex LU (zgetrf dense, zgbtrf band) and
  !> iterative refinement with extended-precision residuals. Matrices are given densely or in
  !> band storage with half-bandwidth kd, all alike.
  subroutine dynamic_solve(omega, beta, k, kb, m, mb, c, cb, kd, b, q, error)
    real(wp), intent(in) :: omega, beta
    real(wp), allocatable, intent(in) :: k(:, :), kb(:, :), m(:, :), mb(:, :), c(:, :), cb(:, :)
    integer, intent(in) :: kd
    complex(wp), intent(in) :: b(:, :)
    complex(wp), intent(out) :: q(:, :)
    type(error_type), allocatable, intent(out) :: error
    complex(wp), allocatable :: lu(:, :), d(:)
    complex(wp) :: fk
    integer, allocatable :: ipiv(:)
    integer :: n, nrhs, info, i, j, ldab, it, kdu
    logical :: band, explicit
    character(len=24) :: buf
    real(wp), allocatable :: xrh(:), xrl(:), xih(:), xil(:), th(:), tl(:), uh(:), ul(:), &
      & rr(:), ri(:)
    real(wp) :: dnorm, dprev

    band = allocated(kb)
    explicit = allocated(c) .or. allocated(cb)
    n = size(b, 1)
    nrhs = size(b, 2)
    kdu = max(kd, 0)
    ! D = (1 + i omega beta) K - omega^2 M + i omega C
    fk = cmplx(1.0_wp, omega*beta, wp)
    if (explicit) fk = (1.0_wp, 0.0_wp)
    allocate(ipiv(n))
    if (band) then
      ldab = 3*kdu + 1
      allocate(lu(ldab, n), source=(0.0_wp, 0.0_wp))
      do j = 1, n
        do i = max(1, j-kdu), min(n, j+kdu)
          lu(2*kdu+1+i-j, j) = d_entry(i, j)
        end do
      end do
      call zgbtrf(n, n, kdu, kdu, lu, ldab, ipiv, info)
    else
      allocate(lu(n, n))
      do j = 1, n
        do i = 1, n
          lu(i, j) = d_entry(i, j)
        end do
      end do
      call zgetrf(n, n, lu, n, ipiv, info)
    end if
    if (info /= 0) then
      write(buf, fmt_i) info
      if (band) then
        call fatal_error(error, "the dynamic stiffness D(omega) is singular (zgbtrf info = "// &
          & trim(buf)//")", UDMAP_ENUMERIC)
      else
        call fatal_error(error, "the dynamic stiffness D(omega) is singular (zgetrf info = "// &
          & trim(buf)//")", UDMAP_ENUMERIC)
      end if
      return
    end if

    q = b
    call lu_solve(q)
    allocate(xrh(n), xrl(n), xih(n), xil(n), th(n), tl(n), uh(n), ul(n), rr(n), ri(n), d(n))
    do j = 1, nrhs
      xrh = q(:, j)%re
      xih = q(:, j)%im
      xrl = 0.0_wp
      xil = 0.0_wp
      dprev = huge(1.0_wp)
      do it = 1, max_refine
        ! r = b - D x in double-double: D x = K x + i omega beta K x - omega^2 M x + i omega C x
        ! (fk = 1 + i omega beta; fk = 1 with explicit C).
        call residual_part(xrh, xrl, xih, xil, real(b(:, j)), -1.0_wp, rr)
        call residual_part(xih, xil, xrh, xrl, aimag(b(:, j)), 1.0_wp, ri)
        d = cmplx(rr, ri, wp)
        call lu_solve_1(d)
        call dd_add_d(xrh, xrl, d%re, th, tl)
        xrh = th
        xrl = tl
        call dd_add_d(xih, xil, d%im, th, tl)
        xih = th
        xil = tl
        dnorm = maxval(abs(d))
        if (dnorm <= refine_tol*sqrt(maxval(xrh**2 + xih**2)) .or. dnorm > 0.5_wp*dprev) exit
        dprev = dnorm
      end do
      q(:, j) = cmplx(xrh, xih, wp)
    end do

  contains

    !> One part (real: sgn = -1, x = real part, y = imaginary part; imaginary: sgn = +1 with x, y
    !> swapped) of r = b - D (x + i y): r = b - (K x + sgn fk_im K y - omega^2 M x
    !> + sgn omega C y), every product exact and every sum compensated.
    subroutine residual_part(xh, xl, yh, yl, bp, sgn, r)
      real(wp), intent(in) :: xh(:), xl(:), yh(:), yl(:), bp(:), sgn
      real(wp), intent(out) :: r(:)
      real(wp), allocatable :: ah(:), al(:)
      allocate(ah(n), al(n))
      call sym_matvec_dd(k, kb, kdu, xh, xl, th, tl)
      if (fk%im /= 0.0_wp) then
        call sym_matvec_dd(k, kb, kdu, yh, yl, uh, ul)
        call dd_mul_d(uh, ul, sgn*fk%im, ah, al)
        call dd_add(th, tl, ah, al, uh, ul)
        th = uh
        tl = ul
      end if
      call sym_matvec_dd(m, mb, kdu, xh, xl, uh, ul)
      call dd_mul_d(uh, ul, -omega, ah, al)
      call dd_mul_d(ah, al, omega, uh, ul)
      call dd_add(th, tl, uh, ul, ah, al)
      th = ah
      tl = al
      if (explicit) then
        call sym_matvec_dd(c, cb, kdu, yh, yl, uh, ul)
        call dd_mul_d(uh, ul, sgn*omega, ah, al)
        call dd_add(th, tl, ah, al, uh, ul)
        th = uh
        tl = ul
      end if
      call dd_add_d(-th, -tl, bp, ah, al)
      r = ah
    end subroutine residual_part

    complex(wp) function d_entry(i, j)
      integer, intent(in) :: i, j
      d_entry = fk*sym_entry(k, kb, kdu, i, j) - omega**2*sym_entry(m, mb, kdu, i, j)
      if (explicit) d_entry = d_entry + cmplx(0.0_wp, omega*sym_entry(c, cb, kdu, i, j), wp)
    end function d_entry

    subroutine lu_solve(x)
      complex(wp), intent(inout) :: x(:, :)
      integer :: info2
      if (band) then
        call zgbtrs('N', n, kdu, kdu, size(x, 2), lu, ldab, ipiv, x, n, info2)
      else
        call zgetrs('N', n, size(x, 2), lu, n, ipiv, x, n, info2)
      end if
    end subroutine lu_solve

    subroutine lu_solve_1(x)
      complex(wp), intent(inout) :: x(:)
      integer :: info2
      if (band) then
        call zgbtrs('N', n, kdu, kdu, 1, lu, ldab, ipiv, x, n, info2)
      else
        call zgetrs('N', n, 1, lu, n, ipiv, x, n, info2)
      end if
    end subroutine lu_solve_1
  end subroutine dynamic_solve
end module udmap_blade_linear_solve
