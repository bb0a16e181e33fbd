!> The asymmetric flat/curved damper (PHYSICS.md 2.1) as a hysteretic element for the standard
!> method, the time integration and the multi-harmonic layers: the exact event-driven tracer of
!> udmap_damper_tracer driven along gamma, the loaded state (virgin state and CF ramp) computed
!> once and restored by load, the stick/slip/open transitions on the way returned as events (M_r is
!> affine in gamma between them), the tangent of the last segment, and the lift-off flag. The stuck
!> stiffness (the starting guess of the standard method) is the first harmonic of a tiny loop.
module udmap_contact_element_asymmetric
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_damper_params, only: asymmetric_params_type
  use udmap_damper_tracer_core, only: damper_geometry_type, damper_state_type, &
    & branch_record_type, equilibrium_cache_type, rates_cache_type, contact_forces, CONTACT_OPEN
  use udmap_damper_tracer, only: new_damper_geometry, virgin_state, ramp_CF, trace_gamma, &
    & restoring_moment, reset_record, record_start
  use udmap_contact_element, only: hysteretic_element_type, event_list_type
  use udmap_contact_aft_moment, only: aft_workspace_type, aft_moment
  implicit none
  private
  public :: contact_element_type, new_contact_element

  !> The asymmetric damper driven along gamma.
  type, extends(hysteretic_element_type) :: contact_element_type
    type(damper_geometry_type) :: geo
    !> State after the CF ramp at gamma = 0 (history steps 0 and 1), and the current state.
    type(damper_state_type) :: loaded, state
    !> Stuck stiffness (first harmonic of a tiny loop) [N m/rad].
    real(wp) :: k_stuck = 0.0_wp
    !> Force scale of the state comparisons: the centrifugal load [N].
    real(wp) :: F_scale = 1.0_wp
    !> Vertices of the last traced path (kept to avoid allocations).
    type(branch_record_type) :: rec
    !> The equilibrium matrices of the damper's contact states met so far (its geometry is
    !> fixed: the same arithmetic, kept).
    type(equilibrium_cache_type) :: eqc
    !> The rates of those contact states in gamma (the same arithmetic, kept).
    type(rates_cache_type) :: rates
  contains
    procedure :: load => contact_load
    procedure :: advance => contact_advance
    procedure :: copy_state => contact_copy_state
    procedure :: same_state => contact_same_state
    procedure :: stuck_stiffness => contact_stuck_stiffness
    procedure :: gamma => contact_gamma
    procedure :: moment => contact_moment
  end type contact_element_type

contains

  !> The element of the damper `params`: geometry, CF ramp from the virgin state, and the stuck
  !> tangent from a small excursion.
  subroutine new_contact_element(element, params, error)
    type(contact_element_type), intent(out) :: element
    type(asymmetric_params_type), intent(in) :: params
    type(error_type), allocatable, intent(out) :: error
    type(aft_workspace_type) :: ws
    complex(wp) :: G(1), M(1)
    real(wp) :: dg, M0
    call new_damper_geometry(element%geo, params, error)
    if (allocated(error)) return
    element%F_scale = params%CF
    call virgin_state(element%geo, element%loaded)
    call ramp_CF(element%geo, element%loaded, params%CF, error)
    if (allocated(error)) return
    element%state = element%loaded
    element%k_stuck = 0.0_wp
    ! stuck stiffness: the first harmonic of a loop far below any slip (after the ramp the
    ! contacts may sit on their cones, so the first tangent is not the stuck one)
    dg = 1.0e-6_wp*params%CF/max(element%geo%rate_scale, tiny(1.0_wp))
    G = cmplx(dg, 0.0_wp, wp)
    call aft_moment(element, ws, 0.0_wp, G, 0, 1, 8, 1.0e-12_wp, M0, M, error)
    if (allocated(error)) return
    element%k_stuck = real(M(1), wp)/dg
    element%state = element%loaded
    element%lift_off = .false.
  end subroutine new_contact_element

  subroutine contact_load(self, error)
    class(contact_element_type), intent(inout) :: self
    type(error_type), allocatable, intent(out) :: error
    self%state = self%loaded
    self%lift_off = .false.
  end subroutine contact_load

  subroutine contact_advance(self, gamma_target, M_r, k_t, error, events)
    class(contact_element_type), intent(inout) :: self
    real(wp), intent(in) :: gamma_target
    real(wp), intent(out) :: M_r, k_t
    type(error_type), allocatable, intent(out) :: error
    type(event_list_type), intent(inout), optional :: events
    integer :: j
    k_t = self%k_stuck
    if (gamma_target == self%state%gamma) then
      M_r = restoring_moment(self%geo, self%state)
      return
    end if
    call reset_record(self%rec)
    call record_start(self%geo, self%state, self%rec)
    call trace_gamma(self%geo, self%state, gamma_target, 0.0_wp, error, self%rec, cache=self%eqc, &
      & rates=self%rates)
    if (allocated(error)) then
      M_r = 0.0_wp
      return
    end if
    M_r = restoring_moment(self%geo, self%state)
    if (self%rec%n >= 2) k_t = self%rec%slope(self%rec%n)
    if (self%rec%opened .or. any(self%state%mode == CONTACT_OPEN)) self%lift_off = .true.
    if (present(events)) then
      ! vertices strictly between the start (1) and the target (n)
      do j = 2, self%rec%n - 1
        call events%push(self%rec%gamma(j), self%rec%M(j))
      end do
    end if
  end subroutine contact_advance

  subroutine contact_copy_state(self, other)
    class(contact_element_type), intent(inout) :: self
    class(hysteretic_element_type), intent(in) :: other
    select type (other)
    type is (contact_element_type)
      self%state = other%state
      self%lift_off = other%lift_off
    end select
  end subroutine contact_copy_state

  !> Same contact states and forces (both states of this damper: copies made by copy_state carry
  !> no geometry): the future path is then the same (the sliders of slipping
  !> contacts are only refreshed when the tracer moves on, so they are not compared).
  logical function contact_same_state(self, other, rtol)
    class(contact_element_type), intent(in) :: self
    class(hysteretic_element_type), intent(in) :: other
    real(wp), intent(in) :: rtol
    real(wp) :: g(3), sd(3), Na(3), Ta(3), Nb(3), Tb(3)
    contact_same_state = .false.
    select type (other)
    type is (contact_element_type)
      if (any(self%state%mode /= other%state%mode)) return
      if (self%state%gamma /= other%state%gamma) return
      call contact_forces(self%geo, self%state%mode, self%state%q, self%state%gamma, &
        & self%state%w, g, sd, Na, Ta)
      call contact_forces(self%geo, other%state%mode, other%state%q, other%state%gamma, &
        & other%state%w, g, sd, Nb, Tb)
      contact_same_state = all(abs(Na - Nb) <= rtol*self%F_scale) .and. &
        & all(abs(Ta - Tb) <= rtol*self%F_scale)
    end select
  end function contact_same_state

  real(wp) function contact_stuck_stiffness(self)
    class(contact_element_type), intent(in) :: self
    contact_stuck_stiffness = self%k_stuck
  end function contact_stuck_stiffness

  real(wp) function contact_gamma(self)
    class(contact_element_type), intent(in) :: self
    contact_gamma = self%state%gamma
  end function contact_gamma

  real(wp) function contact_moment(self)
    class(contact_element_type), intent(in) :: self
    contact_moment = restoring_moment(self%geo, self%state)
  end function contact_moment
end module udmap_contact_element_asymmetric
