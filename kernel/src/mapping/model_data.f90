!> The coupled blade-damper model of the mapping (PHYSICS.md 3-5): its settings, its result
!> types, its caches, and the limit force. The algorithms live in udmap_mapping_backbone,
!> udmap_mapping_response and udmap_mapping_curves; udmap_mapping_model builds a model
!> (new_model) and gathers everything for users. Data only: nothing here uses an algorithm.
module udmap_mapping_model_data
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_core_strings, only: gtoa
  use udmap_blade_type, only: blade_type, receptances_type, layer_response
  use udmap_damper_type, only: damper_type
  use udmap_mapping_caches, only: bare_type, layer_peak_type, secular_type
  use udmap_mapping_harmonic_types, only: harmonic_workspace_type, force_table_type
  implicit none
  private
  public :: analysis_type, point_type, curve_type, model_type, backbone_table_type, &
    & backbone_eval_type
  public :: check_model_damper, set_damper, limit_force, limit_force_or_huge, regime_of, &
    & fill_point, check_forces, check_response_frequency, &
    & limit_force_backbone, damper_fingerprint
  public :: EIGEN_AUTO, EIGEN_DIRECT, EIGEN_MODAL
  public :: REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT
  public :: BRANCH_LOWER, BRANCH_UPPER, BRANCH_TURNING

  !> The response at a fixed frequency reaches this many times f_max.
  real(wp), parameter :: RESPONSE_REACH = 3

  !> Eigenvalue start: a direct solver once per model for the first layer, then the secular
  !> equation from layer to layer (default).
  integer, parameter :: EIGEN_AUTO = 0
  !> Eigenvalue start: the direct solver for every layer (slow; for checks).
  integer, parameter :: EIGEN_DIRECT = 1
  !> Eigenvalue start: the secular equation only (no dense or ARPACK solve at all).
  integer, parameter :: EIGEN_MODAL = 2

  !> Damper stuck: gamma_P <= gamma_s.
  integer, parameter :: REGIME_STUCK = 0
  !> Partial slip: gamma_s < gamma_P < gamma_b.
  integer, parameter :: REGIME_PARTIAL_SLIP = 1
  !> Full slip: gamma_P >= gamma_b.
  integer, parameter :: REGIME_FULL_SLIP = 2
  !> At or above the limit force: F_E >= F_lim.
  integer, parameter :: REGIME_LIMIT = 3

  !> Response curve point below the peak frequency of its layer.
  integer, parameter :: BRANCH_LOWER = 0
  !> Response curve point above the peak frequency of its layer.
  integer, parameter :: BRANCH_UPPER = 1
  !> Response curve point on the backbone (the layer just touches F_E: a peak or the bottom
  !> of a detached part).
  integer, parameter :: BRANCH_TURNING = 2

  !> Analysis settings. The first five are those of the C struct udmap_analysis.
  type :: analysis_type
    !> Band [Hz] in which resonances are sought.
    real(wp) :: f_min = 0, f_max = 0
    !> Allowable alternating stress amplitude [Pa] of the HCF criterion.
    real(wp) :: sigma_all = 80e6_wp
    !> Relative tolerance of every peak and root refinement.
    real(wp) :: rtol = 1e-12_wp
    !> Points per decade of the amplitude grid on which roots are bracketed.
    integer :: grid_per_decade = 24
    !> How the eigenvalue start is obtained (EIGEN_AUTO, EIGEN_DIRECT, EIGEN_MODAL).
    integer :: eigen_method = EIGEN_AUTO
    !> Largest ndof solved by dense zggev; larger banded models go to ARPACK.
    integer :: dense_max = 200
    !> Bare-blade frequency samples over the band for the response curves (root
    !> bracketing only: every crossing is then refined with exact receptances).
    integer :: sweep_points = 400
    !> Evaluate the bare receptances in the band through the checked interpolant of
    !> udmap_mapping_band_receptances (off: the blade's own evaluation every time).
    logical :: band_interpolation = .true.
    !> Harmonics of the platform rotation (PHYSICS.md 4.1): 1 the single-harmonic method,
    !> H > 1 harmonics 0..H in multi-harmonic layers, 0 automatic (raised until the outputs
    !> change by less than harmonic_tol).
    integer :: harmonics = 1
    !> Relative change of the outputs that stops the automatic choice of H.
    real(wp) :: harmonic_tol = 1e-3_wp
    !> Interblade phase angle phi [deg] of the traveling wave (PHYSICS.md 2.6); 0 in phase.
    real(wp) :: ibpa_deg = 0
  end type analysis_type

  !> One point of the non-linear response: at resonance (backbone) or at a given frequency.
  type :: point_type
    !> Excitation force amplitude [N].
    real(wp) :: F_E = 0
    !> Platform rotation amplitude [rad] (the largest root).
    real(wp) :: gamma_P = 0
    !> Frequency of the peak, or the given excitation frequency [Hz].
    real(wp) :: f_res = 0
    !> Alternating stress amplitude at the airfoil-platform junction [Pa] (0 without
    !> stress rows).
    real(wp) :: sigma_a = 0
    !> Displacement amplitude at E [m].
    real(wp) :: u_E = 0
    !> Damper stiffness k_Re + i k_Im at gamma_P [N m/rad].
    complex(wp) :: k = 0
    !> REGIME_STUCK, REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP or REGIME_LIMIT.
    integer :: regime = REGIME_STUCK
    !> HCF criterion: F_E <= 0.5 F_lim and sigma_a <= sigma_all.
    logical :: hcf_ok = .false.
    !> No structural damping and F_E >= F_lim: no finite response (numbers are 0).
    logical :: unbounded = .false.
    !> gamma_P is the amplitude gamma_c of a jump of k(gamma) and k is interpolated between
    !> its one-sided values (PHYSICS.md 2.5).
    logical :: jump = .false.
    !> Every gamma_P root [rad], ascending.
    real(wp), allocatable :: roots(:)
    !> Largest excursions of gamma(t) [rad] and sigma(t) [Pa] from their means (gamma_P and
    !> sigma_a at H = 1).
    real(wp) :: gamma_max = 0, sigma_max = 0
    !> Harmonics used (1: the single-harmonic method).
    integer :: harmonics = 1
    !> |Gamma_h| [rad] and |sigma_h| [Pa], h = 0..harmonics (multi-harmonic points only).
    real(wp), allocatable :: gamma_h(:), sigma_h(:)
  end type point_type

  !> One non-linear response curve, points in path order.
  type :: curve_type
    !> Excitation force amplitude [N].
    real(wp) :: F_E = 0
    !> Frequency [Hz], platform rotation amplitude [rad], stress amplitude [Pa].
    real(wp), allocatable :: f(:), gamma_P(:), sigma_a(:)
    !> BRANCH_LOWER, BRANCH_UPPER or BRANCH_TURNING per point.
    integer, allocatable :: branch(:)
    !> Index (1, 2, ...) of the connected part of the curve each point belongs to: part 1
    !> is the main resonance curve, higher parts are detached (isolas).
    integer, allocatable :: part(:)
  end type curve_type

  !> F_bb at one amplitude with everything that comes with it.
  type :: backbone_eval_type
    !> Amplitude [rad], F_bb = gamma / max |g~| [N], d ln F_bb / d ln gamma.
    real(wp) :: gamma = 0, F_bb = 0, slope = 1
    !> Damper stiffness at gamma and the tracked eigenvalue [rad^2/s^2].
    complex(wp) :: k = 0, lambda = 0
    !> The layer's peak (frequency, |g~|, bare receptances there).
    type(layer_peak_type) :: peak
  end type backbone_eval_type

  !> F_bb on the grid gamma_j = gamma_ref 10^(j/grid_per_decade), j = j_lo..j_hi, for one
  !> damper revision.
  type :: backbone_table_type
    !> Damper revision the table belongs to (none yet: -huge), and the damper's summary
    !> numbers then (gamma_b, gamma_s, M_max, M_min, k_stuck), which also invalidate the table
    !> if they change (a damper rebuilt in place restarts its revision count).
    integer :: revision = -huge(1)
    real(wp) :: fingerprint(5) = 0
    !> The eigenvalue start it was built with (analysis%eigen_method then): another rebuilds it.
    integer :: eigen_method = -1
    !> Grid anchor (the damper's gamma_b) [rad].
    real(wp) :: gamma_ref = 0
    !> Nodes present; below node(j_lo)%gamma the damper is stuck (k constant), F_bb linear.
    integer :: j_lo = 0, j_hi = -1
    type(backbone_eval_type), allocatable :: node(:)
    !> The damper's jumps of k (PHYSICS.md 2.5): the backbone points at gamma_c with k(gamma_c-)
    !> and k(gamma_c+), side(1:2, i), computed once the grid reaches gamma_c (n_side of them).
    integer :: n_side = 0
    type(backbone_eval_type), allocatable :: side(:,:)
  end type backbone_table_type

  !> A blade and a damper coupled over a band. It borrows both (they must outlive it and
  !> stay at the same address) and caches what it derives from them: the bare-blade data
  !> for good, the backbone table until the damper's revision changes.
  type :: model_type
    type(blade_type), pointer :: blade => null()
    type(damper_type), pointer :: damper => null()
    type(analysis_type) :: analysis
    !> Receptance evaluator and its counter.
    type(bare_type) :: bare
    !> Secular equation of the gamma DOF (eigenvalue tracking).
    type(secular_type) :: secular
    !> Band [rad/s].
    real(wp) :: omega_lo = 0, omega_hi = 0
    !> |phi_E / phi_g| of the bare first mode.
    real(wp) :: phi_ratio = 0
    !> Modal viscous coefficient of mode 1, phi_1^T C phi_1 [1/s].
    real(wp) :: c1 = 0
    !> No structural damping at all (zeta = 0, or an explicit C = 0).
    logical :: undamped = .false.
    !> Whether the direct eigenvalue start has been done, and its value.
    logical :: have_direct = .false.
    complex(wp) :: lambda_direct = 0
    type(backbone_table_type) :: table
    !> Bare-blade sweep over the band (for the response curves), computed on first use.
    real(wp), allocatable :: sweep_omega(:)
    type(receptances_type), allocatable :: sweep_r(:)
    !> Contact element and scratch of the multi-harmonic layers (PHYSICS.md 4.1).
    type(harmonic_workspace_type) :: harm
    !> Backbone points at H /= 1 after a change of F_E alone: interpolated in a verified table
    !> of exact points where one holds F_E (udmap_mapping_harmonic_force_table), when force_table is
    !> set.
    logical :: force_table = .false.
    type(force_table_type) :: ftable
  end type model_type

contains

  !> Couples another damper to the model (borrowed like the first): the bare-blade data stay,
  !> the backbone table is rebuilt on next use. This is the cheap path after a change of the
  !> damper's parameters (build the new damper, then set it).
  subroutine set_damper(model, damper, error)
    type(model_type), intent(inout) :: model
    type(damper_type), target, intent(in) :: damper
    type(error_type), allocatable, intent(out) :: error
    if (.not.associated(model%blade)) then
      call fatal_error(error, "set_damper: the model is not built", UDMAP_EINPUT)
      return
    end if
    call check_model_damper(damper, error)
    if (allocated(error)) return
    model%damper => damper
    model%table%revision = -huge(1)
  end subroutine set_damper

  !> The damper a model can take: one with a positive base-cycle amplitude gamma_b.
  subroutine check_model_damper(damper, error)
    type(damper_type), intent(in) :: damper
    type(error_type), allocatable, intent(out) :: error
    if (.not.(damper%gamma_b > 0)) call fatal_error(error, "model: the damper has no "// &
      & "positive base-cycle amplitude gamma_b", UDMAP_EINPUT)
  end subroutine check_model_damper

  !> The damper's summary numbers that the backbone table depends on besides k(gamma).
  pure function damper_fingerprint(damper) result(fp)
    type(damper_type), intent(in) :: damper
    real(wp) :: fp(5)
    fp = [damper%gamma_b, damper%gamma_s, damper%M_max, damper%M_min, damper%k_stuck]
  end function damper_fingerprint

  !> The limit excitation force F_lim = 2 Delta_M / (pi |phi_E/phi_g|) (PHYSICS.md 5) [N].
  !> An error when the damper has no slip moment range (a measured table without delta_M).
  subroutine limit_force(model, F_lim, error)
    type(model_type), intent(in) :: model
    real(wp), intent(out) :: F_lim
    type(error_type), allocatable, intent(out) :: error
    F_lim = 0
    if (.not.associated(model%damper)) then
      call fatal_error(error, "limit_force: the model is not built", UDMAP_EINPUT)
      return
    end if
    if (.not.(model%damper%M_max - model%damper%M_min > 0)) then
      call fatal_error(error, "limit_force: the damper has no slip moment range "// &
        & "(M_max - M_min = 0; a measured table needs delta_M)", UDMAP_EINPUT)
      return
    end if
    F_lim = 2*(model%damper%M_max - model%damper%M_min)/(pi*model%phi_ratio)
  end subroutine limit_force

  !> F_lim for the classification of results: huge when the damper has no slip moment range
  !> (no limit known: no point is then at or above F_lim, unbounded, or HCF-admissible).
  pure real(wp) function limit_force_or_huge(model) result(F_lim)
    type(model_type), intent(in) :: model
    F_lim = huge(1.0_wp)
    if (model%damper%M_max - model%damper%M_min > 0) &
      & F_lim = 2*(model%damper%M_max - model%damper%M_min)/(pi*model%phi_ratio)
  end function limit_force_or_huge

  !> F_lim_backbone (PHYSICS.md 5) [N]: the level that F_bb of the blade without structural
  !> damping approaches at large amplitude, lim gamma k_Im(gamma) / |phi_E/phi_g|, since there
  !> k -> 0 and the layer peak tends to |phi_E/phi_g| / k_Im. With
  !> E/gamma -> dE/dgamma = 2 Delta_M (plateaus that bound the moment) it is F_lim exactly;
  !> with lift-off the damper dissipates less per unit rotation and the level lies below.
  !> huge when no limit is known (no slip moment range, or E growing faster than gamma).
  pure real(wp) function limit_force_backbone(model) result(F)
    type(model_type), intent(in) :: model
    real(wp) :: dEdp
    F = limit_force_or_huge(model)
    if (F == huge(1.0_wp)) return
    dEdp = model%damper%energy_slope()
    if (dEdp < huge(1.0_wp)) F = dEdp/(pi*model%phi_ratio)
    if (dEdp == 2*(model%damper%M_max - model%damper%M_min)) F = limit_force_or_huge(model)
  end function limit_force_backbone

  !> Regime of a response point: REGIME_LIMIT when F_E >= F_lim, else by gamma_P against
  !> the damper's gamma_s and gamma_b.
  pure integer function regime_of(damper, F_E, F_lim, gamma_P) result(regime)
    type(damper_type), intent(in) :: damper
    real(wp), intent(in) :: F_E, F_lim, gamma_P
    if (F_E >= F_lim) then
      regime = REGIME_LIMIT
    else if (gamma_P <= damper%gamma_s) then
      regime = REGIME_STUCK
    else if (gamma_P < damper%gamma_b) then
      regime = REGIME_PARTIAL_SLIP
    else
      regime = REGIME_FULL_SLIP
    end if
  end function regime_of

  !> Fills a response point from the bare receptances r at omega, the stiffness k at
  !> gamma_P and the roots (the largest is gamma_P).
  pure subroutine fill_point(model, point, F_E, F_lim, omega, r, k, roots)
    type(model_type), intent(in) :: model
    type(point_type), intent(out) :: point
    real(wp), intent(in) :: F_E, F_lim, omega
    type(receptances_type), intent(in) :: r
    complex(wp), intent(in) :: k
    real(wp), intent(in) :: roots(:)
    complex(wp) :: g, s, uE
    point%F_E = F_E
    point%roots = roots
    point%gamma_P = roots(size(roots))
    point%f_res = omega/(2*pi)
    point%k = k
    call layer_response(r, k, g, s, uE)
    if (model%blade%has_stress) point%sigma_a = F_E*abs(s)
    point%u_E = F_E*abs(uE)
    point%gamma_max = point%gamma_P
    point%sigma_max = point%sigma_a
    point%harmonics = 1
    point%regime = regime_of(model%damper, F_E, F_lim, point%gamma_P)
    ! criterion (8a) cannot be checked without F_lim: not admissible then
    point%hcf_ok = F_E <= 0.5_wp*F_lim .and. point%sigma_a <= model%analysis%sigma_all .and. &
      & F_lim < huge(1.0_wp)
    point%unbounded = .false.
  end subroutine fill_point

  !> Every force must be a positive finite number.
  pure subroutine check_forces(F_E, where, error)
    real(wp), intent(in) :: F_E(:)
    character(len=*), intent(in) :: where
    type(error_type), allocatable, intent(out) :: error
    integer :: i
    character(len=12) :: buf
    do i = 1, size(F_E)
      if (.not.(F_E(i) > 0 .and. F_E(i) < huge(1.0_wp))) then
        write(buf, '(i0)') i
        call fatal_error(error, where//": F_E("//trim(buf)//") must be a positive number [N]", &
          & UDMAP_EINPUT)
        return
      end if
    end do
  end subroutine check_forces

  !> The response at a fixed frequency is answered up to RESPONSE_REACH f_max: the reach of a
  !> reduced FE blade (its modes go to 3 f_max, PHYSICS.md 1.3); the band is where the
  !> resonance is sought, not a limit of the blade's receptances.
  pure subroutine check_response_frequency(analysis, f_exc, error)
    type(analysis_type), intent(in) :: analysis
    real(wp), intent(in) :: f_exc
    type(error_type), allocatable, intent(out) :: error
    if (f_exc > 0 .and. f_exc <= RESPONSE_REACH*analysis%f_max) return
    call fatal_error(error, "response: f_exc = "//gtoa(f_exc, 6)//" Hz must lie in (0, "// &
      & "3 f_max] = (0, "//gtoa(RESPONSE_REACH*analysis%f_max, 6)//"] Hz (f_max = "// &
      & gtoa(analysis%f_max, 6)//" Hz: a reduced blade holds its modes up to 3 f_max)", &
      & UDMAP_EINPUT)
  end subroutine check_response_frequency
end module udmap_mapping_model_data
