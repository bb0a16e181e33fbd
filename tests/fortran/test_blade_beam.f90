!> The built-in beam blade (PHYSICS.md 1.1): blade A's DOF layout and bare first frequency, the
!> airfoil as a clamped cantilever (closed form), convergence under mesh refinement (O(h^4) for
!> cubic Hermite elements) and validation of every parameter.
module test_blade_beam
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade, new_matrices_blade
  use fixtures, only: blade_a_beam_params, ieee_nan, ieee_inf
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_blade_beam

contains

  !> The built-in beam blade (PHYSICS.md 1.1).
  subroutine collect_blade_beam(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("layout_and_first_frequency", layout_and_first_frequency), &
      & new_unittest("cantilever_airfoil", cantilever_airfoil), &
      & new_unittest("mesh_convergence", mesh_convergence), &
      & new_unittest("bad_parameters", bad_parameters)]
  end subroutine collect_blade_beam

  !> Blade A's DOF layout, band storage and bare first frequency (187.119057 Hz).
  subroutine layout_and_first_frequency(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type) :: b
    type(error_type), allocatable :: error
    real(wp) :: f(3), q(64)
    integer :: i, j
    call new_beam_blade(b, blade_a_beam_params(), error)
    call check_no_error(suite, "blade A builds", error)
    if (allocated(error)) return
    call check_true(suite, "blade A has 64 DOFs", b%ndof == 64)
    call check_true(suite, "gamma_P is DOF 16 (after 7 neck nodes and w_P)", b%gamma_dof == 16)
    call check_true(suite, "E is w of airfoil node 12, DOF 39", b%exc_dof == 39)
    call check_true(suite, "half-bandwidth 3", b%kd == 3)
    call check_true(suite, "stress rows present", b%has_stress)
    ! Band and dense storage agree and K, M are banded.
    call check_true(suite, "dense copies present", allocated(b%K) .and. allocated(b%M))
    do j = 1, b%ndof
      do i = 1, b%ndof
        if (abs(i - j) > 3 .and. (b%K(i, j) /= 0.0_wp .or. b%M(i, j) /= 0.0_wp)) then
          call check_true(suite, "K and M are zero outside the band", .false.)
          return
        end if
      end do
    end do
    call check_close(suite, "band K(15,16) = dense K(15,16)", b%Kb(3, 16), b%K(15, 16), 0.0_wp)
    call b%natural_frequencies(f, error)
    call check_no_error(suite, "natural frequencies", error)
    write(*, '(a, 3f18.9)') "blade A bare natural frequencies [Hz]: ", f
    ! PHYSICS.md 1.1: 187.119 Hz; 187.119057 to 1e-7 (brief).
    call check_close(suite, "blade A f1 = 187.119057 Hz", f(1), 187.119057_wp, 1.0e-7_wp)
    ! Independent dense computation (numpy/scipy eigh of the same assembly, inverted pencil).
    call check_close(suite, "blade A f2 (independent assembly)", f(2), 1079.37511776_wp, 1.0e-9_wp)
    call check_close(suite, "blade A f3 (independent assembly)", f(3), 2712.93099443_wp, 1.0e-9_wp)
    call check_close(suite, "omega1 = 2 pi f1", b%omega1, 2*pi*f(1), 1.0e-15_wp)
    call check_close(suite, "beta = 2 zeta/omega1", b%beta, 2*0.002_wp/b%omega1, 1.0e-15_wp)
    ! Mass normalisation and orthogonality of the modes (dense check).
    call check_close(suite, "phi_1^T M phi_1 = 1", dot_product(b%phi(:, 1), matmul(b%M, b%phi(:, 1))), &
      & 1.0_wp, 1.0e-13_wp)
    call check_close(suite, "phi_1^T M phi_2 = 0", dot_product(b%phi(:, 1), matmul(b%M, b%phi(:, 2))), &
      & 0.0_wp, 0.0_wp, 1.0e-12_wp)
    call check_close(suite, "phi_1^T K phi_1 = omega1^2", &
      & dot_product(b%phi(:, 1), matmul(b%K, b%phi(:, 1))), b%omega1**2, 1.0e-11_wp)
    ! The stress row is the first airfoil element's moment row times (h/2)/I: its entries on
    ! the free DOFs of airfoil node 1 are (EI/L^3)(-6L, 2L^2) (h/2)/I = E (h/2)(-6/L^2, 2/L).
    call check_close(suite, "s_K at w of airfoil node 1", b%s_K(17), &
      & -6*170e9_wp*0.002_wp/0.005_wp**2, 1.0e-14_wp)
    call check_close(suite, "s_K at theta of airfoil node 1", b%s_K(18), &
      & 2*170e9_wp*0.002_wp/0.005_wp, 1.0e-14_wp)
    ! Rigid motions of the first airfoil element strain nothing: translation (w_P = w1 = 1) and
    ! rotation (gamma_P = theta1 = 1, w1 = L_p/2 + L_e with L_e = 0.005) give zero stress.
    q = 0
    q(15) = 1
    q(17) = 1
    call check_close(suite, "rigid translation gives no stress", dot_product(b%s_K, q), 0.0_wp, 0.0_wp, &
      & 1.0e-12_wp*abs(b%s_K(17)))
    q = 0
    q(16) = 1
    q(17) = 0.005_wp + 0.005_wp
    q(18) = 1
    call check_close(suite, "rigid rotation gives no stress", dot_product(b%s_K, q), 0.0_wp, 0.0_wp, &
      & 1.0e-12_wp*abs(b%s_K(17)))
  end subroutine layout_and_first_frequency

  !> Platform DOFs held fixed: the airfoil alone is a clamped cantilever. The reduced problem
  !> keeps the rows and columns of the airfoil nodes (DOFs 17..64) of blade A's K and M.
  subroutine cantilever_airfoil(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: a
    type(blade_type) :: b, c
    type(error_type), allocatable :: error
    real(wp) :: f1, ei, ra, exact
    a = blade_a_beam_params()
    call new_beam_blade(b, a, error)
    if (allocated(error)) return
    call new_matrices_blade(c, b%M(17:64, 17:64), b%K(17:64, 17:64), 1, 2, 0.0_wp, error)
    call check_no_error(suite, "reduced cantilever builds", error)
    if (allocated(error)) return
    f1 = c%omega(1)/(2*pi)
    ei = a%E*a%airfoil_b*a%airfoil_h**3/12
    ra = a%rho*a%airfoil_b*a%airfoil_h
    exact = 1.87510407_wp**2/(2*pi)*sqrt(ei/(ra*a%airfoil_L**4))
    write(*, '(a, f18.9, a, f18.9, a, es10.2)') "cantilever airfoil f1 = ", f1, " Hz, closed form ", &
      & exact, " Hz, rel. diff ", abs(f1 - exact)/exact
    call check_close(suite, "clamped airfoil f1 = 1.87510407^2/(2 pi) sqrt(EI/(rho A L^4))", f1, exact, &
      & 1.0e-5_wp)
    ! The second cantilever root 4.69409113 as well.
    exact = 4.69409113_wp**2/(2*pi)*sqrt(ei/(ra*a%airfoil_L**4))
    call check_close(suite, "clamped airfoil f2 (root 4.69409113)", c%omega(2)/(2*pi), exact, 1.0e-5_wp)
  end subroutine cantilever_airfoil

  !> f1 of blade A with 2, 4, 8, 16 airfoil elements against 2048 elements (large banded model):
  !> frequencies decrease monotonically (nested conforming meshes) and the error falls by ~16
  !> per halving (O(h^4)); 24 elements are within 1e-7 of the fine mesh.
  subroutine mesh_convergence(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type) :: b
    type(error_type), allocatable :: error
    type(beam_params_type) :: p
    real(wp) :: f(5), fine
    integer :: k
    integer, parameter :: ne(5) = [2, 4, 8, 16, 24]
    p = blade_a_beam_params()
    p%airfoil_elements = 2048
    call new_beam_blade(b, p, error)
    call check_no_error(suite, "2048-element airfoil builds", error)
    if (allocated(error)) return
    call check_true(suite, "2048 elements: 4112 DOFs, band only", b%ndof == 4112 .and. &
      & .not.allocated(b%K) .and. allocated(b%Kb))
    call check_true(suite, "2048 elements: 20 modes kept", b%nmodes == 20)
    fine = b%omega(1)/(2*pi)
    do k = 1, 5
      p%airfoil_elements = ne(k)
      call new_beam_blade(b, p, error)
      if (allocated(error)) return
      f(k) = b%omega(1)/(2*pi)
    end do
    write(*, '(a, 5f16.9, a, f16.9)') "f1 for 2, 4, 8, 16, 24 airfoil elements: ", f, "; 2048: ", fine
    call check_true(suite, "f1 decreases under refinement", all(f(1:4) > f(2:5)) .and. f(5) > fine)
    call check_close(suite, "error ratio 4 -> 8 elements ~ 16", (f(2) - fine)/(f(3) - fine), 16.0_wp, 0.2_wp)
    call check_close(suite, "error ratio 8 -> 16 elements ~ 16", (f(3) - fine)/(f(4) - fine), 16.0_wp, 0.2_wp)
    call check_close(suite, "24 elements within 1e-7 of 2048", f(5), fine, 1.0e-7_wp)
  end subroutine mesh_convergence

  !> Every beam parameter is validated with a message naming the field.
  subroutine bad_parameters(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: a, p
    type(blade_type) :: b
    type(error_type), allocatable :: error
    real(wp) :: nan
    a = blade_a_beam_params()
    nan = ieee_nan()
    p = a; p%neck_L = -0.02_wp
    call new_beam_blade(b, p, error)
    call check_error(suite, "negative neck length", error, UDMAP_EINPUT, &
      & "blade.neck.L must be a positive finite number")
    p = a; p%E = nan
    call new_beam_blade(b, p, error)
    call check_error(suite, "NaN Young's modulus", error, UDMAP_EINPUT, "blade.E")
    p = a; p%rho = 0
    call new_beam_blade(b, p, error)
    call check_error(suite, "zero density", error, UDMAP_EINPUT, "blade.rho")
    p = a; p%zeta = -0.01_wp
    call new_beam_blade(b, p, error)
    call check_error(suite, "negative zeta", error, UDMAP_EINPUT, "blade.zeta must be a non-negative")
    p = a; p%zeta = nan
    call new_beam_blade(b, p, error)
    call check_error(suite, "NaN zeta", error, UDMAP_EINPUT, "blade.zeta")
    p = a; p%neck_h = ieee_inf()
    call new_beam_blade(b, p, error)
    call check_error(suite, "infinite neck height", error, UDMAP_EINPUT, "blade.neck.h")
    p = a; p%neck_b = 0
    call new_beam_blade(b, p, error)
    call check_error(suite, "zero neck width", error, UDMAP_EINPUT, "blade.neck.b")
    p = a; p%platform_L = -1
    call new_beam_blade(b, p, error)
    call check_error(suite, "negative platform length", error, UDMAP_EINPUT, "blade.platform.L")
    p = a; p%platform_m = nan
    call new_beam_blade(b, p, error)
    call check_error(suite, "NaN platform mass", error, UDMAP_EINPUT, "blade.platform.m")
    p = a; p%platform_J = -1e-6_wp
    call new_beam_blade(b, p, error)
    call check_error(suite, "negative platform inertia", error, UDMAP_EINPUT, "blade.platform.J")
    p = a; p%airfoil_L = 0
    call new_beam_blade(b, p, error)
    call check_error(suite, "zero airfoil length", error, UDMAP_EINPUT, "blade.airfoil.L")
    p = a; p%airfoil_h = nan
    call new_beam_blade(b, p, error)
    call check_error(suite, "NaN airfoil height", error, UDMAP_EINPUT, "blade.airfoil.h")
    p = a; p%airfoil_b = -0.03_wp
    call new_beam_blade(b, p, error)
    call check_error(suite, "negative airfoil width", error, UDMAP_EINPUT, "blade.airfoil.b")
    p = a; p%neck_elements = 0
    call new_beam_blade(b, p, error)
    call check_error(suite, "no neck elements", error, UDMAP_EINPUT, "blade.neck.elements")
    p = a; p%airfoil_elements = 23
    call new_beam_blade(b, p, error)
    call check_error(suite, "odd airfoil elements", error, UDMAP_EINPUT, &
      & "blade.airfoil.elements must be an even integer")
    p = a; p%airfoil_elements = 0
    call new_beam_blade(b, p, error)
    call check_error(suite, "no airfoil elements", error, UDMAP_EINPUT, "blade.airfoil.elements")
    p = a; p%neck_elements = 1; p%airfoil_elements = 2
    call new_beam_blade(b, p, error)
    call check_no_error(suite, "coarsest beam (1 + 2 elements) builds", error)
    call check_true(suite, "coarsest beam: 6 DOFs, gamma 2, E 3", b%ndof == 6 .and. b%gamma_dof == 2 &
      & .and. b%exc_dof == 3)
  end subroutine bad_parameters
end module test_blade_beam
