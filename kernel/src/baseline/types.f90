!> The standard method's data (PHYSICS.md 6): its settings, the peak and curve it reports, and
!> the state of one force's continuation (problem_type, owned by the driver, nothing global),
!> with the metric of the arc-length continuation on it.
module udmap_baseline_types
  use udmap_core_kinds, only: wp
  use udmap_baseline_linear_structure, only: structure_receptances_type
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_aft_moment, only: aft_workspace_type
  implicit none
  private
  public :: hbm_settings_type, hbm_point_type, hbm_curve_type, HBM_CONDENSED, HBM_FULL, &
    & HBM_MAX_PEAKS, amplitude, amplitude_scale, scaled_dot, converged, problem_type, &
    & curve_point_type, seconds_since

  !> Variant: condensed onto the damper DOF (one unknown per harmonic) or on all DOFs.
  integer, parameter :: HBM_CONDENSED = 0, HBM_FULL = 1
  !> Capacity of the list of local maxima reported per force.
  integer, parameter :: HBM_MAX_PEAKS = 8

  !> Numerical settings of the standard method (every knob of the run time vs error trade-off).
  type :: hbm_settings_type
    integer :: harmonics = 1            !< H: harmonics 1..H
    logical :: harmonic0 = .false.      !< also balance the static harmonic 0
    integer :: variant = HBM_CONDENSED  !< HBM_CONDENSED or HBM_FULL
    real(wp) :: tol = 1.0e-10_wp        !< Newton: relative step tolerance at the peak and outputs
    real(wp) :: tol_path = 1.0e-6_wp    !< Newton: relative step tolerance along the path
    integer :: max_iter = 30            !< Newton iterations per corrector
    real(wp) :: ds_initial = 0.05_wp    !< first arc-length step (relative amplitude/frequency units)
    real(wp) :: ds_min = 1.0e-9_wp      !< smallest step before giving up
    real(wp) :: ds_max = 0.3_wp         !< largest step
    integer :: target_iter = 4          !< step control: Newton iterations aimed at per step
    real(wp) :: max_angle = 0.35_wp     !< largest turn of the tangent per step [rad]
    integer :: max_steps = 20000        !< continuation steps per force
    real(wp) :: peak_tol = 1.0e-10_wp   !< peak refinement: tolerance on the arc-length parameter
    integer :: aft_samples = 0          !< 0: exact event-driven AFT; N > 0: N samples per period
    integer :: aft_min_periods = 1      !< AFT: least periods after the ramp
    integer :: aft_max_periods = 8      !< AFT: most periods until the loop repeats
    real(wp) :: aft_loop_rtol = 1.0e-12_wp  !< AFT: state agreement that closes the loop
    real(wp) :: fd_step = 1.0e-7_wp     !< relative finite-difference step of the damper Jacobian
    real(wp) :: gamma_limit = 10.0_wp   !< amplitude [rad] beyond which the response is unbounded
    logical :: full_band = .true.       !< continue to f_max; else stop when past the peak
    !> Keep the damper Jacobian from one Newton iteration (and step) to the next while Newton
    !> contracts well (chord steps: one AFT per iteration); .false.: new one every iteration.
    logical :: jacobian_reuse = .true.
    !> hbm_peaks: 0 sweeps the band for every force; 1: from the second force on, start at the
    !> previous force's peak (its state scaled by the force ratio, Newton at that frequency)
    !> and climb the new curve to its peak instead of sweeping the band; 2: the first force
    !> too, from the peak of the linear response with the stuck damper. A climb that fails
    !> falls back to the sweep. Only the peak reached by climbing is found: for curves with a
    !> single peak per force.
    integer :: warm_start = 0
  end type hbm_settings_type

  !> The peak of the response for one force (fields as the backbone's, plus statistics).
  type :: hbm_point_type
    real(wp) :: F_E = 0.0_wp       !< excitation force amplitude [N]
    real(wp) :: gamma_P = 0.0_wp   !< first-harmonic amplitude of gamma_P at the peak [rad]
    real(wp) :: f_res = 0.0_wp     !< frequency of the peak [Hz]
    real(wp) :: sigma_a = 0.0_wp   !< first-harmonic stress amplitude at f_res [Pa]
    real(wp) :: u_E = 0.0_wp       !< first-harmonic displacement amplitude at E [m]
    real(wp) :: k_re = 0.0_wp, k_im = 0.0_wp   !< M_1/Gamma_1 at the peak [N m/rad]
    real(wp) :: gamma_max = 0.0_wp !< largest gamma(t) over the period at the peak [rad]
    logical :: lift_off = .false.  !< a damper contact opens during the cycle at the peak
    integer :: npeaks = 0          !< number of local maxima of gamma_1 on the curve
    real(wp) :: peaks(HBM_MAX_PEAKS) = 0.0_wp   !< their gamma_1, ascending
    real(wp) :: peak_f(HBM_MAX_PEAKS) = 0.0_wp  !< their frequencies [Hz]
    real(wp), allocatable :: gamma_h(:)         !< |Gamma_h|, h = 1..H, at the peak [rad]
    integer :: steps = 0           !< accepted continuation steps
    integer :: iterations = 0      !< Newton iterations (all correctors)
    integer :: aft_calls = 0       !< AFT evaluations (including the Jacobians)
    real(wp) :: seconds = 0.0_wp   !< wall time of this force [s]
  end type hbm_point_type

  !> The continued response curve of one force (accepted points, in order).
  type :: hbm_curve_type
    integer :: n = 0
    real(wp), allocatable :: f(:)          !< frequency [Hz]
    real(wp), allocatable :: gamma_1(:)    !< |Gamma_1| [rad]
    real(wp), allocatable :: sigma_1(:)    !< first-harmonic stress amplitude [Pa]
    real(wp), allocatable :: gamma_max(:)  !< largest gamma(t) [rad]
  end type hbm_curve_type

  !> Everything one force's continuation needs; owned by the driver, nothing global.
  type :: problem_type
    type(hbm_settings_type) :: set
    integer :: H = 1, h0 = 0, m = 2, b = 2, nx = 2, goff = 0, n = 1
    real(wp) :: F = 0.0_wp, W_s = 1.0_wp, k_stuck = 0.0_wp, Hgg0 = 0.0_wp, M_ref = 0.0_wp
    class(hysteretic_element_type), allocatable :: el
    type(aft_workspace_type) :: ws
    ! damper moment at the last evaluation and its Jacobian d(M vector)/d(gamma unknowns)
    real(wp) :: M0 = 0.0_wp, gmax = 0.0_wp
    complex(wp), allocatable :: Mh(:)
    real(wp), allocatable :: JM(:,:)
    ! receptances at h*omega (condensed) and the omega they belong to
    type(structure_receptances_type), allocatable :: rec(:)
    real(wp) :: omega_rec = -1.0_wp
    ! factorised x-Jacobian: dense (condensed) or banded LU (full)
    real(wp), allocatable :: Jd(:,:), LU(:,:)
    integer, allocatable :: ipiv(:)
    integer :: kb = 0
    logical :: banded = .false.
    !> omega-derivative of the residual at the last Newton iterate (its J_x is still factorised)
    real(wp), allocatable :: Jw_last(:)
    !> p%JM holds a damper Jacobian that may be reused
    logical :: jm_valid = .false.
    !> full variant: the entries (i, j) of K, M, C inside the band, row by row (j = lo..hi),
    !> and the row i and column j of each
    real(wp), allocatable :: Kij(:), Mij(:), Cij(:)
    integer, allocatable :: Ie(:), Je(:)
    integer :: iterations = 0
  end type problem_type

  !> A converged point of the curve with its tangent (unscaled) and metric.
  type :: curve_point_type
    real(wp), allocatable :: x(:), tx(:)
    real(wp) :: omega = 0.0_wp, tw = 0.0_wp, A = 0.0_wp, dA = 0.0_wp, A_s = 1.0_wp
  end type curve_point_type

contains

  !> Newton convergence: the step is below tol, or the next one, predicted from two successive
  !> contractions, is (saves the confirming iteration of a quadratically converging Newton), or
  !> the steps stagnate just above tol (the rounding floor of an ill-conditioned full system).
  pure logical function converged(tol, stepn, prev, prev2)
    real(wp), intent(in) :: tol, stepn, prev, prev2
    converged = stepn <= tol
    if (converged .or. prev >= huge(1.0_wp)) return
    converged = stepn <= 100.0_wp*tol .and. prev <= 100.0_wp*tol .and. stepn > 0.5_wp*prev
    if (converged .or. prev2 >= huge(1.0_wp)) return
    converged = stepn <= 0.2_wp*prev .and. prev <= 0.5_wp*prev2 .and. stepn**2/prev <= tol
  end function converged

  !> Wall time [s] since the count c0 of system_clock (count rate `rate`).
  real(wp) function seconds_since(c0, rate)
    integer(8), intent(in) :: c0, rate
    integer(8) :: c1
    call system_clock(c1)
    seconds_since = real(c1 - c0, wp)/real(rate, wp)
  end function seconds_since

  !> |Gamma_1| of the unknowns.
  pure real(wp) function amplitude(p, x)
    type(problem_type), intent(in) :: p
    real(wp), intent(in) :: x(:)
    amplitude = hypot(x(p%goff+p%h0+1), x(p%goff+p%h0+2))
  end function amplitude

  !> Amplitude scale of the metric: the norm of the gamma unknowns (never zero).
  pure real(wp) function amplitude_scale(p, x)
    type(problem_type), intent(in) :: p
    real(wp), intent(in) :: x(:)
    amplitude_scale = max(norm2(x(p%goff+1:p%goff+p%m)), 1.0e-300_wp)
  end function amplitude_scale

  !> <(x1, w1), (x2, w2)> in the metric: gamma unknowns over A_s, omega over W_s.
  pure real(wp) function scaled_dot(p, x1, w1, x2, w2, A_s)
    type(problem_type), intent(in) :: p
    real(wp), intent(in) :: x1(:), w1, x2(:), w2, A_s
    scaled_dot = dot_product(x1(p%goff+1:p%goff+p%m), x2(p%goff+1:p%goff+p%m))/A_s**2 + &
      & w1*w2/p%W_s**2
  end function scaled_dot
end module udmap_baseline_types
