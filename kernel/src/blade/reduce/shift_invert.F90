!> The lowest eigenpairs of K phi = lambda M phi (K, M symmetric, M positive semi-definite,
!> K - sigma M positive definite) by ARPACK's symmetric Lanczos in shift-invert mode (dsaupd
!> mode 3, OP = (K - sigma M)^-1 M), with the sparse factorisation of K - sigma M that the
!> caller made and owns. M is never inverted: a massless direction (M z = 0) is an infinite
!> eigenvalue, outside the range of OP in which ARPACK starts (its dgetv0 applies OP to the
!> start vector) and works, where the M inner product is a norm; dseupd purifies the vectors.
!>
!> ARPACK keeps internal `save` state between the reverse-communication calls of one solve
!> (and a saved random seed, which is why the start vector is given here, info = 1). A solve
!> runs to completion inside lowest_modes, so sequential solves never interleave; two solves
!> must not run at once in two threads of one process (the reduction is not called from the
!> FMU, whose kernel is built without ARPACK and MUMPS).
module udmap_blade_reduce_shift_invert
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC
  use udmap_blade_reduce_sparse_coo, only: coo_type, sym_matvec
  use udmap_blade_reduce_sparse_factor, only: sparse_factor_type, factor_solve
  implicit none
  private
  public :: lowest_modes

#ifdef UDMAP_WITH_ARPACK
  interface
    !> ARPACK reverse-communication Lanczos (real symmetric).
    subroutine dsaupd(ido, bmat, n, which, nev, tol, resid, ncv, v, ldv, iparam, ipntr, &
        & workd, workl, lworkl, info)
      import :: wp
      integer, intent(inout) :: ido, info
      character(len=1), intent(in) :: bmat
      character(len=2), intent(in) :: which
      integer, intent(in) :: n, nev, ncv, ldv, lworkl
      real(wp), intent(inout) :: tol
      real(wp), intent(inout) :: resid(*), v(ldv, *), workd(*), workl(*)
      integer, intent(inout) :: iparam(11), ipntr(11)
    end subroutine dsaupd
    !> ARPACK eigenvalues and vectors after dsaupd.
    subroutine dseupd(rvec, howmny, select, d, z, ldz, sigma, bmat, n, which, nev, tol, &
        & resid, ncv, v, ldv, iparam, ipntr, workd, workl, lworkl, info)
      import :: wp
      logical, intent(in) :: rvec
      character(len=1), intent(in) :: howmny, bmat
      character(len=2), intent(in) :: which
      logical, intent(inout) :: select(*)
      integer, intent(in) :: ldz, n, nev, ncv, ldv, lworkl
      real(wp), intent(out) :: d(*), z(ldz, *)
      real(wp), intent(in) :: sigma
      real(wp), intent(inout) :: tol
      real(wp), intent(inout) :: resid(*), v(ldv, *), workd(*), workl(*)
      integer, intent(inout) :: iparam(11), ipntr(11)
      integer, intent(out) :: info
    end subroutine dseupd
  end interface
#endif

contains

  !> The nev eigenvalues of (K, M) nearest sigma (the lowest when K - sigma M has no negative
  !> pivot below them), ascending, with M-orthonormal vectors phi(n, nev). `factor` holds
  !> K - sigma M; `m` is M (lower triangle).
  subroutine lowest_modes(factor, sigma, m, nev, lambda, phi, error)
    type(sparse_factor_type), intent(inout) :: factor
    real(wp), intent(in) :: sigma
    type(coo_type), intent(in) :: m
    integer, intent(in) :: nev
    real(wp), allocatable, intent(out) :: lambda(:), phi(:, :)
    type(error_type), allocatable, intent(out) :: error
