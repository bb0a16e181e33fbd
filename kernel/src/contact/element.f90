!> The damper seen by the standard method, the time integration and the multi-harmonic layers: a
!> rate-independent hysteretic element on the platform rotation gamma, driven along a path gamma(t)
!> with its loading history, returning the restoring moment M_r (PHYSICS.md 2.1: the moment the
!> damper exerts on the blade is -M_r; for a linear damper M_r = k gamma).
!>
!> Implementations: the rotational Jenkins element (PHYSICS.md 2.4) in
!> udmap_contact_element_jenkins; the asymmetric contact model in udmap_contact_element_asymmetric.
module udmap_contact_element
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  implicit none
  private
  public :: hysteretic_element_type, event_list_type

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
end module udmap_contact_element
