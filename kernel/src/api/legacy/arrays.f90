!> Plain-array API for codes that cannot use derived types (FORTRAN 77/90 programs, or any
!> language that can pass arrays and scalars by reference): LAPACK-style subroutines with
!> explicit-shape arrays, scalar arguments and an INFO code. No module is needed to call them:
!>
!>       DOUBLE PRECISION BEAM(14), DAMPER(16), ANALYS(2), FE(3), GAMMAP(3), FRES(3),
!>      $                 SIGMAA(3), UE(3), FLIM
!>       INTEGER REGIME(3), INFO
!>       CALL UDMAP_BACKBONE_ARRAYS(BEAM, 14, DAMPER, 16, ANALYS, 2, 3, FE, GAMMAP, FRES,
!>      $                           SIGMAA, UE, REGIME, FLIM, INFO)
!>
!> The symbols are the lower-case names with one trailing underscore (udmap_backbone_arrays_),
!> which is what gfortran and most Unix Fortran compilers generate for an external
!> subroutine; from C declare e.g. `void udmap_backbone_arrays_(const double *beam,
!> const int *nbeam, ...)`. Fortran 90+ callers get explicit interfaces from `use udmap`.
!>
!> Parameter arrays (in the order of the C structs in udmap.h):
!>   BEAM(14), the built-in beam blade (udmap_beam_params, PHYSICS.md 1.1):
!>     1 E [Pa], 2 rho [kg/m^3], 3 zeta [1], 4 neck_L, 5 neck_h, 6 neck_b [m],
!>     7 platform_L [m], 8 platform_m [kg], 9 platform_J [kg m^2],
!>     10 airfoil_L, 11 airfoil_h, 12 airfoil_b [m],
!>     13 neck_elements, 14 airfoil_elements (whole numbers; airfoil_elements even).
!>   DAMPER(NDAMPER), the damper; its kind follows from NDAMPER:
!>     NDAMPER = 16, asymmetric flat/curved damper (udmap_asymmetric_params, PHYSICS.md 2.1):
!>       1 CF [N], 2 mu [1], 3 pitch [m], 4 y_P [m], 5 beta_L_deg, 6 beta_R_deg [deg],
!>       7 flat1_x, 8 flat1_y, 9 flat2_x, 10 flat2_y, 11 curved_x, 12 curved_y [m],
!>       13 kn_flat, 14 kt_flat, 15 kn_curved, 16 kt_curved [N/m];
!>     NDAMPER = 2, rotational Jenkins element (PHYSICS.md 2.4): 1 kt [N m/rad], 2 M_slip [N m].
!>   ANALYS(NANALY), the analysis settings (udmap_analysis), 2 <= NANALY <= 8; entries beyond
!>     NANALY take their defaults:
!>     1 f_min, 2 f_max [Hz] (band of the resonance), 3 sigma_all [Pa] (default 80e6),
!>     4 rtol (default 1e-12), 5 grid_per_decade (whole number, default 24),
!>     6 harmonics (whole number: 1 the single-harmonic method (default), 2..64 harmonics
!>     0..H in multi-harmonic layers, 0 automatic; PHYSICS.md 4.1), 7 harmonic_tol (default
!>     1e-3), 8 ibpa_deg (the interblade phase angle of a traveling wave [deg], PHYSICS.md
!>     2.6; default 0, in phase). With harmonics /= 1 GAMMAP and SIGMAA stay first-harmonic
!>     amplitudes.
!>
!> INFO: 0 success; -i: the i-th argument is invalid (for an array, one of its entries: the
!> derived-type API and the C API give the message naming it); UDMAP_EPHYSICS = 3: a physics
!> failure (jammed damper, no resonance in the band); UDMAP_ENUMERIC = 4: a LAPACK/ARPACK
!> failure. On INFO /= 0 the outputs are zero.
!>
!> Every call builds the blade, the damper (tracing its loops) and the model anew and keeps
!> nothing: pass all forces of interest in one call. Calls are independent and thread-safe as
!> far as the kernel is (see udmap.h).
submodule (udmap_api_legacy_interface) udmap_api_legacy_arrays
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_core_version, only: udmap_version_major, udmap_version_minor, udmap_version_patch
  ! the array layouts, generated from kernel/parameters.toml
  use udmap_api_legacy_parameters, only: LEGACY_BEAM_NECK_ELEMENTS, &
    & LEGACY_BEAM_AIRFOIL_ELEMENTS, LEGACY_JENKINS_KT, LEGACY_JENKINS_M_SLIP, &
    & LEGACY_ANALYSIS_F_MIN, LEGACY_ANALYSIS_F_MAX, LEGACY_ANALYSIS_SIGMA_ALL, &
    & LEGACY_ANALYSIS_RTOL, LEGACY_ANALYSIS_GRID_PER_DECADE, LEGACY_ANALYSIS_HARMONICS, &
    & LEGACY_ANALYSIS_HARMONIC_TOL, LEGACY_ANALYSIS_IBPA_DEG, beam_from_array, &
    & asymmetric_from_array
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_damper_type, only: damper_type, new_asymmetric_damper, new_jenkins_damper
  use udmap_mapping_model, only: analysis_type, point_type, curve_type, model_type, new_model, &
    & limit_force, backbone, response, response_curves, REGIME_LIMIT
  implicit none

