!> The rotational Jenkins element (PHYSICS.md 2.4) as a hysteretic element: spring kt in series
!> with a slider of limit M_slip, exact along any path (the time-domain face of
!> udmap_damper_jenkins).
module udmap_contact_element_jenkins
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_contact_element, only: hysteretic_element_type, event_list_type
  implicit none
  private
  public :: jenkins_element_type, new_jenkins_element

  !> Rotational Jenkins element: spring kt in series with a slider of limit M_slip.
  type, extends(hysteretic_element_type) :: jenkins_element_type
    real(wp) :: kt = 0.0_wp        !< spring stiffness [N m/rad]
    real(wp) :: M_slip = 0.0_wp    !< slip moment [N m]
    real(wp) :: w = 0.0_wp         !< slider position [rad]
    real(wp) :: g = 0.0_wp         !< current gamma [rad]
    real(wp) :: M = 0.0_wp         !< current moment [N m]
  contains
    procedure :: load => jenkins_load
    procedure :: advance => jenkins_advance
    procedure :: copy_state => jenkins_copy_state
    procedure :: same_state => jenkins_same_state
    procedure :: stuck_stiffness => jenkins_stuck_stiffness
    procedure :: gamma => jenkins_gamma
    procedure :: moment => jenkins_moment
  end type jenkins_element_type

contains

  !> A Jenkins element with stiffness kt [N m/rad] and slip moment M_slip [N m], virgin state.
  subroutine new_jenkins_element(element, kt, M_slip, error)
    type(jenkins_element_type), intent(out) :: element
    real(wp), intent(in) :: kt, M_slip
    type(error_type), allocatable, intent(out) :: error
    if (.not.(kt >= 0.0_wp) .or. kt > huge(1.0_wp)) then
      call fatal_error(error, "jenkins element: kt must be finite and >= 0", UDMAP_EINPUT)
      return
    end if
    if (.not.(M_slip >= 0.0_wp) .or. M_slip > huge(1.0_wp)) then
      call fatal_error(error, "jenkins element: M_slip must be finite and >= 0", UDMAP_EINPUT)
      return
    end if
    element%kt = kt
    element%M_slip = M_slip
  end subroutine new_jenkins_element

  subroutine jenkins_load(self, error)
    class(jenkins_element_type), intent(inout) :: self
    type(error_type), allocatable, intent(out) :: error
    ! No centrifugal preload in this element: the loaded state is the virgin one.
    self%w = 0.0_wp
    self%g = 0.0_wp
    self%M = 0.0_wp
  end subroutine jenkins_load

  subroutine jenkins_advance(self, gamma_target, M_r, k_t, error, events)
    class(jenkins_element_type), intent(inout) :: self
    real(wp), intent(in) :: gamma_target
    real(wp), intent(out) :: M_r, k_t
    type(error_type), allocatable, intent(out) :: error
    type(event_list_type), intent(inout), optional :: events
    real(wp) :: trial, s, gamma_e
    if (.not.(abs(gamma_target) <= huge(1.0_wp))) then
      call fatal_error(error, "jenkins element: gamma is not finite", UDMAP_EINPUT)
      M_r = 0.0_wp
      k_t = 0.0_wp
      return
    end if
    trial = self%kt*(gamma_target - self%w)
    if (abs(trial) <= self%M_slip) then
      self%M = trial
      k_t = self%kt
    else
      s = sign(1.0_wp, trial)
      ! the spring reaches the slip limit at gamma_e, after which the moment stays s*M_slip
      gamma_e = self%w + s*self%M_slip/self%kt
      if (present(events)) then
        if ((gamma_e - self%g)*s > 0.0_wp) call events%push(gamma_e, s*self%M_slip)
      end if
      self%w = gamma_target - s*self%M_slip/self%kt
      self%M = s*self%M_slip
      k_t = 0.0_wp
    end if
    self%g = gamma_target
    M_r = self%M
  end subroutine jenkins_advance

  subroutine jenkins_copy_state(self, other)
    class(jenkins_element_type), intent(inout) :: self
    class(hysteretic_element_type), intent(in) :: other
    select type (other)
    type is (jenkins_element_type)
      self%w = other%w
      self%g = other%g
      self%M = other%M
    end select
  end subroutine jenkins_copy_state

  logical function jenkins_same_state(self, other, rtol)
    class(jenkins_element_type), intent(in) :: self
    class(hysteretic_element_type), intent(in) :: other
    real(wp), intent(in) :: rtol
    real(wp) :: scale
    jenkins_same_state = .false.
    select type (other)
    type is (jenkins_element_type)
      scale = max(abs(self%w), abs(other%w), abs(self%g), tiny(1.0_wp))
      if (self%kt > 0.0_wp) scale = max(scale, self%M_slip/self%kt)
      jenkins_same_state = abs(self%w - other%w) <= rtol*scale .and. &
        & abs(self%g - other%g) <= rtol*scale
    end select
  end function jenkins_same_state

  real(wp) function jenkins_stuck_stiffness(self)
    class(jenkins_element_type), intent(in) :: self
    jenkins_stuck_stiffness = self%kt
  end function jenkins_stuck_stiffness

  real(wp) function jenkins_gamma(self)
    class(jenkins_element_type), intent(in) :: self
    jenkins_gamma = self%g
  end function jenkins_gamma

  real(wp) function jenkins_moment(self)
    class(jenkins_element_type), intent(in) :: self
    jenkins_moment = self%M
  end function jenkins_moment
end module udmap_contact_element_jenkins
