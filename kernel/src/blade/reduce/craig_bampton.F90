!> Platform Centred Reduction (PHYSICS.md 1.3, paper section 2.1) of a sparse FE blade to a
!> small dense model: the rigid platform by transformation (udmap_blade_reduce_rigid_platform), then
!> a Craig-Bampton reduction onto the seven boundary DOFs (the platform's six rigid DOFs, gamma_P
!> first, and the excitation DOF u_E last): static constraint modes Psi = -K_II^-1 K_IB, the
!> lowest fixed-interface modes (ARPACK shift-invert on a MUMPS factorisation), and optionally
!> blocks of residual (Krylov) vectors K_II^-1 M_II X that carry the inertia of the modes left
!> out, so that the band is exact to a tolerance far below what the truncation alone gives.
!> The reduced K, M are the Galerkin projections V^T K_t V, V^T M_t V (exact, no model of them).
!> MUMPS's inertia counts check that no fixed-interface mode below the cut-off, and no full-model
!> mode in the check band, was missed.
module udmap_blade_reduce_craig_bampton
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC, UDMAP_EPHYSICS
  use udmap_core_strings, only: itoa
  use udmap_blade_reduce_sparse_coo, only: coo_type, sym_matvec, sym_matmul
  use udmap_blade_reduce_sparse_factor, only: sparse_factor_type, factor_analyse, factor_numeric, &
    & factor_solve, factor_free
  use udmap_blade_reduce_shift_invert, only: lowest_modes
  use udmap_blade_reduce_rigid_platform, only: platform_map_type, new_platform_map, &
    & transform_matrix, transform_vector, n_boundary, b_gamma, b_exc
  use udmap_core_lapack, only: dsygv, dgemm, dgemv
  implicit none
  private
  public :: reduction_type, platform_centred_reduction, mass_tol

  !> M is accepted positive semi-definite: no eigenvalue below -mass_tol max|M| (PHYSICS.md 1.3).
  real(wp), parameter :: mass_tol = 1e-12_wp

  !> The reduced model and its checks.
  type :: reduction_type
    !> Reduced size r = 7 + modes + residual vectors; gamma_P and u_E (1-based).
    integer :: r = 0, n_modes = 0, n_residual = 0, gamma_dof = b_gamma, exc_dof = b_exc
    !> Reduced mass and stiffness (r x r), stress rows s_r = V^T T^T s (r x n_stress).
    real(wp), allocatable :: M(:, :), K(:, :), S(:, :)
    !> Eigenfrequencies [Hz] of the reduced model (all r, ascending) and of the full model with
    !> the rigid platform in [0, f_check] (when checked).
    real(wp), allocatable :: freqs_reduced(:), freqs_full(:)
    !> Top of the check band [Hz] (3 f_max, or the highest kept fixed-interface mode).
    real(wp) :: f_check = 0
    !> Fixed-interface cut-off [Hz]: MUMPS's count of modes below it and the modes found below.
    real(wp) :: f_cut = 0
    integer :: cut_count = -1, cut_found = -1
    !> Full model: MUMPS's count below f_check and modes found below (-1: not checked).
    integer :: full_count = -1, full_found = -1
    !> Transformed DOFs, interior DOFs, entries of the largest factor.
    integer :: n_t = 0, n_i = 0
    integer(8) :: factor_entries = 0
    !> Wall times [s]: transformation, factorisations and static modes, fixed-interface modes,
    !> projection, full-model check.
    real(wp) :: timings(5) = 0
  end type reduction_type

