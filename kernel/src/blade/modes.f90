!> Bare natural modes of the blade, K phi = omega^2 M phi, mass-normalised (phi^T M phi = 1).
!>
!> Accuracy matters here: near resonance the receptance is proportional to
!> 1/(omega_1^2 (1 + i omega beta) - omega^2), so a relative error e in omega_1^2 becomes an
!> error e/(2 zeta) in the receptance. A textbook dense solve of K phi = lambda M phi makes
!> absolute errors ~ eps lambda_max in every eigenvalue (relative 1e-7 for the lowest mode of
!> blade A). Hence:
!> - all modes (small models): dsygvd on the inverted pencil M z = mu K z, whose largest mu are
!>   the lowest modes, each then polished through its coupling by K computed in double-double;
!> - the lowest modes (large models): subspace iteration with K^-1 M (Bathe), whose solves are
!>   refined in double-double once the subspace has settled.
module udmap_blade_modes
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC
  use udmap_core_lapack, only: dsygvd, dsyev
  use udmap_blade_band, only: sym_matvec
  use udmap_blade_dd, only: sym_matvec_dd
  use udmap_blade_linear_solve, only: spd_factor_type, spd_solve
  implicit none
  private
  public :: all_modes, lowest_modes, polish

  character(len=*), parameter :: fmt_i = '(i0)'
  integer, parameter :: i8 = selected_int_kind(18)
  !> Eigenvalues mu = 1/lambda of the inverted pencil at or below this fraction of the largest
  !> are M's null space (massless directions, infinite lambda) when M is semi-definite.
  real(wp), parameter :: massless_tol = 1.0e-12_wp

