!> The standard method's equations (PHYSICS.md 6): the problem set up for one force, the residual
!> R(x, omega) of the condensed or the full variant with the damper moment by AFT, its
!> finite-difference damper Jacobian, the factorised x-Jacobian (dense or banded LU) and the
!> bordered solve of the arc-length system, and the stuck-damper starting guess.
module udmap_baseline_residual
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, require, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_core_strings, only: itoa
  use udmap_core_lapack, only: dgesv, dgbtrf, dgbtrs, dgetrf, dgetrs
  use udmap_baseline_linear_structure, only: structure_type, structure_receptances_type, &
    & structure_receptances
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_aft_moment, only: aft_moment
  use udmap_baseline_types, only: hbm_settings_type, HBM_CONDENSED, HBM_FULL, problem_type
  implicit none
  private
  public :: setup, evaluate, factor, bordered_solve, stuck_guess

contains

  subroutine setup(p, st, element, f_min, f_max, F_E, settings, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    class(hysteretic_element_type), intent(in) :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    type(hbm_settings_type), intent(in) :: settings
    type(error_type), allocatable, intent(out) :: error
    type(structure_receptances_type) :: r0
    call require(st%ndof >= 1, "hbm: the structure is empty", error)
    call require(F_E > 0.0_wp .and. F_E <= huge(1.0_wp), &
      & "hbm: F_E must be positive and finite", error)
    call require(f_min > 0.0_wp .and. f_max > f_min .and. f_max <= huge(1.0_wp), &
      & "hbm: need 0 < f_min < f_max (finite)", error)
    call require(settings%harmonics >= 1 .and. settings%harmonics <= 64, &
      & "hbm: harmonics must be in 1..64", error)
    call require(settings%variant == HBM_CONDENSED .or. settings%variant == HBM_FULL, &
      & "hbm: variant must be condensed (0) or full (1)", error)
    call require(settings%tol > 0.0_wp .and. settings%tol_path > 0.0_wp .and. &
      & settings%ds_min > 0.0_wp .and. settings%ds_max >= settings%ds_min .and. &
      & settings%ds_initial > 0.0_wp .and. settings%fd_step > 0.0_wp .and. &
      & settings%peak_tol > 0.0_wp .and. settings%max_angle > 0.0_wp .and. &
      & settings%gamma_limit > 0.0_wp .and. settings%aft_loop_rtol > 0.0_wp .and. &
      & settings%max_iter >= 2 .and. settings%max_steps >= 1 .and. settings%target_iter >= 1 &
      & .and. settings%aft_samples >= 0 .and. settings%aft_max_periods >= 1 .and. &
      & settings%warm_start >= 0 .and. settings%warm_start <= 2, &
      & "hbm: invalid numerical settings (tolerances and steps must be positive, "// &
      & "max_iter >= 2, aft_samples >= 0, warm_start 0, 1 or 2)", error)
    call require(settings%aft_samples <= 0 .or. settings%aft_samples >= 2*settings%harmonics + 1, &
      & "hbm: aft_samples must be 0 (exact) or >= 2 H + 1", error)
    if (allocated(error)) return
    p%set = settings
    p%H = settings%harmonics
    p%h0 = merge(1, 0, settings%harmonic0)
    p%m = 2*p%H + p%h0
    p%F = F_E
    p%n = st%ndof
    p%W_s = 2.0_wp*pi*f_min
    if (settings%variant == HBM_CONDENSED) then
      p%b = p%m
      p%nx = p%m
      p%goff = 0
    else
      p%b = p%m
      p%nx = p%m*st%ndof
      p%goff = (st%gamma_dof - 1)*p%b
      if (st%kd >= 0) p%kb = (st%kd + 1)*p%b - 1
      p%banded = st%kd >= 0
    end if
    if (settings%variant == HBM_FULL) call band_entries(st, p%Ie, p%Je, p%Kij, p%Mij, p%Cij)
    allocate(p%el, source=element)
    allocate(p%Mh(p%H), p%JM(p%m, p%m), p%rec(p%H))
    call p%el%load(error)
    if (allocated(error)) return
    p%k_stuck = p%el%stuck_stiffness()
    ! the static moment of the loaded damper is in equilibrium with the blade's reference state
    p%M_ref = p%el%moment()
    if (p%h0 == 1 .and. settings%variant == HBM_CONDENSED) then
      call structure_receptances(st, 0.0_wp, r0, error)
      if (allocated(error)) return
      p%Hgg0 = real(r0%gg, wp)
    end if
  end subroutine setup

  ! ------------------------------------------------------------------ residual and Jacobian

  !> The residual R(x, omega), its omega-derivative Jw and the damper Jacobian p%JM (finite
  !> differences of the AFT in the gamma unknowns, forward or central).
  subroutine evaluate(p, st, x, omega, R, error, Jw, central, damper_jacobian)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: x(:), omega
    real(wp), intent(out) :: R(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: Jw(:)
    logical, intent(in), optional :: central
    !> With Jw: also the damper Jacobian by finite differences (default); .false. keeps p%JM.
    logical, intent(in), optional :: damper_jacobian
    real(wp), allocatable :: xg(:), Mv(:), Mp(:), Mm(:)
    real(wp) :: delta, scale
    integer :: c
    logical :: cen, fd
    cen = .false.
    if (present(central)) cen = central
    fd = present(Jw)
    if (present(damper_jacobian)) fd = fd .and. damper_jacobian
    allocate(xg(p%m))
    xg = x(p%goff+1:p%goff+p%m)
    call damper_vector(p, xg, Mv, error)
    if (allocated(error)) return
    call unpack_moment(p, Mv)
    if (fd) then
      p%jm_valid = .true.
      scale = max(norm2(xg), tiny(1.0_wp))
      do c = 1, p%m
        delta = p%set%fd_step*scale
        xg(c) = x(p%goff+c) + delta
        call damper_vector(p, xg, Mp, error)
        if (allocated(error)) return
        if (cen) then
          xg(c) = x(p%goff+c) - delta
          call damper_vector(p, xg, Mm, error)
          if (allocated(error)) return
          p%JM(:, c) = (Mp - Mm)/(2.0_wp*delta)
        else
          p%JM(:, c) = (Mp - Mv)/delta
        end if
        xg(c) = x(p%goff+c)
      end do
      ! restore the moment of the base point (damper_vector overwrote nothing else)
      call unpack_moment(p, Mv)
    end if
    call variant_residual(p, st, x, omega, R, error, Jw)
  end subroutine evaluate

  !> The damper moment as a real vector in the layout of the gamma unknowns.
  subroutine damper_vector(p, xg, Mv, error)
    type(problem_type), intent(inout) :: p
    real(wp), intent(in) :: xg(:)
    real(wp), allocatable, intent(out) :: Mv(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: G0, M0
    complex(wp) :: G(p%H), M(p%H)
    integer :: h
    G0 = 0.0_wp
    if (p%h0 == 1) G0 = xg(1)
    do h = 1, p%H
      G(h) = cmplx(xg(p%h0+2*h-1), xg(p%h0+2*h), wp)
    end do
    call aft_moment(p%el, p%ws, G0, G, p%set%aft_samples, p%set%aft_min_periods, &
      & p%set%aft_max_periods, p%set%aft_loop_rtol, M0, M, error, gamma_max=p%gmax)
    allocate(Mv(p%m))
    if (allocated(error)) return
    if (p%h0 == 1) Mv(1) = M0
    do h = 1, p%H
      Mv(p%h0+2*h-1) = real(M(h), wp)
      Mv(p%h0+2*h) = aimag(M(h))
    end do
  end subroutine damper_vector

  pure subroutine unpack_moment(p, Mv)
    type(problem_type), intent(inout) :: p
    real(wp), intent(in) :: Mv(:)
    integer :: h
    p%M0 = 0.0_wp
    if (p%h0 == 1) p%M0 = Mv(1)
    do h = 1, p%H
      p%Mh(h) = cmplx(Mv(p%h0+2*h-1), Mv(p%h0+2*h), wp)
    end do
  end subroutine unpack_moment

  !> Receptances at h omega, h = 1..H (cached per omega).
  subroutine update_receptances(p, st, omega, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    type(error_type), allocatable, intent(out) :: error
    integer :: h
    if (omega == p%omega_rec) return
    do h = 1, p%H
      call structure_receptances(st, h*omega, p%rec(h), error)
      if (allocated(error)) return
    end do
    p%omega_rec = omega
  end subroutine update_receptances

  !> The residual of the chosen variant at the damper moment in p: condensed on the gamma
  !> unknowns (receptances at h omega), else the full one (full_residual).
  subroutine variant_residual(p, st, x, omega, R, error, Jw)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: x(:), omega
    real(wp), intent(out) :: R(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: Jw(:)
    complex(wp) :: G, Rh, dR
    integer :: h, i
    if (p%set%variant /= HBM_CONDENSED) then
      call full_residual(p, st, x, omega, R, Jw)
      return
    end if
    call update_receptances(p, st, omega, error)
    if (allocated(error)) return
    if (p%h0 == 1) then
      R(1) = x(1) + p%Hgg0*(p%M0 - p%M_ref)
      if (present(Jw)) Jw(1) = 0.0_wp
    end if
    do h = 1, p%H
      i = p%h0 + 2*h - 1
      G = cmplx(x(i), x(i+1), wp)
      Rh = G + p%rec(h)%gg*p%Mh(h)
      if (h == 1) Rh = Rh - p%rec(1)%gE*p%F
      R(i) = real(Rh, wp)
      R(i+1) = aimag(Rh)
      if (present(Jw)) then
        dR = h*p%rec(h)%dgg*p%Mh(h)
        if (h == 1) dR = dR - p%rec(1)%dgE*p%F
        Jw(i) = real(dR, wp)
        Jw(i+1) = aimag(dR)
      end if
    end do
  end subroutine variant_residual

  pure subroutine full_residual(p, st, x, omega, R, Jw)
    type(problem_type), intent(in) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: x(:), omega
    real(wp), intent(out) :: R(:)
    real(wp), intent(out), optional :: Jw(:)
    integer :: h, bi, bj, cr, e
    real(wp) :: kij, mij, cij, Om, a, bb, dm
    R = 0.0_wp
    if (present(Jw)) Jw = 0.0_wp
    do e = 1, size(p%Kij)
      bi = (p%Ie(e) - 1)*p%b
      bj = (p%Je(e) - 1)*p%b
      kij = p%Kij(e); mij = p%Mij(e); cij = p%Cij(e)
      if (p%h0 == 1) R(bi+1) = R(bi+1) + kij*x(bj+1)
      do h = 1, p%H
        cr = p%h0 + 2*h - 1
        Om = h*omega
        a = kij - Om**2*mij
        bb = Om*cij
        R(bi+cr) = R(bi+cr) + a*x(bj+cr) - bb*x(bj+cr+1)
        R(bi+cr+1) = R(bi+cr+1) + bb*x(bj+cr) + a*x(bj+cr+1)
        if (present(Jw)) then
          ! d/domega of D(h omega) Q_h = h (-2 h omega M + i C) Q_h
          dm = -2.0_wp*h*Om*mij
          Jw(bi+cr) = Jw(bi+cr) + dm*x(bj+cr) - h*cij*x(bj+cr+1)
          Jw(bi+cr+1) = Jw(bi+cr+1) + h*cij*x(bj+cr) + dm*x(bj+cr+1)
        end if
      end do
    end do
    bi = (st%exc_dof - 1)*p%b
    R(bi+p%h0+1) = R(bi+p%h0+1) - p%F
    bi = p%goff
    if (p%h0 == 1) R(bi+1) = R(bi+1) + p%M0 - p%M_ref
    do h = 1, p%H
      cr = p%h0 + 2*h - 1
      R(bi+cr) = R(bi+cr) + real(p%Mh(h), wp)
      R(bi+cr+1) = R(bi+cr+1) + aimag(p%Mh(h))
    end do
  end subroutine full_residual

  !> The entries (i, j) of K, M and C that the full variant assembles, with their row Ie and
  !> column Je, in its loop order (rows i, then columns j inside the band), so that the Newton
  !> loop reads them in sequence.
  pure subroutine band_entries(st, Ie, Je, Kij, Mij, Cij)
    type(structure_type), intent(in) :: st
    integer, allocatable, intent(out) :: Ie(:), Je(:)
    real(wp), allocatable, intent(out) :: Kij(:), Mij(:), Cij(:)
    integer :: i, j, lo, hi, r, c, e, n
    n = st%ndof
    lo = n
    if (st%kd >= 0) lo = min(n, 2*st%kd + 1)
    allocate(Ie(n*lo), Je(n*lo))
    e = 0
    do i = 1, n
      lo = 1; hi = n
      if (st%kd >= 0) then
        lo = max(1, i - st%kd); hi = min(n, i + st%kd)
      end if
      do j = lo, hi
        e = e + 1
        Ie(e) = i; Je(e) = j
      end do
    end do
    Ie = Ie(1:e); Je = Je(1:e)
    allocate(Kij(e), Mij(e), Cij(e))
    do e = 1, size(Ie)
      i = Ie(e); j = Je(e)
      if (st%kd < 0) then
        Kij(e) = st%K(i, j); Mij(e) = st%M(i, j); Cij(e) = st%C(i, j)
      else
        ! symmetric upper band storage: A(r, c) = X(kd + 1 + r - c, c), r <= c
        r = min(i, j); c = max(i, j)
        r = st%kd + 1 + r - c
        Kij(e) = st%K(r, c); Mij(e) = st%M(r, c); Cij(e) = st%C(r, c)
      end if
    end do
  end subroutine band_entries

  !> Assembles and factorises J_x (dense for condensed, banded or dense LU for full).
  subroutine factor(p, st, omega, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    type(error_type), allocatable, intent(out) :: error
    integer :: i, h, c, cc, bi, bj, cr, info, ldab, kb, r0, sy, e
    real(wp) :: kij, mij, cij, Om, a, bb, gr, gi
    if (p%set%variant == HBM_CONDENSED) then
      ! J_x = I + blockdiag(H_gg(h omega)) JM, complex products as 2x2 real blocks
      if (.not.allocated(p%Jd)) allocate(p%Jd(p%m, p%m))
      p%Jd = 0.0_wp
      do c = 1, p%m
        p%Jd(c, c) = 1.0_wp
      end do
      if (p%h0 == 1) p%Jd(1, :) = p%Jd(1, :) + p%Hgg0*p%JM(1, :)
      do h = 1, p%H
        cr = p%h0 + 2*h - 1
        gr = real(p%rec(h)%gg, wp)
        gi = aimag(p%rec(h)%gg)
        p%Jd(cr, :) = p%Jd(cr, :) + gr*p%JM(cr, :) - gi*p%JM(cr+1, :)
        p%Jd(cr+1, :) = p%Jd(cr+1, :) + gi*p%JM(cr, :) + gr*p%JM(cr+1, :)
      end do
      return
    end if
    kb = p%kb
    if (st%kd >= 0) then
      ldab = 3*kb + 1
      if (.not.allocated(p%LU)) allocate(p%LU(ldab, p%nx), p%ipiv(p%nx))
      r0 = 2*kb + 1
      sy = 1
    else
      if (.not.allocated(p%LU)) allocate(p%LU(p%nx, p%nx), p%ipiv(p%nx))
      r0 = 0
      sy = 0
    end if
    p%LU = 0.0_wp
    ! entry (row, col) of J_x is stored at LU(r0 + row - col, col) in band storage and at
    ! LU(row, col) in dense storage: LU(base + row - sy*col, col) with base = r0 or 0
    do e = 1, size(p%Kij)
      bi = (p%Ie(e) - 1)*p%b
      bj = (p%Je(e) - 1)*p%b
      kij = p%Kij(e); mij = p%Mij(e); cij = p%Cij(e)
      if (p%h0 == 1) p%LU(r0+bi+1-sy*(bj+1), bj+1) = p%LU(r0+bi+1-sy*(bj+1), bj+1) + kij
      do h = 1, p%H
        cr = p%h0 + 2*h - 1
        Om = h*omega
        a = kij - Om**2*mij
        bb = Om*cij
        c = bj + cr
        p%LU(r0+bi+cr-sy*c, c) = p%LU(r0+bi+cr-sy*c, c) + a
        p%LU(r0+bi+cr+1-sy*c, c) = p%LU(r0+bi+cr+1-sy*c, c) + bb
        c = bj + cr + 1
        p%LU(r0+bi+cr-sy*c, c) = p%LU(r0+bi+cr-sy*c, c) - bb
        p%LU(r0+bi+cr+1-sy*c, c) = p%LU(r0+bi+cr+1-sy*c, c) + a
      end do
    end do
    do cc = 1, p%m
      c = p%goff + cc
      do i = 1, p%m
        p%LU(r0+p%goff+i-sy*c, c) = p%LU(r0+p%goff+i-sy*c, c) + p%JM(i, cc)
      end do
    end do
    if (st%kd >= 0) then
      call dgbtrf(p%nx, p%nx, kb, kb, p%LU, size(p%LU, 1), p%ipiv, info)
    else
      call dgetrf(p%nx, p%nx, p%LU, p%nx, p%ipiv, info)
    end if
    if (info /= 0) then
      call fatal_error(error, "hbm: dgbtrf/dgetrf failed on the full Jacobian (info = "// &
        & itoa(info)//")", UDMAP_ENUMERIC)
    end if
  end subroutine factor

  !> Solves [J_x Jw; cx^T cw] [dx; dw] = [rx; rn], cx acting on the gamma unknowns only.
  subroutine bordered_solve(p, Jw, cx, cw, rx, rn, dx, dw, error)
    type(problem_type), intent(inout) :: p
    real(wp), intent(in) :: Jw(:), cx(:), cw, rx(:), rn
    real(wp), intent(out) :: dx(:), dw
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: A(:,:), rhs(:,:)
    integer, allocatable :: ipiv(:)
    integer :: m, info
    real(wp) :: den
    if (p%set%variant == HBM_CONDENSED) then
      m = p%m
      allocate(A(m+1, m+1), rhs(m+1, 1), ipiv(m+1))
      A(1:m, 1:m) = p%Jd
      A(1:m, m+1) = Jw
      A(m+1, 1:m) = cx
      A(m+1, m+1) = cw
      rhs(1:m, 1) = rx
      rhs(m+1, 1) = rn
      call dgesv(m+1, 1, A, m+1, ipiv, rhs, m+1, info)
      if (info /= 0) then
        call fatal_error(error, "hbm: dgesv failed on the bordered Jacobian (info = "// &
          & itoa(info)//")", UDMAP_ENUMERIC)
        return
      end if
      dx = rhs(1:m, 1)
      dw = rhs(m+1, 1)
      return
    end if
    ! full: bordering with the LU of J_x
    allocate(rhs(p%nx, 2))
    rhs(:, 1) = rx
    rhs(:, 2) = Jw
    if (p%banded) then
      call dgbtrs('N', p%nx, p%kb, p%kb, 2, p%LU, size(p%LU, 1), p%ipiv, rhs, p%nx, info)
    else
      call dgetrs('N', p%nx, 2, p%LU, p%nx, p%ipiv, rhs, p%nx, info)
    end if
    if (info /= 0) then
      call fatal_error(error, "hbm: dgbtrs/dgetrs failed (info = "//itoa(info)//")", &
        & UDMAP_ENUMERIC)
      return
    end if
    den = cw - dot_product(cx, rhs(p%goff+1:p%goff+p%m, 2))
    if (den == 0.0_wp) then
      call fatal_error(error, "hbm: singular bordered system (fold of the response curve)", &
        & UDMAP_ENUMERIC)
      return
    end if
    dw = (rn - dot_product(cx, rhs(p%goff+1:p%goff+p%m, 1)))/den
    dx = rhs(:, 1) - rhs(:, 2)*dw
  end subroutine bordered_solve

  ! ------------------------------------------------------------------ helpers

  !> Linear response with the stuck damper (k_stuck) at omega: the starting guess.
  subroutine stuck_guess(p, st, omega, x, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    real(wp), intent(out) :: x(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: R(:), Jw(:), dx(:), cx(:)
    real(wp) :: dw, Msave0
    complex(wp), allocatable :: Msave(:)
    integer :: c
    allocate(R(p%nx), Jw(p%nx), dx(p%nx), cx(p%m))
    x = 0.0_wp
    cx = 0.0_wp
    ! residual at x = 0 with the damper linearised as k_stuck (no AFT needed)
    Msave = p%Mh
    Msave0 = p%M0
    p%Mh = (0.0_wp, 0.0_wp)
    p%M0 = p%M_ref
    p%JM = 0.0_wp
    do c = 1, p%m
      p%JM(c, c) = p%k_stuck
    end do
    call variant_residual(p, st, x, omega, R, error, Jw)
    if (allocated(error)) return
    call factor(p, st, omega, error)
    if (allocated(error)) return
    call bordered_solve(p, Jw, cx, 1.0_wp, -R, 0.0_wp, dx, dw, error)
    if (allocated(error)) return
    x = dx
    p%Mh = Msave
    p%M0 = Msave0
  end subroutine stuck_guess
end module udmap_baseline_residual
