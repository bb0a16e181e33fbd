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
    & compute_rates, rates_type, code_modes, CONTACT_OPEN, CONTACT_STICK, CONTACT_SLIP_POS, &
    & CONTACT_SLIP_NEG
  use udmap_damper_tracer, only: along
  implicit none
  private
  public :: path_tangent_type, new_path_tangent, path_tangent_segment, path_tangent_actions

  !> The derivatives of the damper's state along a path, one column a parameter.
  type :: path_tangent_type
    integer :: np = 0
    !> Damper DOFs and sliders at the current point.
    real(wp), allocatable :: q_p(:, :), w_p(:, :)
    !> s_p(:, j): derivatives of the place (fraction of the segment) of the last segment's
    !> vertex j, the end of its step j.
    real(wp), allocatable :: s_p(:, :)
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

  !> The derivatives carried along the segment of trace_path from X_from to X_to that left
  !> the log lg and started in the contact states `entry` (mode_code), the segment's ends
  !> moving by Xs_p(:, k) and Xe_p(:, k) per unit of parameter k.
  subroutine path_tangent_segment(geo, tan, X_from, X_to, Xs_p, Xe_p, entry, lg)
    type(damper_geometry_type), intent(in) :: geo
    type(path_tangent_type), intent(inout) :: tan
    real(wp), intent(in) :: X_from(6), X_to(6), Xs_p(:, :), Xe_p(:, :)
    integer, intent(in) :: entry
    type(mode_log_type), intent(in) :: lg
    type(damper_geometry_type) :: seg, segp(tan%np)
    type(rates_type) :: rt, rtp
    real(wp) :: s0, step, step_p, fp, dfp, off(2, 3), g(3), sv(3), N(3), T(3)
    real(wp), allocatable :: tmp(:, :)
    integer :: m_old(3), m_new(3), j, k, i, e
    logical :: ok, changed(3)

    if (lg%n == 0) return
    if (size(tan%s_p, 2) < lg%n) then
      allocate(tmp(tan%np, 2*lg%n))
      call move_alloc(tmp, tan%s_p)
    end if
    seg = along(geo, X_to - X_from)
    do k = 1, tan%np
      segp(k) = along(geo, Xe_p(:, k) - Xs_p(:, k))
    end do
    m_old = code_modes(entry)
    s0 = 0
    do j = 1, lg%n
      m_new = code_modes(lg%code(j))
      changed = (m_old == CONTACT_OPEN) .neqv. (m_new == CONTACT_OPEN)
      call compute_rates(seg, m_new, 1.0_wp, 0.0_wp, rt, ok)
      step = lg%s(j) - s0
      e = lg%event(j)
      do k = 1, tan%np
        off = offsets(Xs_p(:, k) + s0*(Xe_p(:, k) - Xs_p(:, k)))
        ! the sliders where the tracer sets them as a step starts: contacts that do not
        ! stick on their forces (the states before), then contacts that open or close unloaded
        if (any(m_old /= CONTACT_STICK)) then
          call contact_forces(seg, m_old, tan%q_p(:, k), sp(), tan%w_p(:, k), g, sv, N, T, off)
          where (m_old /= CONTACT_STICK) tan%w_p(:, k) = sv + T/geo%kt
        end if
        if (any(changed)) then
          call contact_forces(seg, m_new, tan%q_p(:, k), sp(), tan%w_p(:, k), g, sv, N, T, off)
          where (changed) tan%w_p(:, k) = sv
        end if
        call compute_rates(segp(k), m_new, 1.0_wp, 0.0_wp, rtp, ok)
        if (e == 0) then
          ! the target, s = 1 whatever the parameters
          step_p = -sp()
        else
          ! the event function f of contact i towards its new state: f + step f' = 0
          i = e/4
          call contact_forces(seg, m_new, tan%q_p(:, k), sp(), tan%w_p(:, k), g, sv, N, T, off)
          select case (m_new(i))
          case (CONTACT_STICK)
            select case (mod(e, 4))
            case (CONTACT_SLIP_POS)
              fp = geo%mu*N(i) - T(i)
              dfp = geo%mu*rtp%dN(i) - rtp%dT(i)
            case (CONTACT_SLIP_NEG)
              fp = geo%mu*N(i) + T(i)
              dfp = geo%mu*rtp%dN(i) + rtp%dT(i)
            case default
              fp = N(i)
              dfp = rtp%dN(i)
            end select
          case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
            fp = N(i)
            dfp = rtp%dN(i)
          case default
            fp = -geo%kn(i)*g(i)
            dfp = -geo%kn(i)*rtp%dg(i)
          end select
          step_p = (fp + step*dfp)/lg%rate(j)
        end if
        tan%q_p(:, k) = tan%q_p(:, k) + step_p*rt%dq + step*rtp%dq
        tan%s_p(k, j) = sp() + step_p
      end do
      s0 = lg%s(j)
      m_old = m_new
    end do

  contains

    !> The derivative of the place of the current vertex (the last step's end).
    real(wp) function sp()
      sp = 0
      if (j > 1) sp = tan%s_p(k, j - 1)
    end function sp

    !> The offsets of trace_path's state for the coordinates' derivatives X_p.
    pure function offsets(X_p) result(o)
      real(wp), intent(in) :: X_p(6)
      real(wp) :: o(2, 3)
      integer :: c, m
      do c = 1, 3
        m = 3*(geo%side(c) - 1)
        o(1, c) = dot_product(geo%pn(:, c), X_p(m+1:m+3))
        o(2, c) = dot_product(geo%pt(:, c), X_p(m+1:m+3))
      end do
    end function offsets
  end subroutine path_tangent_segment

  !> The derivatives A_p(:, side, k) of the damper's actions on its two platforms
  !> (trace_path's platform_actions) at a segment's end, the coordinates moving by X_p(:, k),
  !> in the contact states `mode`.
  subroutine path_tangent_actions(geo, tan, mode, X_p, A_p)
    type(damper_geometry_type), intent(in) :: geo
    type(path_tangent_type), intent(in) :: tan
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: X_p(:, :)
    real(wp), intent(out) :: A_p(:, :, :)
    real(wp) :: off(2, 3), g(3), sv(3), N(3), T(3)
    integer :: k, c, m
    A_p = 0
    do k = 1, tan%np
      do c = 1, 3
        m = 3*(geo%side(c) - 1)
        off(1, c) = dot_product(geo%pn(:, c), X_p(m+1:m+3, k))
        off(2, c) = dot_product(geo%pt(:, c), X_p(m+1:m+3, k))
      end do
      call contact_forces(geo, mode, tan%q_p(:, k), 0.0_wp, tan%w_p(:, k), g, sv, N, T, off)
      do c = 1, 3
        A_p(:, geo%side(c), k) = A_p(:, geo%side(c), k) + N(c)*geo%pn(:, c) + T(c)*geo%pt(:, c)
      end do
    end do
  end subroutine path_tangent_actions
end module udmap_damper_tracer_tangent
