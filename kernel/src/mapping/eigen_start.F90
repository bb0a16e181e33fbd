!> The eigenvalue start of the backbone (PHYSICS.md 4): the complex eigenvalue lambda of
!> (K + k e_g e_g^T) phi = lambda M phi nearest the bare first mode, f = Re(sqrt(lambda))/(2 pi).
!> Damping (C) is left out: the start only needs to be near the peak, which the layer peak
!> search then finds exactly (within 1e-3 in frequency for blade A; refinement to rtol).
!>
!> Three ways to get it:
!> - direct, dense (ndof <= dense_max, default 200): LAPACK zggev on the full pencil,
!>   O(ndof^3) (3 ms at 64 DOFs);
!> - direct, banded (ndof > dense_max, built with UDMAP_WITH_ARPACK): ARPACK znaupd/zneupd in
!>   shift-invert mode about the bare omega_1^2, with a complex band LU (zgbtrf) of
!>   K + k e_g e_g^T - sigma M whose solves are refined with quadruple-precision residuals.
!>   ARPACK keeps internal `save` state, so this path must not run in two threads at once; the
!>   FMU is built without it (a build without ARPACK uses the modal start for large models);
!> - modal (secular equation): since the damper is a rank-one change, lambda solves
!>   1/k + h(lambda) = 0 with h(lambda) = e_g^T (K - lambda M)^-1 e_g
!>              = sum_r phi_g,r^2/(omega_r^2 - lambda) + R0 + lambda R1 + lambda^2 R2 + ...
!>   summed over the lowest secular_modes bare modes, R0..R2 standing for the modes above:
!>   R0 = (K^-1)_gg - sum_kept phi_g,r^2/omega_r^2 (all modes, from the static receptance),
!>   R1, R2 = sums of phi_g,r^2/omega_r^4, ^6 over the computed modes above the kept ones
!>   (exact for models whose modes are all computed). The error is then
!>   O((omega/omega_(secular_modes+1))^6) of the dropped modes' share (about 1e-9 for
!>   blade A), far below what a start needs. It costs some 50 flops per Newton step.
!>
!> Policy (analysis%eigen_method): EIGEN_AUTO (default) runs the direct solver (dense or
!> ARPACK by the switch above) once per model, for the first layer of its first backbone
!> table, and tracks the eigenvalue from layer to layer with the secular equation, started
!> from the direct value (later tables, e.g. after set_damper, bracket it from the bare modes);
!> EIGEN_DIRECT runs the direct solver for every layer (slow; for checks); EIGEN_MODAL never
!> runs it.
module udmap_mapping_eigen_start
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_blade_type, only: blade_type, receptances_type
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update
  use udmap_core_lapack, only: zggev, zgbtrf, zgbtrs
  use udmap_mapping_caches, only: secular_type
  implicit none
  private
  public :: new_secular, secular_root, direct_eigen_start, secular_modes

  !> Bare modes summed term by term in the secular equation (the rest enter R0, R1).
  integer, parameter :: secular_modes = 4

