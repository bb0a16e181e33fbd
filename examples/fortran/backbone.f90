!> Blade A with its asymmetric damper through the derived-type API (use udmap): the damper's
!> stiffness table, the limit force, the backbone (resonance peaks) for three forces, the
!> response at a given frequency and a response curve, with errors as values.
!> Build: examples/fortran/CMakeLists.txt (find_package(udmap)), or
!>        gfortran backbone.f90 $(pkg-config --cflags --libs udmap)
program backbone_example
  use udmap, only: wp, error_type, udmap_version, beam_params_type, blade_type, &
    & new_beam_blade, asymmetric_params_type, damper_type, new_asymmetric_damper, &
    & analysis_type, model_type, point_type, curve_type, new_model, limit_force, backbone, &
    & response, response_curves, stiffness_table
  implicit none
  type(beam_params_type) :: beam
  type(asymmetric_params_type) :: contact
  type(analysis_type) :: analysis
  type(blade_type), target :: blade      ! the model borrows blade and damper
  type(damper_type), target :: damper
  type(model_type) :: model
  type(point_type), allocatable :: points(:)
  type(curve_type), allocatable :: curves(:)
  type(error_type), allocatable :: error
  real(wp), parameter :: forces(3) = [1.0_wp, 2.0_wp, 5.0_wp], f_exc = 196.0_wp
  real(wp), parameter :: gammas(3) = [1.0e-4_wp, 5.0e-4_wp, 2.0e-3_wp]
  real(wp) :: F_lim
  complex(wp) :: k(size(gammas))
  integer :: i

  ! blade A and its damper (cases/blade_a.json)
  beam = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, &
    & neck_L=0.020_wp, neck_h=0.008_wp, neck_b=0.020_wp, &
    & platform_L=0.010_wp, platform_m=0.021_wp, platform_J=1.4e-6_wp, &
    & airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
    & neck_elements=8, airfoil_elements=24)
  contact = asymmetric_params_type(CF=900.0_wp, mu=0.3_wp, pitch=0.026_wp, y_P=0.006_wp, &
    & beta_L_deg=45.0_wp, beta_R_deg=45.0_wp, &
    & flat=reshape([-6.724e-3_wp, -1.724e-3_wp, -1.068e-3_wp, 3.932e-3_wp], [2, 2]), &
    & curved=[3.268e-3_wp, 1.768e-3_wp], &
    & kn_flat=60e6_wp, kt_flat=40e6_wp, kn_curved=80e6_wp, kt_curved=50e6_wp)
  analysis%f_min = 150.0_wp
  analysis%f_max = 230.0_wp

  call new_beam_blade(blade, beam, error)
  if (allocated(error)) call fail("blade")
  call new_asymmetric_damper(damper, contact, error)
  if (allocated(error)) call fail("damper")
  call new_model(model, blade, damper, analysis, error)
  if (allocated(error)) call fail("model")

  print '(a)', "udmap "//udmap_version()//", blade A"
  call stiffness_table(damper, gammas, k, error)
  if (allocated(error)) call fail("table")
  print '(a)', "# table gamma [rad]  k_re  k_im [N m/rad]"
  do i = 1, size(gammas)
    print '(a,3es16.8)', "table", gammas(i), k(i)%re, k(i)%im
  end do

  call limit_force(model, F_lim, error)
  if (allocated(error)) call fail("limit force")
  print '(a,es16.8,a)', "F_lim = ", F_lim, " N"

  call backbone(model, forces, points, error)
  if (allocated(error)) call fail("backbone")
  print '(a)', "# F_E [N]  gamma_P [rad]  f_res [Hz]  sigma_a [Pa]"
  do i = 1, size(points)
    print '(4es16.8)', points(i)%F_E, points(i)%gamma_P, points(i)%f_res, points(i)%sigma_a
  end do

  call response(model, f_exc, forces, points, error)
  if (allocated(error)) call fail("response")
  print '(a)', "# response f_exc [Hz]  F_E [N]  gamma_P [rad]  sigma_a [Pa]"
  do i = 1, size(points)
    print '(a,4es16.8)', "response", f_exc, points(i)%F_E, points(i)%gamma_P, points(i)%sigma_a
  end do

  call response_curves(model, forces(2:2), 200, curves, error)
  if (allocated(error)) call fail("curves")
  print '(a)', "# curve F_E [N]  points  max gamma_P [rad]"
  print '(a,es16.8,i8,es16.8)', "curve", curves(1)%F_E, size(curves(1)%f), &
    & maxval(curves(1)%gamma_P)

contains

  !> Reports the error and stops with its status (2 input, 3 physics, 4 numerics).
  subroutine fail(what)
    character(len=*), intent(in) :: what
    write(0, '(a)') "backbone: "//what//": "//error%message
    error stop error%stat
  end subroutine fail
end program backbone_example
