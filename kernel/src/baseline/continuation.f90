!> The standard method's path following (PHYSICS.md 6): Newton at fixed frequency and on the
!> arc-length constraint, the tangent and its renormalisation, the step acceptance (angle and
!> iteration count), the corrector step and the landing on a given frequency.
module udmap_baseline_continuation
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_baseline_linear_structure, only: structure_type
  use udmap_baseline_types, only: amplitude, amplitude_scale, scaled_dot, converged, &
    & problem_type, curve_point_type
  use udmap_baseline_residual, only: evaluate, factor, bordered_solve
  implicit none
  private
  public :: newton_fixed, newton_arclength, tangent, check_step, corrector_step, land_at, &
    & check_bounded, accept_step

contains

  !> Whether a corrected step from cur to nxt (step ds) is acceptable: no jump to another part
  !> of the curve (far from the predictor: a corner of angle theta puts it ds tan(theta) away;
  !> or the amplitude changed threefold) and a turn of the tangent of at most max_angle, unless
  !> the turn does not shrink with a small step (a corner of the curve: a stick-slip transition
  !> of the damper). angle_rejected: the turn of the last rejected attempt.
  subroutine check_step(p, cur, nxt, ds, angle_rejected, ok)
    type(problem_type), intent(in) :: p
    type(curve_point_type), intent(in) :: cur, nxt
    real(wp), intent(in) :: ds
    real(wp), intent(inout) :: angle_rejected
    logical, intent(out) :: ok
    real(wp) :: cosang, angle
    ok = nxt%A <= 3.0_wp*cur%A .and. 3.0_wp*nxt%A >= cur%A
    if (ok) ok = sqrt(scaled_dot(p, nxt%x - cur%x - ds*cur%tx, nxt%omega - cur%omega - &
      & ds*cur%tw, nxt%x - cur%x - ds*cur%tx, nxt%omega - cur%omega - ds*cur%tw, cur%A_s)) &
      & <= 3.0_wp*ds
    if (.not.ok) return
    cosang = scaled_dot(p, cur%tx, cur%tw, nxt%tx, nxt%tw, cur%A_s)
    angle = acos(max(-1.0_wp, min(1.0_wp, cosang)))
    if (angle > p%set%max_angle .and. .not.(angle > 0.7_wp*angle_rejected .and. &
        & ds <= 0.01_wp .and. angle < 0.5_wp*pi)) then
      ok = .false.
      angle_rejected = angle
    end if
  end subroutine check_step

  !> Step control on the Newton iterations it of the last step: the factor for the next ds.
  pure real(wp) function step_factor(p, it) result(fac)
    type(problem_type), intent(in) :: p
    integer, intent(in) :: it
    if (2*it <= p%set%target_iter) then
      fac = 2.0_wp
    else if (it < p%set%target_iter) then
      fac = 1.5_wp
    else if (it > p%set%target_iter + 1) then
      fac = 0.6_wp
    else
      fac = 1.0_wp
    end if
  end function step_factor

  !> The unbounded-response error when the amplitude of pt exceeds gamma_limit.
  subroutine check_bounded(p, pt, error)
    type(problem_type), intent(in) :: p
    type(curve_point_type), intent(in) :: pt
    type(error_type), allocatable, intent(out) :: error
    if (pt%A > p%set%gamma_limit) call fatal_error(error, "hbm: the response exceeds "// &
      & "gamma_limit (unbounded: F_E at or above the limit force with little damping, or a "// &
      & "force far beyond the model)", UDMAP_EPHYSICS)
  end subroutine check_bounded

  !> Makes the accepted point nxt the current one (nxt's arrays move to cur): the next step
  !> length from the Newton iterations it, the amplitude scale at the new point and the tangent
  !> renormalised in that metric.
  subroutine accept_step(p, it, ds, cur, nxt)
    type(problem_type), intent(in) :: p
    integer, intent(in) :: it
    real(wp), intent(inout) :: ds
    type(curve_point_type), intent(inout) :: cur, nxt
    ds = min(p%set%ds_max, ds*step_factor(p, it))
    call move_alloc(nxt%x, cur%x)
    call move_alloc(nxt%tx, cur%tx)
    cur%omega = nxt%omega
    cur%tw = nxt%tw
    cur%A = nxt%A
    cur%dA = nxt%dA
    cur%A_s = amplitude_scale(p, cur%x)
    call renormalise(p, cur)
  end subroutine accept_step

  !> Predictor along the tangent of cur, pseudo-arc-length corrector; nxt gets its tangent.
  subroutine corrector_step(p, st, cur, ds, nxt, ok, it, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: cur
    real(wp), intent(in) :: ds
    type(curve_point_type), intent(out) :: nxt
    logical, intent(out) :: ok
    integer, intent(out) :: it
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: xp(:)
    real(wp) :: wp_
    xp = cur%x + ds*cur%tx
    wp_ = cur%omega + ds*cur%tw
    nxt%x = xp
    nxt%omega = wp_
    call newton_arclength(p, st, nxt%x, nxt%omega, cur, xp, wp_, p%set%tol_path, ok, it, error)
    if (allocated(error) .or. .not.ok) return
    nxt%A_s = cur%A_s
    allocate(nxt%tx(p%nx))
    ! tangent from a new Jacobian at the converged point; with jacobian_reuse it also serves
    ! the chord iterations of the next corrector
    call tangent(p, st, nxt, cur%tx, cur%tw, error, cur%A_s, reuse=.not.p%set%jacobian_reuse)
  end subroutine corrector_step

  !> Replaces nxt (beyond omega_end) by the point at omega_end, by Newton at fixed frequency
  !> from the linear interpolation between cur and nxt.
  subroutine land_at(p, st, cur, nxt, omega_end, tol, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(in) :: cur
    type(curve_point_type), intent(inout) :: nxt
    real(wp), intent(in) :: omega_end, tol
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: th
    real(wp), allocatable :: tx_old(:)
    real(wp) :: tw_old
    logical :: ok
    integer :: it
    th = 1.0_wp
    if (nxt%omega /= cur%omega) th = (omega_end - cur%omega)/(nxt%omega - cur%omega)
    nxt%x = cur%x + th*(nxt%x - cur%x)
    nxt%omega = omega_end
    call newton_fixed(p, st, nxt%x, nxt%omega, tol, ok, it, error)
    if (allocated(error)) return
    if (.not.ok) then
      call fatal_error(error, "hbm: Newton did not converge at the band end", UDMAP_ENUMERIC)
      return
    end if
    tx_old = nxt%tx
    tw_old = nxt%tw
    call tangent(p, st, nxt, tx_old, tw_old, error, cur%A_s)
  end subroutine land_at

  ! ------------------------------------------------------------------ Newton

  !> Newton at fixed omega from x.
  subroutine newton_fixed(p, st, x, omega, tol, ok, it, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(inout) :: x(:)
    real(wp), intent(in) :: omega, tol
    logical, intent(out) :: ok
    integer, intent(out) :: it
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: R(:), Jw(:), dx(:), cx(:)
    real(wp) :: dw, A_s, stepn, prev, prev2
    allocate(R(p%nx), Jw(p%nx), dx(p%nx), cx(p%m))
    cx = 0.0_wp
    ok = .false.
    prev = huge(1.0_wp)
    prev2 = huge(1.0_wp)
    do it = 1, p%set%max_iter
      call evaluate(p, st, x, omega, R, error, Jw=Jw)
      if (allocated(error)) return
      call factor(p, st, omega, error)
      if (allocated(error)) return
      call bordered_solve(p, Jw, cx, 1.0_wp, -R, 0.0_wp, dx, dw, error)
      if (allocated(error)) return
      x = x + dx
      p%iterations = p%iterations + 1
      A_s = amplitude_scale(p, x)
      stepn = norm2(dx(p%goff+1:p%goff+p%m))/A_s
      if (.not.(stepn <= huge(1.0_wp))) return
      if (converged(tol, stepn, prev, prev2)) then
        ok = .true.
        return
      end if
      if (amplitude(p, x) > 10.0_wp*p%set%gamma_limit) return
      prev2 = prev
      prev = stepn
    end do
  end subroutine newton_fixed

  !> Newton on [R = 0; <t, y - y_p> = 0] with the tangent and metric of `base`.
  subroutine newton_arclength(p, st, x, omega, base, xp, omega_p, tol, ok, it, error)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    real(wp), intent(inout) :: x(:), omega
    type(curve_point_type), intent(in) :: base
    real(wp), intent(in) :: xp(:), omega_p, tol
    logical, intent(out) :: ok
    integer, intent(out) :: it
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: R(:), Jw(:), dx(:), cx(:)
    real(wp) :: dw, cw, Nres, stepn, prev, prev2
    integer :: grow
    logical :: fresh
    allocate(R(p%nx), Jw(p%nx), dx(p%nx))
    cx = base%tx(p%goff+1:p%goff+p%m)/base%A_s**2
    cw = base%tw/p%W_s**2
    ok = .false.
    prev = huge(1.0_wp)
    prev2 = huge(1.0_wp)
    grow = 0
    fresh = .not.(p%set%jacobian_reuse .and. p%jm_valid)
    do it = 1, p%set%max_iter
      call evaluate(p, st, x, omega, R, error, Jw=Jw, damper_jacobian=fresh)
      if (allocated(error)) return
      call factor(p, st, omega, error)
      if (allocated(error)) return
      Nres = dot_product(cx, x(p%goff+1:p%goff+p%m) - xp(p%goff+1:p%goff+p%m)) + &
        & cw*(omega - omega_p)
      call bordered_solve(p, Jw, cx, cw, -R, -Nres, dx, dw, error)
      if (allocated(error)) return
      p%Jw_last = Jw
      x = x + dx
      omega = omega + dw
      p%iterations = p%iterations + 1
      stepn = norm2(dx(p%goff+1:p%goff+p%m))/base%A_s + abs(dw)/p%W_s
      if (.not.(stepn <= huge(1.0_wp)) .or. .not.(omega > 0.0_wp)) exit
      ! converged when the step, or the next one predicted from the contraction rate, is small
      if (converged(tol, stepn, prev, prev2)) then
        ok = .true.
        return
      end if
      if (amplitude(p, x) > 10.0_wp*p%set%gamma_limit) exit
      ! divergence: the step keeps growing
      if (stepn > prev) then
        grow = grow + 1
        if (grow >= 3) exit
      end if
      ! a reused damper Jacobian that no longer contracts well is renewed
      fresh = .not.p%set%jacobian_reuse .or. stepn > 0.25_wp*prev
      prev2 = prev
      prev = stepn
    end do
    ! failed: start the next attempt with a new Jacobian
    p%jm_valid = .false.
  end subroutine newton_arclength

  !> Tangent at pt (converged): solves [J_x Jw; <t_ref, .>] t = [0; 1], normalises it in the
  !> metric and sets pt%A, pt%dA. With central, the damper Jacobian by central differences.
  subroutine tangent(p, st, pt, tx_ref, tw_ref, error, A_s, central, reuse)
    type(problem_type), intent(inout) :: p
    type(structure_type), intent(in) :: st
    type(curve_point_type), intent(inout) :: pt
    real(wp), intent(in) :: tx_ref(:), tw_ref
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: A_s
    logical, intent(in), optional :: central
    !> Use the Jacobian of the last Newton iterate (already factorised) instead of a new one.
    logical, intent(in), optional :: reuse
    real(wp), allocatable :: R(:), Jw(:), cx(:), zero(:)
    real(wp) :: cw, tw, nrm, As
    logical :: again
    allocate(R(p%nx), Jw(p%nx), zero(p%nx))
    zero = 0.0_wp
    As = amplitude_scale(p, pt%x)
    if (present(A_s)) As = A_s
    again = .false.
    if (present(reuse)) again = reuse .and. allocated(p%Jw_last)
    if (again) then
      Jw = p%Jw_last
    else
      call evaluate(p, st, pt%x, pt%omega, R, error, Jw=Jw, central=central)
      if (allocated(error)) return
      call factor(p, st, pt%omega, error)
      if (allocated(error)) return
    end if
    cx = tx_ref(p%goff+1:p%goff+p%m)/As**2
    cw = tw_ref/p%W_s**2
    call bordered_solve(p, Jw, cx, cw, zero, 1.0_wp, pt%tx, tw, error)
    if (allocated(error)) return
    pt%tw = tw
    nrm = sqrt(scaled_dot(p, pt%tx, pt%tw, pt%tx, pt%tw, As))
    if (.not.(nrm > 0.0_wp) .or. nrm > huge(1.0_wp)) then
      call fatal_error(error, "hbm: the tangent of the response curve is degenerate", &
        & UDMAP_ENUMERIC)
      return
    end if
    pt%tx = pt%tx/nrm
    pt%tw = pt%tw/nrm
    pt%A_s = As
    pt%A = amplitude(p, pt%x)
    pt%dA = 0.0_wp
    if (pt%A > 0.0_wp) pt%dA = (pt%x(p%goff+p%h0+1)*pt%tx(p%goff+p%h0+1) + &
      & pt%x(p%goff+p%h0+2)*pt%tx(p%goff+p%h0+2))/pt%A/As
  end subroutine tangent

  !> Re-normalises the tangent of pt in its current metric (after A_s changed).
  subroutine renormalise(p, pt)
    type(problem_type), intent(in) :: p
    type(curve_point_type), intent(inout) :: pt
    real(wp) :: nrm
    nrm = sqrt(scaled_dot(p, pt%tx, pt%tw, pt%tx, pt%tw, pt%A_s))
    if (nrm > 0.0_wp) then
      pt%tx = pt%tx/nrm
      pt%tw = pt%tw/nrm
    end if
    if (pt%A > 0.0_wp) pt%dA = (pt%x(p%goff+p%h0+1)*pt%tx(p%goff+p%h0+1) + &
      & pt%x(p%goff+p%h0+2)*pt%tx(p%goff+p%h0+2))/pt%A/pt%A_s
  end subroutine renormalise
end module udmap_baseline_continuation
