!> Parameters of the asymmetric flat/curved rigid damper (PHYSICS.md 2.1) and their checks.
module udmap_damper_params
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, require
  implicit none
  private
  public :: asymmetric_params_type, check_asymmetric_params, blade_a_damper_params

  !> The asymmetric damper as the case file gives it (SI units, angles in degrees).
  type :: asymmetric_params_type
    !> Centrifugal load on the damper [N] and friction coefficient of all contacts.
    real(wp) :: CF = 0, mu = 0
    !> Blade pitch [m] and radial position of the platform centres P_L, P_R [m].
    real(wp) :: pitch = 0, y_P = 0
    !> Inclinations of the flat (left) and curved (right) platform faces [deg].
    real(wp) :: beta_L_deg = 0, beta_R_deg = 0
    !> flat(:,i) = (x, y) of flat point i [m], in the damper frame (origin at G).
    real(wp) :: flat(2,2) = 0
    !> (x, y) of the curved point [m].
    real(wp) :: curved(2) = 0
    !> Normal and tangential contact stiffnesses [N/m].
    real(wp) :: kn_flat = 0, kt_flat = 0, kn_curved = 0, kt_curved = 0
  end type asymmetric_params_type

contains

  !> The damper of the reference case blade_a (cases/blade_a.json).
  pure function blade_a_damper_params() result(params)
    type(asymmetric_params_type) :: params
    params%CF = 900.0_wp
    params%mu = 0.3_wp
    params%pitch = 0.026_wp
    params%y_P = 0.006_wp
    params%beta_L_deg = 45.0_wp
    params%beta_R_deg = 45.0_wp
    params%flat(:,1) = [-6.724e-3_wp, -1.724e-3_wp]
    params%flat(:,2) = [-1.068e-3_wp, 3.932e-3_wp]
    params%curved = [3.268e-3_wp, 1.768e-3_wp]
    params%kn_flat = 60e6_wp
    params%kt_flat = 40e6_wp
    params%kn_curved = 80e6_wp
    params%kt_curved = 50e6_wp
  end function blade_a_damper_params

  !> Rejects NaN, infinite, negative or degenerate parameters with a message naming the field.
  pure subroutine check_asymmetric_params(params, error)
    type(asymmetric_params_type), intent(in) :: params
    type(error_type), allocatable, intent(out) :: error

    call positive("CF", params%CF, error)
    call positive("mu", params%mu, error)
    call positive("pitch", params%pitch, error)
    call finite("y_P", params%y_P, error)
    call angle("beta_L_deg", params%beta_L_deg, error)
    call angle("beta_R_deg", params%beta_R_deg, error)
    call finite("flat_points[0][0] (flat1_x)", params%flat(1,1), error)
    call finite("flat_points[0][1] (flat1_y)", params%flat(2,1), error)
    call finite("flat_points[1][0] (flat2_x)", params%flat(1,2), error)
    call finite("flat_points[1][1] (flat2_y)", params%flat(2,2), error)
    call finite("curved_point[0] (curved_x)", params%curved(1), error)
    call finite("curved_point[1] (curved_y)", params%curved(2), error)
    call positive("kn_flat", params%kn_flat, error)
    call positive("kt_flat", params%kt_flat, error)
    call positive("kn_curved", params%kn_curved, error)
    call positive("kt_curved", params%kt_curved, error)
    call require(any(params%flat(:,1) /= params%flat(:,2)), &
      & "damper parameter 'flat_points': the two flat points coincide", error)
  end subroutine check_asymmetric_params

  pure logical function is_finite(x)
    real(wp), intent(in) :: x
    is_finite = x == x .and. abs(x) <= huge(x)
  end function is_finite

  !> The checks of one field, as a series of `require` (the first failure is kept).
  pure subroutine finite(name, x, error)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_type), allocatable, intent(inout) :: error
    call require(is_finite(x), "damper parameter '"//name//"' is not a finite number", error)
  end subroutine finite

  pure subroutine positive(name, x, error)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_type), allocatable, intent(inout) :: error
    call finite(name, x, error)
    call require(x > 0, "damper parameter '"//name//"' must be positive", error)
  end subroutine positive

  pure subroutine angle(name, x, error)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_type), allocatable, intent(inout) :: error
    call finite(name, x, error)
    call require(x >= 0 .and. x < 90, "damper parameter '"//name// &
      & "' must lie in [0, 90) degrees", error)
  end subroutine angle
end module udmap_damper_params
