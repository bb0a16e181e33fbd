!> The plain-array API (kernel/src/api/legacy/): the Jenkins describing function of
!> PHYSICS.md 2.4 through UDMAP_TABLE_ARRAYS; blade A through UDMAP_BACKBONE_ARRAYS,
!> UDMAP_RESPONSE_ARRAYS and UDMAP_CURVE_ARRAYS against the derived-type API; every INFO code.
module test_api_legacy
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  use udmap, only: wp, error_type, beam_params_type, blade_type, new_beam_blade, &
    & asymmetric_params_type, damper_type, new_asymmetric_damper, analysis_type, model_type, &
    & point_type, curve_type, new_model, limit_force, backbone, response, response_curves, &
    & udmap_version_numbers, udmap_table_arrays, udmap_backbone_arrays, udmap_response_arrays, &
    & udmap_curve_arrays, udmap_version_major, udmap_version_minor, udmap_version_patch, &
    & UDMAP_EPHYSICS
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  private
  public :: collect_api_legacy

  real(wp), parameter :: beam_a(14) = [170e9_wp, 8200.0_wp, 0.002_wp, 0.020_wp, 0.008_wp, &
    & 0.020_wp, 0.010_wp, 0.021_wp, 1.4e-6_wp, 0.120_wp, 0.004_wp, 0.030_wp, 8.0_wp, 24.0_wp]
  real(wp), parameter :: damper_a(16) = [900.0_wp, 0.3_wp, 0.026_wp, 0.006_wp, 45.0_wp, &
    & 45.0_wp, -6.724e-3_wp, -1.724e-3_wp, -1.068e-3_wp, 3.932e-3_wp, 3.268e-3_wp, &
    & 1.768e-3_wp, 60e6_wp, 40e6_wp, 80e6_wp, 50e6_wp]
  real(wp), parameter :: band(2) = [150.0_wp, 230.0_wp]
  real(wp), parameter :: forces(3) = [1.0_wp, 2.0_wp, 5.0_wp]

