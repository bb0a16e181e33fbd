!> Shared fixtures of the Fortran test suites: blade A's beam parameters (blade_a.json; its
!> damper is udmap_damper_params' blade_a_damper_params), the scenes of blade, damper and
!> model that the mapping suites build, the spring chain, the independent quadruple-precision
!> references and small helpers that several suites need.
module fixtures
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade, new_matrices_blade
  use udmap_damper_type, only: damper_type, new_asymmetric_damper, new_jenkins_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer_core, only: CONTACT_SLIP_POS, CONTACT_SLIP_NEG
  use udmap_mapping_model, only: analysis_type, model_type, point_type, new_model, backbone
  use udmap_contact_aft_moment, only: aft_workspace_type
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type
  use udmap_baseline_newmark, only: dti_settings_type, dti_point_type
  use testing, only: test_suite, check_no_error, check_true
  implicit none
  private
  public :: scene_type, scene_model, jenkins_oscillator, oscillator_model
  public :: blade_a_beam_params, spring_chain, dense_gamma, layer_force, band_min_force, sign_of
  public :: one_dof_blade, blade_a_with_damper, blade_a_band, blade_a_model, refined_backbone_change
  public :: stress_run_type, stress_run, check_finite_or_error
  public :: ieee_nan, ieee_inf, temp_dir, qp, receptances_from_solution, zgesv
  public :: uniform_sequence_type

  !> A blade, its damper, the analysis settings and the model of the three. Declare a scene
  !> `target`: the model keeps pointers to the blade and the damper, so a scene must not be
  !> copied or moved once its model is built.
  type :: scene_type
    type(blade_type) :: blade
    type(damper_type) :: damper
    type(analysis_type) :: analysis
    type(model_type) :: model
  end type scene_type

  !> The AFT workspace, the settings and the last points of a stress test's calls of the
  !> standard method and the time integration.
  type :: stress_run_type
    type(aft_workspace_type) :: ws
    type(hbm_settings_type) :: set
    type(hbm_point_type) :: pt
    type(dti_settings_type) :: dset
    type(dti_point_type) :: dp
  end type stress_run_type

  !> The real kind of the quadruple-precision references.
  integer, parameter :: qp = selected_real_kind(30)

  !> LAPACK (not in udmap_core_lapack, which holds what the kernel calls).
  interface
    subroutine zgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb
      complex(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine zgesv
  end interface

  !> A fixed sequence of uniform numbers in [0, 1) (a linear congruential generator): random
  !> test inputs that are the same on every run and every machine.
  type :: uniform_sequence_type
    integer(8) :: state = 1
  contains
    procedure :: next => uniform_next
  end type uniform_sequence_type

contains

  !> Blade A (blade_a.json): 8 neck and 24 airfoil elements, 64 DOFs, f1 = 187.119 Hz bare.
  function blade_a_beam_params() result(p)
    type(beam_params_type) :: p
    p = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, &
      & neck_L=0.020_wp, neck_h=0.008_wp, neck_b=0.020_wp, &
      & platform_L=0.010_wp, platform_m=0.021_wp, platform_J=1.4e-6_wp, &
      & airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
      & neck_elements=8, airfoil_elements=24)
  end function blade_a_beam_params

  !> The one-DOF oscillator of PHYSICS.md 8 as a matrices blade: m = 1, k = 1, the explicit
  !> damping c_visc, excitation at the gamma DOF.
  subroutine one_dof_blade(blade, c_visc, error)
    type(blade_type), intent(out) :: blade
    real(wp), intent(in) :: c_visc
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: M(1, 1), K(1, 1), C(1, 1)
    M = 1
    K = 1
    C = c_visc
    call new_matrices_blade(blade, M, K, 1, 1, 0.0_wp, error, C=C)
  end subroutine one_dof_blade

  !> The model of the scene's blade and damper under its analysis.
  subroutine scene_model(scene, error)
    type(scene_type), target, intent(inout) :: scene
    type(error_type), allocatable, intent(out) :: error
    call new_model(scene%model, scene%blade, scene%damper, scene%analysis, error)
  end subroutine scene_model

  !> The Jenkins oscillator of PHYSICS.md 8: one_dof_blade with c_visc and a Jenkins damper
  !> (kt, slip) on the same DOF; checks that each builds.
  subroutine jenkins_oscillator(suite, scene, c_visc, kt, slip, error)
    type(test_suite), intent(inout) :: suite
    type(scene_type), intent(inout) :: scene
    real(wp), intent(in) :: c_visc, kt, slip
    type(error_type), allocatable, intent(out) :: error
    call one_dof_blade(scene%blade, c_visc, error)
    call check_no_error(suite, "blade", error)
    call new_jenkins_damper(scene%damper, kt, slip, error)
    call check_no_error(suite, "damper", error)
  end subroutine jenkins_oscillator

  !> The model of a one-DOF scene over the band [w_min, w_max] in rad/s (the oscillator's
  !> equations are in rad/s, the band in Hz); checks that it builds.
  subroutine oscillator_model(suite, scene, w_min, w_max, error)
    type(test_suite), intent(inout) :: suite
    type(scene_type), target, intent(inout) :: scene
    real(wp), intent(in) :: w_min, w_max
    type(error_type), allocatable, intent(out) :: error
    scene%analysis%f_min = w_min/(2*pi)
    scene%analysis%f_max = w_max/(2*pi)
    call scene_model(scene, error)
    call check_no_error(suite, "model", error)
  end subroutine oscillator_model

  !> Blade A and its asymmetric damper; checks that each builds.
  subroutine blade_a_with_damper(suite, blade, damper, error)
    type(test_suite), intent(inout) :: suite
    type(blade_type), intent(out) :: blade
    type(damper_type), intent(out) :: damper
    type(error_type), allocatable, intent(out) :: error
    call new_beam_blade(blade, blade_a_beam_params(), error)
    call check_no_error(suite, "blade A", error)
    call new_asymmetric_damper(damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
  end subroutine blade_a_with_damper

  !> Blade A's band for its first mode: 150 to 230 Hz.
  subroutine blade_a_band(analysis)
    type(analysis_type), intent(inout) :: analysis
    analysis%f_min = 150
    analysis%f_max = 230
  end subroutine blade_a_band

  !> The model of blade and damper over blade A's band (analysis keeps its other settings);
  !> checks that it builds.
  subroutine blade_a_model(suite, blade, damper, analysis, model, error)
    type(test_suite), intent(inout) :: suite
    type(blade_type), target, intent(in) :: blade
    type(damper_type), target, intent(in) :: damper
    type(analysis_type), intent(inout) :: analysis
    type(model_type), intent(out) :: model
    type(error_type), allocatable, intent(out) :: error
    call blade_a_band(analysis)
    call new_model(model, blade, damper, analysis, error)
    call check_no_error(suite, "model", error)
  end subroutine blade_a_model

  !> The backbone of model at F_E = 1, ..., 10 N (points) and its largest relative change in
  !> gamma_P, f_res and sigma_a when the tolerance and the grid step are halved (worst); error
  !> is that of the refined backbone.
  subroutine refined_backbone_change(model, blade, damper, analysis, points, worst, error)
    type(model_type), intent(inout) :: model
    type(blade_type), target, intent(in) :: blade
    type(damper_type), target, intent(in) :: damper
    type(analysis_type), intent(in) :: analysis
    type(point_type), allocatable, intent(out) :: points(:)
    real(wp), intent(out) :: worst
    type(error_type), allocatable, intent(out) :: error
    type(analysis_type) :: fine
    type(model_type) :: model_fine
    type(point_type), allocatable :: points_fine(:)
    integer :: i
    call backbone(model, [(real(i, wp), i = 1, 10)], points, error)
    fine = analysis
    fine%rtol = analysis%rtol/2
    fine%grid_per_decade = 2*analysis%grid_per_decade
    call new_model(model_fine, blade, damper, fine, error)
    call backbone(model_fine, [(real(i, wp), i = 1, 10)], points_fine, error)
    worst = 0
    do i = 1, 10
      worst = max(worst, abs(points_fine(i)%gamma_P/points(i)%gamma_P - 1), &
        & abs(points_fine(i)%f_res/points(i)%f_res - 1), &
        & abs(points_fine(i)%sigma_a/points(i)%sigma_a - 1))
    end do
  end subroutine refined_backbone_change

  !> The settings of the stress suites: arc-length steps up to 0.3, 64 time steps a period and
  !> at most max_periods periods (a hang shows as a time-out, not as an endless run).
  function stress_run(max_periods) result(run)
    integer, intent(in) :: max_periods
    type(stress_run_type) :: run
    run%set%ds_max = 0.3_wp
    run%dset%steps_per_period = 64
    run%dset%max_periods = max_periods
  end function stress_run

  !> Checks that a call either succeeded with finite, non-negative outputs a and b, or failed
  !> with a message and an input, physics or numerics status; clears error for the next call.
  !> failed: whether it failed.
  subroutine check_finite_or_error(suite, name, error, a, b, failed)
    type(test_suite), intent(inout) :: suite
    character(len=*), intent(in) :: name
    type(error_type), allocatable, intent(inout) :: error
    real(wp), intent(in) :: a, b
    logical, intent(out), optional :: failed
    logical :: fine
    if (present(failed)) failed = allocated(error)
    if (allocated(error)) then
      fine = (error%stat == UDMAP_EINPUT .or. error%stat == UDMAP_EPHYSICS .or. &
        & error%stat == UDMAP_ENUMERIC) .and. len_trim(error%message) > 0
      deallocate(error)
    else
      fine = a >= 0.0_wp .and. a <= huge(1.0_wp) .and. b >= 0.0_wp .and. b <= huge(1.0_wp)
    end if
    call check_true(suite, name, fine)
  end subroutine check_finite_or_error

  !> The chain of unit springs (100) and masses (1 + 0.1 i): spring i joins node i-1 (the
  !> ground for i = 1) and node i.
  subroutine spring_chain(M, K)
    real(wp), intent(out) :: M(:, :), K(:, :)
    integer :: i, n
    n = size(M, 1)
    M = 0.0_wp
    K = 0.0_wp
    do i = 1, n
      M(i,i) = 1.0_wp + 0.1_wp*i
      K(i,i) = K(i,i) + 100.0_wp
    end do
    do i = 2, n
      K(i-1,i-1) = K(i-1,i-1) + 100.0_wp
      K(i-1,i) = K(i-1,i) - 100.0_wp
      K(i,i-1) = K(i,i-1) - 100.0_wp
    end do
  end subroutine spring_chain

  !> |gamma| of the layer solved directly on the dense blade matrices with the damper
  !> stiffness k(gamma) at DOF gamma: double-precision LU refined twice with quadruple-precision
  !> residuals (the independent reference of the layer and curve tests).
  real(wp) function dense_gamma(blade, damper, gamma, F_E, w) result(amp)
    type(blade_type), intent(in) :: blade
    type(damper_type), intent(in) :: damper
    real(wp), intent(in) :: gamma, F_E, w
    complex(wp), allocatable :: D(:, :), LU(:, :), q(:, :), dq(:, :)
    complex(qp), allocatable :: D_quad(:, :), res(:)
    integer, allocatable :: ipiv(:)
    integer :: n, info, it
    n = blade%ndof
    allocate(D_quad(n, n), res(n), q(n, 1), dq(n, 1), ipiv(n))
    D_quad = cmplx(real(blade%K, qp) - real(w, qp)**2*real(blade%M, qp), &
      & real(w, qp)*real(blade%beta, qp)*real(blade%K, qp), qp)
    D_quad(blade%gamma_dof, blade%gamma_dof) = D_quad(blade%gamma_dof, blade%gamma_dof) + &
      & cmplx(damper%stiffness(gamma), kind=qp)
    D = cmplx(D_quad, kind=wp)
    q = 0
    q(blade%exc_dof, 1) = F_E
    LU = D
    call zgesv(n, 1, LU, n, ipiv, q, n, info)
    do it = 1, 2
      res = -matmul(D_quad, cmplx(q(:, 1), kind=qp))
      res(blade%exc_dof) = res(blade%exc_dof) + F_E
      dq(:, 1) = cmplx(res, kind=wp)
      LU = D
      call zgesv(n, 1, LU, n, ipiv, dq, n, info)
      q = q + dq
    end do
    amp = abs(q(blade%gamma_dof, 1))
  end function dense_gamma

  !> The receptances of blade bl at omega [rad/s] from x = [q_E, q_g], the solutions for unit
  !> forces at the excitation and the gamma DOF: gE = q_E(g), gg = q_g(g), EE = q_E(E),
  !> sE = s^T q_E, sg = s^T q_g.
  function receptances_from_solution(bl, omega, x) result(r)
    type(blade_type), intent(in) :: bl
    real(wp), intent(in) :: omega
    complex(qp), intent(in) :: x(:, :)
    type(receptances_type) :: r
    complex(qp), allocatable :: s(:)
    allocate(s(bl%ndof))
    s = real(bl%s_K, qp) - real(omega, qp)**2*real(bl%s_M, qp)
    r%gE = cmplx(x(bl%gamma_dof, 1), kind=wp)
    r%gg = cmplx(x(bl%gamma_dof, 2), kind=wp)
    r%EE = cmplx(x(bl%exc_dof, 1), kind=wp)
    r%sE = cmplx(sum(s*x(:, 1)), kind=wp)
    r%sg = cmplx(sum(s*x(:, 2)), kind=wp)
  end function receptances_from_solution

  !> F(omega) = gamma/|g~| and dF/d omega of the layer gamma (stiffness k).
  subroutine layer_force(blade, gamma, k, w, F, dF, error)
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: gamma, w
    complex(wp), intent(in) :: k
    real(wp), intent(out) :: F, dF
    type(error_type), allocatable, intent(inout) :: error
    type(receptances_type) :: r
    complex(wp) :: g, dg
    call blade%receptances(w, r, error, derivatives=.true.)
    g = r%gE/(1 + k*r%gg)
    dg = r%dgE/(1 + k*r%gg) - r%gE*k*r%dgg/(1 + k*r%gg)**2
    F = gamma/abs(g)
    dF = -F*real(dg*conjg(g), wp)/abs(g)**2
  end subroutine layer_force

  !> min over the band [f_min, f_max] of F(omega) for the layer gamma: 4000 samples, then
  !> golden section around the smallest.
  real(wp) function band_min_force(blade, damper, analysis, gamma, error) result(Fmin)
    type(blade_type), intent(in) :: blade
    type(damper_type), intent(in) :: damper
    type(analysis_type), intent(in) :: analysis
    real(wp), intent(in) :: gamma
    type(error_type), allocatable, intent(inout) :: error
    real(wp), parameter :: gr = 0.618033988749895_wp
    complex(wp) :: kk
    real(wp) :: a, b, c, d, Fc, Fd, dummy, w0, h, vals(0:4000)
    integer :: n, best, it
    kk = damper%stiffness(gamma)
    w0 = 2*pi*analysis%f_min
    h = 2*pi*(analysis%f_max - analysis%f_min)/4000
    do n = 0, 4000
      call layer_force(blade, gamma, kk, w0 + n*h, vals(n), dummy, error)
    end do
    best = minloc(vals, 1) - 1
    a = w0 + max(best - 1, 0)*h
    b = w0 + min(best + 1, 4000)*h
    c = b - (b - a)*gr
    d = a + (b - a)*gr
    call layer_force(blade, gamma, kk, c, Fc, dummy, error)
    call layer_force(blade, gamma, kk, d, Fd, dummy, error)
    do it = 1, 100
      if (Fc < Fd) then
        b = d; d = c; Fd = Fc
        c = b - (b - a)*gr
        call layer_force(blade, gamma, kk, c, Fc, dummy, error)
      else
        a = c; c = d; Fc = Fd
        d = a + (b - a)*gr
        call layer_force(blade, gamma, kk, d, Fd, dummy, error)
      end if
    end do
    Fmin = min(minval(vals), Fc, Fd)
  end function band_min_force

  !> The slip direction of each of the three contacts of a topology mode (0 when not slipping).
  pure function sign_of(mode) result(s)
    integer, intent(in) :: mode(3)
    integer :: s(3)
    s = 0
    where (mode == CONTACT_SLIP_POS) s = 1
    where (mode == CONTACT_SLIP_NEG) s = -1
  end function sign_of

  function ieee_nan() result(x)
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    real(wp) :: x
    x = ieee_value(x, ieee_quiet_nan)
  end function ieee_nan

  function ieee_inf() result(x)
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    real(wp) :: x
    x = ieee_value(x, ieee_positive_inf)
  end function ieee_inf

  !> A fresh directory $TMPDIR/udmap_test_<name>_<random> (/tmp without TMPDIR).
  function temp_dir(name) result(dir)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: dir
    character(len=256) :: base
    character(len=12) :: suffix
    real(wp) :: u
    integer :: stat
    call get_environment_variable("TMPDIR", base, status=stat)
    if (stat /= 0 .or. len_trim(base) == 0) base = "/tmp"
    call random_init(.false., .true.)
    call random_number(u)
    write(suffix, '(i12.12)') int(u*1.0e12_wp, kind=8)
    dir = trim(base)//"/udmap_test_"//name//"_"//suffix
    call execute_command_line("mkdir -p "//dir)
  end function temp_dir

  !> The next number of the sequence.
  real(wp) function uniform_next(self) result(u)
    class(uniform_sequence_type), intent(inout) :: self
    self%state = iand(6364136223846793005_8*self%state + 1442695040888963407_8, &
      & huge(self%state))
    u = real(ishft(self%state, -11), wp)/real(ishft(huge(self%state), -11), wp)
  end function uniform_next
end module fixtures