#ifdef UDMAP_WITH_ARPACK
    integer :: n, ncv, lworkl, ido, info, iparam(11), ipntr(11), i, nconv
    real(wp) :: tol
    real(wp), allocatable :: resid(:), v(:, :), workd(:), workl(:), d(:), x(:, :)
    logical, allocatable :: select(:)
    character(len=80) :: buf
    n = m%n
    allocate(lambda(0), phi(n, 0))
    if (nev <= 0) return
    if (nev >= n) then
      call fatal_error(error, "shift-invert: asked for as many modes as DOFs", UDMAP_ENUMERIC)
      return
    end if
    ncv = min(n, max(2*nev + 1, nev + 20))
    lworkl = ncv*(ncv + 8)
    allocate(resid(n), v(n, ncv), workd(3*n), workl(lworkl), d(nev), select(ncv), x(n, 1))
    ! A fixed, irregular start vector: reproducible, whereas ARPACK's own
    ! random start would depend on its saved seed, i.e. on earlier solves
    do i = 1, n
      resid(i) = 1 + 0.5_wp*sin(0.7_wp*i) + 0.25_wp*cos(1.3_wp*i + 0.1_wp*real(i, wp)**2)
    end do
    iparam = 0
    iparam(1) = 1
    iparam(3) = 1000
    iparam(7) = 3
    ipntr = 0
    tol = 0
    ido = 0
    info = 1
    do
      call dsaupd(ido, 'G', n, 'LM', nev, tol, resid, ncv, v, n, iparam, ipntr, workd, workl, &
        & lworkl, info)
      select case (ido)
      case (-1)
        ! y = (K - sigma M)^-1 M x
        call sym_matvec(m, workd(ipntr(1):ipntr(1)+n-1), x(:, 1))
        call factor_solve(factor, x, error)
        if (allocated(error)) return
        workd(ipntr(2):ipntr(2)+n-1) = x(:, 1)
      case (1)
        ! M x is given in ipntr(3)
        x(:, 1) = workd(ipntr(3):ipntr(3)+n-1)
        call factor_solve(factor, x, error)
        if (allocated(error)) return
        workd(ipntr(2):ipntr(2)+n-1) = x(:, 1)
      case (2)
        call sym_matvec(m, workd(ipntr(1):ipntr(1)+n-1), x(:, 1))
        workd(ipntr(2):ipntr(2)+n-1) = x(:, 1)
      case default
        exit
      end select
    end do
    if (info /= 0) then
      write(buf, '(a,i0,a,i0,a,i0)') "ARPACK dsaupd failed (info = ", info, ", converged ", &
        & iparam(5), " of ", nev
      call fatal_error(error, trim(buf)//")", UDMAP_ENUMERIC)
      return
    end if
    deallocate(phi)
    allocate(phi(n, nev))
    call dseupd(.true., 'A', select, d, phi, n, sigma, 'G', n, 'LM', nev, tol, resid, ncv, v, &
      & n, iparam, ipntr, workd, workl, lworkl, info)
    nconv = iparam(5)
    if (info /= 0 .or. nconv < nev) then
      write(buf, '(a,i0,a,i0,a,i0,a)') "ARPACK dseupd failed (info = ", info, ", converged ", &
        & nconv, " of ", nev, ")"
      call fatal_error(error, trim(buf), UDMAP_ENUMERIC)
      return
    end if
    lambda = d(1:nev)
    call sort_pairs(lambda, phi)
#else
    allocate(lambda(0), phi(m%n, 0))
    if (nev < 0 .or. sigma /= sigma .or. factor%n < 0) continue
    call fatal_error(error, "shift-invert eigen-solve: udmap was built without ARPACK", &
      & UDMAP_ENUMERIC)
#endif
  end subroutine lowest_modes

#ifdef UDMAP_WITH_ARPACK
  !> Sorts eigenvalues ascending, with their vectors (insertion sort: nev is small).
  pure subroutine sort_pairs(lambda, phi)
    real(wp), intent(inout) :: lambda(:), phi(:, :)
    integer :: i, j
    real(wp) :: t
    real(wp), allocatable :: v(:)
    do i = 2, size(lambda)
      t = lambda(i)
      v = phi(:, i)
      j = i - 1
      do while (j >= 1)
        if (lambda(j) <= t) exit
        lambda(j+1) = lambda(j)
        phi(:, j+1) = phi(:, j)
        j = j - 1
      end do
      lambda(j+1) = t
      phi(:, j+1) = v
    end do
  end subroutine sort_pairs
#endif
end module udmap_blade_reduce_shift_invert