contains

  !> Reduces the FE model (K, M by their lower-triangle entries, 1-based, row >= col) with
  !> the rigid platform, clamp and excitation of new_platform_map. `stress` (n x n_stress)
  !> holds stress rows over the full DOFs. Fixed-interface modes: `n_modes` (>= 0) or, when
  !> n_modes < 0, all below 3 f_max. `n_residual` blocks of residual vectors. check_full adds
  !> the checks that cost a factorisation each: M positive semi-definite (no eigenvalue of
  !> T^T M T below -mass_tol max|M|) and the full model's eigenfrequencies in [0, f_check] (with their inertia count).
  !> The inertia check of the fixed-interface modes is always made.
  subroutine platform_centred_reduction(n, k_row, k_col, k_val, m_row, m_col, m_val, dof_node, &
      & dof_comp, node_ids, node_xyz, platform_nodes, ref_point, axis, exc_node, exc_direction, &
      & clamp_nodes, stress, n_modes, f_max, n_residual, check_full, red, error)
    integer, intent(in) :: n
    integer, intent(in) :: k_row(:), k_col(:), m_row(:), m_col(:)
    real(wp), intent(in) :: k_val(:), m_val(:)
    integer, intent(in) :: dof_node(:), dof_comp(:), node_ids(:), platform_nodes(:)
    integer, intent(in) :: exc_node, clamp_nodes(:), n_modes, n_residual
    real(wp), intent(in) :: node_xyz(:, :), ref_point(3), axis(3), exc_direction(3)
    real(wp), intent(in) :: stress(:, :), f_max
    logical, intent(in) :: check_full
    type(reduction_type), intent(out) :: red
    type(error_type), allocatable, intent(out) :: error
    type(platform_map_type) :: map
    type(coo_type) :: kt, mt, kii, mii
    type(sparse_factor_type) :: fac
    real(wp), allocatable :: kib(:, :), mib(:, :), psi(:, :), lambda(:), phi(:, :), x(:, :)
    real(wp), allocatable :: v(:, :), w(:, :), y(:), st(:)
    integer(8) :: t0
    integer :: nev, nask, ni, nt, r, j, nr
    real(wp) :: sig_cut
    logical :: m_checked

    call check_input(error)
    if (allocated(error)) return
    t0 = clock()
    call new_platform_map(map, dof_node, dof_comp, node_ids, node_xyz, platform_nodes, &
      & ref_point, axis, exc_node, exc_direction, clamp_nodes, error)
    if (allocated(error)) return
    call transform_matrix(map, k_row, k_col, k_val, kt)
    call transform_matrix(map, m_row, m_col, m_val, mt)
    ni = map%n_i
    nt = map%n_t
    red%n_t = nt
    red%n_i = ni
    call split(kt, kii, kib)
    call split(mt, mii, mib)
    red%timings(1) = seconds(t0)

    ! The full-model check first when its band is known: it also checks M on every kept DOF.
    allocate(red%freqs_full(0))
    m_checked = .false.
    if (check_full .and. f_max > 0) then
      t0 = clock()
      red%f_check = 3*f_max
      call full_check(error)
      if (allocated(error)) goto 90
      call factor_free(fac)
      m_checked = .true.
      red%timings(5) = seconds(t0)
    end if

    ! Interior: K_II - sigma M_II on one analysed pattern, refactorised per shift.
    t0 = clock()
    call factor_analyse(fac, ni, [kii%row, mii%row], [kii%col, mii%col], error)
    if (allocated(error)) goto 90
    if (check_full .and. .not.m_checked) then
      ! M must be positive semi-definite: no eigenvalue of M_II below -tol max|M|.
      call check_mass(kii, mii, "M_II", error)
      if (allocated(error)) goto 90
    end if
    if (n_modes < 0) then
      red%f_cut = 3*f_max
      sig_cut = (2*pi*red%f_cut)**2
      call factor_numeric(fac, [kii%val, -sig_cut*mii%val], "K_II - sigma M_II", error)
      if (allocated(error)) goto 90
      nev = fac%negative_pivots
      red%cut_count = nev
      nask = nev
    else
      nev = n_modes
      nask = nev + 1
    end if
    if (nask > ni - 2) then
      call fatal_error(error, "n_modes: "//itoa(nev)//" fixed-interface modes asked, but the "// &
        & "model has only "//itoa(ni)//" interior DOFs")
      goto 90
    end if
    call factor_numeric(fac, [kii%val, 0*mii%val], &
      & "K_II (the blade held at the platform and clamp: a part is not restrained)", error)
    if (allocated(error)) goto 90
    if (fac%negative_pivots /= 0) then
      call fatal_error(error, "K: the stiffness matrix is indefinite ("// &
        & itoa(fac%negative_pivots)//" negative pivots of K_II)")
      goto 90
    end if
    red%factor_entries = max(red%factor_entries, fac%factor_entries)
    ! Static constraint modes.
    psi = -kib
    call factor_solve(fac, psi, error)
    if (allocated(error)) goto 90
    red%timings(2) = seconds(t0)

    ! Fixed-interface modes (shift 0: K_II is positive definite).
    t0 = clock()
    mii%n = ni
    call lowest_modes(fac, 0.0_wp, mii, nask, lambda, phi, error)
    if (allocated(error)) goto 90
    ! Residual vectors: X_1 = K_II^-1 (M_II Psi + M_IB), X_p+1 = K_II^-1 M_II X_p.
    call residual_vectors(error)
    if (allocated(error)) goto 90
    ! Inertia check: MUMPS counts the modes below the cut-off; all must have been found.
    if (n_modes >= 0) then
      if (nask > nev) then
        sig_cut = 0.5_wp*(lambda(nev+1) + merge(lambda(max(nev, 1)), 0.0_wp, nev > 0))
      end if
      red%f_cut = sqrt(sig_cut)/(2*pi)
      call factor_numeric(fac, [kii%val, -sig_cut*mii%val], "K_II - sigma M_II", error)
      if (allocated(error)) goto 90
      red%cut_count = fac%negative_pivots
    end if
    red%cut_found = count(lambda < sig_cut)
    if (red%cut_count /= nev .or. red%cut_found /= nev) then
      call fatal_error(error, "fixed-interface modes: MUMPS counts "//itoa(red%cut_count)// &
        & " below the cut-off, ARPACK found "//itoa(red%cut_found)//" (a mode was missed)", &
        & UDMAP_ENUMERIC)
      goto 90
    end if
    call factor_free(fac)
    red%n_modes = nev
    red%timings(3) = seconds(t0)

    ! Projection: V (r x n_t, row-wise) = [Psi; I] static, [Phi; 0] modes, [X; 0] residual.
    t0 = clock()
    nr = size(x, 2)
    red%n_residual = nr
    r = n_boundary + nev + nr
    red%r = r
    allocate(v(r, nt), source=0.0_wp)
    do j = 1, n_boundary
      v(j, 1:ni) = psi(:, j)
      v(j, ni+j) = 1
    end do
    do j = 1, nev
      v(n_boundary+j, 1:ni) = phi(:, j)
    end do
    do j = 1, nr
      v(n_boundary+nev+j, 1:ni) = x(:, j)
    end do
    deallocate(psi, phi, x)
    allocate(w(r, nt), red%K(r, r), red%M(r, r))
    call sym_matmul(kt, v, w)
    call dgemm('N', 'T', r, r, nt, 1.0_wp, v, r, w, r, 0.0_wp, red%K, r)
    call sym_matmul(mt, v, w)
    call dgemm('N', 'T', r, r, nt, 1.0_wp, v, r, w, r, 0.0_wp, red%M, r)
    deallocate(w)
    red%K = 0.5_wp*(red%K + transpose(red%K))
    red%M = 0.5_wp*(red%M + transpose(red%M))
    allocate(red%S(r, size(stress, 2)))
    do j = 1, size(stress, 2)
      st = transform_vector(map, stress(:, j))
      red%S(:, j) = matmul(v, st)
    end do
    deallocate(v)
    call reduced_frequencies(error)
    if (allocated(error)) goto 90
    red%timings(4) = seconds(t0)

    ! Check without f_max: the full model up to the highest kept fixed-interface mode.
    if (f_max > 0) then
      red%f_check = 3*f_max
    else if (nev > 0) then
      red%f_check = sqrt(lambda(nev))/(2*pi)
    end if
    if (check_full .and. .not.m_checked .and. red%f_check > 0) then
      t0 = clock()
      call full_check(error)
      if (allocated(error)) goto 90
      red%timings(5) = seconds(t0)
    end if
90  call factor_free(fac)
    if (allocated(error)) then
      ! nothing half-made goes back
      if (allocated(red%K)) deallocate(red%K)
      if (allocated(red%M)) deallocate(red%M)
      if (allocated(red%S)) deallocate(red%S)
      red%r = 0
    end if

  contains

    subroutine check_input(error)
      type(error_type), allocatable, intent(out) :: error
      if (n < 1) then
        call fatal_error(error, "n: the model has no DOF")
      else if (size(k_col) /= size(k_row) .or. size(k_val) /= size(k_row)) then
        call fatal_error(error, "K: row, col and val have different lengths")
      else if (size(m_col) /= size(m_row) .or. size(m_val) /= size(m_row)) then
        call fatal_error(error, "M: row, col and val have different lengths")
      else if (size(dof_node) /= n) then
        call fatal_error(error, "dof_node: has "//itoa(size(dof_node))//" entries, K has "// &
          & itoa(n)//" rows")
      else if (size(stress, 1) /= n) then
        call fatal_error(error, "stress_rows: rows have "//itoa(size(stress, 1))// &
          & " entries, K has "//itoa(n)//" rows")
      else if (any(k_row < 1) .or. any(k_row > n) .or. any(k_col < 1) .or. any(k_col > n)) then
        call fatal_error(error, "K: an index is outside 1.."//itoa(n))
      else if (any(m_row < 1) .or. any(m_row > n) .or. any(m_col < 1) .or. any(m_col > n)) then
        call fatal_error(error, "M: an index is outside 1.."//itoa(n))
      else if (any(k_row < k_col)) then
        call fatal_error(error, "K: give the lower triangle only (row >= col)")
      else if (any(m_row < m_col)) then
        call fatal_error(error, "M: give the lower triangle only (row >= col)")
      else if (.not.all(abs(k_val) <= huge(1.0_wp))) then
        call fatal_error(error, "K: a value is not finite")
      else if (.not.all(abs(m_val) <= huge(1.0_wp))) then
        call fatal_error(error, "M: a value is not finite")
      else if (.not.all(abs(stress) <= huge(1.0_wp))) then
        call fatal_error(error, "stress_rows: a value is not finite")
      else if (n_modes < 0 .and. .not.(f_max > 0)) then
        call fatal_error(error, "n_modes/f_max: give the number of modes or f_max > 0")
      else if (n_residual < 0 .or. n_residual > 20) then
        call fatal_error(error, "n_residual: must be 0 to 20")
      else if (f_max /= f_max .or. f_max > huge(1.0_wp)) then
        call fatal_error(error, "f_max: not finite")
      end if
    end subroutine check_input

    !> Interior block (entries with both DOFs interior) and the dense interior-boundary block.
    subroutine split(at, aii, aib)
      type(coo_type), intent(in) :: at
      type(coo_type), intent(out) :: aii
      real(wp), allocatable, intent(out) :: aib(:, :)
      integer(8) :: e, c
      logical, allocatable :: inner(:)
      inner = at%row <= ni
      c = count(inner, kind=8)
      aii%n = ni
      aii%nnz = c
      aii%row = pack(at%row, inner)
      aii%col = pack(at%col, inner)
      aii%val = pack(at%val, inner)
      allocate(aib(ni, n_boundary), source=0.0_wp)
      ! lower triangle: a boundary row (> n_i) with an interior column
      do e = 1, at%nnz
        if (at%row(e) > ni .and. at%col(e) <= ni) then
          aib(at%col(e), at%row(e) - ni) = aib(at%col(e), at%row(e) - ni) + at%val(e)
        end if
      end do
    end subroutine split

    subroutine residual_vectors(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: blk(:, :), keep(:, :)
      real(wp) :: before, after
      integer :: p, j, nk, pass
      allocate(x(ni, 0), blk(ni, n_boundary), y(ni))
      do j = 1, n_boundary
        call sym_matvec(mii, psi(:, j), y)
        blk(:, j) = y + mib(:, j)
      end do
      do p = 1, n_residual
        call factor_solve(fac, blk, error)
        if (allocated(error)) return
        ! M_II-orthonormalise against the modes and the earlier vectors: classical Gram-Schmidt
        ! twice ("twice is enough"), one product with M_II per pass
        allocate(keep(ni, 0))
        do j = 1, size(blk, 2)
          call sym_matvec(mii, blk(:, j), y)
          before = sqrt(max(dot_product(blk(:, j), y), 0.0_wp))
          if (before == 0) cycle
          do pass = 1, 2
            if (pass == 2) call sym_matvec(mii, blk(:, j), y)
            call project_out(phi(:, 1:nev), y, blk(:, j))
            call project_out(x, y, blk(:, j))
            call project_out(keep, y, blk(:, j))
          end do
          call sym_matvec(mii, blk(:, j), y)
          after = sqrt(max(dot_product(blk(:, j), y), 0.0_wp))
          if (after <= 1e-8_wp*before) cycle
          keep = reshape([keep, blk(:, j)/after], [ni, size(keep, 2) + 1])
        end do
        nk = size(keep, 2)
        x = reshape([x, keep], [ni, size(x, 2) + nk])
        ! next block: K_II^-1 M_II of this one
        deallocate(blk)
        allocate(blk(ni, nk))
        do j = 1, nk
          call sym_matvec(mii, keep(:, j), blk(:, j))
        end do
        deallocate(keep)
        if (nk == 0) exit
      end do
      ! only the nev modes asked are kept (the extra one served the inertia check)
      if (size(lambda) > nev) then
        phi = phi(:, 1:nev)
      end if
    end subroutine residual_vectors

    !> b = b - Q (Q^T y) with y = M_II b: removes b's M_II-components along the
    !> M_II-orthonormal columns of Q.
    subroutine project_out(q, y, b)
      real(wp), intent(in) :: q(:, :), y(:)
      real(wp), intent(inout) :: b(:)
      real(wp), allocatable :: c(:)
      integer :: k
      k = size(q, 2)
      if (k == 0) return
      allocate(c(k))
      call dgemv('T', ni, k, 1.0_wp, q, ni, y, 1, 0.0_wp, c, 1)
      call dgemv('N', ni, k, -1.0_wp, q, ni, c, 1, 1.0_wp, b, 1)
    end subroutine project_out

    subroutine reduced_frequencies(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: a(:, :), b(:, :), ev(:), work(:)
      integer :: info, j
      allocate(a, source=red%K)
      allocate(b, source=red%M)
      allocate(ev(r), work(max(1, 3*r)))
      call dsygv(1, 'N', 'U', r, a, r, b, r, ev, work, size(work), info)
      if (info > r) then
        ! M_r is singular (a massless direction of M): the inverted pencil M z = mu K z with
        ! K_r positive definite; mu = 0 is an infinite eigenfrequency
        a = red%M
        b = red%K
        call dsygv(1, 'N', 'U', r, a, r, b, r, ev, work, size(work), info)
        if (info == 0) then
          allocate(red%freqs_reduced(r))
          do j = 1, r
            if (ev(r+1-j) > mass_tol*ev(r)) then
              red%freqs_reduced(j) = sqrt(1/ev(r+1-j))/(2*pi)
            else
              red%freqs_reduced(j) = ieee_value(1.0_wp, ieee_positive_inf)
            end if
          end do
          return
        end if
      end if
      if (info /= 0) then
        call fatal_error(error, "reduced model: LAPACK dsygv failed (info = "//itoa(info)// &
          & "; reduced M not positive definite?)", UDMAP_ENUMERIC)
        return
      end if
      red%freqs_reduced = sqrt(max(ev, 0.0_wp))/(2*pi)
    end subroutine reduced_frequencies

    !> M (on the pattern of `ka` + `ma`, analysed in fac) must be positive semi-definite:
    !> Sylvester's inertia of M + tau I, tau = mass_tol max|M|, counts the eigenvalues of M below
    !> -tau (a massless DOF, a zero eigenvalue, is fine: shift-invert never inverts M). The
    !> diagonal of K's pattern carries tau (K_II positive definite has every diagonal entry).
    subroutine check_mass(ka, ma, what, error)
      type(coo_type), intent(in) :: ka, ma
      character(len=*), intent(in) :: what
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: tau
      real(wp), allocatable :: diag(:)
      integer(8) :: e
      integer, allocatable :: cnt(:)
      tau = mass_tol*maxval(abs(m_val))
      ! tau once on each diagonal, over its duplicate entries (they add up)
      allocate(cnt(ka%n), source=0)
      allocate(diag(ka%nnz), source=0.0_wp)
      do e = 1, ka%nnz
        if (ka%row(e) == ka%col(e)) cnt(ka%row(e)) = cnt(ka%row(e)) + 1
      end do
      do e = 1, ka%nnz
        if (ka%row(e) == ka%col(e)) diag(e) = tau/cnt(ka%row(e))
      end do
      call factor_numeric(fac, [diag, ma%val], what//" + tau I", error)
      if (.not.allocated(error)) then
        if (fac%negative_pivots == 0) return
        call fatal_error(error, "M: the mass matrix is not positive definite (nor "// &
          & "semi-definite: "//itoa(fac%negative_pivots)//" eigenvalues of "//what// &
          & " below -1e-12 max|M|)")
      else
        error%message = "M: the mass matrix is not positive definite (nor "// &
          & "semi-definite: "//error%message//")"
        error%stat = UDMAP_EINPUT
      end if
    end subroutine check_mass

    subroutine full_check(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: sig_top, sig_shift
      real(wp), allocatable :: lam(:), vec(:, :)
      integer :: cnt
      sig_top = (2*pi*red%f_check)**2
      sig_shift = -1e-2_wp*sig_top
      call factor_analyse(fac, nt, [kt%row, mt%row], [kt%col, mt%col], error)
      if (allocated(error)) return
      ! M on every kept DOF (the interior check above misses the platform's and u_E's)
      call check_mass(kt, mt, "T^T M T", error)
      if (allocated(error)) return
      call factor_numeric(fac, [kt%val, -sig_top*mt%val], "K_t - sigma M_t", error)
      if (allocated(error)) return
      cnt = fac%negative_pivots
      red%full_count = cnt
      if (cnt > nt - 2) then
        call fatal_error(error, "full-model check: the band holds nearly all modes", &
          & UDMAP_ENUMERIC)
        return
      end if
      call factor_numeric(fac, [kt%val, -sig_shift*mt%val], "K_t - sigma M_t", error)
      if (allocated(error)) return
      if (fac%negative_pivots /= 0) then
        call fatal_error(error, "K: the stiffness matrix is indefinite ("// &
          & itoa(fac%negative_pivots)//" negative pivots of K + s M)")
        return
      end if
      if (fac%factor_entries > red%factor_entries) red%factor_entries = fac%factor_entries
      call lowest_modes(fac, sig_shift, mt, cnt, lam, vec, error)
      if (allocated(error)) return
      red%full_found = count(lam < sig_top)
      if (red%full_found /= cnt) then
        call fatal_error(error, "full-model check: MUMPS counts "//itoa(cnt)//" modes below "// &
          & "3 f_max, ARPACK found "//itoa(red%full_found), UDMAP_ENUMERIC)
        return
      end if
      red%freqs_full = sqrt(max(lam, 0.0_wp))/(2*pi)
    end subroutine full_check
  end subroutine platform_centred_reduction

  integer(8) function clock()
    call system_clock(clock)
  end function clock

  real(wp) function seconds(t0)
    integer(8), intent(in) :: t0
    integer(8) :: t1, rate
    call system_clock(t1, rate)
    seconds = real(t1 - t0, wp)/real(rate, wp)
  end function seconds
end module udmap_blade_reduce_craig_bampton
