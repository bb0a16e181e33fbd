!> The rotational Jenkins element on gamma_P (PHYSICS.md 2.4, damper kind "jenkins").
module udmap_damper_jenkins
  use udmap_core_kinds, only: wp, pi
  implicit none
  private
  public :: jenkins_stiffness, jenkins_loop_moment

contains

  !> Describing function of a Jenkins element (stiffness kt [N m/rad], slip moment M_slip [N m])
  !> at amplitude a [rad]: k = kt for a <= a_s = M_slip/kt, else with cos(beta) = 1 - 2 a_s/a
  !> k_Re = (kt/pi)(beta - sin(2 beta)/2), k_Im = (4 M_slip/(pi a))(1 - a_s/a). With
  !> derivative = .true. its derivative dk/da instead (0 below a_s).
  elemental function jenkins_stiffness(kt, M_slip, a, derivative) result(k)
    real(wp), intent(in) :: kt, M_slip, a
    logical, intent(in), optional :: derivative
    complex(wp) :: k
    real(wp) :: a_s, beta
    logical :: slope
    slope = .false.
    if (present(derivative)) slope = derivative
    a_s = M_slip/kt
    if (.not. (a > a_s)) then
      if (slope) then
        k = 0
      else
        k = cmplx(kt, 0.0_wp, wp)
      end if
      return
    end if
    beta = half_angle(a_s/a)
    if (slope) then
      k = cmplx(-4*kt*a_s*sin(beta)/(pi*a**2), (4*M_slip/pi)*(2*a_s/a**3 - 1/a**2), wp)
    else
      k = cmplx((kt/pi)*(beta - sin(2*beta)/2), (4*M_slip/(pi*a))*(1 - a_s/a), wp)
    end if
  end function jenkins_stiffness

  !> Steady loop M(tau) for gamma = a cos(tau) after the history of PHYSICS.md 2.1 (virgin
  !> slider, ramp to +a, cycles): elastic below a_s, else branches of slope kt between
  !> the plateaus +-M_slip.
  elemental function jenkins_loop_moment(kt, M_slip, a, tau) result(M)
    real(wp), intent(in) :: kt, M_slip, a, tau
    real(wp) :: M
    real(wp) :: t
    if (.not. (a > M_slip/kt)) then
      M = kt*a*cos(tau)
      return
    end if
    t = modulo(tau, 2*pi)
    if (t <= pi) then
      M = max(M_slip - kt*2*a*sin(t/2)**2, -M_slip)
    else
      M = min(-M_slip + kt*2*a*cos(t/2)**2, M_slip)
    end if
  end function jenkins_loop_moment

  !> beta in [0, pi] with cos(beta) = 1 - 2x, accurate at both ends.
  elemental real(wp) function half_angle(x) result(beta)
    real(wp), intent(in) :: x
    if (x <= 0.5_wp) then
      beta = 2*asin(sqrt(x))
    else
      beta = pi - 2*asin(sqrt(1 - x))
    end if
  end function half_angle
end module udmap_damper_jenkins
