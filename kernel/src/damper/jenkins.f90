!> The rotational Jenkins element on gamma_P (PHYSICS.md 2.4, damper kind "jenkins").
module udmap_damper_jenkins
  use udmap_core_kinds, only: wp, pi
  implicit none
  private
  public :: jenkins_stiffness, jenkins_stiffness_derivative, jenkins_loop_moment

contains

  !> Describing function of a Jenkins element (stiffness kt [N m/rad], slip moment M_slip [N m])
  !> at amplitude a [rad]: k = kt for a <= a_s = M_slip/kt, else with cos(beta) = 1 - 2 a_s/a
  !> k_Re = (kt/pi)(beta - sin(2 beta)/2), k_Im = (4 M_slip/(pi a))(1 - a_s/a).
  elemental function jenkins_stiffness(kt, M_slip, a) result(k)
    real(wp), intent(in) :: kt, M_slip, a
    complex(wp) :: k
    real(wp) :: a_s, beta
    a_s = M_slip/kt
    if (.not. (a > a_s)) then
      k = cmplx(kt, 0.0_wp, wp)
      return
    end if
    beta = half_angle(a_s/a)
    k = cmplx((kt/pi)*(beta - sin(2*beta)/2), (4*M_slip/(pi*a))*(1 - a_s/a), wp)
  end function jenkins_stiffness

  !> dk/da of jenkins_stiffness (0 below a_s).
  elemental function jenkins_stiffness_derivative(kt, M_slip, a) result(dk)
    real(wp), intent(in) :: kt, M_slip, a
    complex(wp) :: dk
    real(wp) :: a_s, beta
    a_s = M_slip/kt
    if (.not. (a > a_s)) then
      dk = 0
      return
    end if
    beta = half_angle(a_s/a)
    dk = cmplx(-4*kt*a_s*sin(beta)/(pi*a**2), (4*M_slip/pi)*(2*a_s/a**3 - 1/a**2), wp)
  end function jenkins_stiffness_derivative

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