#ifdef UDMAP_WITH_ARPACK
  interface
    !> ARPACK reverse-communication Arnoldi (complex).
    subroutine znaupd(ido, bmat, n, which, nev, tol, resid, ncv, v, ldv, iparam, ipntr, &
        & workd, workl, lworkl, rwork, info)
      import :: wp
      integer, intent(inout) :: ido, info
      character(len=1), intent(in) :: bmat
      character(len=2), intent(in) :: which
      integer, intent(in) :: n, nev, ncv, ldv, lworkl
      ! ARPACK replaces tol <= 0 by the machine precision
      real(wp), intent(inout) :: tol
      complex(wp), intent(inout) :: resid(*), v(ldv, *), workd(*), workl(*)
      integer, intent(inout) :: iparam(11), ipntr(14)
      real(wp), intent(inout) :: rwork(*)
    end subroutine znaupd
    !> ARPACK eigenvalues (and vectors) after znaupd.
    subroutine zneupd(rvec, howmny, select, d, z, ldz, sigma, workev, bmat, n, which, nev, &
        & tol, resid, ncv, v, ldv, iparam, ipntr, workd, workl, lworkl, rwork, info)
      import :: wp
      logical, intent(in) :: rvec
      character(len=1), intent(in) :: howmny, bmat
      character(len=2), intent(in) :: which
      logical, intent(inout) :: select(*)
      integer, intent(in) :: ldz, n, nev, ncv, ldv, lworkl
      complex(wp), intent(out) :: d(*), z(ldz, *), workev(*)
      complex(wp), intent(in) :: sigma
      real(wp), intent(inout) :: tol
      complex(wp), intent(inout) :: resid(*), v(ldv, *), workd(*), workl(*)
      integer, intent(inout) :: iparam(11), ipntr(14), info
      real(wp), intent(inout) :: rwork(*)
    end subroutine zneupd
  end interface
#endif