contains

  !> All modes of the dense pencil (K, M): lambda = omega^2 ascending, phi mass-normalised.
  !> The lowest `npolish` are polished (see polish); the others keep the accuracy of the
  !> inverted pencil, absolute eps mu_1 in mu = 1/lambda.
  !> With `zinf` (M only positive semi-definite, checked by the caller): the eigenvalues
  !> mu <= massless_tol mu_max of the inverted pencil are M's null space, infinite lambda; only
  !> the finite modes are returned, and the null space's vectors, K-normalised, in zinf(n, :)
  !> (their part of the receptances is static: z z^T, with no 1/mu).
  subroutine all_modes(k, m, npolish, lambda, phi, error, zinf)
    real(wp), intent(in) :: k(:, :), m(:, :)
    integer, intent(in) :: npolish
    real(wp), allocatable, intent(out) :: lambda(:), phi(:, :)
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable, intent(inout), optional :: zinf(:, :)
    real(wp), allocatable :: a(:, :), b(:, :), mu(:), work(:), x(:, :)
    integer, allocatable :: iwork(:)
    real(wp) :: wq(1)
    integer :: iq(1), n, info, lwork, liwork, r, ninf
    character(len=24) :: buf
    n = size(k, 1)
    allocate(a, source=m)
    allocate(b, source=k)
    allocate(mu(n))
    call dsygvd(1, 'V', 'U', n, a, n, b, n, mu, wq, -1, iq, -1, info)
    lwork = max(1, int(wq(1)))
    liwork = max(1, iq(1))
    allocate(work(lwork), iwork(liwork))
    call dsygvd(1, 'V', 'U', n, a, n, b, n, mu, work, lwork, iwork, liwork, info)
    if (info /= 0) then
      write(buf, fmt_i) info
      call fatal_error(error, "eigenvalues of the blade failed (dsygvd info = "//trim(buf)//")", &
        & UDMAP_ENUMERIC)
      return
    end if
    ninf = 0
    if (present(zinf)) then
      ninf = count(mu <= massless_tol*mu(n))
      if (allocated(zinf)) deallocate(zinf)
      zinf = a(:, 1:ninf)
      if (ninf == n) then
        call fatal_error(error, "eigenvalues of the blade failed: M is zero", UDMAP_ENUMERIC)
        return
      end if
    else if (mu(1) <= 0.0_wp) then
      call fatal_error(error, "eigenvalues of the blade failed: M is not positive definite", &
        & UDMAP_ENUMERIC)
      return
    end if
    ! z^T K z = 1 and z^T M z = mu: phi = z/sqrt(mu), lambda = 1/mu; largest mu first.
    n = n - ninf
    allocate(x(size(k, 1), n), lambda(n))
    do r = 1, n
      x(:, r) = a(:, ninf+n+1-r)/sqrt(mu(ninf+n+1-r))
      lambda(r) = 1.0_wp/mu(ninf+n+1-r)
    end do
    deallocate(a)
    block
      real(wp), allocatable :: none(:, :), kk(:, :), mm(:, :), lp(:), pp(:, :)
      integer :: np
      np = max(1, min(n, npolish))
      allocate(kk, source=k)
      allocate(mm, source=m)
      call polish(kk, none, mm, none, 0, x, lambda, np, lp, pp)
      lambda(1:np) = lp
      x(:, 1:np) = pp
    end block
    call move_alloc(x, phi)
  end subroutine all_modes

  !> The lowest p modes by subspace iteration on A = K^-1 M (M-self-adjoint, eigenvalues
  !> mu = 1/lambda) with q = min(n, max(2p, p+8)) vectors, using the Cholesky factor `kf` of K.
  !> Each step: M-orthonormal basis Q (modified Gram-Schmidt, twice), Z = A Q, Rayleigh-Ritz on
  !> T = Q^T M A Q = (M Q)^T Z. Working with mu keeps the lowest modes accurate to rounding:
  !> the textbook Q^T K Q would need products with the stiff K, and Y^T M Y of the raw iterates
  !> squares their conditioning. Converged when ||A x_r - mu_r x_r||_M (r < p) and the changes
  !> of mu_1..mu_p are below 1e-16 mu_1, or have settled at their rounding floor (<= 1e-11 mu_1
  !> and no longer halving); the solves are refined in double-double once plain solves stop
  !> improving. The Ritz vectors are then polished (see polish).
  subroutine lowest_modes(k, kb, m, mb, kd, kf, p, lambda, phi, error)
    real(wp), allocatable, intent(in) :: k(:, :), kb(:, :), m(:, :), mb(:, :)
    integer, intent(in) :: kd, p
    type(spd_factor_type), intent(in) :: kf
    real(wp), allocatable, intent(out) :: lambda(:), phi(:, :)
    type(error_type), allocatable, intent(out) :: error
    integer, parameter :: max_iter = 500
    real(wp), parameter :: tol = 1.0e-16_wp
    real(wp), allocatable :: qb(:, :), mq(:, :), z(:, :), t(:, :), mu(:), mu_old(:), work(:), &
      & x(:, :), ax(:, :), v(:, :)
    real(wp) :: wq(1), worst, prev_worst
    integer :: n, q, j, it, info, lwork, seed, refined_steps
    logical :: refine
    character(len=24) :: buf

    n = kf%n
    q = min(n, max(2*p, p+8))
    allocate(qb(n, q), mq(n, q), z(n, q), t(q, q), mu(q), mu_old(q), x(n, q), ax(n, q), v(q, q))
    seed = 12345
    call random_columns(qb, 1, seed)
    call orthonormalize(qb, mq, seed)
    call dsyev('V', 'U', q, t, q, mu, wq, -1, info)
    lwork = max(1, int(wq(1)), 3*q)
    allocate(work(lwork))

    mu_old = 0.0_wp
    refine = .false.
    refined_steps = 0
    prev_worst = huge(1.0_wp)
    do it = 1, max_iter
      call spd_solve(kf, k, kb, mq, z, refine)
      t = matmul(transpose(mq), z)
      t = 0.5_wp*(t + transpose(t))
      call dsyev('V', 'U', q, t, q, mu, work, lwork, info)
      if (info /= 0) then
        write(buf, fmt_i) info
        call fatal_error(error, "subspace iteration for the lowest modes failed (dsyev info = "// &
          & trim(buf)//")", UDMAP_ENUMERIC)
        return
      end if
      ! Descending mu = ascending lambda.
      mu = mu(q:1:-1)
      v = t(:, q:1:-1)
      x = matmul(qb, v)
      ax = matmul(z, v)
      worst = 0.0_wp
      do j = 1, p
        if (j < p) worst = max(worst, m_norm(ax(:, j) - mu(j)*x(:, j))/mu(1))
        worst = max(worst, abs(mu(j) - mu_old(j))/mu(1))
      end do
      mu_old = mu
      if (refine) then
        refined_steps = refined_steps + 1
        ! Converged, or settled at the rounding floor (the residual stops decreasing).
        if (refined_steps >= 2 .and. (worst <= tol .or. &
          & (worst <= 1.0e-11_wp .and. worst > 0.5_wp*prev_worst))) exit
      else if (worst <= 1.0e-9_wp .or. (it > 8 .and. worst > 0.5_wp*prev_worst)) then
        ! As far as plain double solves go: refine from now on.
        refine = .true.
      end if
      prev_worst = worst
      qb = ax
      call orthonormalize(qb, mq, seed)
    end do
    if (it > max_iter) then
      call fatal_error(error, "subspace iteration for the lowest modes did not converge", &
        & UDMAP_ENUMERIC)
      return
    end if
    if (.not.(mu(p) > 0.0_wp)) then
      call fatal_error(error, "subspace iteration for the lowest modes failed: M is singular", &
        & UDMAP_ENUMERIC)
      return
    end if
    call polish(k, kb, m, mb, kd, x, 1.0_wp/mu, p, lambda, phi)

  contains


    real(wp) function m_norm(w)
      real(wp), intent(in) :: w(:)
      real(wp), allocatable :: mw(:)
      allocate(mw(size(w)))
      call sym_matvec(m, mb, kd, w, mw)
      m_norm = sqrt(max(dot_product(w, mw), 0.0_wp))
    end function m_norm

    !> Modified Gram-Schmidt in the M inner product, each column twice ("twice is enough");
    !> a column that vanishes (dependent) is replaced by a pseudo-random one. mq = M qb.
    subroutine orthonormalize(qb, mq, seed)
      real(wp), intent(inout) :: qb(:, :)
      real(wp), intent(out) :: mq(:, :)
      integer, intent(inout) :: seed
      real(wp) :: before, after
      integer :: i, jj, pass, tries
      do jj = 1, size(qb, 2)
        tries = 0
        do
          call sym_matvec(m, mb, kd, qb(:, jj), mq(:, jj))
          before = sqrt(max(dot_product(qb(:, jj), mq(:, jj)), 0.0_wp))
          do pass = 1, 2
            do i = 1, jj - 1
              qb(:, jj) = qb(:, jj) - dot_product(mq(:, i), qb(:, jj))*qb(:, i)
            end do
          end do
          call sym_matvec(m, mb, kd, qb(:, jj), mq(:, jj))
          after = sqrt(max(dot_product(qb(:, jj), mq(:, jj)), 0.0_wp))
          if (after > 1.0e-10_wp*before .and. after > 0.0_wp) exit
          tries = tries + 1
          if (tries > 3) exit
          call random_columns(qb(:, jj:jj), jj, seed)
        end do
        qb(:, jj) = qb(:, jj)/after
        mq(:, jj) = mq(:, jj)/after
      end do
    end subroutine orthonormalize
  end subroutine lowest_modes

  !> Polishes the first p of the approximate eigenvectors x (n, q), M-orthonormal, with
  !> eigenvalue estimates lam(q), through their exact coupling by K: with K_r = X^T K x_j (K x_j
  !> accumulated in double-double, where it cancels digits),
  !> phi_j = x_j + sum_(i /= j) x_i K_r,ij/(K_r,jj - d_i), d_i = K_r,ii for i <= p else lam(i),
  !> lambda_j = K_r,jj (the Rayleigh quotient, second-order accurate), then mass-normalised.
  !> Eigenvectors of the inverted pencil carry errors ~ eps mu_1/gap, large for the higher
  !> modes; this removes them to second order. Pairs too close for a first-order step are left.
  subroutine polish(k, kb, m, mb, kd, x, lam, p, lambda, phi)
    real(wp), allocatable, intent(in) :: k(:, :), kb(:, :), m(:, :), mb(:, :)
    integer, intent(in) :: kd, p
    real(wp), intent(in) :: x(:, :), lam(:)
    real(wp), allocatable, intent(out) :: lambda(:), phi(:, :)
    real(wp), allocatable :: kx(:, :), kr(:, :), mphi(:), d(:), zero(:), yl(:)
    integer :: i, j, n, nq
    n = size(x, 1)
    nq = size(x, 2)
    allocate(kx(n, p), mphi(n), lambda(p), d(nq), zero(n), yl(n))
    zero = 0.0_wp
    do j = 1, p
      call sym_matvec_dd(k, kb, kd, x(:, j), zero, kx(:, j), yl)
    end do
    kr = matmul(transpose(x), kx)
    d = lam
    do j = 1, p
      d(j) = kr(j, j)
    end do
    allocate(phi, source=x(:, 1:p))
    do j = 1, p
      lambda(j) = kr(j, j)
      do i = 1, nq
        if (i == j) cycle
        if (abs(kr(i, j)) < 0.1_wp*abs(d(j) - d(i))) &
          & phi(:, j) = phi(:, j) + x(:, i)*(kr(i, j)/(d(j) - d(i)))
      end do
      call sym_matvec(m, mb, kd, phi(:, j), mphi)
      phi(:, j) = phi(:, j)/sqrt(dot_product(phi(:, j), mphi))
    end do
  end subroutine polish

  !> Deterministic pseudo-random entries in [-1/2, 1/2) (a local linear congruential
  !> generator: no global state).
  pure subroutine random_columns(x, first, seed)
    real(wp), intent(out) :: x(:, :)
    integer, intent(in) :: first
    integer, intent(inout) :: seed
    integer :: i, j
    seed = seed + first
    do j = 1, size(x, 2)
      do i = 1, size(x, 1)
        seed = int(modulo(1103515245_i8*seed + 12345_i8, 2147483648_i8))
        x(i, j) = real(seed, wp)/2147483648.0_wp - 0.5_wp
      end do
    end do
  end subroutine random_columns
end module udmap_blade_modes
