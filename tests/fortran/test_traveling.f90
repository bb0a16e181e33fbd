!> Traveling waves (PHYSICS.md 2.6) on blade A, checked against what needs none of the kernel's
!> traveling-wave code: the in-phase describing function and limit force, the stuck damper as a
!> linear Hermitian coupling of the two platforms (its 6x6 stiffness condensed here from the
!> contact springs), the energy balance of the traced loops, and the in-phase answer as phi -> 0.
module test_traveling
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_core_lapack, only: zgetrs
  use udmap_blade_type, only: blade_type, new_beam_blade, new_matrices_blade
  use udmap_damper_type, only: damper_type, new_asymmetric_damper
  use udmap_damper_params, only: asymmetric_params_type, blade_a_damper_params
  use udmap_contact_element_wave, only: wave_aft, wave_settings_type, wave_result_type
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, &
    & limit_force, backbone, REGIME_STUCK
  use udmap_baseline_wave, only: wave_hbm_type, wave_hbm_point_type, new_wave_hbm, wave_hbm_peak
  use fixtures, only: scene_type, scene_model, blade_a_beam_params, blade_a_band, zgesv
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_traveling

contains

  subroutine collect_traveling(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("wave_aft_in_phase", run_wave_aft_in_phase), &
      & new_unittest("wave_energy", run_wave_energy), &
      & new_unittest("wave_derivatives", run_wave_derivatives), &
      & new_unittest("stuck_hermitian", run_stuck_hermitian), &
      & new_unittest("phi_to_zero", run_phi_to_zero), &
      & new_unittest("inputs", run_inputs), &
      & new_unittest("standard_method", run_standard_method)]
  end subroutine collect_traveling

  !> At phi = 0 the wave trace is the in-phase loop: the moment's first harmonic is k(gamma)
  !> gamma (to the sampling of the AFT), and the forces on the blade have no first harmonic
  !> (flat and curved side cancel exactly).
  subroutine run_wave_aft_in_phase(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: damper
    type(error_type), allocatable :: error
    type(wave_settings_type) :: settings
    real(wp) :: A0(3), g
    complex(wp) :: P(3, 1), A(3, 1), k
    integer :: i
    real(wp), parameter :: gammas(3) = [2e-4_wp, 1e-3_wp, 4e-3_wp]
    call new_asymmetric_damper(damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
    settings%samples = 512
    do i = 1, size(gammas)
      g = gammas(i)
      P = 0
      P(3, 1) = g
      call wave_aft(damper%geometry, damper%params%CF, 0.0_wp, [0.0_wp, 0.0_wp, 0.0_wp], P, &
        & settings, A0, A, error)
      call check_no_error(suite, "wave_aft", error)
      k = damper%stiffness_exact(g)
      call check_close(suite, "k_Re from the wave trace", real(A(3, 1), wp)/g, real(k, wp), &
        & rtol=2e-4_wp)
      call check_close(suite, "k_Im from the wave trace", aimag(A(3, 1))/g, aimag(k), &
        & rtol=2e-3_wp, atol=1e-6_wp*abs(k))
      call check_true(suite, "no first harmonic of the forces in phase", &
        & maxval(abs(A(1:2, 1)))*0.01_wp <= 1e-9_wp*abs(A(3, 1)))
    end do
  end subroutine run_wave_aft_in_phase

  !> The energy dissipated per cycle, from the traced loops (trapezoid on the samples of
  !> A.dp), equals the first-harmonic work pi Im(A_1 . conj(P_1)) of a single-harmonic path, and
  !> is positive, at several phases.
  subroutine run_wave_energy(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: damper
    type(error_type), allocatable :: error
    type(wave_settings_type) :: settings
    type(wave_result_type) :: res
    real(wp) :: A0(3), W1
    complex(wp) :: P(3, 1), A(3, 1)
    integer :: i
    real(wp), parameter :: phis(3) = [0.5_wp, pi/2, 2.5_wp]
    call new_asymmetric_damper(damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
    settings%samples = 1024
    do i = 1, size(phis)
      P(:, 1) = [cmplx(-4e-6_wp, 1e-6_wp, wp), cmplx(0.0_wp, 0.0_wp, wp), &
        & cmplx(1e-3_wp, 0.0_wp, wp)]
      call wave_aft(damper%geometry, damper%params%CF, phis(i), [0.0_wp, 0.0_wp, 0.0_wp], P, &
        & settings, A0, A, error, res)
      call check_no_error(suite, "wave_aft", error)
      W1 = pi*sum(aimag(A(:, 1)*conjg(P(:, 1))))
      call check_true(suite, "energy positive", res%energy > 0 .and. res%slipped)
      call check_close(suite, "loop area = first-harmonic work", res%energy, W1, rtol=1e-4_wp)
    end do
  end subroutine run_wave_energy

  !> The derivatives of the traced action with respect to the platform's harmonics (the
  !> tracer's forward mode, udmap_damper_tracer_tangent) equal central differences of the
  !> traced action itself: H = 1 and 3, stuck, slipping and lifting off (relative to the
  !> action's size over gamma_1).
  subroutine run_wave_derivatives(suite)
    type(test_suite), intent(inout) :: suite
    type(damper_type) :: damper
    type(asymmetric_params_type) :: prm
    type(error_type), allocatable :: error
    type(wave_settings_type) :: settings
    type(wave_result_type) :: res
    real(wp) :: A0(3), A0p(3), A0m(3), P0(3), dP0(3, 14), dA0(3, 14), y(14), scale, dy, err, big
    complex(wp) :: P(3, 3), Ap(3, 3), Am(3, 3), A(3, 3), dP(3, 3, 14), dA(3, 3, 14)
    integer :: ic, H, k, j, ny
    real(wp), parameter :: phis(3) = [0.6_wp, pi/2, 0.05_wp]
    ! (mu, gamma_1 [rad]): stuck, slipping, lifting off (blade A's damper)
    real(wp), parameter :: cases(2, 3) = reshape([1.5_wp, 2e-4_wp, 0.3_wp, 1.5e-3_wp, &
      & 0.5_wp, 4e-3_wp], [2, 3])
    do ic = 1, 3
      prm = blade_a_damper_params()
      prm%mu = cases(1, ic)
      call new_asymmetric_damper(damper, prm, error)
      call check_no_error(suite, "damper", error)
      if (allocated(error)) return
      do H = 1, 3, 2
        settings%samples = max(64, 8*H)
        ! y: gamma_0, then Re and Im of u_h, v_h (h = 1..H), then gamma_1 (real); the other
        ! harmonics of gamma at fixed small values
        ny = 4*H + 2
        y(1) = 1e-5_wp*cases(2, ic)
        do k = 1, H
          y(4*k-2:4*k+1) = cases(2, ic)*0.006_wp*[0.4_wp, -0.3_wp, 0.2_wp, 0.5_wp]/k
        end do
        y(ny) = cases(2, ic)
        call unpack(y, P0, P)
        dP0 = 0
        dP = 0
        dP0(3, 1) = 1
        ! y(4 h - 2 + c), c = 0..3: Re, Im of P(1, h), then of P(2, h)
        do k = 1, H
          do j = 0, 3
            dP(merge(1, 2, j < 2), k, 4*k - 2 + j) = merge((1.0_wp, 0.0_wp), &
              & (0.0_wp, 1.0_wp), mod(j, 2) == 0)
          end do
        end do
        ! gamma_1, and the higher harmonics of gamma that unpack scales with it
        dP(3, 1:H, ny) = P(3, 1:H)/y(ny)
        call wave_aft(damper%geometry, prm%CF, phis(ic), P0, P(:, 1:H), settings, A0, &
          & A(:, 1:H), error, res, dP0(:, 1:ny), dP(:, 1:H, 1:ny), dA0(:, 1:ny), &
          & dA(:, 1:H, 1:ny))
        call check_no_error(suite, "wave_aft with derivatives", error)
        if (allocated(error)) return
        if (H == 1) call check_true(suite, "the cases are stuck, slip and lift off", &
          & (ic == 1 .neqv. res%slipped) .and. (ic == 3 .eqv. res%lifted))
        scale = maxval(abs(A(:, 1:H)))/cases(2, ic)
        big = 0
        do k = 1, ny
          dy = 1e-6_wp*merge(cases(2, ic), 0.006_wp*cases(2, ic), k == 1 .or. k == ny)
          call unpack(y + dy*unit(k), P0, P)
          call wave_aft(damper%geometry, prm%CF, phis(ic), P0, P(:, 1:H), settings, A0p, &
            & Ap(:, 1:H), error)
          call unpack(y - dy*unit(k), P0, P)
          call wave_aft(damper%geometry, prm%CF, phis(ic), P0, P(:, 1:H), settings, A0m, &
            & Am(:, 1:H), error)
          call check_no_error(suite, "wave_aft", error)
          err = max(maxval(abs((Ap(:, 1:H) - Am(:, 1:H))/(2*dy) - dA(:, 1:H, k))), &
            & maxval(abs((A0p - A0m)/(2*dy) - dA0(:, k))))
          big = max(big, err/scale)
        end do
        ! (central differences: rounding, 2e-6 at the stuck amplitude; lifting off, the
        ! events that cross an instant leave O(h^3) in the traced action: 1e-5 of its
        ! derivatives)
        call check_true(suite, "derivatives = central differences", &
          & big <= merge(5e-5_wp, 1e-5_wp, ic == 3))
        print '(a, i0, a, i0, a, es10.3)', "  wave derivatives, case ", ic, ", H = ", H, &
          & ": largest difference from central differences ", big
      end do
    end do

  contains

    function unit(k) result(e)
      integer, intent(in) :: k
      real(wp) :: e(14)
      e = 0
      e(k) = 1
    end function unit

    subroutine unpack(yv, P0v, Pv)
      real(wp), intent(in) :: yv(14)
      real(wp), intent(out) :: P0v(3)
      complex(wp), intent(out) :: Pv(3, 3)
      integer :: kk
      P0v = [0.0_wp, 0.0_wp, yv(1)]
      Pv = 0
      do kk = 1, H
        Pv(1, kk) = cmplx(yv(4*kk-2), yv(4*kk-1), wp)
        Pv(2, kk) = cmplx(yv(4*kk), yv(4*kk+1), wp)
        if (kk > 1) Pv(3, kk) = cmplx(0.05_wp, -0.03_wp, wp)*yv(ny)/kk
      end do
      Pv(3, 1) = yv(ny)
    end subroutine unpack
  end subroutine run_wave_derivatives

  !> Friction so high that nothing slips at a small force: the damper is a linear spring between the two
  !> platforms, K_d (6x6, condensed here from the contact springs and the damper's
  !> equilibrium), and the wave couples blade 0 through the Hermitian
  !> K(phi) = K_LL + K_RR + e^{i phi} K_LR + e^{-i phi} K_RL. The peak of |gamma_P| of the
  !> blade with K(phi) on its platform (dense complex solves) is the layered f_res to 1e-8.
  subroutine run_stuck_hermitian(suite)
    type(test_suite), intent(inout) :: suite
    type(scene_type), target :: scene
    type(asymmetric_params_type) :: prm
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:)
    real(wp) :: Kd(6, 6), f_direct
    complex(wp) :: Kphi(3, 3)
    integer :: i
    real(wp), parameter :: ibpa(3) = [90.0_wp, 165.0_wp, -45.0_wp]
    call new_beam_blade(scene%blade, blade_a_beam_params(), error)
    call check_no_error(suite, "blade", error)
    prm = blade_a_damper_params()
    prm%mu = 1.5_wp
    call new_asymmetric_damper(scene%damper, prm, error)
    call check_no_error(suite, "damper", error)
    if (allocated(error)) return
    Kd = stuck_stiffness(prm)
    do i = 1, size(ibpa)
      scene%analysis = analysis_type()
      call blade_a_band(scene%analysis)
      scene%analysis%ibpa_deg = ibpa(i)
      call scene_model(scene, error)
      call check_no_error(suite, "model", error)
      if (allocated(error)) return
      call backbone(scene%model, [0.02_wp], points, error)
      call check_no_error(suite, "backbone, stuck", error)
      if (allocated(error)) return
      call check_true(suite, "stuck regime", points(1)%regime == REGIME_STUCK)
      Kphi = Kd(1:3, 1:3) + Kd(4:6, 4:6) + exp(cmplx(0.0_wp, ibpa(i)*pi/180, wp))*Kd(1:3, 4:6) &
        & + exp(cmplx(0.0_wp, -ibpa(i)*pi/180, wp))*Kd(4:6, 1:3)
      f_direct = linear_peak(scene%blade, Kphi)
      call check_close(suite, "stuck f_res against the Hermitian linear problem", &
        & points(1)%f_res, f_direct, rtol=1e-8_wp)
    end do
  end subroutine run_stuck_hermitian

  !> phi -> 0 gives the in-phase answer (to the sampling of the wave AFT), and 360 deg is phi = 0.
  subroutine run_phi_to_zero(suite)
    type(test_suite), intent(inout) :: suite
    ! the scene's model is the one in phase
    type(scene_type), target :: scene
    type(model_type) :: model_eps, model_360
    type(error_type), allocatable :: error
    type(point_type), allocatable :: p0(:), pe(:), p360(:)
    real(wp) :: F0, Fe
    integer :: i
    real(wp), parameter :: forces(3) = [1.0_wp, 5.0_wp, 10.0_wp]
    call new_beam_blade(scene%blade, blade_a_beam_params(), error)
    call new_asymmetric_damper(scene%damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
    call blade_a_band(scene%analysis)
    call scene_model(scene, error)
    scene%analysis%ibpa_deg = 1e-6_wp
    call new_model(model_eps, scene%blade, scene%damper, scene%analysis, error)
    scene%analysis%ibpa_deg = 360
    call new_model(model_360, scene%blade, scene%damper, scene%analysis, error)
    call check_no_error(suite, "models", error)
    call backbone(scene%model, forces, p0, error)
    call backbone(model_eps, forces, pe, error)
    call check_no_error(suite, "backbone near phi = 0", error)
    call backbone(model_360, forces, p360, error)
    if (allocated(error)) return
    do i = 1, size(forces)
      call check_close(suite, "gamma_P", pe(i)%gamma_P, p0(i)%gamma_P, rtol=1e-4_wp)
      call check_close(suite, "sigma_a", pe(i)%sigma_a, p0(i)%sigma_a, rtol=1e-4_wp)
      call check_close(suite, "f_res", pe(i)%f_res, p0(i)%f_res, rtol=2e-6_wp)
      call check_true(suite, "360 deg is in phase, bit for bit", &
        & p360(i)%gamma_P == p0(i)%gamma_P .and. p360(i)%f_res == p0(i)%f_res)
    end do
    call limit_force(scene%model, F0, error)
    call limit_force(model_eps, Fe, error)
    call check_no_error(suite, "limit forces", error)
    call check_close(suite, "F_lim(phi -> 0) = 2 Delta_M/(pi |phi_E/phi_g|)", Fe, F0, rtol=1e-3_wp)
  end subroutine run_phi_to_zero

  !> A blade without platform translations cannot carry a traveling wave.
  subroutine run_inputs(suite)
    type(test_suite), intent(inout) :: suite
    type(blade_type) :: beam
    type(scene_type), target :: scene
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:)
    call new_beam_blade(beam, blade_a_beam_params(), error)
    call new_matrices_blade(scene%blade, beam%M, beam%K, beam%gamma_dof, beam%exc_dof, 0.002_wp, &
      & error)
    call check_no_error(suite, "matrices blade", error)
    call new_asymmetric_damper(scene%damper, blade_a_damper_params(), error)
    call blade_a_band(scene%analysis)
    scene%analysis%ibpa_deg = 90
    call scene_model(scene, error)
    call check_no_error(suite, "model", error)
    call backbone(scene%model, [2.0_wp], points, error)
    call check_error(suite, "phi /= 0 without u_P", error, UDMAP_EINPUT, "u_dof")
  end subroutine run_inputs

  !> Same equations, same answers: the layered peaks and the standard method (force given,
  !> Newton on every harmonic, continuation and the maximum over frequency) agree to 1e-6.
  subroutine run_standard_method(suite)
    type(test_suite), intent(inout) :: suite
    type(scene_type), target :: scene
    type(error_type), allocatable :: error
    type(point_type), allocatable :: points(:)
    type(wave_hbm_type) :: hbm
    type(wave_hbm_point_type) :: pt
    integer :: i, j, k
    real(wp), parameter :: ibpa(2) = [90.0_wp, 270.0_wp], forces(2) = [2.0_wp, 10.0_wp]
    integer, parameter :: harmonics(2) = [1, 3]
    call new_beam_blade(scene%blade, blade_a_beam_params(), error)
    call new_asymmetric_damper(scene%damper, blade_a_damper_params(), error)
    call check_no_error(suite, "damper", error)
    do k = 1, size(harmonics)
      do i = 1, size(ibpa)
        scene%analysis = analysis_type()
        call blade_a_band(scene%analysis)
        scene%analysis%ibpa_deg = ibpa(i)
        scene%analysis%harmonics = harmonics(k)
        call scene_model(scene, error)
        call backbone(scene%model, forces, points, error)
        call check_no_error(suite, "layered backbone", error)
        if (allocated(error)) return
        call new_wave_hbm(hbm, scene%blade, scene%damper%geometry, scene%damper%params%CF, &
          & ibpa(i)*pi/180, harmonics(k), error)
        call check_no_error(suite, "standard method", error)
        do j = 1, size(forces)
          call wave_hbm_peak(hbm, forces(j), 2*pi*points(j)%f_res*1.01_wp, 2*pi*150, pt, error)
          call check_no_error(suite, "standard method peak", error)
          if (allocated(error)) return
          call check_close(suite, "gamma_P, layered = standard", points(j)%gamma_P, &
            & abs(pt%P(3, 1)), rtol=1e-6_wp)
          call check_close(suite, "f_res, layered = standard", points(j)%f_res, &
            & pt%omega/(2*pi), rtol=1e-6_wp)
          call check_close(suite, "sigma_a, layered = standard", points(j)%sigma_a, &
            & abs(pt%sigma_1), rtol=1e-6_wp)
        end do
      end do
    end do
  end subroutine run_standard_method

  ! ------------------------------------------------------------------ independent pieces

  !> The stuck damper's stiffness between X = (u, v, gamma of the flat-side platform, then of
  !> the curved-side one) and the restoring actions (force on the damper, moment about P) on
  !> each side, from PHYSICS.md 2.1 and 2.6 directly.
  function stuck_stiffness(prm) result(Kd)
    type(asymmetric_params_type), intent(in) :: prm
    real(wp) :: Kd(6, 6)
    real(wp) :: n(2), t(2), r(2), P(2), Kc(2, 2), G(2, 3), E(2, 6), Kqq(3, 3), Kqx(3, 6)
    real(wp) :: Kxx(6, 6), bL, bR, inv(3, 3)
    integer :: i, s
    bL = prm%beta_L_deg*pi/180
    bR = prm%beta_R_deg*pi/180
    Kqq = 0
    Kqx = 0
    Kxx = 0
    do i = 1, 3
      if (i <= 2) then
        r = prm%flat(:, i)
        n = [sin(bL), -cos(bL)]
        P = [-prm%pitch/2, prm%y_P]
        Kc = prm%kn_flat*outer2(n, n) + prm%kt_flat*outer2([-n(2), n(1)], [-n(2), n(1)])
        s = 0
      else
        r = prm%curved
        n = [-sin(bR), -cos(bR)]
        P = [prm%pitch/2, prm%y_P]
        t = [-n(2), n(1)]
        Kc = prm%kn_curved*outer2(n, n) + prm%kt_curved*outer2(t, t)
        s = 3
      end if
      ! damper point: (x - theta r_y, y + theta r_x); platform point: (u, v) + gamma a
      G = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, -r(2), r(1)], [2, 3])
      E = 0
      E(:, s+1) = [1.0_wp, 0.0_wp]
      E(:, s+2) = [0.0_wp, 1.0_wp]
      E(:, s+3) = [-(r(2) - P(2)), r(1) - P(1)]
      Kqq = Kqq + matmul(transpose(G), matmul(Kc, G))
      Kqx = Kqx + matmul(transpose(G), matmul(Kc, E))
      Kxx = Kxx + matmul(transpose(E), matmul(Kc, E))
    end do
    inv = inverse3(Kqq)
    Kd = Kxx - matmul(transpose(Kqx), matmul(inv, Kqx))
  end function stuck_stiffness

  !> Frequency [Hz] of the peak of |gamma_P| of blade A with Kphi on (u_P, v_P, gamma_P) =
  !> (-w_P, 0, gamma_P): bisection on the sign of d|z_g|^2/domega = 2 Re(conj(z_g) z_g'),
  !> z = D^-1 e_E, z' = -D^-1 D' z from dense complex solves (the peak is too flat for a
  !> search on |z_g| itself to reach 1e-8).
  real(wp) function linear_peak(blade, Kphi) result(f)
    type(blade_type), intent(in) :: blade
    complex(wp), intent(in) :: Kphi(3, 3)
    real(wp) :: a, b, c
    integer :: it
    a = 2*pi*150
    b = 2*pi*230
    do it = 1, 200
      c = 0.5_wp*(a + b)
      if (b - a < 1e-14_wp*b) exit
      if (slope(c) > 0) then
        a = c
      else
        b = c
      end if
    end do
    f = (a + b)/(4*pi)
  contains
    real(wp) function slope(w)
      real(wp), intent(in) :: w
      complex(wp), allocatable :: D(:, :), z(:, :), B(:, :), dD(:, :)
      integer, allocatable :: ipiv(:)
      integer :: nd, info
      nd = blade%ndof
      allocate(B(nd, 3), z(nd, 2), ipiv(nd))
      B = 0
      B(blade%gamma_dof - 1, 1) = -1
      B(blade%gamma_dof, 3) = 1
      D = cmplx(blade%K - w**2*blade%M, w*blade%beta*blade%K, wp) + &
        & matmul(B, matmul(Kphi, transpose(B)))
      dD = cmplx(-2*w*blade%M, blade%beta*blade%K, wp)
      z = 0
      z(blade%exc_dof, 1) = 1
      call zgesv(nd, 1, D, nd, ipiv, z, nd, info)
      z(:, 2) = -matmul(dD, z(:, 1))
      call zgetrs('N', nd, 1, D, nd, ipiv, z(:, 2), nd, info)
      slope = 2*real(conjg(z(blade%gamma_dof, 1))*z(blade%gamma_dof, 2), wp)
    end function slope
  end function linear_peak

  pure function outer2(a, b) result(c)
    real(wp), intent(in) :: a(2), b(2)
    real(wp) :: c(2, 2)
    c(:, 1) = a*b(1)
    c(:, 2) = a*b(2)
  end function outer2

  pure function inverse3(A) result(B)
    real(wp), intent(in) :: A(3, 3)
    real(wp) :: B(3, 3), det
    B(1, 1) = A(2, 2)*A(3, 3) - A(2, 3)*A(3, 2)
    B(1, 2) = A(1, 3)*A(3, 2) - A(1, 2)*A(3, 3)
    B(1, 3) = A(1, 2)*A(2, 3) - A(1, 3)*A(2, 2)
    B(2, 1) = A(2, 3)*A(3, 1) - A(2, 1)*A(3, 3)
    B(2, 2) = A(1, 1)*A(3, 3) - A(1, 3)*A(3, 1)
    B(2, 3) = A(1, 3)*A(2, 1) - A(1, 1)*A(2, 3)
    B(3, 1) = A(2, 1)*A(3, 2) - A(2, 2)*A(3, 1)
    B(3, 2) = A(1, 2)*A(3, 1) - A(1, 1)*A(3, 2)
    B(3, 3) = A(1, 1)*A(2, 2) - A(1, 2)*A(2, 1)
    det = A(1, 1)*B(1, 1) + A(1, 2)*B(2, 1) + A(1, 3)*B(3, 1)
    B = B/det
  end function inverse3
end module test_traveling