contains

  !> Secular equation data from the blade's kept bare modes and its static receptance.
  subroutine new_secular(sec, blade, error)
    type(secular_type), intent(out) :: sec
    type(blade_type), intent(in) :: blade
    type(error_type), allocatable, intent(out) :: error
    type(receptances_type) :: r
    integer :: nm, nk
    if (.not.allocated(blade%omega) .or. .not.allocated(blade%phi)) then
      call fatal_error(error, "eigenvalue start: the blade has no bare modes", UDMAP_EINPUT)
      return
    end if
    nm = size(blade%omega)
    if (nm < 1) then
      call fatal_error(error, "eigenvalue start: the blade has no bare modes", UDMAP_EINPUT)
      return
    end if
    nk = min(nm, secular_modes)
    sec%s = blade%omega(1:nk)**2
    sec%w = blade%phi(blade%gamma_dof, 1:nk)**2
    if (nm > nk) then
      sec%R1 = sum(blade%phi(blade%gamma_dof, nk+1:nm)**2/blade%omega(nk+1:nm)**4)
      sec%R2 = sum(blade%phi(blade%gamma_dof, nk+1:nm)**2/blade%omega(nk+1:nm)**6)
    end if
    ! (K^-1)_gg from the receptance at a frequency far below the first mode (the real part
    ! is even in omega, so the error is O((omega/omega_1)^2) = 1e-12)
    call blade%receptances(1.0e-6_wp*blade%omega(1), r, error, derivatives=.false.)
    if (allocated(error)) return
    sec%R0 = real(r%gg, wp) - sum(sec%w/sec%s)
    ! a residual below rounding of the modal sum is rounding
    if (abs(sec%R0) <= 64*epsilon(1.0_wp)*sum(sec%w/sec%s)) sec%R0 = 0
  end subroutine new_secular

  !> h(lambda) and h'(lambda) of the secular equation (real arithmetic in the loop).
  pure subroutine secular_h(sec, lambda, h, dh)
    type(secular_type), intent(in) :: sec
    complex(wp), intent(in) :: lambda
    complex(wp), intent(out) :: h, dh
    real(wp) :: a, b, t, tr, ti, hr, hi, dr, di
    integer :: r
    a = real(lambda, wp)
    b = aimag(lambda)
    ! R0 + lambda R1 + lambda^2 R2
    hr = sec%R0 + a*sec%R1 + (a*a - b*b)*sec%R2
    hi = b*sec%R1 + 2*a*b*sec%R2
    dr = sec%R1 + 2*a*sec%R2
    di = 2*b*sec%R2
    do r = 1, size(sec%s)
      ! 1/(s - lambda) = (s - a + i b)/((s - a)^2 + b^2)
      t = 1/((sec%s(r) - a)**2 + b*b)
      tr = (sec%s(r) - a)*t
      ti = b*t
      hr = hr + sec%w(r)*tr
      hi = hi + sec%w(r)*ti
      dr = dr + sec%w(r)*(tr*tr - ti*ti)
      di = di + sec%w(r)*2*tr*ti
    end do
    h = cmplx(hr, hi, wp)
    dh = cmplx(dr, di, wp)
  end subroutine secular_h

  !> Newton on 1/k + h(lambda) = 0 from lambda, with step halving while |residual| grows,
  !> until a relative step of secular_tol (Newton converges quadratically, so lambda is then
  !> good to about secular_tol^2 = 1e-14).
  pure subroutine secular_newton(sec, k, lambda, ok)
    type(secular_type), intent(in) :: sec
    complex(wp), intent(in) :: k
    complex(wp), intent(inout) :: lambda
    logical, intent(out) :: ok
    real(wp), parameter :: secular_tol = 1.0e-7_wp
    complex(wp) :: h, dh, f, step, trial, ft, kinv
    integer :: it, half
    ok = .false.
    kinv = 1/k
    call secular_h(sec, lambda, h, dh)
    f = kinv + h
    do it = 1, 60
      if (dh == 0) return
      step = f/dh
      trial = lambda - step
      do half = 1, 30
        call secular_h(sec, trial, h, dh)
        ft = kinv + h
        if (abs2(ft) <= abs2(f)) exit
        step = step/2
        trial = lambda - step
      end do
      lambda = trial
      f = ft
      if (abs2(step) <= secular_tol**2*abs2(lambda)) then
        ok = .true.
        return
      end if
    end do
  end subroutine secular_newton

  !> |z|^2.
  elemental real(wp) function abs2(z)
    complex(wp), intent(in) :: z
    abs2 = real(z, wp)**2 + aimag(z)**2
  end function abs2

  !> The eigenvalue lambda of (K + k e_g e_g^T, M) continuing the bare first mode, from the
  !> secular equation. With lambda0 it is tracked by Newton from there (the previous layer);
  !> without, the real-stiffness root is bracketed between the poles and continued to the
  !> complex k. ok is .false. when no root was found.
  pure subroutine secular_root(sec, k, lambda, ok, lambda0)
    type(secular_type), intent(in) :: sec
    complex(wp), intent(in) :: k
    complex(wp), intent(out) :: lambda
    logical, intent(out) :: ok
    complex(wp), intent(in), optional :: lambda0
    type(brent_type) :: brent
    complex(wp) :: h, dh, kt, lambda_real
    real(wp) :: a, b, fa, fb, x, s1, upper, t
    logical :: more
    integer :: r, nstep, i
    ok = .false.
    s1 = sec%s(1)
    lambda = s1
    if (k == (0.0_wp, 0.0_wp)) then
      ok = .true.
      return
    end if
    if (present(lambda0)) then
      lambda = lambda0
      call secular_newton(sec, k, lambda, ok)
      if (ok) return
    end if
    ! real part of k: h is increasing between consecutive poles, from -inf to +inf
    if (real(k, wp) > 0) then
      upper = huge(1.0_wp)
      do r = 2, size(sec%s)
        if (sec%w(r) > 0 .and. sec%s(r) > s1) then
          upper = sec%s(r)
          exit
        end if
      end do
      if (upper == huge(1.0_wp)) then
        ! no pole above: h -> R0 at infinity; bound the root from the first pole alone
        upper = s1 + 2*sec%w(1)/(1/real(k, wp) + max(sec%R0, 0.0_wp))
      end if
      a = s1*(1 + 4*epsilon(1.0_wp))
      b = upper*(1 - 4*epsilon(1.0_wp))
      call secular_h(sec, cmplx(a, 0.0_wp, wp), h, dh)
      fa = 1/real(k, wp) + real(h, wp)
      call secular_h(sec, cmplx(b, 0.0_wp, wp), h, dh)
      fb = 1/real(k, wp) + real(h, wp)
      if ((fa > 0) .eqv. (fb > 0)) then
        lambda = cmplx(s1 + sec%w(1)*real(k, wp), 0.0_wp, wp)
      else
        call brent_start(brent, a, fa, b, fb, 4*epsilon(1.0_wp)*b)
        do
          call brent_next(brent, x, more)
          if (.not.more) exit
          call secular_h(sec, cmplx(x, 0.0_wp, wp), h, dh)
          call brent_update(brent, 1/real(k, wp) + real(h, wp))
        end do
        lambda = cmplx(brent%b, 0.0_wp, wp)
      end if
    else
      lambda = cmplx(s1 + sec%w(1)*real(k, wp), 0.0_wp, wp)
    end if
    ! continue in the imaginary part of k
    lambda_real = lambda
    do nstep = 1, 64, 7
      ok = .true.
      lambda = lambda_real
      do i = 1, nstep
        t = real(i, wp)/nstep
        kt = cmplx(real(k, wp), t*aimag(k), wp)
        if (kt == (0.0_wp, 0.0_wp)) cycle
        call secular_newton(sec, kt, lambda, ok)
        if (.not.ok) exit
      end do
      if (ok) return
    end do
  end subroutine secular_root

  !> The eigenvalue of (K + k e_g e_g^T, M) nearest the bare omega_1^2 by a direct solver:
  !> zggev when ndof <= dense_max and the dense matrices are present, else ARPACK
  !> shift-invert on the band matrices (when built with ARPACK).
  subroutine direct_eigen_start(blade, k, dense_max, lambda, error)
    type(blade_type), intent(in) :: blade
    complex(wp), intent(in) :: k
    integer, intent(in) :: dense_max
    complex(wp), intent(out) :: lambda
    type(error_type), allocatable, intent(out) :: error
    logical :: dense_ok, band_ok
    dense_ok = allocated(blade%K) .and. allocated(blade%M)
    band_ok = blade%kd >= 0 .and. allocated(blade%Kb) .and. allocated(blade%Mb)
    if (dense_ok .and. (blade%ndof <= dense_max .or. .not.band_ok)) then
      call dense_eigen(blade, k, lambda, error)
    else if (band_ok) then
      call band_eigen(blade, k, lambda, error)
    else
      call fatal_error(error, "direct_eigen_start: the blade has neither dense nor band "// &
        & "matrices", UDMAP_EINPUT)
    end if
  end subroutine direct_eigen_start

  !> zggev on the dense pencil (K + k e_g e_g^T, M); the finite eigenvalue nearest omega_1^2.
  subroutine dense_eigen(blade, k, lambda, error)
    type(blade_type), intent(in) :: blade
    complex(wp), intent(in) :: k
    complex(wp), intent(out) :: lambda
    type(error_type), allocatable, intent(out) :: error
    complex(wp), allocatable :: A(:,:), B(:,:), alpha(:), beta(:), work(:)
    complex(wp) :: vl(1,1), vr(1,1), wq(1)
    real(wp), allocatable :: rwork(:)
    real(wp) :: s1, best
    integer :: n, g, info, i
    character(len=12) :: buf
    n = blade%ndof
    g = blade%gamma_dof
    allocate(A(n, n), B(n, n), alpha(n), beta(n), rwork(8*n))
    A(:, :) = cmplx(blade%K(1:n, 1:n), 0.0_wp, wp)
    A(g, g) = A(g, g) + k
    B(:, :) = cmplx(blade%M(1:n, 1:n), 0.0_wp, wp)
    call zggev('N', 'N', n, A, n, B, n, alpha, beta, vl, 1, vr, 1, wq, -1, rwork, info)
    allocate(work(max(1, int(real(wq(1), wp)))))
    call zggev('N', 'N', n, A, n, B, n, alpha, beta, vl, 1, vr, 1, work, size(work), rwork, info)
    if (info /= 0) then
      write(buf, '(i0)') info
      call fatal_error(error, "eigenvalue start: zggev failed, info = "//trim(buf), UDMAP_ENUMERIC)
      return
    end if
    s1 = blade%omega1**2
    best = huge(1.0_wp)
    lambda = s1
    do i = 1, n
      if (abs(beta(i)) <= 1.0e3_wp*epsilon(1.0_wp)*abs(alpha(i))) cycle
      if (abs(alpha(i)/beta(i) - s1) < best) then
        best = abs(alpha(i)/beta(i) - s1)
        lambda = alpha(i)/beta(i)
      end if
    end do
    if (best == huge(1.0_wp)) then
      call fatal_error(error, "eigenvalue start: zggev found no finite eigenvalue", UDMAP_ENUMERIC)
    end if
  end subroutine dense_eigen

  !> ARPACK shift-invert about omega_1^2 on the band matrices, complex band LU (zgbtrf) of
  !> K + k e_g e_g^T - sigma M; the converged eigenvalue nearest the shift.
  subroutine band_eigen(blade, k, lambda, error)
    type(blade_type), intent(in) :: blade
    complex(wp), intent(in) :: k
    complex(wp), intent(out) :: lambda
    type(error_type), allocatable, intent(out) :: error
#ifdef UDMAP_WITH_ARPACK
    integer, parameter :: nev = 2
    complex(wp), allocatable :: ab(:,:), resid(:), v(:,:), workd(:), workl(:), d(:), z(:,:), &
      & workev(:), x(:)
    real(wp), allocatable :: rwork(:)
    logical, allocatable :: select(:)
    integer, allocatable :: ipiv(:)
    integer :: n, kd, ldab, ncv, lworkl, ido, info, iparam(11), ipntr(14), i, j, g, nconv, it
    complex(wp) :: sigma
    real(wp) :: best, tol
    character(len=12) :: buf
    n = blade%ndof
    kd = blade%kd
    g = blade%gamma_dof
    sigma = cmplx(blade%omega1**2, 0.0_wp, wp)
    ! general band storage of A - sigma M, A = K + k e_g e_g^T, kl = ku = kd
    ldab = 3*kd + 1
    allocate(ab(ldab, n), ipiv(n))
    ab = 0
    do j = 1, n
      do i = max(1, j - kd), j
        ab(2*kd + 1 + i - j, j) = blade%Kb(kd + 1 + i - j, j) - sigma*blade%Mb(kd + 1 + i - j, j)
        ab(2*kd + 1 + j - i, i) = ab(2*kd + 1 + i - j, j)
      end do
    end do
    ab(2*kd + 1, g) = ab(2*kd + 1, g) + k
    call zgbtrf(n, n, kd, kd, ab, ldab, ipiv, info)
    if (info /= 0) then
      write(buf, '(i0)') info
      call fatal_error(error, "eigenvalue start: zgbtrf failed, info = "//trim(buf), UDMAP_ENUMERIC)
      return
    end if
    ncv = min(n, 20)
    lworkl = 3*ncv**2 + 5*ncv
    allocate(resid(n), v(n, ncv), workd(3*n), workl(lworkl), rwork(ncv), d(nev + 1), &
      & z(n, nev), workev(2*ncv), select(ncv), x(n))
    iparam = 0
    ipntr = 0
    iparam(1) = 1
    iparam(3) = 500
    iparam(7) = 3
    ido = 0
    info = 0
    tol = 0
    do it = 1, 100000
      call znaupd(ido, 'G', n, 'LM', nev, tol, resid, ncv, v, n, iparam, ipntr, workd, &
        & workl, lworkl, rwork, info)
      select case (ido)
      case (-1)
        call band_mass(workd(ipntr(1):ipntr(1) + n - 1), x)
        call refined_solve(x)
        workd(ipntr(2):ipntr(2) + n - 1) = x
      case (1)
        x = workd(ipntr(3):ipntr(3) + n - 1)
        call refined_solve(x)
        workd(ipntr(2):ipntr(2) + n - 1) = x
      case (2)
        call band_mass(workd(ipntr(1):ipntr(1) + n - 1), x)
        workd(ipntr(2):ipntr(2) + n - 1) = x
      case default
        exit
      end select
    end do
    if (info < 0 .or. (info /= 0 .and. info /= 1)) then
      write(buf, '(i0)') info
      call fatal_error(error, "eigenvalue start: ARPACK znaupd failed, info = "//trim(buf), &
        & UDMAP_ENUMERIC)
      return
    end if
    call zneupd(.false., 'A', select, d, z, n, sigma, workev, 'G', n, 'LM', nev, tol, &
      & resid, ncv, v, n, iparam, ipntr, workd, workl, lworkl, rwork, info)
    if (info /= 0) then
      write(buf, '(i0)') info
      call fatal_error(error, "eigenvalue start: ARPACK zneupd failed, info = "//trim(buf), &
        & UDMAP_ENUMERIC)
      return
    end if
    nconv = iparam(5)
    if (nconv < 1) then
      call fatal_error(error, "eigenvalue start: ARPACK converged no eigenvalue", UDMAP_ENUMERIC)
      return
    end if
    best = huge(1.0_wp)
    lambda = sigma
    do i = 1, nconv
      if (abs(d(i) - sigma) < best) then
        best = abs(d(i) - sigma)
        lambda = d(i)
      end if
    end do
  contains
    !> x <- (A - sigma M)^-1 x by the band LU and two steps of iterative refinement with the
    !> residual in quadruple precision: the shifted stiffness of a fine mesh has a condition
    !> number near 1/eps (omega_max^2/omega_1^2), so a plain double solve loses the low mode.
    subroutine refined_solve(xb)
      complex(wp), intent(inout) :: xb(:)
      integer, parameter :: qp = selected_real_kind(30)
      complex(wp) :: y(n), dy(n)
      complex(qp) :: res(n), aij, sq, kq
      integer :: ii, jj, step, inf
      y = xb
      call zgbtrs('N', n, kd, kd, 1, ab, ldab, ipiv, y, n, inf)
      sq = cmplx(sigma, kind=qp)
      kq = cmplx(k, kind=qp)
      do step = 1, 2
        res = cmplx(xb, kind=qp)
        do jj = 1, n
          do ii = max(1, jj - kd), jj
            aij = real(blade%Kb(kd + 1 + ii - jj, jj), qp) - sq*real(blade%Mb(kd + 1 + ii - jj, jj), qp)
            res(ii) = res(ii) - aij*cmplx(y(jj), kind=qp)
            if (ii /= jj) res(jj) = res(jj) - aij*cmplx(y(ii), kind=qp)
          end do
        end do
        res(g) = res(g) - kq*cmplx(y(g), kind=qp)
        dy = cmplx(res, kind=wp)
        call zgbtrs('N', n, kd, kd, 1, ab, ldab, ipiv, dy, n, inf)
        y = y + dy
      end do
      xb = y
    end subroutine refined_solve

    !> y = M x with M in symmetric upper band storage.
    subroutine band_mass(xin, y)
      complex(wp), intent(in) :: xin(:)
      complex(wp), intent(out) :: y(:)
      integer :: ii, jj
      y = 0
      do jj = 1, n
        y(jj) = y(jj) + blade%Mb(kd + 1, jj)*xin(jj)
        do ii = max(1, jj - kd), jj - 1
          y(ii) = y(ii) + blade%Mb(kd + 1 + ii - jj, jj)*xin(jj)
          y(jj) = y(jj) + blade%Mb(kd + 1 + ii - jj, jj)*xin(ii)
        end do
      end do
    end subroutine band_mass
#else
    character(len=12) :: buf
    lambda = k
    write(buf, '(i0)') blade%ndof
    call fatal_error(error, "eigenvalue start: this build has no ARPACK for banded models "// &
      & "(ndof = "//trim(buf)//"; use the modal start)", UDMAP_EINPUT)
#endif
  end subroutine band_eigen
end module udmap_mapping_eigen_start