contains

  !> UDMAP_VERSION_NUMBERS(MAJOR, MINOR, PATCH): the version of the library.
  !>   MAJOR, MINOR, PATCH (output) INTEGER: e.g. 0, 1, 0 for "0.1.0".
  module procedure udmap_version_numbers
    major = int(udmap_version_major, c_int)
    minor = int(udmap_version_minor, c_int)
    patch = int(udmap_version_patch, c_int)
  end procedure udmap_version_numbers

  !> UDMAP_TABLE_ARRAYS(DAMPER, NDAMPER, NGAMMA, GAMMA, KRE, KIM, BASE, INFO):
  !> the damper's complex stiffness k(gamma) = KRE + i KIM (PHYSICS.md 2.2) and its base cycle.
  !>   1 DAMPER (input) DOUBLE PRECISION array, dimension (NDAMPER): see the module header.
  !>   2 NDAMPER (input) INTEGER: 16 (asymmetric damper) or 2 (Jenkins element).
  !>   3 NGAMMA (input) INTEGER: number of amplitudes, >= 0.
  !>   4 GAMMA (input) DOUBLE PRECISION array, dimension (NGAMMA): rotation amplitudes [rad],
  !>     positive.
  !>   5 KRE (output) DOUBLE PRECISION array, dimension (NGAMMA): k_Re [N m/rad].
  !>   6 KIM (output) DOUBLE PRECISION array, dimension (NGAMMA): k_Im [N m/rad], >= 0.
  !>   7 BASE (output) DOUBLE PRECISION array, dimension (6): gamma_b [rad], gamma_s [rad],
  !>     M_max [N m], M_min [N m], k_stuck [N m/rad], lift_off (1 if a contact opens, else 0).
  !>   8 INFO (output) INTEGER: 0, -i for an invalid i-th argument, or 3, 4 (module header).
  module procedure udmap_table_arrays
    type(damper_type) :: d
    type(error_type), allocatable :: error
    complex(wp) :: k
    integer :: i

    base = 0
    info = 0
    if (ndamper /= LEGACY_NDAMPER_ASYMMETRIC .and. ndamper /= LEGACY_NDAMPER_JENKINS) then
      info = -2
    else if (ngamma < 0) then
      info = -3
    end if
    if (info /= 0) return
    k_re = 0
    k_im = 0
    do i = 1, ngamma
      if (.not.(gamma(i) > 0 .and. gamma(i) <= huge(1.0_c_double))) info = -4
    end do
    if (info /= 0) return
    call build_damper(damper, ndamper, d, error)
    if (allocated(error)) then
      info = info_of(error, 1)
      return
    end if
    if (any(gamma > d%gamma_max)) then
      info = -4  ! a measured table without extrapolation ends at its last row
      return
    end if
    do i = 1, ngamma
      k = d%stiffness(real(gamma(i), wp))
      k_re(i) = real(k%re, c_double)
      k_im(i) = real(k%im, c_double)
    end do
    base = real([d%gamma_b, d%gamma_s, d%M_max, d%M_min, d%k_stuck, &
      & merge(1.0_wp, 0.0_wp, d%lift_off)], c_double)
  end procedure udmap_table_arrays

  !> UDMAP_BACKBONE_ARRAYS(BEAM, NBEAM, DAMPER, NDAMPER, ANALYS, NANALY, NFORCE, FE, GAMMAP,
  !>                       FRES, SIGMAA, UE, REGIME, FLIM, INFO):
  !> the peaks of the non-linear forced response (PHYSICS.md 4) of the beam blade with the
  !> damper, one per excitation force, and the limit force (PHYSICS.md 5).
  !>   1 BEAM (input) DOUBLE PRECISION array, dimension (NBEAM): the blade (module header).
  !>   2 NBEAM (input) INTEGER: 14.
  !>   3 DAMPER (input) DOUBLE PRECISION array, dimension (NDAMPER): the damper.
  !>   4 NDAMPER (input) INTEGER: 16 (asymmetric damper) or 2 (Jenkins element).
  !>   5 ANALYS (input) DOUBLE PRECISION array, dimension (NANALY): f_min, f_max [Hz], ...
  !>   6 NANALY (input) INTEGER: 2 to 5.
  !>   7 NFORCE (input) INTEGER: number of forces, >= 0 (0: only FLIM is computed).
  !>   8 FE (input) DOUBLE PRECISION array, dimension (NFORCE): excitation force amplitudes at
  !>     E [N], positive.
  !>   9 GAMMAP (output) DOUBLE PRECISION array, dimension (NFORCE): platform rotation
  !>     amplitude at the peak [rad] (the largest root if there are several).
  !>  10 FRES (output) DOUBLE PRECISION array, dimension (NFORCE): peak frequency [Hz].
  !>  11 SIGMAA (output) DOUBLE PRECISION array, dimension (NFORCE): alternating stress
  !>     amplitude at the airfoil-platform junction at the peak [Pa].
  !>  12 UE (output) DOUBLE PRECISION array, dimension (NFORCE): displacement amplitude at E [m].
  !>  13 REGIME (output) INTEGER array, dimension (NFORCE): 0 stuck, 1 partial slip, 2 full
  !>     slip, 3 at or above F_lim, 4 unbounded (zeta = 0 and F_E >= F_lim: the numbers are 0).
  !>  14 FLIM (output) DOUBLE PRECISION: the limit force F_lim [N].
  !>  15 INFO (output) INTEGER: 0, -i for an invalid i-th argument, or 3, 4 (module header).
  module procedure udmap_backbone_arrays
    call solve_points(beam, nbeam, damper, ndamper, analysis, nanalysis, nforce, F_E, gamma_P, &
      & f_res, sigma_a, u_E, regime, F_lim, info)
  end procedure udmap_backbone_arrays

  !> UDMAP_RESPONSE_ARRAYS(BEAM, NBEAM, DAMPER, NDAMPER, ANALYS, NANALY, FEXC, NFORCE, FE,
  !>                       GAMMAP, SIGMAA, UE, REGIME, FLIM, INFO):
  !> the steady response at the excitation frequency FEXC (PHYSICS.md 4, last paragraph).
  !>   1-6 BEAM, NBEAM, DAMPER, NDAMPER, ANALYS, NANALY: as in UDMAP_BACKBONE_ARRAYS.
  !>   7 FEXC (input) DOUBLE PRECISION: excitation frequency [Hz], f_min <= FEXC <= f_max.
  !>   8 NFORCE (input) INTEGER: number of forces, >= 0.
  !>   9 FE (input) DOUBLE PRECISION array, dimension (NFORCE): force amplitudes [N], positive.
  !>  10 GAMMAP (output) DOUBLE PRECISION array, dimension (NFORCE): platform rotation
  !>     amplitude [rad] (the largest root if there are several).
  !>  11 SIGMAA (output) DOUBLE PRECISION array, dimension (NFORCE): stress amplitude [Pa].
  !>  12 UE (output) DOUBLE PRECISION array, dimension (NFORCE): displacement amplitude at E [m].
  !>  13 REGIME (output) INTEGER array, dimension (NFORCE): as in UDMAP_BACKBONE_ARRAYS.
  !>  14 FLIM (output) DOUBLE PRECISION: the limit force F_lim [N].
  !>  15 INFO (output) INTEGER: 0, -i for an invalid i-th argument, or 3, 4 (module header).
  module procedure udmap_response_arrays
    real(c_double), allocatable :: f_res(:)
    allocate(f_res(max(nforce, 0_c_int)))
    call solve_points(beam, nbeam, damper, ndamper, analysis, nanalysis, nforce, F_E, gamma_P, &
      & f_res, sigma_a, u_E, regime, F_lim, info, f_exc)
  end procedure udmap_response_arrays

  !> UDMAP_CURVE_ARRAYS(BEAM, NBEAM, DAMPER, NDAMPER, ANALYS, NANALY, FE, LAYERS, MAXPTS,
  !>                    NPTS, F, GAMMAP, SIGMAA, BRANCH, INFO):
  !> the non-linear response curve for one force by amplitude layered force mapping
  !> (PHYSICS.md 3), points in path order.
  !>   1-6 BEAM, NBEAM, DAMPER, NDAMPER, ANALYS, NANALY: as in UDMAP_BACKBONE_ARRAYS.
  !>   7 FE (input) DOUBLE PRECISION: excitation force amplitude [N], positive.
  !>   8 LAYERS (input) INTEGER: number of amplitude layers before adaptive refinement,
  !>     >= 2 (the CLI's default is 200).
  !>   9 MAXPTS (input) INTEGER: the length of F, GAMMAP, SIGMAA and BRANCH. If MAXPTS = -1, a
  !>     size query: only NPTS is computed (LAPACK's LWORK = -1 convention).
  !>  10 NPTS (output) INTEGER: number of points of the curve (also when MAXPTS is too small,
  !>     in which case INFO = -9 and nothing else is returned).
  !>  11 F (output) DOUBLE PRECISION array, dimension (MAXPTS): frequency [Hz].
  !>  12 GAMMAP (output) DOUBLE PRECISION array, dimension (MAXPTS): rotation amplitude [rad].
  !>  13 SIGMAA (output) DOUBLE PRECISION array, dimension (MAXPTS): stress amplitude [Pa].
  !>  14 BRANCH (output) INTEGER array, dimension (MAXPTS): 0 below the peak frequency of the
  !>     layer, 1 above, 2 on the backbone.
  !>  15 INFO (output) INTEGER: 0, -i for an invalid i-th argument, or 3, 4 (module header).
  module procedure udmap_curve_arrays
    type(blade_type), target :: blade
    type(damper_type), target :: d
    type(model_type) :: model
    type(curve_type), allocatable :: curves(:)
    type(error_type), allocatable :: error
    real(c_double) :: F_lim, force(1)

    npts = 0
    force(1) = F_E
    call check_common(nbeam, ndamper, nanalysis, 1_c_int, force, 7, 7, info)
    if (info /= 0) return
    if (layers < 2) then
      info = -8
    else if (maxpts < -1) then
      info = -9
    end if
    if (info /= 0) return
    call build_model(beam, damper, ndamper, analysis, nanalysis, blade, d, model, F_lim, &
      & 1, 3, 5, info)
    if (info /= 0) return
    call response_curves(model, [real(F_E, wp)], int(layers), curves, error)
    if (allocated(error)) then
      info = info_of(error, 7)
      return
    end if
    npts = int(size(curves(1)%f), c_int)
    if (maxpts == -1) return
    if (maxpts < npts) then
      info = -9
      return
    end if
    f(1:npts) = curves(1)%f
    gamma_P(1:npts) = curves(1)%gamma_P
    sigma_a(1:npts) = curves(1)%sigma_a
    branch(1:npts) = int(curves(1)%branch, c_int)
  end procedure udmap_curve_arrays

  ! ------------------------------------------------------------------ helpers

  !> UDMAP_BACKBONE_ARRAYS or, given f_exc, UDMAP_RESPONSE_ARRAYS (whose arguments from
  !> NFORCE on stand one later, FEXC being the 7th).
  subroutine solve_points(beam, nbeam, damper, ndamper, analysis, nanalysis, nforce, F_E, &
      & gamma_P, f_res, sigma_a, u_E, regime, F_lim, info, f_exc)
    integer(c_int), intent(in) :: nbeam, ndamper, nanalysis, nforce
    real(c_double), intent(in) :: beam(*), damper(*), analysis(*), F_E(*)
    real(c_double), intent(out) :: gamma_P(*), f_res(*), sigma_a(*), u_E(*), F_lim
    integer(c_int), intent(out) :: regime(*), info
    real(c_double), intent(in), optional :: f_exc
    type(blade_type), target :: blade
    type(damper_type), target :: d
    type(model_type) :: model
    type(point_type), allocatable :: points(:)
    type(error_type), allocatable :: error
    integer :: shift

    shift = merge(1, 0, present(f_exc))
    F_lim = 0
    call check_common(nbeam, ndamper, nanalysis, nforce, F_E, 7 + shift, 8 + shift, info)
    if (info /= 0) return
    call zero_points(nforce, gamma_P, f_res, sigma_a, u_E, regime)
    if (present(f_exc)) then
      if (.not.(f_exc >= analysis(LEGACY_ANALYSIS_F_MIN) .and. &
        & f_exc <= analysis(LEGACY_ANALYSIS_F_MAX))) then
        info = -7
        return
      end if
    end if
    call build_model(beam, damper, ndamper, analysis, nanalysis, blade, d, model, F_lim, &
      & 1, 3, 5, info)
    if (info /= 0) return
    if (nforce == 0) return
    if (present(f_exc)) then
      call response(model, real(f_exc, wp), real(F_E(1:nforce), wp), points, error)
    else
      call backbone(model, real(F_E(1:nforce), wp), points, error)
    end if
    if (allocated(error)) then
      info = info_of(error, 8 + shift)
      F_lim = 0
      return
    end if
    call store_points(points, gamma_P, f_res, sigma_a, u_E, regime)
  end subroutine solve_points

  !> INFO from a kernel error: -arg for bad input (the argument whose values were rejected),
  !> the status (3 physics, 4 numerics) otherwise.
  pure function info_of(error, arg) result(info)
    type(error_type), intent(in) :: error
    integer, intent(in) :: arg
    integer(c_int) :: info
    if (error%stat == UDMAP_EINPUT) then
      info = int(-arg, c_int)
    else
      info = int(error%stat, c_int)
    end if
  end function info_of

  !> Checks the lengths and the forces (arguments 2, 4, 6, nforce_arg and force_arg).
  subroutine check_common(nbeam, ndamper, nanalysis, nforce, F_E, nforce_arg, force_arg, info)
    integer(c_int), intent(in) :: nbeam, ndamper, nanalysis, nforce
    real(c_double), intent(in) :: F_E(*)
    integer, intent(in) :: nforce_arg, force_arg
    integer(c_int), intent(out) :: info
    integer :: i
    info = 0
    if (nbeam /= LEGACY_NBEAM) then
      info = -2
    else if (ndamper /= LEGACY_NDAMPER_ASYMMETRIC .and. ndamper /= LEGACY_NDAMPER_JENKINS) then
      info = -4
    else if (nanalysis < LEGACY_NANALYSIS_MIN .or. nanalysis > LEGACY_NANALYSIS_MAX) then
      info = -6
    else if (nforce < 0) then
      info = int(-nforce_arg, c_int)
    else
      do i = 1, nforce
        if (.not.(F_E(i) > 0 .and. F_E(i) <= huge(1.0_c_double))) then
          info = int(-force_arg, c_int)
          exit
        end if
      end do
    end if
  end subroutine check_common

  !> Zeroes the per-force outputs.
  pure subroutine zero_points(nforce, gamma_P, f_res, sigma_a, u_E, regime)
    integer(c_int), intent(in) :: nforce
    real(c_double), intent(out) :: gamma_P(*), f_res(*), sigma_a(*), u_E(*)
    integer(c_int), intent(out) :: regime(*)
    gamma_P(1:nforce) = 0
    f_res(1:nforce) = 0
    sigma_a(1:nforce) = 0
    u_E(1:nforce) = 0
    regime(1:nforce) = 0
  end subroutine zero_points

  !> Copies the points into the output arrays; an unbounded point gets REGIME 4 and zeros.
  pure subroutine store_points(points, gamma_P, f_res, sigma_a, u_E, regime)
    type(point_type), intent(in) :: points(:)
    real(c_double), intent(inout) :: gamma_P(*), f_res(*), sigma_a(*), u_E(*)
    integer(c_int), intent(inout) :: regime(*)
    integer :: i
    do i = 1, size(points)
      if (points(i)%unbounded) then
        regime(i) = int(LEGACY_REGIME_UNBOUNDED, c_int)
        cycle
      end if
      gamma_P(i) = real(points(i)%gamma_P, c_double)
      f_res(i) = real(points(i)%f_res, c_double)
      sigma_a(i) = real(points(i)%sigma_a, c_double)
      u_E(i) = real(points(i)%u_E, c_double)
      regime(i) = int(points(i)%regime, c_int)
    end do
  end subroutine store_points

  !> The damper from its parameter array (asymmetric for 16 entries, Jenkins for 2).
  subroutine build_damper(p, n, damper, error)
    real(c_double), intent(in) :: p(*)
    integer(c_int), intent(in) :: n
    type(damper_type), intent(out) :: damper
    type(error_type), allocatable, intent(out) :: error
    if (n == LEGACY_NDAMPER_JENKINS) then
      call new_jenkins_damper(damper, real(p(LEGACY_JENKINS_KT), wp), &
        & real(p(LEGACY_JENKINS_M_SLIP), wp), error)
      return
    end if
    call new_asymmetric_damper(damper, asymmetric_from_array(p(1:LEGACY_NDAMPER_ASYMMETRIC)), &
      & error)
  end subroutine build_damper

  !> Blade, damper and model from the parameter arrays, and F_lim; INFO names the array
  !> (beam_arg, damper_arg, analysis_arg) whose values were rejected.
  subroutine build_model(beam, damper, ndamper, analysis, nanalysis, blade, d, model, F_lim, &
      & beam_arg, damper_arg, analysis_arg, info)
    real(c_double), intent(in) :: beam(*), damper(*), analysis(*)
    integer(c_int), intent(in) :: ndamper, nanalysis
    type(blade_type), target, intent(inout) :: blade
    type(damper_type), target, intent(inout) :: d
    type(model_type), intent(inout) :: model
    real(c_double), intent(out) :: F_lim
    integer, intent(in) :: beam_arg, damper_arg, analysis_arg
    integer(c_int), intent(out) :: info
    type(analysis_type) :: a
    type(error_type), allocatable :: error
    real(wp) :: F

    F_lim = 0
    info = 0
    if (.not.(whole(beam(LEGACY_BEAM_NECK_ELEMENTS)) .and. &
      & whole(beam(LEGACY_BEAM_AIRFOIL_ELEMENTS)))) then
      info = int(-beam_arg, c_int)
      return
    end if
    ! grid_per_decade and harmonics, where given, are whole numbers
    if (.not.all(whole(analysis(LEGACY_ANALYSIS_GRID_PER_DECADE:min(int(nanalysis), &
      & LEGACY_ANALYSIS_HARMONICS))))) then
      info = int(-analysis_arg, c_int)
      return
    end if
    call new_beam_blade(blade, beam_from_array(beam(1:LEGACY_NBEAM)), error)
    if (allocated(error)) then
      info = info_of(error, beam_arg)
      return
    end if
    call build_damper(damper, ndamper, d, error)
    if (allocated(error)) then
      info = info_of(error, damper_arg)
      return
    end if
    a%f_min = real(analysis(LEGACY_ANALYSIS_F_MIN), wp)
    a%f_max = real(analysis(LEGACY_ANALYSIS_F_MAX), wp)
    if (nanalysis >= LEGACY_ANALYSIS_SIGMA_ALL) &
      & a%sigma_all = real(analysis(LEGACY_ANALYSIS_SIGMA_ALL), wp)
    if (nanalysis >= LEGACY_ANALYSIS_RTOL) a%rtol = real(analysis(LEGACY_ANALYSIS_RTOL), wp)
    if (nanalysis >= LEGACY_ANALYSIS_GRID_PER_DECADE) &
      & a%grid_per_decade = nint(analysis(LEGACY_ANALYSIS_GRID_PER_DECADE))
    if (nanalysis >= LEGACY_ANALYSIS_HARMONICS) &
      & a%harmonics = nint(analysis(LEGACY_ANALYSIS_HARMONICS))
    if (nanalysis >= LEGACY_ANALYSIS_HARMONIC_TOL) &
      & a%harmonic_tol = real(analysis(LEGACY_ANALYSIS_HARMONIC_TOL), wp)
    if (nanalysis >= LEGACY_ANALYSIS_IBPA_DEG) &
      & a%ibpa_deg = real(analysis(LEGACY_ANALYSIS_IBPA_DEG), wp)
    call new_model(model, blade, d, a, error)
    if (allocated(error)) then
      info = info_of(error, analysis_arg)
      return
    end if
    call limit_force(model, F, error)
    if (allocated(error)) then
      info = info_of(error, damper_arg)
      return
    end if
    F_lim = real(F, c_double)
  end subroutine build_model

  !> Whether x is a whole number that fits a default integer.
  elemental function whole(x) result(ok)
    real(c_double), intent(in) :: x
    logical :: ok
    ok = abs(x) < real(huge(1), c_double)
    if (ok) ok = x == aint(x)
  end function whole
end submodule udmap_api_legacy_arrays
