!> The damper as a complex stiffness k(gamma) = k_Re + i k_Im on the platform rotation
!> (PHYSICS.md section 2): the asymmetric flat/curved damper (traced exactly, tabulated once),
!> a rotational Jenkins element, or a measured table.
module udmap_damper_type
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_core_strings, only: indexed_name
  use udmap_damper_params, only: asymmetric_params_type
  use udmap_damper_tracer_core, only: damper_geometry_type
  use udmap_damper_tracer, only: new_damper_geometry
  use udmap_damper_loops, only: ramp_type, loop_type, loop_workspace_type, trace_ramp, &
    & cf_only_ramp, steady_loop, loop_moment, loop_stiffness
  use udmap_damper_stiffness_table, only: stiffness_table_type, build_stiffness_table, &
    & table_stiffness, table_stiffness_derivative, table_stiffness_exact, table_energy_slope
  use udmap_damper_jenkins, only: jenkins_stiffness, jenkins_loop_moment
  use udmap_damper_measured, only: measured_table_type, new_measured_table, measured_stiffness
  implicit none
  private
  public :: asymmetric_params_type, damper_type
  public :: new_asymmetric_damper, new_jenkins_damper, new_table_damper
  public :: stiffness_table, check_amplitudes

  !> Damper kinds (case file "kind": "asymmetric", "jenkins", "table").
  integer, parameter, public :: DAMPER_ASYMMETRIC = 1, DAMPER_JENKINS = 2, DAMPER_TABLE = 3
  !> A face with |mu - tan(beta)| <= NEUTRAL_TOL tan(beta) is a neutral wedge; its one-sided
  !> dampers are traced at tan(beta) (1 -+ NEUTRAL_SIDE) and agree if they differ by at most
  !> NEUTRAL_AGREE (relative; continuity in mu gives 1e-6 there, the jump at tan(beta) O(1)).
  real(wp), parameter :: NEUTRAL_TOL = 1e-8_wp, NEUTRAL_SIDE = 1e-6_wp, NEUTRAL_AGREE = 1e-4_wp

  !> A damper and everything derived from it for evaluating k(gamma).
  type :: damper_type
    !> DAMPER_* (0: not created).
    integer :: kind = 0
    !> Base-cycle amplitude and largest amplitude without slip [rad], plateau moments [N m],
    !> stuck stiffness (k_Re at small amplitude) [N m/rad].
    real(wp) :: gamma_b = 0, gamma_s = 0, M_max = 0, M_min = 0, k_stuck = 0
    !> A contact opens during the cycle at some amplitude (the damper left its design envelope).
    logical :: lift_off = .false.
    !> Incremented by every change (creation, set_CF) so that caches can tell.
    integer :: revision = 0
    !> Largest amplitude with a defined k: a table without delta_M ends at its last row [rad].
    real(wp) :: gamma_max = huge(1.0_wp)
    !> Asymmetric kind: parameters (CF and contact stiffnesses current), reference CF of the
    !> tracing, CF/CF_ref; k_scale (kappa) the common factor of the contact stiffnesses against
    !> the traced ones (k_ref: kn_flat, kt_flat, kn_curved, kt_curved then), and gamma_scale =
    !> CF_scale/k_scale, the factor of every amplitude (PHYSICS.md 2.3).
    type(asymmetric_params_type) :: params
    real(wp) :: CF_ref = 0, CF_scale = 1, k_scale = 1, gamma_scale = 1
    real(wp) :: k_ref(4) = 0
    type(damper_geometry_type) :: geometry
    type(ramp_type) :: ramp
    type(stiffness_table_type) :: table
    !> Jenkins kind: stiffness [N m/rad] and slip moment [N m].
    real(wp) :: kt = 0, M_slip = 0
    !> Table kind.
    type(measured_table_type) :: measured
  contains
    !> k(gamma) [N m/rad] for an amplitude gamma [rad] (tens of ns), or dk/dgamma.
    procedure :: stiffness
    !> dk/dgamma [N m/rad^2] (closed forms; no interpolation).
    procedure :: stiffness_derivative
    !> k(gamma) exactly from the traced topology intervals (no interpolation; slower).
    procedure :: stiffness_exact
    !> k(gamma) from a loop traced at this amplitude from the virgin state (asymmetric kind;
    !> the other kinds return stiffness).
    procedure :: stiffness_direct
    !> New centrifugal load: rescales (PHYSICS.md 2.3), no new tracing.
    procedure :: set_CF
    !> New CF and a common factor of the contact stiffnesses: rescales, no new tracing.
    procedure :: set_scale
    !> The steady loop M_r(tau) at amplitude gamma_a, gamma = gamma_a cos(tau).
    procedure :: loop
    !> Number of jumps of k(gamma) (PHYSICS.md 2.5; asymmetric kind with lift-off only).
    procedure :: jump_count
    !> Jump i (ascending gamma_c): its amplitude and the one-sided k and dk/dgamma.
    procedure :: jump
    !> lim E(gamma)/gamma at large amplitude [N m] (2 Delta_M when the plateaus bound the
    !> moment; less with lift-off; huge if it grows without bound).
    procedure :: energy_slope
  end type damper_type

