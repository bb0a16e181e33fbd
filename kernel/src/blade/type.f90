!> The linear blade (PHYSICS.md 1 and 3): matrices, bare modes and the receptances
!> H_ab(omega) = e_a^T D(omega)^-1 e_b, D = K - omega^2 M + i omega C, between the platform
!> rotation gamma_P (g), the excitation DOF (E) and the root stress functional (s), plus the
!> Sherman-Morrison layer response for a damper stiffness k on gamma_P.
!>
!> How the receptances are evaluated (the hot path of the mapping, millions of calls):
!> - C = beta K (no explicit C): modal sums, exact for this damping,
!>     H_ab = sum_r c_ab,r / (w_r^2 f - omega^2),  f = 1 + i omega beta,
!>   with the products c_ab,r = phi_a,r phi_b,r (and (s_K.phi_r) phi_b,r, (s_M.phi_r) phi_b,r for
!>   the stress sigma = (s_K - omega^2 s_M)^T q) stored per mode. The lowest `nfast` modes are
!>   summed term by term; the modes above enter through the series
!>     sum_dropped c_r/(w_r^2 f - omega^2) = (1/f) sum_n R_n z^n,  z = omega^2/f,
!>     R_n = sum_dropped c_r / w_r^(2(n+1)),
!>   valid for omega <= omega_d/2 (omega_d = w_(nfast+1), so |z|/omega_d^2 <= 1/4). Each call
!>   takes as many terms as the actual |z| needs for 1e-17 relative (a handful in the band of a
!>   resonance; at most blade_residual_terms = 28), so the sum is exact to rounding, without
!>   allocation or LAPACK. Above omega_d/2: the direct solve below (a modal sum far above the
!>   first modes cancels digits between its terms).
!>   * ndof <= blade_full_modal_limit, or dense storage only: all modes by dsygvd on the
!>     inverted pencil (the lowest blade_polish_modes polished in double-double);
!>     nfast = min(ndof, blade_fast_modes) and the moments R_n are sums over the computed
!>     modes. (kept_modes >= ndof: every mode summed term by term, no series.)
!>   * larger banded models (or kept_modes < ndof): the lowest kept_modes (default
!>     blade_kept_modes) by subspace iteration; the moments come from refined solves with K,
!>     projected off the kept modes, R_n = a^T K^-1 (M K^-1)^n b - sum_kept c_r/w_r^(2(n+1)),
!>     without that cancellation.
!>   The stress products use s_K^T q = r_K^T K q, r_K = K^-1 s_K, where that is better
!>   conditioned (s_K holds element stiffnesses: stress from displacements cancels digits).
!> - explicit C: a direct complex solve of D(omega) for e_E and e_g per frequency (zgetrf for
!>   dense storage, zgbtrf for band), refined in double-double; derivatives from
!>   dD/domega = -2 omega M + i C. This path allocates and costs ~1 ms for 64 DOFs.
!> Accuracy (tests/fortran/test_blade_receptances.f90, test_blade_large.f90): 1e-12 or better
!> against quadruple-precision direct solves in the band of the first mode.
!> Storage: dense M, K (and C) when ndof <= blade_dense_limit; band storage (uplo = 'U') for the
!> beam and for large or narrow-banded imported models.
module udmap_blade_type
  use udmap_core_kinds, only: wp, pi
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_core_strings, only: itoa, ftoa
  use udmap_blade_beam, only: beam_params_type, assemble_beam, beam_kd
  use udmap_blade_dd, only: dot_dd
  use udmap_blade_band, only: band_to_dense, dense_to_band, dense_bandwidth, sym_matvec
  use udmap_blade_linear_solve, only: spd_factor_type, spd_factor, spd_solve, dynamic_solve
  use udmap_blade_modes, only: all_modes, lowest_modes
  implicit none
  private
  public :: receptances_type, blade_type, new_beam_blade, new_matrices_blade, layer_response, &
    & blade_dense_limit, blade_full_modal_limit, blade_kept_modes, blade_fast_modes, &
    & blade_residual_terms
  !> For the Matrix Market import and export (udmap_blade_io_matrices).
  public :: common_checks, check_symmetric, store_dense, finish_import, symmetry_rtol
  !> Public so that gfortran keeps it for the receptances submodule (it drops unused private
  !> procedures whose only callers are in submodules).
  public :: finite

  !> Largest ndof held in dense storage (larger models are held in band storage only).
  integer, parameter :: blade_dense_limit = 2000
  !> Largest ndof for which all modes are computed (dsygvd) by default when band storage is
  !> available; dense-only models (no narrow band) always compute all modes.
  integer, parameter :: blade_full_modal_limit = 128
  !> Modes polished (double-double products with K) when all modes are computed.
  integer, parameter :: blade_polish_modes = 64
  !> Modes computed and summed term by term in larger models (the rest enter the series).
  integer, parameter :: blade_kept_modes = 20
  !> Modes summed term by term in models with every mode computed (the rest enter the series).
  integer, parameter :: blade_fast_modes = 8
  !> M may be positive semi-definite: no eigenvalue below -mass_tol max|M| (PHYSICS.md 1.3).
  real(wp), parameter :: mass_tol = 1.0e-12_wp
  !> omega_d [rad/s] when every finite mode is summed term by term and only massless directions
  !> (infinite frequencies) are left: the series is then R_0 alone.
  real(wp), parameter :: omega_massless = 1.0e140_wp
  !> Most terms of the series of the dropped modes: (1/4)^28/(3/4) < 1e-16.
  integer, parameter :: blade_residual_terms = 28
  !> Relative truncation tolerance of the series.
  real(wp), parameter :: series_tol = 1.0e-17_wp
  !> Relative tolerance of the symmetry check of imported matrices (per entry pair, plus
  !> 1e-14 of the largest entry); the accepted matrix is symmetrised.
  real(wp), parameter :: symmetry_rtol = 1.0e-7_wp

  !> Receptances at one frequency and, when requested, their derivatives d/d omega
  !> (omega in rad/s). g: gamma_P, E: excitation DOF, s: root stress functional.
  type :: receptances_type
    complex(wp) :: gE = 0, gg = 0, EE = 0, sE = 0, sg = 0
    complex(wp) :: dgE = 0, dgg = 0, dEE = 0, dsE = 0, dsg = 0
  end type receptances_type

  !> A linear blade with its bare modes and what the receptances need.
  type :: blade_type
    !> Number of DOFs; gamma_P and excitation DOF (1-based).
    integer :: ndof = 0, gamma_dof = 0, exc_dof = 0
    !> Stress rows present.
    logical :: has_stress = .false.
    !> Platform translations (PHYSICS.md 2.6) as rows of q: u_P = platform_uv(:,1).q
    !> (circumferential), v_P = platform_uv(:,2).q (radial; a zero row: held); not allocated
    !> when the blade does not know them (traveling waves are then refused).
    real(wp), allocatable :: platform_uv(:, :)
    !> The beam's parameters, when the blade is the built-in beam (the plausibility checks read
    !> its platform and sections); not allocated for imported blades.
    type(beam_params_type), allocatable :: beam
    !> Damping is the explicit matrix C (else C = beta K).
    logical :: explicit_C = .false.
    !> Modal damping ratio of mode 1 and the stiffness-proportional factor beta = 2 zeta/omega_1.
    real(wp) :: zeta = 0, beta = 0
    !> First bare natural circular frequency [rad/s].
    real(wp) :: omega1 = 0
    !> Half-bandwidth of the band storage, or -1 if dense only.
    integer :: kd = -1
    !> Dense matrices (ndof <= blade_dense_limit); C only with explicit damping.
    real(wp), allocatable :: M(:, :), K(:, :), C(:, :)
    !> Symmetric band storage (kd+1, ndof), uplo = 'U'; Cb only with explicit damping.
    real(wp), allocatable :: Mb(:, :), Kb(:, :), Cb(:, :)
    !> Stress rows: sigma = (s_K - omega^2 s_M)^T q.
    real(wp), allocatable :: s_K(:), s_M(:)
    !> r_K = K^-1 s_K, so that s_K^T q = r_K^T K q: the stress from displacements cancels
    !> digits (s_K holds element stiffnesses), from forces it does not.
    real(wp), allocatable :: r_K(:)
    !> Computed bare natural circular frequencies [rad/s], ascending (all of them for
    !> ndof <= blade_full_modal_limit, else the lowest kept_modes).
    real(wp), allocatable :: omega(:)
    !> Computed mass-normalised mode shapes (ndof, nmodes).
    real(wp), allocatable :: phi(:, :)
    !> Number of computed modes.
    integer :: nmodes = 0
    !> Modes summed term by term on the fast path; the rest enter the series.
    integer :: nfast = 0
    !> Stored terms of the series (0 when nfast = ndof).
    integer :: nres = 0
    !> First mode of the series, w_(nfast+1) [rad/s] (0 when nfast = ndof).
    real(wp) :: omega_d = 0
    !> The modal path (and its series) is used up to this circular frequency, the direct solve
    !> above.
    real(wp) :: omega_fast_max = huge(1.0_wp)
    !> omega_r^2 of the computed modes.
    real(wp), allocatable :: w2(:)
    !> Modal products per mode (8, nmodes): phi_g phi_E, phi_g^2, phi_E^2, (s_K.phi) phi_E,
    !> (s_M.phi) phi_E, (s_K.phi) phi_g, (s_M.phi) phi_g, 0.
    real(wp), allocatable :: coef(:, :)
    !> Scaled moments of the series (8, nres): column n+1 is R_n omega_d^(2n).
    real(wp), allocatable :: res(:, :)
  contains
    !> Receptances (and optionally their derivatives) at omega [rad/s].
    procedure :: receptances
    !> The lowest size(f_hz) bare natural frequencies [Hz].
    procedure :: natural_frequencies
    !> Entries phi_g and phi_E of the bare first mode (mass-normalised).
    procedure :: first_mode
  end type blade_type

  interface
    !> Receptances (and optionally their derivatives) at omega [rad/s] (blade/receptances.f90).
    module subroutine receptances(self, omega, r, error, derivatives)
      class(blade_type), intent(in) :: self
      real(wp), intent(in) :: omega
      type(receptances_type), intent(out) :: r
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: derivatives
    end subroutine receptances
  end interface