contains

  !> The plain-array API (kernel/src/api/legacy/).
  subroutine collect_api_legacy(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("version_numbers", version_numbers), &
      & new_unittest("jenkins_table", jenkins_table), &
      & new_unittest("blade_a_against_module_api", blade_a_against_module_api), &
      & new_unittest("info_codes", info_codes)]
  end subroutine collect_api_legacy

  !> The version numbers of the plain-array API are the module's.
  subroutine version_numbers(suite)
    type(test_suite), intent(inout) :: suite
    integer :: major, minor, patch
    call udmap_version_numbers(major, minor, patch)
    call check_true(suite, "version numbers", major == udmap_version_major .and. &
      & minor == udmap_version_minor .and. patch == udmap_version_patch)
  end subroutine version_numbers

  !> PHYSICS.md 2.4: kt = 2, M_slip = 3 at a = 1.6, 2, 5 (six digits given); a = 1 is stuck.
  subroutine jenkins_table(suite)
    type(test_suite), intent(inout) :: suite
    real(wp) :: gamma(4), k_re(4), k_im(4), base(6)
    integer :: info
    gamma = [1.0_wp, 1.6_wp, 2.0_wp, 5.0_wp]
    call udmap_table_arrays([2.0_wp, 3.0_wp], 2, 4, gamma, k_re, k_im, base, info)
    call check_true(suite, "jenkins table info", info == 0)
    call check_close(suite, "jenkins k_re stuck", k_re(1), 2.0_wp, 1e-14_wp)
    call check_close(suite, "jenkins k_im stuck", k_im(1), 0.0_wp, 0.0_wp, 1e-14_wp)
    call check_close(suite, "jenkins k_re a=1.6", k_re(2), 1.947954_wp, 0.0_wp, 5e-7_wp)
    call check_close(suite, "jenkins k_im a=1.6", k_im(2), 0.149208_wp, 0.0_wp, 5e-7_wp)
    call check_close(suite, "jenkins k_re a=2", k_re(3), 1.608998_wp, 0.0_wp, 5e-7_wp)
    call check_close(suite, "jenkins k_im a=2", k_im(3), 0.477465_wp, 0.0_wp, 5e-7_wp)
    call check_close(suite, "jenkins k_re a=5", k_re(4), 0.504632_wp, 0.0_wp, 5e-7_wp)
    call check_close(suite, "jenkins k_im a=5", k_im(4), 0.534761_wp, 0.0_wp, 5e-7_wp)
    ! gamma_b = M_slip/kt, Delta_M = 2 M_slip
    call check_close(suite, "jenkins gamma_b", base(1), 1.5_wp, 1e-14_wp)
    call check_close(suite, "jenkins Delta_M", base(3) - base(4), 6.0_wp, 1e-14_wp)
    call check_close(suite, "jenkins k_stuck", base(5), 2.0_wp, 1e-14_wp)
  end subroutine jenkins_table

  !> The arrays give what the derived-type API gives for the same blade and damper.
  subroutine blade_a_against_module_api(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: bp
    type(asymmetric_params_type) :: ap
    type(analysis_type) :: analysis
    type(blade_type), target :: blade
    type(damper_type), target :: damper
    type(model_type) :: model
    type(point_type), allocatable :: points(:)
    type(curve_type), allocatable :: curves(:)
    type(error_type), allocatable :: error
    real(wp) :: gamma_P(3), f_res(3), sigma_a(3), u_E(3), F_lim, F_lim_ref
    real(wp) :: f(5000), gc(5000), sc(5000), d1(1), d2(1), d3(1)
    integer :: regime(3), branch(5000), ibranch(1), info, npts, nquery, i
    character(len=16) :: tag

    bp = beam_params_type(E=beam_a(1), rho=beam_a(2), zeta=beam_a(3), neck_L=beam_a(4), &
      & neck_h=beam_a(5), neck_b=beam_a(6), platform_L=beam_a(7), platform_m=beam_a(8), &
      & platform_J=beam_a(9), airfoil_L=beam_a(10), airfoil_h=beam_a(11), &
      & airfoil_b=beam_a(12), neck_elements=8, airfoil_elements=24)
    ap = asymmetric_params_type(CF=damper_a(1), mu=damper_a(2), pitch=damper_a(3), &
      & y_P=damper_a(4), beta_L_deg=damper_a(5), beta_R_deg=damper_a(6), &
      & flat=reshape(damper_a(7:10), [2, 2]), curved=damper_a(11:12), kn_flat=damper_a(13), &
      & kt_flat=damper_a(14), kn_curved=damper_a(15), kt_curved=damper_a(16))
    analysis%f_min = band(1)
    analysis%f_max = band(2)
    call new_beam_blade(blade, bp, error)
    call check_no_error(suite, "module blade", error)
    call new_asymmetric_damper(damper, ap, error)
    call check_no_error(suite, "module damper", error)
    call new_model(model, blade, damper, analysis, error)
    call check_no_error(suite, "module model", error)
    call limit_force(model, F_lim_ref, error)
    call check_no_error(suite, "module F_lim", error)

    call backbone(model, forces, points, error)
    call check_no_error(suite, "module backbone", error)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, band, 2, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "backbone arrays info", info == 0)
    call check_close(suite, "backbone arrays F_lim", F_lim, F_lim_ref, 1e-14_wp)
    do i = 1, 3
      write(tag, '(a,i0)') " F_E#", i
      call check_close(suite, "backbone gamma_P"//trim(tag), gamma_P(i), points(i)%gamma_P, &
        & 1e-13_wp)
      call check_close(suite, "backbone f_res"//trim(tag), f_res(i), points(i)%f_res, 1e-13_wp)
      call check_close(suite, "backbone sigma_a"//trim(tag), sigma_a(i), points(i)%sigma_a, &
        & 1e-13_wp)
      call check_close(suite, "backbone u_E"//trim(tag), u_E(i), points(i)%u_E, 1e-13_wp)
      call check_true(suite, "backbone regime"//trim(tag), regime(i) == points(i)%regime)
    end do

    call response(model, 196.0_wp, forces, points, error)
    call check_no_error(suite, "module response", error)
    call udmap_response_arrays(beam_a, 14, damper_a, 16, band, 2, 196.0_wp, 3, forces, &
      & gamma_P, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "response arrays info", info == 0)
    do i = 1, 3
      write(tag, '(a,i0)') " F_E#", i
      call check_close(suite, "response gamma_P"//trim(tag), gamma_P(i), points(i)%gamma_P, &
        & 1e-13_wp)
      call check_close(suite, "response sigma_a"//trim(tag), sigma_a(i), points(i)%sigma_a, &
        & 1e-13_wp)
    end do

    call response_curves(model, [2.0_wp], 50, curves, error)
    call check_no_error(suite, "module curves", error)
    call udmap_curve_arrays(beam_a, 14, damper_a, 16, band, 2, 2.0_wp, 50, -1, nquery, d1, &
      & d2, d3, ibranch, info)
    call check_true(suite, "curve size query", info == 0 .and. nquery == size(curves(1)%f))
    call udmap_curve_arrays(beam_a, 14, damper_a, 16, band, 2, 2.0_wp, 50, size(f), npts, f, &
      & gc, sc, branch, info)
    call check_true(suite, "curve arrays info and size", info == 0 .and. npts == nquery)
    if (npts == size(curves(1)%f)) then
      call check_close(suite, "curve f", maxval(abs(f(1:npts) - curves(1)%f)), 0.0_wp, &
        & 0.0_wp, 1e-9_wp)
      call check_close(suite, "curve gamma_P", maxval(abs(gc(1:npts) - curves(1)%gamma_P)), &
        & 0.0_wp, 0.0_wp, 1e-15_wp)
      call check_true(suite, "curve branch", all(branch(1:npts) == curves(1)%branch))
    end if
    call udmap_curve_arrays(beam_a, 14, damper_a, 16, band, 2, 2.0_wp, 50, npts - 1, nquery, &
      & f, gc, sc, branch, info)
    call check_true(suite, "curve MAXPTS too small: INFO = -9, NPTS the size needed", &
      & info == -9 .and. nquery == npts)
  end subroutine blade_a_against_module_api

  !> INFO = -i names the argument; 3 for a physics failure; outputs zero.
  subroutine info_codes(suite)
    type(test_suite), intent(inout) :: suite
    real(wp) :: beam(14), damper(16), gamma_P(3), f_res(3), sigma_a(3), u_E(3), F_lim
    real(wp) :: k_re(1), k_im(1), base(6), nan
    integer :: regime(3), info
    nan = ieee_value(1.0_wp, ieee_quiet_nan)

    call udmap_backbone_arrays(beam_a, 13, damper_a, 16, band, 2, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "NBEAM = 13: INFO = -2", info == -2)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 5, band, 2, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "NDAMPER = 5: INFO = -4", info == -4)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, band, 1, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "NANALY = 1: INFO = -6", info == -6)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, band, 2, -1, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "NFORCE = -1: INFO = -7", info == -7)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, band, 2, 3, [1.0_wp, -2.0_wp, 3.0_wp], &
      & gamma_P, f_res, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "negative force: INFO = -8", info == -8)

    beam = beam_a
    beam(1) = nan
    call udmap_backbone_arrays(beam, 14, damper_a, 16, band, 2, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "E = NaN: INFO = -1", info == -1)
    call check_true(suite, "outputs zero on failure", all(gamma_P == 0) .and. F_lim == 0)
    beam = beam_a
    beam(14) = 24.5_wp
    call udmap_backbone_arrays(beam, 14, damper_a, 16, band, 2, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "airfoil_elements = 24.5: INFO = -1", info == -1)
    damper = damper_a
    damper(2) = -0.3_wp
    call udmap_backbone_arrays(beam_a, 14, damper, 16, band, 2, 3, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "mu < 0: INFO = -3", info == -3)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, [230.0_wp, 150.0_wp], 2, 3, forces, &
      & gamma_P, f_res, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "f_max < f_min: INFO = -5", info == -5)
    call udmap_response_arrays(beam_a, 14, damper_a, 16, band, 2, 250.0_wp, 3, forces, &
      & gamma_P, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "f_exc outside the band: INFO = -7", info == -7)
    call udmap_table_arrays(damper_a, 16, 1, [0.0_wp], k_re, k_im, base, info)
    call check_true(suite, "gamma = 0: INFO = -4", info == -4)

    ! ANALYS(6) = harmonics, ANALYS(7) = harmonic_tol: H = 3 against the module API, and a
    ! harmonics that is no whole number or out of range is an invalid ANALYS
    block
      type(blade_type), target :: bl
      type(damper_type), target :: dm
      type(model_type) :: md
      type(analysis_type) :: an
      type(point_type), allocatable :: pts(:)
      type(error_type), allocatable :: err
      type(asymmetric_params_type) :: dp
      call udmap_backbone_arrays(beam_a, 14, damper_a, 16, [band, 80e6_wp, 1e-12_wp, 24.0_wp, &
        & 3.0_wp, 1e-3_wp], 7, 2, forces(1:2), gamma_P(1:2), f_res(1:2), sigma_a(1:2), &
        & u_E(1:2), regime(1:2), F_lim, info)
      call check_true(suite, "ANALYS(6) = 3: info", info == 0)
      call new_beam_blade(bl, beam_params_type(E=beam_a(1), rho=beam_a(2), zeta=beam_a(3), &
        & neck_L=beam_a(4), neck_h=beam_a(5), neck_b=beam_a(6), platform_L=beam_a(7), &
        & platform_m=beam_a(8), platform_J=beam_a(9), airfoil_L=beam_a(10), &
        & airfoil_h=beam_a(11), airfoil_b=beam_a(12), neck_elements=nint(beam_a(13)), &
        & airfoil_elements=nint(beam_a(14))), err)
      dp = asymmetric_params_type(CF=damper_a(1), mu=damper_a(2), pitch=damper_a(3), &
        & y_P=damper_a(4), beta_L_deg=damper_a(5), beta_R_deg=damper_a(6), &
        & flat=reshape(damper_a(7:10), [2, 2]), curved=damper_a(11:12), &
        & kn_flat=damper_a(13), kt_flat=damper_a(14), kn_curved=damper_a(15), &
        & kt_curved=damper_a(16))
      call new_asymmetric_damper(dm, dp, err)
      an%f_min = band(1)
      an%f_max = band(2)
      an%harmonics = 3
      call new_model(md, bl, dm, an, err)
      call backbone(md, forces(1:2), pts, err)
      call check_no_error(suite, "module backbone H = 3", err)
      if (allocated(pts)) then
        call check_close(suite, "ANALYS(6) = 3: gamma_P as the module API", gamma_P(2), &
          & pts(2)%gamma_P, 1e-12_wp)
        call check_close(suite, "ANALYS(6) = 3: sigma_a as the module API", sigma_a(2), &
          & pts(2)%sigma_a, 1e-12_wp)
      end if
    end block
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, [band, 80e6_wp, 1e-12_wp, 24.0_wp, &
      & 2.5_wp], 6, 3, forces, gamma_P, f_res, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "ANALYS(6) = 2.5: INFO = -5", info == -5)
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, [band, 80e6_wp, 1e-12_wp, 24.0_wp, &
      & 65.0_wp], 6, 3, forces, gamma_P, f_res, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "ANALYS(6) = 65: INFO = -5", info == -5)

    ! The first mode (near 197 Hz with the damper) lies outside 300..400 Hz.
    call udmap_backbone_arrays(beam_a, 14, damper_a, 16, [300.0_wp, 400.0_wp], 2, 3, forces, &
      & gamma_P, f_res, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "no resonance in the band: INFO = 3", info == UDMAP_EPHYSICS)

    ! zeta = 0: above F_lim the response is unbounded: REGIME = 4 and zeros.
    beam = beam_a
    beam(3) = 0
    call udmap_backbone_arrays(beam, 14, damper_a, 16, band, 2, 0, forces, gamma_P, f_res, &
      & sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "NFORCE = 0 gives F_lim", info == 0 .and. F_lim > 0)
    call udmap_backbone_arrays(beam, 14, damper_a, 16, band, 2, 3, &
      & [0.5_wp, 1.5_wp, 2.0_wp]*F_lim, gamma_P, f_res, sigma_a, u_E, regime, F_lim, info)
    call check_true(suite, "zeta = 0 info", info == 0)
    call check_true(suite, "zeta = 0 below F_lim: finite", regime(1) <= 2 .and. gamma_P(1) > 0)
    call check_true(suite, "zeta = 0 above F_lim: REGIME = 4, zeros", all(regime(2:3) == 4) &
      & .and. all(gamma_P(2:3) == 0) .and. all(sigma_a(2:3) == 0))
  end subroutine info_codes
end module test_api_legacy
