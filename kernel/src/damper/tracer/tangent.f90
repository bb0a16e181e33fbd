!> Derivatives of a path of udmap_damper_tracer's trace_path (PHYSICS.md 2.6) with respect to
!> parameters that move both platforms' coordinates: forward mode through the tracer's steps,
!> replayed from the log of each segment (the contact states of every step, the event that
!> ended it and that event's rate), so that the traced path itself is untouched.
!>
!! Why: the traveling-wave point linearises the damper's action in the platform's harmonics,
!! and by differences that costs one trace a direction. For fixed contact states everything is
!! affine in the segment's end points, so the derivatives follow the steps exactly: within a
!! step the damper moves by step * rates (the rates are linear in the segment's direction),
!! and the step, the travel to the event that ends it (step = f/(-f')), moves with the event
!! function's value and rate. The sliders are reset where the tracer resets them. This is the
!! derivative of the traced function to rounding, wherever the order of the events does not
!! change, at the cost of a 3x3 solve and a few products per step and direction.
module udmap_damper_tracer_tangent
  use udmap_core_kinds, only: wp
  use udmap_damper_tracer_core, only: damper_geometry_type, mode_log_type, contact_forces, &
    & mode_stiffness, cofactors3, code_modes, CONTACT_OPEN, CONTACT_STICK, &
    & CONTACT_SLIP_POS, CONTACT_SLIP_NEG
  implicit none
  private
  public :: path_tangent_type, new_path_tangent, path_tangent_levers, &
    & path_tangent_segment, path_tangent_actions, contact_levers, mode_rates, invert3

  !> The derivatives of the damper's state along a path, one column a parameter.
  type :: path_tangent_type
    integer :: np = 0
    !> Damper DOFs and sliders at the current point.
    real(wp), allocatable :: q_p(:, :), w_p(:, :)
    !> s_p(:, j): derivatives of the place (fraction of the segment) of the last segment's
    !> vertex j, the end of its step j.
    real(wp), allocatable :: s_p(:, :)
    !> The inverse of the equilibrium matrix of the contact states k_code (mode_code; -1: none):
    !> the states of most steps are the last step's.
    integer :: k_code = -1
    real(wp) :: Ki(3, 3) = 0
  end type path_tangent_type

contains

  !> Zero derivatives of np parameters (the virgin state and the CF ramp do not depend on them).
  subroutine new_path_tangent(tan, np)
    type(path_tangent_type), intent(out) :: tan
    integer, intent(in) :: np
    tan%np = np
    allocate(tan%q_p(3, np), tan%w_p(3, np), tan%s_p(np, 16))
    tan%q_p = 0
    tan%w_p = 0
    tan%s_p = 0
  end subroutine new_path_tangent

  !> The contacts' travel along their normals (ln) and tangents (lt) for the derivatives
  !> X_p(:, k) of both platforms' coordinates at an instant.
  pure subroutine path_tangent_levers(geo, X_p, ln, lt)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: X_p(:, :)
    real(wp), intent(out) :: ln(:, :), lt(:, :)
    integer :: k
    do k = 1, size(X_p, 2)
      call contact_levers(geo, X_p(:, k), ln(:, k), lt(:, k))
    end do
  end subroutine path_tangent_levers

  !> The derivatives carried along the segment of trace_path from X_from to X_to that left
  !> the log lg and started in the contact states `entry` (mode_code); the contacts' travel
  !> for the derivatives of the segment's ends is (ls_n, ls_t) and (le_n, le_t)
  !> (path_tangent_levers).
  subroutine path_tangent_segment(geo, tan, X_from, X_to, ls_n, ls_t, le_n, le_t, entry, lg)
    type(damper_geometry_type), intent(in) :: geo
    type(path_tangent_type), intent(inout) :: tan
    real(wp), intent(in) :: X_from(6), X_to(6)
    real(wp), intent(in) :: ls_n(3, tan%np), ls_t(3, tan%np), le_n(3, tan%np), le_t(3, tan%np)
    integer, intent(in) :: entry
    type(mode_log_type), intent(in) :: lg
    type(damper_geometry_type) :: seg
    real(wp) :: cn(3), ct(3), off(2, 3), dn(3), dt(3)
    real(wp) :: Ks(3, 3), Ki(3, 3), dq(3), dq_p(3), dg_p, dN_p, dT_p, ds_p
    real(wp) :: s0, step, step_p, fp, dfp, g(3), sv(3), N(3), T(3), sp
    real(wp), allocatable :: tmp(:, :)
    integer :: m_old(3), m_new(3), j, k, i, e, c
    logical :: ok, changed(3), slips(3)

    if (lg%n == 0) return
    if (size(tan%s_p, 2) < lg%n) then
      allocate(tmp(tan%np, 2*lg%n))
      call move_alloc(tmp, tan%s_p)
    end if
    call contact_levers(geo, X_to - X_from, cn, ct)
    ! the segment's geometry (its levers), as trace_path traces it
    seg = geo
    seg%cn = cn
    seg%ct = ct
    m_old = code_modes(entry)
    s0 = 0
    do j = 1, lg%n
      m_new = code_modes(lg%code(j))
      changed = (m_old == CONTACT_OPEN) .neqv. (m_new == CONTACT_OPEN)
      slips = m_old /= CONTACT_STICK
      ! the step's equilibrium, K dq = h(levers), for the segment and each derivative
      if (lg%code(j) /= tan%k_code) then
        call mode_stiffness(geo, m_new, Ks)
        call invert3(Ks, tan%Ki, ok)
        ! (regular: the tracer took this step in these states, which resolve_mode requires)
        if (.not. ok) then
          tan%k_code = -1
          return
        end if
        tan%k_code = lg%code(j)
      end if
      Ki = tan%Ki
      dq = mat3(Ki, mode_rhs(geo, m_new, cn, ct))
      step = lg%s(j) - s0
      e = lg%event(j)
      i = e/4
      do k = 1, tan%np
        sp = 0
        if (j > 1) sp = tan%s_p(k, j - 1)
        ! the levers of the derivatives along the segment, and their offsets at the step's
        ! start (fixed-size copies: no temporaries in the innermost loop)
        dn = le_n(:, k) - ls_n(:, k)
        dt = le_t(:, k) - ls_t(:, k)
        off(1, :) = ls_n(:, k) + s0*dn
        off(2, :) = ls_t(:, k) + s0*dt
        ! the sliders where the tracer sets them as a step starts: contacts that do not
        ! stick on their forces (the states before), then contacts that open or close unloaded
        if (any(slips) .or. any(changed)) then
          call contact_forces(seg, m_old, tan%q_p(:, k), sp, tan%w_p(:, k), g, sv, N, T, off)
          do c = 1, 3
            if (slips(c)) tan%w_p(c, k) = sv(c) + T(c)/geo%kt(c)
            if (changed(c)) tan%w_p(c, k) = sv(c)
          end do
        end if
        dq_p = mat3(Ki, mode_rhs(geo, m_new, dn, dt))
        if (e == 0) then
          ! the target, s = 1 whatever the parameters
          step_p = -sp
        else
          ! the event function f of contact i towards its new state: f + step f' = 0
          call contact_forces(seg, m_new, tan%q_p(:, k), sp, tan%w_p(:, k), g, sv, N, T, off)
          dg_p = -dot_product(geo%bn(:, i), dq_p) + dn(i)
          ds_p = dot_product(geo%bt(:, i), dq_p) - dt(i)
          dN_p = geo%kn(i)*dg_p
          select case (m_new(i))
          case (CONTACT_STICK)
            dT_p = -geo%kt(i)*ds_p
            select case (mod(e, 4))
            case (CONTACT_SLIP_POS)
              fp = geo%mu*N(i) - T(i)
              dfp = geo%mu*dN_p - dT_p
            case (CONTACT_SLIP_NEG)
              fp = geo%mu*N(i) + T(i)
              dfp = geo%mu*dN_p + dT_p
            case default
              fp = N(i)
              dfp = dN_p
            end select
          case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
            fp = N(i)
            dfp = dN_p
          case default
            fp = -geo%kn(i)*g(i)
            dfp = -geo%kn(i)*dg_p
          end select
          step_p = (fp + step*dfp)/lg%rate(j)
        end if
        tan%q_p(:, k) = tan%q_p(:, k) + step_p*dq + step*dq_p
        tan%s_p(k, j) = sp + step_p
      end do
      s0 = lg%s(j)
      m_old = m_new
    end do

  contains

  end subroutine path_tangent_segment

  !> The derivatives A_p(:, side, k) of the damper's actions on its two platforms
  !> (trace_path's platform_actions) at a segment's end, whose coordinates' derivatives have
  !> the contacts' travel (le_n, le_t), in the contact states `mode`.
  subroutine path_tangent_actions(geo, tan, mode, le_n, le_t, A_p)
    type(damper_geometry_type), intent(in) :: geo
    type(path_tangent_type), intent(in) :: tan
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: le_n(3, tan%np), le_t(3, tan%np)
    real(wp), intent(out) :: A_p(:, :, :)
    real(wp) :: off(2, 3), g(3), sv(3), N(3), T(3)
    integer :: k, c
    A_p = 0
    do k = 1, tan%np
      off(1, :) = le_n(:, k)
      off(2, :) = le_t(:, k)
      call contact_forces(geo, mode, tan%q_p(:, k), 0.0_wp, tan%w_p(:, k), g, sv, N, T, off)
      do c = 1, 3
        A_p(:, geo%side(c), k) = A_p(:, geo%side(c), k) + N(c)*geo%pn(:, c) + T(c)*geo%pt(:, c)
      end do
    end do
  end subroutine path_tangent_actions

  !> The contacts' travel along the normal (cn) and the tangent (ct) for both platforms'
  !> coordinates moving by dX (trace_path's lever arms, its offsets, or rates for a velocity).
  pure subroutine contact_levers(geo, dX, cn, ct)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: dX(6)
    real(wp), intent(out) :: cn(3), ct(3)
    integer :: c, m
    do c = 1, 3
      m = 3*(geo%side(c) - 1)
      cn(c) = dot_product(geo%pn(:, c), dX(m+1:m+3))
      ct(c) = dot_product(geo%pt(:, c), dX(m+1:m+3))
    end do
  end subroutine contact_levers

  !> The right-hand side h of the equilibrium's rates for the contacts' travel (cn, ct).
  pure function mode_rhs(geo, mode, cn, ct) result(h)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: cn(3), ct(3)
    real(wp) :: h(3)
    integer :: c
    h = 0
    do c = 1, 3
      select case (mode(c))
      case (CONTACT_STICK)
        h = h + geo%kn(c)*cn(c)*geo%bn(:, c) + geo%kt(c)*ct(c)*geo%bt(:, c)
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        h = h + geo%kn(c)*cn(c)*(geo%bn(:, c) + &
          & merge(1, -1, mode(c) == CONTACT_SLIP_POS)*geo%mu*geo%bt(:, c))
      end select
    end do
  end function mode_rhs

  !> The contact forces' rates (dN, dT) in the contact states `mode` for the contacts'
  !> travel (cn, ct), Ki the inverse of mode_stiffness (compute_rates with K inverted once).
  pure subroutine mode_rates(geo, mode, Ki, cn, ct, dN, dT)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: Ki(3, 3), cn(3), ct(3)
    real(wp), intent(out) :: dN(3), dT(3)
    type(damper_geometry_type) :: arc
    real(wp) :: g(3), s(3)
    ! the forces' law applied to the rates (linear and homogeneous), with the levers (cn, ct)
    arc = geo
    arc%cn = cn
    arc%ct = ct
    call contact_forces(arc, mode, mat3(Ki, mode_rhs(geo, mode, cn, ct)), 1.0_wp, &
      & [0.0_wp, 0.0_wp, 0.0_wp], g, s, dN, dT)
  end subroutine mode_rates

  !> A x for a 3x3 A, without the temporaries of matmul on expressions.
  pure function mat3(A, x) result(y)
    real(wp), intent(in) :: A(3, 3), x(3)
    real(wp) :: y(3)
    y = A(:, 1)*x(1) + A(:, 2)*x(2) + A(:, 3)*x(3)
  end function mat3

  !> The inverse of a 3x3 matrix by cofactors; ok is false if it is numerically singular.
  pure subroutine invert3(A, Ai, ok)
    real(wp), intent(in) :: A(3, 3)
    real(wp), intent(out) :: Ai(3, 3)
    logical, intent(out) :: ok
    real(wp) :: C(3, 3), det
    call cofactors3(A, C, det, ok)
    Ai = 0
    if (ok) Ai = transpose(C)/det
  end subroutine invert3
end module udmap_damper_tracer_tangent