contains

  ! ------------------------------------------------------------------ constructors

  !> The built-in beam blade (PHYSICS.md 1.1).
  subroutine new_beam_blade(blade, params, error, kept_modes)
    !> The blade to build.
    type(blade_type), intent(out) :: blade
    !> Beam parameters.
    type(beam_params_type), intent(in) :: params
    type(error_type), allocatable, intent(out) :: error
    !> Modes computed and summed term by term, the rest entering the series (default: every
    !> mode computed when ndof <= blade_full_modal_limit, of which blade_fast_modes summed term
    !> by term; else blade_kept_modes). A value < ndof takes the path of large models (subspace
    !> iteration and solves with K); a value >= ndof sums every mode term by term (needs
    !> ndof <= blade_dense_limit).
    integer, intent(in), optional :: kept_modes
    call assemble_beam(params, blade%Kb, blade%Mb, blade%s_K, blade%s_M, blade%gamma_dof, &
      & blade%exc_dof, error)
    if (allocated(error)) return
    blade%ndof = size(blade%Kb, 2)
    blade%kd = beam_kd
    allocate(blade%beam, source=params)
    blade%zeta = params%zeta
    blade%has_stress = .true.
    ! w points along -x (PHYSICS.md 2.6): u_P = -w_P; the beam has no radial DOF (v_P held)
    allocate(blade%platform_uv(blade%ndof, 2), source=0.0_wp)
    blade%platform_uv(blade%gamma_dof - 1, 1) = -1
    if (blade%ndof <= blade_dense_limit) then
      call band_to_dense(blade%Kb, blade%kd, blade%K)
      call band_to_dense(blade%Mb, blade%kd, blade%M)
    end if
    call setup(blade, error, kept_modes)
  end subroutine new_beam_blade

  !> An imported blade from dense matrices (PHYSICS.md 1.2). gamma_dof, exc_dof are 1-based;
  !> without C the damping is beta K with beta = 2 zeta/omega_1 (zeta is then ignored if C is
  !> given). Stress rows are optional (an absent one of the two is zero).
  subroutine new_matrices_blade(blade, M, K, gamma_dof, exc_dof, zeta, error, C, s_K, s_M, &
      & kept_modes)
    type(blade_type), intent(out) :: blade
    real(wp), intent(in) :: M(:, :), K(:, :)
    integer, intent(in) :: gamma_dof, exc_dof
    real(wp), intent(in) :: zeta
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: C(:, :), s_K(:), s_M(:)
    !> As for new_beam_blade.
    integer, intent(in), optional :: kept_modes
    real(wp), allocatable :: mm(:, :), kk(:, :), cc(:, :)
    integer :: n
    n = size(M, 1)
    if (n < 1 .or. size(M, 2) /= n) then
      call fatal_error(error, "M must be a non-empty square matrix", UDMAP_EINPUT)
      return
    end if
    if (size(K, 1) /= n .or. size(K, 2) /= n) then
      call fatal_error(error, "K must be a square matrix of the size of M ("//itoa(n)//" x "// &
        & itoa(n)//")", UDMAP_EINPUT)
      return
    end if
    if (present(C)) then
      if (size(C, 1) /= n .or. size(C, 2) /= n) then
        call fatal_error(error, "C must be a square matrix of the size of M ("//itoa(n)// &
          & " x "//itoa(n)//")", UDMAP_EINPUT)
        return
      end if
    end if
    mm = M
    call check_symmetric(mm, "M", error)
    if (allocated(error)) return
    kk = K
    call check_symmetric(kk, "K", error)
    if (allocated(error)) return
    if (present(C)) then
      cc = C
      call check_symmetric(cc, "C", error)
      if (allocated(error)) return
    end if
    call common_checks(n, gamma_dof, exc_dof, zeta, error, s_K, s_M)
    if (allocated(error)) return
    call store_dense(blade, mm, kk, cc)
    call finish_import(blade, gamma_dof, exc_dof, zeta, error, s_K, s_M, kept_modes)
  end subroutine new_matrices_blade

  !> The lowest size(f_hz) bare natural frequencies [Hz]; an error if more are asked than kept.
  subroutine natural_frequencies(self, f_hz, error)
    class(blade_type), intent(in) :: self
    real(wp), intent(out) :: f_hz(:)
    type(error_type), allocatable, intent(out) :: error
    if (size(f_hz) < 1 .or. size(f_hz) > self%nmodes) then
      call fatal_error(error, "the number of natural frequencies must be from 1 to "// &
        & itoa(self%nmodes)//" (the modes computed)", UDMAP_EINPUT)
      return
    end if
    f_hz = self%omega(1:size(f_hz))/(2*pi)
  end subroutine natural_frequencies

  !> Entries phi_g = phi(gamma_dof, 1) and phi_E = phi(exc_dof, 1) of the mass-normalised bare
  !> first mode (the limit force needs |phi_E/phi_g|).
  pure subroutine first_mode(self, phi_g, phi_E)
    class(blade_type), intent(in) :: self
    real(wp), intent(out) :: phi_g, phi_E
    phi_g = self%phi(self%gamma_dof, 1)
    phi_E = self%phi(self%exc_dof, 1)
  end subroutine first_mode

  !> Layer response to a unit force at E with damper stiffness k on gamma_P (Sherman-Morrison):
  !> g~ = H_gE/(1 + k H_gg), s~ = H_sE - k H_sg g~, u~_E = H_EE - k H_gE g~.
  !> The caller checks 1 + k H_gg /= 0 (zero only at an undamped natural frequency of the
  !> blade with a real damper stiffness).
  elemental subroutine layer_response(r, k, g, s, uE)
    type(receptances_type), intent(in) :: r
    complex(wp), intent(in) :: k
    complex(wp), intent(out) :: g, s, uE
    g = r%gE/(1.0_wp + k*r%gg)
    s = r%sE - k*r%sg*g
    uE = r%EE - k*r%gE*g
  end subroutine layer_response

  ! ------------------------------------------------------------------ setup

  !> Bare modes, modal products and the moments of the series (matrices stored and checked).
  subroutine setup(blade, error, kept_modes)
    type(blade_type), intent(inout) :: blade
    type(error_type), allocatable, intent(out) :: error
    integer, intent(in), optional :: kept_modes
    type(spd_factor_type) :: kf, mf
    real(wp), allocatable :: lambda(:), phi(:, :), mrk(:), rk(:, :), zinf(:, :)
    real(wp) :: sk, sm, pg, pe
    integer :: n, nkeep, m
    logical :: massless

    n = blade%ndof
    nkeep = blade_kept_modes
    if (n <= blade_full_modal_limit .or. .not.allocated(blade%Kb)) nkeep = n
    if (present(kept_modes)) then
      if (kept_modes < 1) then
        call fatal_error(error, "kept_modes must be at least 1", UDMAP_EINPUT)
        return
      end if
      nkeep = min(kept_modes, n)
    end if
    if (nkeep == n .and. .not.allocated(blade%K)) then
      call fatal_error(error, "computing all modes needs ndof <= "//itoa(blade_dense_limit)// &
        & " (kept_modes)", UDMAP_EINPUT)
      return
    end if

    call spd_factor(blade%M, blade%Mb, blade%kd, "M", mf, error)
    massless = .false.
    if (allocated(error)) then
      ! M positive semi-definite (massless DOFs) is valid: no eigenvalue below -1e-12 max|M|
      if (error%stat /= UDMAP_EINPUT) return
      deallocate(error)
      call check_semi_definite(blade, error)
      if (allocated(error)) return
      massless = .true.
    end if
    call spd_factor(blade%K, blade%Kb, blade%kd, "K", kf, error)
    if (allocated(error)) return

    if (nkeep == n .and. massless) then
      ! the finite modes, and M's null space (infinite frequencies) in zinf
      call all_modes(blade%K, blade%M, blade_polish_modes, lambda, phi, error, zinf)
      if (allocated(error)) return
      nkeep = size(lambda)
      blade%nfast = min(nkeep, blade_fast_modes)
      if (present(kept_modes)) blade%nfast = nkeep
    else if (nkeep == n) then
      call all_modes(blade%K, blade%M, blade_polish_modes, lambda, phi, error)
      if (allocated(error)) return
      blade%nfast = min(n, blade_fast_modes)
      if (present(kept_modes)) blade%nfast = n
    else
      call lowest_modes(blade%K, blade%Kb, blade%M, blade%Mb, max(blade%kd, 0), kf, nkeep + 1, &
        & lambda, phi, error)
      if (allocated(error)) return
      blade%nfast = nkeep
    end if
    if (.not.(lambda(1) > 0.0_wp)) then
      call fatal_error(error, "the first natural frequency is not positive (K or M singular)", &
        & UDMAP_EINPUT)
      return
    end if
    blade%nmodes = nkeep
    blade%w2 = lambda(1:nkeep)
    blade%omega = sqrt(blade%w2)
    blade%phi = phi(:, 1:nkeep)
    blade%omega1 = blade%omega(1)
    if (blade%explicit_C) then
      blade%beta = 0.0_wp
    else
      blade%beta = 2*blade%zeta/blade%omega1
    end if

    if (blade%has_stress) then
      allocate(blade%r_K(n), mrk(n), rk(n, 1))
      call spd_solve(kf, blade%K, blade%Kb, reshape(blade%s_K, [n, 1]), rk, .true.)
      blade%r_K = rk(:, 1)
      call sym_matvec(blade%M, blade%Mb, max(blade%kd, 0), blade%r_K, mrk)
    end if
    allocate(blade%coef(8, nkeep))
    do m = 1, nkeep
      pg = blade%phi(blade%gamma_dof, m)
      pe = blade%phi(blade%exc_dof, m)
      sk = 0.0_wp
      sm = 0.0_wp
      if (blade%has_stress) then
        sk = stress_dot(blade%s_K, blade%phi(:, m), mrk, blade%w2(m))
        sm = dot_dd(blade%s_M, blade%phi(:, m))
      end if
      blade%coef(:, m) = [pg*pe, pg*pg, pe*pe, sk*pe, sm*pe, sk*pg, sm*pg, 0.0_wp]
    end do

    blade%nres = 0
    blade%omega_d = 0.0_wp
    blade%omega_fast_max = huge(1.0_wp)
    if (blade%nfast < n .and. .not.blade%explicit_C) then
      blade%nres = blade_residual_terms
      if (blade%nmodes == n) then
        blade%omega_d = blade%omega(blade%nfast+1)
        call modal_moments(blade)
      else if (allocated(zinf)) then
        ! all finite modes computed; the massless directions enter R_0 only
        blade%omega_d = omega_massless
        if (blade%nfast < blade%nmodes) blade%omega_d = blade%omega(blade%nfast+1)
        call modal_moments(blade, zinf)
      else
        blade%omega_d = sqrt(lambda(nkeep+1))
        call residual_moments(blade, kf)
      end if
      blade%omega_fast_max = 0.5_wp*blade%omega_d
    end if
  end subroutine setup

  !> Scaled moments Rt_n = omega_d^(2n) R_n = sum_(r > nfast) c_r (w_d^2/w_r^2)^n / w_r^2 over the
  !> computed modes (models with every mode computed; all terms positive-weighted, no cancellation).
  !> With `zinf` (M's null space, K-normalised: modes of infinite frequency), their limit
  !> c_r/w_r^2 -> (a.z)(b.z) is added to Rt_0 (they add nothing to the higher moments).
  subroutine modal_moments(blade, zinf)
    type(blade_type), intent(inout) :: blade
    real(wp), intent(in), optional :: zinf(:, :)
    real(wp) :: q, wd2, zg, ze, sk, sm
    integer :: m, nn
    wd2 = blade%omega_d**2
    allocate(blade%res(8, blade%nres), source=0.0_wp)
    do m = blade%nfast + 1, blade%nmodes
      q = wd2/blade%w2(m)
      do nn = 1, blade%nres
        blade%res(:, nn) = blade%res(:, nn) + blade%coef(:, m)*(q**(nn-1)/blade%w2(m))
      end do
    end do
    if (.not.present(zinf)) return
    do m = 1, size(zinf, 2)
      zg = zinf(blade%gamma_dof, m)
      ze = zinf(blade%exc_dof, m)
      sk = 0.0_wp
      sm = 0.0_wp
      if (blade%has_stress) then
        sk = dot_dd(blade%s_K, zinf(:, m))
        sm = dot_dd(blade%s_M, zinf(:, m))
      end if
      blade%res(:, 1) = blade%res(:, 1) + [zg*ze, zg*zg, ze*ze, sk*ze, sm*ze, sk*zg, sm*zg, &
        & 0.0_wp]
    end do
  end subroutine modal_moments

  !> M positive semi-definite: the Cholesky factorisation of M + tau I, tau = 1e-12 max|M|,
  !> succeeds when no eigenvalue of M lies below -tau (rounding n eps max|M| far below tau).
  subroutine check_semi_definite(blade, error)
    type(blade_type), intent(in) :: blade
    type(error_type), allocatable, intent(out) :: error
    type(spd_factor_type) :: f
    real(wp), allocatable :: a(:, :), ab(:, :)
    real(wp) :: tau
    integer :: i
    if (allocated(blade%Mb)) then
      ab = blade%Mb
      tau = mass_tol*maxval(abs(ab))
      ab(blade%kd+1, :) = ab(blade%kd+1, :) + tau
    else
      a = blade%M
      tau = mass_tol*maxval(abs(a))
      do i = 1, size(a, 1)
        a(i, i) = a(i, i) + tau
      end do
    end if
    call spd_factor(a, ab, blade%kd, "M + 1e-12 max|M| I", f, error)
    if (allocated(error)) error%message = "M is not positive definite (nor semi-definite: "// &
      & error%message//")"
  end subroutine check_semi_definite

  !> Scaled moments Rt_n = omega_d^(2n) R_n of the dropped modes,
  !> R_n,ab = a^T K^-1 (M K^-1)^n b - sum_kept (a.phi)(b.phi)/w^(2(n+1)), computed without the
  !> cancellation of that difference: u_b^(0) = P K^-1 b, u_b^(k) = omega_d^2 P K^-1 M u_b^(k-1)
  !> with P = I - Phi Phi^T M (projection off the kept modes, reapplied at every step), then
  !> Rt_0 = a^T u_b^(0) and Rt_n = omega_d^2 u_a^(j)T M u_b^(k), j + k = n - 1.
  subroutine residual_moments(blade, kf)
    type(blade_type), intent(inout) :: blade
    type(spd_factor_type), intent(in) :: kf
    integer, parameter :: pair_a(7) = [1, 1, 2, 3, 4, 3, 4], pair_b(7) = [2, 1, 2, 2, 2, 1, 1]
    real(wp), allocatable :: loads(:, :), u(:, :, :), w(:, :), mu(:)
    real(wp) :: wd2
    integer :: n, nl, kmax, k, l, c, nn, j, kk, ibdof(2)
    n = blade%ndof
    nl = 2
    if (blade%has_stress) nl = 4
    kmax = (blade%nres - 1)/2
    ibdof = [blade%gamma_dof, blade%exc_dof]
    wd2 = blade%omega_d**2
    allocate(loads(n, nl), source=0.0_wp)
    loads(blade%gamma_dof, 1) = 1.0_wp
    loads(blade%exc_dof, 2) = 1.0_wp
    if (blade%has_stress) then
      loads(:, 3) = blade%s_K
      loads(:, 4) = blade%s_M
    end if
    allocate(u(n, nl, 0:kmax), w(n, nl), mu(n))
    call spd_solve(kf, blade%K, blade%Kb, loads, u(:, :, 0), .true.)
    call project(u(:, :, 0))
    do k = 1, kmax
      do l = 1, nl
        call sym_matvec(blade%M, blade%Mb, max(blade%kd, 0), u(:, l, k-1), w(:, l))
      end do
      call spd_solve(kf, blade%K, blade%Kb, w, u(:, :, k), .true.)
      u(:, :, k) = wd2*u(:, :, k)
      call project(u(:, :, k))
    end do
    allocate(blade%res(8, blade%nres), source=0.0_wp)
    do c = 1, 7
      if (pair_a(c) > nl) cycle
      ! R_0 = b^T P K^-1 a: a component, not a product with the stiff stress row.
      blade%res(c, 1) = u(ibdof(pair_b(c)), pair_a(c), 0)
      do nn = 1, blade%nres - 1
        j = (nn - 1)/2
        kk = nn - 1 - j
        call sym_matvec(blade%M, blade%Mb, max(blade%kd, 0), u(:, pair_b(c), kk), mu)
        blade%res(c, nn+1) = wd2*dot_product(u(:, pair_a(c), j), mu)
      end do
    end do

  contains

    subroutine project(x)
      real(wp), intent(inout) :: x(:, :)
      real(wp), allocatable :: mx(:)
      integer :: col
      allocate(mx(n))
      do col = 1, size(x, 2)
        call sym_matvec(blade%M, blade%Mb, max(blade%kd, 0), x(:, col), mx)
        x(:, col) = x(:, col) - matmul(blade%phi, matmul(mx, blade%phi))
      end do
    end subroutine project
  end subroutine residual_moments

  !> s_K^T phi for a mode (K phi = w2 M phi) in the better conditioned of two exact forms:
  !> directly, or w2 phi^T M r_K with r_K = K^-1 s_K (low modes: s_K^T phi cancels digits).
  !> Products in double-double; the form with the smaller sum of |terms| is taken.
  pure function stress_dot(s_k, phi, mrk, w2) result(v)
    real(wp), intent(in) :: s_k(:), phi(:), mrk(:), w2
    real(wp) :: v
    real(wp) :: a, b, ca, cb
    a = dot_dd(s_k, phi)
    ca = sum(abs(s_k*phi))
    b = w2*dot_dd(mrk, phi)
    cb = w2*sum(abs(mrk*phi))
    ! Compare the conditioning sum |terms| / |sum|.
    if (ca*abs(b) <= cb*abs(a)) then
      v = a
    else
      v = b
    end if
  end function stress_dot

  ! ------------------------------------------------------------------ import helpers

  subroutine common_checks(n, gamma_dof, exc_dof, zeta, error, s_K, s_M)
    integer, intent(in) :: n, gamma_dof, exc_dof
    real(wp), intent(in) :: zeta
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: s_K(:), s_M(:)
    if (gamma_dof < 1 .or. gamma_dof > n) then
      call fatal_error(error, "gamma_dof must be a DOF number from 1 to "//itoa(n)//", got "// &
        & itoa(gamma_dof), UDMAP_EINPUT)
    else if (exc_dof < 1 .or. exc_dof > n) then
      call fatal_error(error, "exc_dof must be a DOF number from 1 to "//itoa(n)//", got "// &
        & itoa(exc_dof), UDMAP_EINPUT)
    else if (.not.ieee_is_finite(zeta)) then
      call fatal_error(error, "zeta must be a non-negative finite number", UDMAP_EINPUT)
    else if (zeta < 0.0_wp) then
      call fatal_error(error, "zeta must be a non-negative finite number", UDMAP_EINPUT)
    end if
    if (allocated(error)) return
    if (present(s_K)) call check_row(s_K, "stress_K")
    if (allocated(error)) return
    if (present(s_M)) call check_row(s_M, "stress_M")

  contains

    subroutine check_row(s, name)
      real(wp), intent(in) :: s(:)
      character(len=*), intent(in) :: name
      if (size(s) /= n) then
        call fatal_error(error, name//" must have "//itoa(n)//" entries (one per DOF), got "// &
          & itoa(size(s)), UDMAP_EINPUT)
      else if (.not.all(ieee_is_finite(s))) then
        call fatal_error(error, name//" has a non-finite entry", UDMAP_EINPUT)
      end if
    end subroutine check_row
  end subroutine common_checks

  !> Checks that `a` is finite and symmetric to symmetry_rtol, then symmetrises it.
  subroutine check_symmetric(a, name, error)
    real(wp), intent(inout) :: a(:, :)
    character(len=*), intent(in) :: name
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: amax
    integer :: i, j
    if (.not.all(ieee_is_finite(a))) then
      call fatal_error(error, name//" has a non-finite entry", UDMAP_EINPUT)
      return
    end if
    amax = maxval(abs(a))
    do j = 1, size(a, 2)
      do i = j + 1, size(a, 1)
        if (abs(a(i, j) - a(j, i)) > symmetry_rtol*max(abs(a(i, j)), abs(a(j, i))) &
            & + 1.0e-14_wp*amax) then
          call fatal_error(error, name//" is not symmetric: entry ("//itoa(i)//", "//itoa(j)// &
            & ") = "//ftoa(a(i, j))//" but ("//itoa(j)//", "//itoa(i)//") = "//ftoa(a(j, i)), &
            & UDMAP_EINPUT)
          return
        end if
        a(i, j) = 0.5_wp*(a(i, j) + a(j, i))
        a(j, i) = a(i, j)
      end do
    end do
  end subroutine check_symmetric

  !> Stores dense matrices, adding band storage when the bandwidth is narrow or ndof large.
  subroutine store_dense(blade, mm, kk, cc)
    type(blade_type), intent(inout) :: blade
    real(wp), allocatable, intent(inout) :: mm(:, :), kk(:, :), cc(:, :)
    integer :: n, kd
    n = size(mm, 1)
    blade%ndof = n
    kd = max(dense_bandwidth(mm), dense_bandwidth(kk))
    if (allocated(cc)) kd = max(kd, dense_bandwidth(cc))
    if (4*(kd + 1) <= n .or. n > blade_dense_limit) then
      blade%kd = kd
      call dense_to_band(mm, kd, blade%Mb)
      call dense_to_band(kk, kd, blade%Kb)
      if (allocated(cc)) call dense_to_band(cc, kd, blade%Cb)
    else
      blade%kd = -1
    end if
    if (n <= blade_dense_limit) then
      call move_alloc(mm, blade%M)
      call move_alloc(kk, blade%K)
      if (allocated(cc)) call move_alloc(cc, blade%C)
    end if
  end subroutine store_dense

  subroutine finish_import(blade, gamma_dof, exc_dof, zeta, error, s_K, s_M, kept_modes)
    type(blade_type), intent(inout) :: blade
    integer, intent(in) :: gamma_dof, exc_dof
    real(wp), intent(in) :: zeta
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: s_K(:), s_M(:)
    integer, intent(in), optional :: kept_modes
    blade%gamma_dof = gamma_dof
    blade%exc_dof = exc_dof
    blade%zeta = zeta
    blade%explicit_C = allocated(blade%C) .or. allocated(blade%Cb)
    blade%has_stress = present(s_K) .or. present(s_M)
    if (blade%has_stress) then
      allocate(blade%s_K(blade%ndof), blade%s_M(blade%ndof), source=0.0_wp)
      if (present(s_K)) blade%s_K = s_K
      if (present(s_M)) blade%s_M = s_M
    end if
    call setup(blade, error, kept_modes)
  end subroutine finish_import

  ! ------------------------------------------------------------------ small utilities

  elemental logical function finite(z)
    complex(wp), intent(in) :: z
    finite = ieee_is_finite(z%re) .and. ieee_is_finite(z%im)
  end function finite
end module udmap_blade_type
