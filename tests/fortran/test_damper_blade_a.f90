!> The asymmetric damper of blade_a (PHYSICS.md 2.1-2.3): reference numbers, full-slip statics,
!> scaling laws, the elongation law against direct loops, and the table against direct loops.
module test_damper_blade_a
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer, only: full_slip_moment
  use udmap_damper_tracer_core, only: CONTACT_SLIP_POS, CONTACT_SLIP_NEG
  use udmap_damper_loops, only: loop_type, loop_workspace_type, ramp_type, cf_only_ramp, &
    & steady_loop, loop_stiffness
  use fixtures, only: sign_of
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_damper_blade_a

contains

  !> The asymmetric damper of blade_a (PHYSICS.md 2.1-2.3).
  subroutine collect_damper_blade_a(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_blade_a", run_damper_blade_a)]
  end subroutine collect_damper_blade_a

  !> Blade A's damper: reference numbers, statics, scaling and elongation laws, table vs loops.
  subroutine run_damper_blade_a(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: d, d3, d2, ds
    type(asymmetric_params_type) :: params
    type(error_type), allocatable :: error
    complex(wp) :: k, kd, k1, k2
    real(wp) :: g, gb, M, N(3), E_b, worst, worst_exact, fr(7)
    logical :: admissible
    integer :: i, j, signs(3)

    params = blade_a_damper_params()
    call new_asymmetric_damper(d, params, error)
    call check_no_error(suite, "blade_a damper", error)
    if (allocated(error)) return
    gb = d%gamma_b

    ! Reference numbers of the issue.
    call check_close(suite, "M_max", d%M_max, 6.44037_wp, 0.0_wp, 1e-5_wp)
    call check_close(suite, "M_min", d%M_min, -6.44037_wp, 0.0_wp, 1e-5_wp)
    call check_close(suite, "gamma_b", d%gamma_b, 5.4829e-4_wp, 1e-4_wp)
    call check_close(suite, "k_stuck", d%k_stuck, 12811.12_wp, 1e-6_wp)
    call check_true(suite, "gamma_s below gamma_b", d%gamma_s > 0 .and. d%gamma_s < gb)
    call check_true(suite, "no lift-off on blade_a", .not. d%lift_off)
    write(*, '(a, es22.14, a, es22.14, a, es22.14, a, es22.14, a, es22.14)') "blade_a: M_max = ", &
      & d%M_max, " M_min = ", d%M_min, " gamma_b = ", d%gamma_b, " gamma_s = ", d%gamma_s, &
      & " k_stuck = ", d%k_stuck

    ! Full-slip statics: both plateaus have every contact slipping, so their moments follow from
    ! equilibrium alone.
    do j = 1, 2
      if (j == 1) then
        signs = sign_of(d%table%base%mode_max)
      else
        signs = sign_of(d%table%base%mode_min)
      end if
      call check_true(suite, "plateau all slip", all(signs /= 0))
      call full_slip_moment(d%geometry, params%CF, signs, M, N, admissible, error)
      call check_no_error(suite, "full-slip statics", error)
      call check_true(suite, "full-slip normal forces compressive", admissible)
      if (j == 1) call check_close(suite, "M_max = full-slip statics", d%M_max, M, 1e-9_wp)
      if (j == 2) call check_close(suite, "M_min = full-slip statics", d%M_min, M, 1e-9_wp)
    end do

    ! All kn, kt scaled by 3: plateaus unchanged, k(gamma; 3) = 3 k(3 gamma; 1).
    params = blade_a_damper_params()
    params%kn_flat = 3*params%kn_flat
    params%kt_flat = 3*params%kt_flat
    params%kn_curved = 3*params%kn_curved
    params%kt_curved = 3*params%kt_curved
    call new_asymmetric_damper(d3, params, error)
    call check_no_error(suite, "stiffer damper", error)
    call check_close(suite, "M_max independent of kn, kt", d3%M_max, d%M_max, 1e-9_wp)
    call check_close(suite, "M_min independent of kn, kt", d3%M_min, d%M_min, 1e-9_wp)
    call check_close(suite, "gamma_b scales as 1/kappa", 3*d3%gamma_b, d%gamma_b, 1e-9_wp)
    fr = [0.2_wp, 0.7_wp, 0.88_wp, 0.95_wp, 1.0_wp, 3.0_wp, 10.0_wp]
    do i = 1, size(fr)
      g = fr(i)*d3%gamma_b
      call check_complex(suite, "stiffness scaling law (table)", d3%stiffness(g), 3*d%stiffness(3*g), &
        & 1e-9_wp)
      call check_complex(suite, "stiffness scaling law (exact)", d3%stiffness_exact(g), &
        & 3*d%stiffness_exact(3*g), 1e-9_wp)
    end do

    ! CF scaling: k(gamma; lambda CF) = k(gamma/lambda; CF), traced afresh and by set_CF.
    params = blade_a_damper_params()
    params%CF = 2*params%CF
    call new_asymmetric_damper(d2, params, error)
    call check_no_error(suite, "damper at 2 CF", error)
    ds = d
    call ds%set_CF(params%CF, error)
    call check_no_error(suite, "set_CF", error)
    call check_true(suite, "set_CF bumps revision", ds%revision == d%revision + 1)
    call check_close(suite, "CF law: gamma_b", d2%gamma_b, 2*d%gamma_b, 1e-9_wp)
    call check_close(suite, "CF law: M_max", d2%M_max, 2*d%M_max, 1e-9_wp)
    call check_close(suite, "set_CF: gamma_b", ds%gamma_b, d2%gamma_b, 1e-9_wp)
    call check_close(suite, "set_CF: gamma_s", ds%gamma_s, d2%gamma_s, 1e-9_wp)
    call check_close(suite, "set_CF: M_min", ds%M_min, d2%M_min, 1e-9_wp)
    do i = 1, size(fr)
      g = fr(i)*d2%gamma_b
      call check_complex(suite, "CF scaling law (traced)", d2%stiffness(g), d%stiffness(g/2), 1e-9_wp)
      call check_complex(suite, "CF scaling law (set_CF)", ds%stiffness(g), d2%stiffness(g), 1e-9_wp)
    end do

    ! Elongation: above gamma_b the base cycle's closed form equals directly traced loops, and
    ! E(gamma) = E_b + 2 Delta_M (gamma - gamma_b).
    call d%stiffness_direct(gb, kd, error)
    call check_no_error(suite, "direct loop at gamma_b", error)
    E_b = pi*gb**2*aimag(kd)
    call check_close(suite, "k at gamma_b: table = direct", real(d%stiffness(gb), wp), real(kd, wp), &
      & 1e-9_wp)
    fr(1:4) = [1.5_wp, 3.0_wp, 10.0_wp, 1.0_wp + 1e-6_wp]
    do i = 1, 4
      g = fr(i)*gb
      call d%stiffness_direct(g, kd, error)
      call check_no_error(suite, "direct loop above gamma_b", error)
      k = d%stiffness(g)
      call check_complex(suite, "elongated base cycle = direct loop", k, kd, 1e-9_wp)
      call check_close(suite, "E = E_b + 2 Delta_M (gamma - gamma_b)", pi*g**2*aimag(kd), &
        & E_b + 2*(d%M_max - d%M_min)*(g - gb), 1e-9_wp)
    end do

    ! The shared ramp gives the same loops as a history traced from the virgin state.
    call check_shared_ramp()

    ! The table between gamma_s and gamma_b against direct loops, at amplitudes between the
    ! nodes, next to every kink and between the Chebyshev points.
    worst = 0
    worst_exact = 0
    do i = 1, 400
      g = d%gamma_s + (gb - d%gamma_s)*(i - 0.5_wp)/400
      call compare(g)
    end do
    do j = 1, d%table%n_int
      call compare(d%table%int_b(j)*(1 - 1e-7_wp))
      call compare(d%table%int_b(j)*(1 + 1e-7_wp))
    end do
    do j = 1, d%table%n_piece
      do i = 1, 9
        call compare(d%table%piece_a(j) + (d%table%piece_b(j) - d%table%piece_a(j))*(i/10.0_wp)**2)
      end do
    end do
    write(*, '(a, i0, a, i0, a, es10.3, a, es10.3)') "table: ", d%table%n_int, &
      & " topology intervals, ", d%table%n_piece, " pieces; max rel. error vs direct loops ", worst, &
      & ", exact intervals ", worst_exact
    call check_true(suite, "table within 1e-6 of direct loops", worst < 1e-6_wp)
    call check_true(suite, "exact intervals within 1e-10 of direct loops", worst_exact < 1e-10_wp)

    ! Range 1e-12 .. 1 rad: finite, k_Im >= 0, stuck limit exact.
    k = d%stiffness(1e-12_wp)
    call check_close(suite, "k(1e-12) = k_stuck", real(k, wp), d%k_stuck, 1e-14_wp)
    call check_close(suite, "k_Im(1e-12) = 0", aimag(k), 0.0_wp, 0.0_wp, 0.0_wp)
    do i = 0, 240
      g = 10.0_wp**(-12 + 12*i/240.0_wp)
      k = d%stiffness(g)
      if (.not. (real(k) > 0 .and. aimag(k) >= 0 .and. abs(k) < 2*d%k_stuck)) then
        call check_true(suite, "k finite, k_Re > 0, k_Im >= 0 over 1e-12..1 rad", .false.)
        exit
      end if
    end do
    call check_true(suite, "k(1 rad) small", abs(d%stiffness(1.0_wp)) < 1e-2_wp*d%k_stuck)
    ! Elemental over arrays; no NaN for degenerate amplitudes.
    block
      real(wp) :: ga(4)
      complex(wp) :: ka(4)
      ga = [0.5_wp, 0.8_wp, 0.95_wp, 4.0_wp]*gb
      ka = d%stiffness(ga)
      do i = 1, 4
        call check_true(suite, "elemental stiffness", ka(i) == d%stiffness(ga(i)))
      end do
      k = d%stiffness(-1.0_wp)
      call check_true(suite, "gamma <= 0 gives the small-amplitude limit", k == d%stiffness(1e-12_wp))
      k = d%stiffness(huge(1.0_wp))
      call check_true(suite, "huge gamma gives finite k", abs(k) < 1 .and. real(k) == real(k))
    end block
    ! k continuous at gamma_s and gamma_b.
    call check_complex(suite, "continuous at gamma_s", d%stiffness(d%gamma_s*(1 - 1e-12_wp)), &
      & d%stiffness(d%gamma_s*(1 + 1e-12_wp)), 1e-9_wp)
    call check_complex(suite, "continuous at gamma_b", d%stiffness(gb*(1 - 1e-12_wp)), &
      & d%stiffness(gb*(1 + 1e-12_wp)), 1e-9_wp)

    ! dk/dgamma against central differences of the exact k.
    fr = [0.65_wp, 0.8_wp, 0.9_wp, 0.93_wp, 0.97_wp, 2.0_wp, 20.0_wp]
    do i = 1, size(fr)
      g = fr(i)*gb
      k1 = d%stiffness_exact(g*(1 - 1e-6_wp))
      k2 = d%stiffness_exact(g*(1 + 1e-6_wp))
      call check_complex(suite, "dk/dgamma = finite difference", d%stiffness_derivative(g), &
        & (k2 - k1)/(2e-6_wp*g), 1e-5_wp, abs(d%k_stuck)/gb*1e-7_wp)
    end do

    ! The loop for plotting: plateaus at M_max, M_min; its describing function by quadrature.
    call check_loop(3*gb)
    call check_loop(0.9_wp*gb)

  contains

    subroutine check_complex(suite, name, actual, expected, rtol, atol)
      type(test_suite), intent(inout) :: suite
      character(len=*), intent(in) :: name
      complex(wp), intent(in) :: actual, expected
      real(wp), intent(in) :: rtol
      real(wp), intent(in), optional :: atol
      real(wp) :: tol
      tol = rtol*abs(expected)
      if (present(atol)) tol = tol + atol
      call check_close(suite, name//" (re)", real(actual, wp), real(expected, wp), 0.0_wp, tol)
      call check_close(suite, name//" (im)", aimag(actual), aimag(expected), 0.0_wp, tol)
    end subroutine check_complex

    subroutine compare(gam)
      real(wp), intent(in) :: gam
      complex(wp) :: kt, ke, kdir
      type(error_type), allocatable :: err
      call d%stiffness_direct(gam, kdir, err)
      call check_no_error(suite, "direct loop", err)
      kt = d%stiffness(gam)
      ke = d%stiffness_exact(gam)
      worst = max(worst, abs(kt - kdir)/abs(kdir))
      worst_exact = max(worst_exact, abs(ke - kdir)/abs(kdir))
    end subroutine compare

    subroutine check_shared_ramp()
      type(ramp_type) :: virgin
      type(loop_type) :: l1, l2
      type(loop_workspace_type) :: work
      type(error_type), allocatable :: err
      complex(wp) :: ka, kb
      real(wp), parameter :: at(5) = [0.3_wp, 0.85_wp, 0.93_wp, 1.1_wp, 1.2_wp]
      integer :: m
      call cf_only_ramp(d%geometry, d%params%CF, virgin, err)
      call check_no_error(suite, "CF ramp", err)
      do m = 1, 5
        g = gb*at(m)
        call steady_loop(d%geometry, d%ramp, g, l1, work, err)
        call check_no_error(suite, "loop on shared ramp", err)
        call steady_loop(d%geometry, virgin, g, l2, work, err)
        call check_no_error(suite, "loop from virgin state", err)
        call loop_stiffness(l1, g, ka)
        call loop_stiffness(l2, g, kb)
        call check_complex(suite, "shared ramp = virgin history", ka, kb, 1e-12_wp)
        call check_true(suite, "loop repeats within three cycles", l2%cycles <= 3)
      end do
    end subroutine check_shared_ramp

    subroutine check_loop(gam)
      real(wp), intent(in) :: gam
      integer, parameter :: n = 20000
      real(wp), allocatable :: tau(:), Mr(:)
      real(wp) :: kre, kim
      type(error_type), allocatable :: err
      integer :: m
      allocate(tau(n), Mr(n))
      do m = 1, n
        tau(m) = 2*pi*(m - 1)/n
      end do
      call d%loop(gam, tau, Mr, err)
      call check_no_error(suite, "loop", err)
      if (gam > gb) then
        call check_close(suite, "loop plateau M_max", maxval(Mr), d%M_max, 1e-12_wp)
        call check_close(suite, "loop plateau M_min", minval(Mr), d%M_min, 1e-12_wp)
      end if
      ! Periodic trapezoid rule; the loop is continuous with kinks, so the error is O(1/n^2).
      kre = sum(Mr*cos(tau))*(2*pi/n)/(pi*gam)
      kim = -sum(Mr*sin(tau))*(2*pi/n)/(pi*gam)
      call check_complex(suite, "loop quadrature = k", cmplx(kre, kim, wp), d%stiffness(gam), 1e-6_wp)
    end subroutine check_loop
  end subroutine run_damper_blade_a
end module test_damper_blade_a