contains

  !> The asymmetric damper of PHYSICS.md 2.1: traces the virgin ramp, the base cycle and the
  !> loops below gamma_b, and tabulates k(gamma).
  !>
  !> The neutral wedge: with mu = tan(beta) of a face the edge of its friction cone is radial,
  !> the damper can slide along that face at no change of its forces, and the answers for mu
  !> just below and just above tan(beta) differ by O(1) (blade A at 45 deg: F_lim_backbone
  !> 25.47 N below, 11.29 N above). The tracer counts rates below TOL_RATE = 1e-9 as zero, so it
  !> cannot tell the two sides apart within a few 1e-9 of tan(beta): there (NEUTRAL_TOL, ten
  !> times that) the damper is traced at tan(beta) (1 -+ NEUTRAL_SIDE) and, when both sides
  !> agree (the limit exists), the side below is used; else an error names mu and the angle.
  recursive subroutine new_asymmetric_damper(damper, params, error)
    type(damper_type), intent(out) :: damper
    type(asymmetric_params_type), intent(in) :: params
    type(error_type), allocatable, intent(out) :: error
    integer :: face

    face = neutral_face(params)
    if (face > 0) then
      call neutral_wedge(damper, params, face, error)
      return
    end if
    call new_damper_geometry(damper%geometry, params, error)
    if (allocated(error)) return
    call trace_ramp(damper%geometry, params%CF, damper%ramp, error)
    if (allocated(error)) return
    call build_stiffness_table(damper%geometry, damper%ramp, damper%table, error)
    if (allocated(error)) return
    damper%kind = DAMPER_ASYMMETRIC
    damper%params = params
    damper%CF_ref = params%CF
    damper%CF_scale = 1
    damper%k_scale = 1
    damper%gamma_scale = 1
    damper%k_ref = [params%kn_flat, params%kt_flat, params%kn_curved, params%kt_curved]
    damper%lift_off = damper%table%lift_off
    damper%k_stuck = damper%table%k_stuck
    call update_scaled(damper)
    damper%revision = 1
  end subroutine new_asymmetric_damper

  !> The face (1 flat, 2 curved) whose tan(beta) equals mu to NEUTRAL_TOL, else 0.
  pure integer function neutral_face(params) result(face)
    type(asymmetric_params_type), intent(in) :: params
    real(wp) :: t(2)
    integer :: i
    face = 0
    t = tan([params%beta_L_deg, params%beta_R_deg]*pi/180)
    do i = 1, 2
      if (abs(params%mu - t(i)) <= NEUTRAL_TOL*t(i)) face = i
    end do
  end function neutral_face

  !> The neutral wedge (see new_asymmetric_damper): the one-sided dampers at
  !> tan(beta) (1 -+ NEUTRAL_SIDE) compared over 1e-2..1e3 gamma_b.
  recursive subroutine neutral_wedge(damper, params, face, error)
    type(damper_type), intent(out) :: damper
    type(asymmetric_params_type), intent(in) :: params
    integer, intent(in) :: face
    type(error_type), allocatable, intent(out) :: error
    type(asymmetric_params_type) :: side
    type(damper_type) :: above
    real(wp) :: beta, t, g, worst
    integer :: i
    character(len=32) :: bm, bb, bw
    character(len=:), allocatable :: name
    if (face == 1) then
      beta = params%beta_L_deg
      name = "beta_L_deg"
    else
      beta = params%beta_R_deg
      name = "beta_R_deg"
    end if
    t = tan(beta*pi/180)
    side = params
    side%mu = t*(1 + NEUTRAL_SIDE)
    call new_asymmetric_damper(above, side, error)
    if (allocated(error)) return
    side%mu = t*(1 - NEUTRAL_SIDE)
    call new_asymmetric_damper(damper, side, error)
    if (allocated(error)) return
    worst = max(abs(above%gamma_b/damper%gamma_b - 1), &
      & abs(above%M_max - damper%M_max)/(damper%M_max - damper%M_min), &
      & abs(above%M_min - damper%M_min)/(damper%M_max - damper%M_min), &
      & abs(above%energy_slope() - damper%energy_slope())/(damper%M_max - damper%M_min))
    do i = 0, 50
      g = damper%gamma_b*10.0_wp**(-2 + 5*i/50.0_wp)
      worst = max(worst, abs(above%stiffness(g) - damper%stiffness(g))/damper%k_stuck)
    end do
    if (.not. (worst <= NEUTRAL_AGREE)) then
      write(bm, '(g0.10)') params%mu
      write(bb, '(g0.10)') beta
      write(bw, '(es9.2)') worst
      call fatal_error(error, "asymmetric damper: mu = "//trim(bm)//" equals tan("//name// &
        & " = "//trim(bb)//" deg) (a neutral wedge: the friction cone's edge is radial and "// &
        & "the damper slides along that face at no change of its forces); the loops for mu "// &
        & "just below and just above tan(beta) differ (by "//trim(adjustl(bw))//" of "// &
        & "k_stuck), so the answer is not defined: change mu or "//name, UDMAP_EPHYSICS)
      return
    end if
    damper%params%mu = params%mu
  end subroutine neutral_wedge

  !> A rotational Jenkins element: kt [N m/rad] > 0, M_slip [N m] > 0.
  subroutine new_jenkins_damper(damper, kt, M_slip, error)
    type(damper_type), intent(out) :: damper
    real(wp), intent(in) :: kt, M_slip
    type(error_type), allocatable, intent(out) :: error
    call check_positive(kt, "jenkins damper: 'kt'", "", error)
    if (allocated(error)) return
    call check_positive(M_slip, "jenkins damper: 'M_slip'", "", error)
    if (allocated(error)) return
    damper%kind = DAMPER_JENKINS
    damper%kt = kt
    damper%M_slip = M_slip
    damper%gamma_b = M_slip/kt
    damper%gamma_s = M_slip/kt
    damper%M_max = M_slip
    damper%M_min = -M_slip
    damper%k_stuck = kt
    damper%revision = 1
  end subroutine new_jenkins_damper

  !> A measured table (gamma ascending > 0, k_re, k_im >= 0); delta_M > 0 enables the
  !> extrapolation beyond the last row. gamma_b is the last row, gamma_s the last row with
  !> k_im = 0 from the first on (0 if none), M_max = -M_min = delta_M/2 (0 without delta_M).
  subroutine new_table_damper(damper, gamma, k_re, k_im, error, delta_M)
    type(damper_type), intent(out) :: damper
    real(wp), intent(in) :: gamma(:), k_re(:), k_im(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: delta_M
    integer :: i, n
    call new_measured_table(damper%measured, gamma, k_re, k_im, error, delta_M)
    if (allocated(error)) return
    n = size(gamma)
    damper%kind = DAMPER_TABLE
    damper%gamma_b = gamma(n)
    damper%gamma_s = 0
    do i = 1, n
      if (k_im(i) /= 0) exit
      damper%gamma_s = gamma(i)
    end do
    if (present(delta_M)) then
      damper%M_max = delta_M/2
      damper%M_min = -delta_M/2
    else
      damper%gamma_max = gamma(n)
    end if
    damper%k_stuck = k_re(1)
    damper%revision = 1
  end subroutine new_table_damper

  !> k(gamma) for an amplitude gamma [rad]. gamma <= 0 (or NaN) gives the small-amplitude
  !> limit; a table without delta_M is held at its last row beyond it (see gamma_max). With
  !> derivative = .true. dk/dgamma instead (see stiffness_derivative).
  elemental function stiffness(self, gamma, derivative) result(k)
    class(damper_type), intent(in) :: self
    real(wp), intent(in) :: gamma
    logical, intent(in), optional :: derivative
    complex(wp) :: k
    logical :: slope
    slope = .false.
    if (present(derivative)) slope = derivative
    select case (self%kind)
    case (DAMPER_ASYMMETRIC)
      if (slope) then
        k = 0
        if (gamma > 0) k = self%k_scale* &
          & table_stiffness_derivative(self%table, gamma/self%gamma_scale)/self%gamma_scale
      else if (gamma > 0) then
        k = self%k_scale*table_stiffness(self%table, gamma/self%gamma_scale)
      else
        k = self%k_scale*self%table%k_small
      end if
    case (DAMPER_JENKINS)
      k = jenkins_stiffness(self%kt, self%M_slip, gamma, slope)
    case (DAMPER_TABLE)
      k = measured_stiffness(self%measured, gamma, slope)
    case default
      k = 0
    end select
  end function stiffness

  !> dk/dgamma [N m/rad^2], exact for the asymmetric and Jenkins kinds, the PCHIP derivative
  !> for a table.
  elemental function stiffness_derivative(self, gamma) result(dk)
    class(damper_type), intent(in) :: self
    real(wp), intent(in) :: gamma
    complex(wp) :: dk
    dk = self%stiffness(gamma, derivative=.true.)
  end function stiffness_derivative

  !> k(gamma) without the table: for the asymmetric kind a loop traced at this amplitude from
  !> the virgin state with the full history of PHYSICS.md 2.1 (exact, about a microsecond).
  subroutine stiffness_direct(self, gamma, k, error)
    class(damper_type), intent(in) :: self
    real(wp), intent(in) :: gamma
    complex(wp), intent(out) :: k
    type(error_type), allocatable, intent(out) :: error
    type(ramp_type) :: ramp
    type(loop_type) :: lp
    type(loop_workspace_type) :: work
    k = 0
    call check_positive(gamma, "damper: amplitude 'gamma'", " [rad]", error)
    if (allocated(error)) return
    if (self%kind /= DAMPER_ASYMMETRIC) then
      k = self%stiffness(gamma)
      return
    end if
    call cf_only_ramp(self%geometry, self%CF_ref, ramp, error)
    if (allocated(error)) return
    call steady_loop(self%geometry, ramp, gamma/self%gamma_scale, lp, work, error)
    if (allocated(error)) return
    call loop_stiffness(lp, lp%p0, k)
    k = self%k_scale*k
  end subroutine stiffness_direct

  !> New centrifugal load CF [N] for the asymmetric kind: k(gamma; CF) = k(gamma CF_ref/CF;
  !> CF_ref), plateau moments and amplitudes scale with CF (PHYSICS.md 2.3).
  subroutine set_CF(self, CF, error)
    class(damper_type), intent(inout) :: self
    real(wp), intent(in) :: CF
    type(error_type), allocatable, intent(out) :: error
    if (self%kind /= DAMPER_ASYMMETRIC) then
      call fatal_error(error, "set_CF: only the asymmetric damper has a centrifugal load "// &
        & "(parameter 'CF')", UDMAP_EINPUT)
      return
    end if
    call check_positive(CF, "set_CF: parameter 'CF'", "", error)
    if (allocated(error)) return
    self%params%CF = CF
    self%CF_scale = CF/self%CF_ref
    self%gamma_scale = self%CF_scale/self%k_scale
    call update_scaled(self)
    self%revision = self%revision + 1
  end subroutine set_CF

  !> New centrifugal load CF [N] and all four contact stiffnesses kappa times the traced ones
  !> (kappa > 0), for the asymmetric kind, without tracing again (PHYSICS.md 2.3):
  !> k(gamma; CF, kappa) = kappa k(gamma CF_ref/(kappa CF); CF_ref, 1); amplitudes scale with
  !> CF/kappa, moments with CF. set_scale(CF_ref, 1) restores the traced damper exactly.
  subroutine set_scale(self, CF, kappa, error)
    class(damper_type), intent(inout) :: self
    real(wp), intent(in) :: CF, kappa
    type(error_type), allocatable, intent(out) :: error
    if (self%kind /= DAMPER_ASYMMETRIC) then
      call fatal_error(error, "set_scale: only the asymmetric damper has contact stiffnesses "// &
        & "and a centrifugal load", UDMAP_EINPUT)
      return
    end if
    call check_positive(kappa, "set_scale: stiffness factor 'kappa'", "", error)
    if (allocated(error)) return
    self%k_scale = kappa
    self%params%kn_flat = kappa*self%k_ref(1)
    self%params%kt_flat = kappa*self%k_ref(2)
    self%params%kn_curved = kappa*self%k_ref(3)
    self%params%kt_curved = kappa*self%k_ref(4)
    call self%set_CF(CF, error)
  end subroutine set_scale

  !> The steady loop at amplitude gamma_a > 0: M_r [N m] at the given tau [rad], with
  !> gamma = gamma_a cos(tau) (asymmetric: traced with the history of PHYSICS.md 2.1;
  !> jenkins: closed form; not available for a table).
  subroutine loop(self, gamma_a, tau, M_r, error)
    class(damper_type), intent(in) :: self
    real(wp), intent(in) :: gamma_a, tau(:)
    real(wp), intent(out) :: M_r(:)
    type(error_type), allocatable, intent(out) :: error
    type(loop_type) :: lp
    type(loop_workspace_type) :: work
    integer :: i
    M_r = 0
    call check_positive(gamma_a, "damper: amplitude 'gamma_a'", " [rad]", error)
    if (allocated(error)) return
    if (size(M_r) /= size(tau)) then
      call fatal_error(error, "loop: arrays 'tau' and 'M_r' differ in length", UDMAP_EINPUT)
      return
    end if
    if (.not. all(abs(tau) <= huge(1.0_wp))) then
      call fatal_error(error, "loop: parameter 'tau' holds a value that is not finite", &
        & UDMAP_EINPUT)
      return
    end if
    select case (self%kind)
    case (DAMPER_ASYMMETRIC)
      call steady_loop(self%geometry, self%ramp, gamma_a/self%gamma_scale, lp, work, error)
      if (allocated(error)) return
      do i = 1, size(tau)
        M_r(i) = self%CF_scale*loop_moment(lp, tau(i))
      end do
    case (DAMPER_JENKINS)
      M_r = jenkins_loop_moment(self%kt, self%M_slip, gamma_a, tau)
    case default
      call fatal_error(error, "loop: a damper of kind 'table' has no loop (only k(gamma))", &
        & UDMAP_EINPUT)
    end select
  end subroutine loop

  !> Number of jumps of k(gamma) (PHYSICS.md 2.5).
  pure integer function jump_count(self) result(n)
    class(damper_type), intent(in) :: self
    n = 0
    if (self%kind == DAMPER_ASYMMETRIC) n = self%table%n_jump
  end function jump_count

  !> Jump i (1..jump_count, ascending): gamma_c [rad] and the one-sided values
  !> k(gamma_c-), k(gamma_c+) [N m/rad] and dk/dgamma there [N m/rad^2], at the current CF.
  pure subroutine jump(self, i, gamma_c, k_minus, k_plus, dk_minus, dk_plus)
    class(damper_type), intent(in) :: self
    integer, intent(in) :: i
    real(wp), intent(out) :: gamma_c
    complex(wp), intent(out) :: k_minus, k_plus
    complex(wp), intent(out), optional :: dk_minus, dk_plus
    gamma_c = self%gamma_scale*self%table%jump_gamma(i)
    k_minus = self%k_scale*self%table%jump_k(1, i)
    k_plus = self%k_scale*self%table%jump_k(2, i)
    if (present(dk_minus)) dk_minus = self%k_scale*self%table%jump_dk(1, i)/self%gamma_scale
    if (present(dk_plus)) dk_plus = self%k_scale*self%table%jump_dk(2, i)/self%gamma_scale
  end subroutine jump

  !> lim E(gamma)/gamma for gamma -> infinity [N m] (E the energy dissipated per cycle):
  !> 2 (M_max - M_min) when the plateaus bound the moment (every kind but an asymmetric damper
  !> whose gaps keep opening); it scales with CF like the moments.
  pure real(wp) function energy_slope(self) result(dEdp)
    class(damper_type), intent(in) :: self
    dEdp = 2*(self%M_max - self%M_min)
    if (self%kind == DAMPER_ASYMMETRIC) then
      dEdp = table_energy_slope(self%table)
      if (dEdp < huge(1.0_wp)) dEdp = self%CF_scale*dEdp
    end if
  end function energy_slope

  !> Fills the CF-dependent fields of the asymmetric kind from the reference table.
  pure subroutine update_scaled(self)
    type(damper_type), intent(inout) :: self
    self%gamma_b = self%gamma_scale*self%table%gamma_b
    self%gamma_s = self%gamma_scale*self%table%gamma_s
    self%k_stuck = self%k_scale*self%table%k_stuck
    self%M_max = self%CF_scale*self%table%base%M_max
    self%M_min = self%CF_scale*self%table%base%M_min
  end subroutine update_scaled

  !> An error "<what> must be a positive finite number<unit>" unless 0 < x < infinity.
  pure subroutine check_positive(x, what, unit, error)
    real(wp), intent(in) :: x
    character(len=*), intent(in) :: what, unit
    type(error_type), allocatable, intent(out) :: error
    if (.not. (x > 0 .and. x <= huge(x))) then
      call fatal_error(error, what//" must be a positive finite number"//unit, UDMAP_EINPUT)
    end if
  end subroutine check_positive

  !> k(gamma) evaluated exactly from the traced topology intervals (asymmetric kind; a few
  !> hundred ns, no interpolation); the other kinds return stiffness.
  elemental function stiffness_exact(self, gamma) result(k)
    class(damper_type), intent(in) :: self
    real(wp), intent(in) :: gamma
    complex(wp) :: k
    if (self%kind == DAMPER_ASYMMETRIC .and. .not. (gamma > 0)) then
      k = self%table%k_small
    else if (self%kind == DAMPER_ASYMMETRIC) then
      k = self%k_scale*table_stiffness_exact(self%table, gamma/self%gamma_scale)
    else
      k = self%stiffness(gamma)
    end if
  end function stiffness_exact

  !> The damper's complex stiffness k(gamma) = k_Re + i k_Im [N m/rad] (PHYSICS.md 2.2) at the
  !> amplitudes gamma [rad]: the table of the damper, with the amplitudes checked
  !> (check_amplitudes).
  subroutine stiffness_table(damper, gamma, k, error)
    type(damper_type), intent(in) :: damper
    real(wp), intent(in) :: gamma(:)
    complex(wp), intent(out) :: k(:)
    type(error_type), allocatable, intent(out) :: error
    k = 0
    if (damper%kind == 0) then
      call fatal_error(error, "stiffness_table: the damper has not been created", UDMAP_EINPUT)
      return
    end if
    if (size(k) /= size(gamma)) then
      call fatal_error(error, "stiffness_table: k must have the size of gamma", UDMAP_EINPUT)
      return
    end if
    call check_amplitudes(damper, gamma, error)
    if (allocated(error)) return
    k = damper%stiffness(gamma)
  end subroutine stiffness_table

  !> Amplitudes at which k(gamma) may be evaluated: positive and finite, and within a measured
  !> table that has no delta_M (such a table ends at its last row, gamma_max). The one check of
  !> the Fortran, C and Python faces; entries are named as C and Python index them.
  subroutine check_amplitudes(damper, gamma, error)
    type(damper_type), intent(in) :: damper
    real(wp), intent(in) :: gamma(:)
    type(error_type), allocatable, intent(out) :: error
    character(len=16) :: buf
    integer :: i
    do i = 1, size(gamma)
      if (.not. (gamma(i) > 0 .and. gamma(i) <= huge(1.0_wp))) then
        call fatal_error(error, "damper stiffness: amplitude '"//indexed_name("gamma", i)// &
          & "' must be a positive finite number [rad]", UDMAP_EINPUT)
        return
      else if (damper%kind == DAMPER_TABLE .and. gamma(i) > damper%gamma_max) then
        write(buf, '(es12.5)') damper%gamma_max
        call fatal_error(error, "damper stiffness: amplitude '"//indexed_name("gamma", i)// &
          & "' lies beyond the table's last row "//trim(buf)//" rad and the table has no "// &
          & "'delta_M'", UDMAP_EINPUT)
        return
      end if
    end do
  end subroutine check_amplitudes
end module udmap_damper_type
