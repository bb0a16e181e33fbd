!> The damper seen by the standard method, the time integration and the multi-harmonic layers: a
!> rate-independent hysteretic element on the platform rotation gamma, driven along a path gamma(t)
!> with its loading history, returning the restoring moment M_r (PHYSICS.md 2.1: the moment the
!> damper exerts on the blade is -M_r; for a linear damper M_r = k gamma).
!>
!> Implementations: the rotational Jenkins element (PHYSICS.md 2.4) here; the asymmetric
!> contact model in udmap_contact_element.
module udmap_hysteretic
  use udmap_kinds, only: wp
  use udmap_error, only: error_type, fatal_error, UDMAP_EINPUT
  implicit none
  private
  public :: hysteretic_element_type, event_list_type, jenkins_element_type, new_jenkins_element

  !> Breakpoints (gamma, M_r) of the piecewise-linear M_r(gamma) crossed along a monotone path.
  type :: event_list_type
    integer :: n = 0                          !< number of events stored
    real(wp), allocatable :: gamma(:)         !< gamma at each event [rad]
    real(wp), allocatable :: M(:)             !< M_r at each event [N m]
  contains
    !> Appends one event, growing the storage when needed.
    procedure :: push => event_list_push
  end type event_list_type

  !> A quasi-static, rate-independent element on gamma with internal state (sliders, contacts).
  type, abstract :: hysteretic_element_type
    !> A contact opened (lift-off, PHYSICS.md 2.3) since the last load or clear_flags.
    logical :: lift_off = .false.
  contains
    !> Virgin state and the centrifugal-load ramp at gamma = 0 (history steps 0 and 1).
    procedure(load_interface), deferred :: load
    !> Exact quasi-static path from the current gamma to gamma_target (monotone travel).
    procedure(advance_interface), deferred :: advance
    !> Copies the state (not the parameters) of another element of the same kind.
    procedure(copy_state_interface), deferred :: copy_state
    !> Whether the state equals another element's state within rtol (loop closure test).
    procedure(same_state_interface), deferred :: same_state
    !> Tangent stiffness dM_r/dgamma of the loaded state at gamma = 0 (stuck damper).
    procedure(scalar_interface), deferred :: stuck_stiffness
    !> Current gamma [rad] and M_r [N m].
    procedure(scalar_interface), deferred :: gamma
    procedure(scalar_interface), deferred :: moment
    !> Whether a contact opened (lift-off, PHYSICS.md 2.3) since the last load or clear_flags.
    procedure :: lifted => element_lifted
    !> Forgets the lift-off flag.
    procedure :: clear_flags => element_clear_flags
  end type hysteretic_element_type

  abstract interface
    subroutine load_interface(self, error)
      import :: hysteretic_element_type, error_type
      class(hysteretic_element_type), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
    end subroutine load_interface
    !> M_r and the tangent k_t = dM_r/dgamma at gamma_target in the direction of travel;
    !> events (if present) receives the breakpoints strictly between start and target.
    subroutine advance_interface(self, gamma_target, M_r, k_t, error, events)
      import :: hysteretic_element_type, error_type, event_list_type, wp
      class(hysteretic_element_type), intent(inout) :: self
      real(wp), intent(in) :: gamma_target
      real(wp), intent(out) :: M_r, k_t
      type(error_type), allocatable, intent(out) :: error
      type(event_list_type), intent(inout), optional :: events
    end subroutine advance_interface
    subroutine copy_state_interface(self, other)
      import :: hysteretic_element_type
      class(hysteretic_element_type), intent(inout) :: self
      class(hysteretic_element_type), intent(in) :: other
    end subroutine copy_state_interface
    logical function same_state_interface(self, other, rtol)
      import :: hysteretic_element_type, wp
      class(hysteretic_element_type), intent(in) :: self, other
      real(wp), intent(in) :: rtol
    end function same_state_interface
    real(wp) function scalar_interface(self)
      import :: hysteretic_element_type, wp
      class(hysteretic_element_type), intent(in) :: self
    end function scalar_interface
  end interface

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

  pure subroutine event_list_push(self, gamma, M)
    class(event_list_type), intent(inout) :: self
    real(wp), intent(in) :: gamma, M
    real(wp), allocatable :: tmp(:)
    if (.not.allocated(self%gamma)) then
      allocate(self%gamma(16), self%M(16))
    else if (self%n >= size(self%gamma)) then
      allocate(tmp(2*size(self%gamma)))
      tmp(1:self%n) = self%gamma(1:self%n)
      call move_alloc(tmp, self%gamma)
      allocate(tmp(2*size(self%M)))
      tmp(1:self%n) = self%M(1:self%n)
      call move_alloc(tmp, self%M)
    end if
    self%n = self%n + 1
    self%gamma(self%n) = gamma
    self%M(self%n) = M
  end subroutine event_list_push

  logical function element_lifted(self)
    class(hysteretic_element_type), intent(in) :: self
    element_lifted = self%lift_off
  end function element_lifted

  subroutine element_clear_flags(self)
    class(hysteretic_element_type), intent(inout) :: self
    self%lift_off = .false.
  end subroutine element_clear_flags

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
end module udmap_hysteretic
