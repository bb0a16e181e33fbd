!> Ground truth of a traveling wave (PHYSICS.md 2.6 last bullet, 7): the whole wheel, N blades
!> and N asymmetric dampers, integrated in time from rest to a steady state under the forces
!> F_j = F_E sin(omega t + j phi), phi = 2 pi EO/N (the single blade's sine, so that EO = 0 is
!> today's in-phase dti; a cosine only shifts the time origin).
!>
!> Damper j touches blade j with its flat side and blade j + 1 (mod N) with its curved side;
!> blade j's platform p_j = B^T q_j, B the rows of (u_P, v_P, gamma_P); blade j receives
!> -B (A_flat of damper j + A_curved of damper j - 1 - A_ref), A_ref the static action of the
!> dampers loaded by CF with the blades at rest (each damper starts virgin, CF ramped first).
!>
!> Each Newmark step (the single blade's scheme, udmap_baseline_newmark) is linear in the
!> blades, so with X_B = K_eff^-1 B and C_pp = B^T X_B the step reduces to the 3N platform
!> coordinates: p_j + C_pp (A_j(p) - A_ref) = p_j,lin. It is solved by Newton with the exact
!> tangent of each damper's final contact states, every damper traced exactly
!> (udmap_damper_tracer: trace_path) from its state at the step's start along the straight line
!> to the trial coordinates, with a backtracking line search. Steady state: the single blade's
!> test on every blade's first harmonic of gamma_P.
module udmap_baseline_wheel
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_core_lapack, only: dgesv
  use udmap_core_strings, only: itoa
  use udmap_blade_platform, only: platform_rows, platform_translations_known
  use udmap_baseline_linear_structure, only: structure_type
  use udmap_baseline_newmark, only: dti_settings_type, dti_point_type, dti_runner_type, &
    & check_inputs, keff_solve, newmark_type, newmark_setup, newmark_load, newmark_commit, &
    & ss_tracker_type, ss_track, ss_relative, step_trace_type
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_element_asymmetric, only: contact_element_type
  use udmap_damper_tracer_core, only: damper_geometry_type, damper_state_type, solve3, &
    & CONTACT_OPEN, CONTACT_STICK, CONTACT_SLIP_POS, CONTACT_SLIP_NEG
  use udmap_damper_tracer, only: trace_path, platform_actions
  implicit none
  private
  public :: wheel_point_type, wheel_response, wheel_peak, damper_tangent

  !> Most blades of a wheel integrated in time: each step's Newton solve on the 3N platform
  !> coordinates is dense (analysis.blades itself goes to 10000).
  integer, parameter :: MAX_BLADES = 100

  !> Steady state of the wheel: blade 0's point (dti_point_type) and the blades' spread.
  type, extends(dti_point_type) :: wheel_point_type
    integer :: blades = 0              !< N
    integer :: engine_order = 0        !< EO
    real(wp) :: phi = 0.0_wp           !< interblade phase 2 pi EO/N [rad]
    !> Largest relative difference of the blades' first-harmonic amplitudes of gamma_P and of
    !> the stress, (max - min)/max.
    real(wp) :: gamma_spread = 0.0_wp, sigma_spread = 0.0_wp
    !> Largest |arg(Gamma_{j+1}/Gamma_j) - phi| over the blades (wrapped to [0, pi]) [rad].
    real(wp) :: phase_spread = 0.0_wp
    !> First harmonics of every blade's gamma_P [rad] and stress [Pa], blade j at index j + 1.
    complex(wp), allocatable :: gamma_b(:), sigma_b(:)
  end type wheel_point_type

  !> The wheel's runs, each run's point kept.
  type, extends(dti_runner_type) :: wheel_runner_type
    integer :: blades = 0, engine_order = 0
    type(wheel_point_type), allocatable :: points(:)
  contains
    procedure :: run => wheel_run
    procedure :: check => check_wheel
  end type wheel_runner_type

contains

  !> Steady state of the wheel at f [Hz], blade 0 under F_E sin(2 pi f t), blade j advanced by
  !> j phi, phi = 2 pi EO/N.
  subroutine wheel_response(st, element, f, F_E, blades, engine_order, settings, point, error)
    type(structure_type), intent(in), target :: st
    class(hysteretic_element_type), intent(in), target :: element
    real(wp), intent(in) :: f, F_E
    integer, intent(in) :: blades, engine_order
    type(dti_settings_type), intent(in) :: settings
    type(wheel_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    call wheel_dti(st, element, F_E, blades, engine_order, settings, point, error, f=f)
  end subroutine wheel_response

  !> The frequency of the largest first harmonic of blade 0's gamma_P, searched around
  !> f_center (by default the in-phase H = 1 standard method's peak in [f_min, f_max]).
  subroutine wheel_peak(st, element, f_min, f_max, F_E, blades, engine_order, settings, point, &
      & error, f_center)
    type(structure_type), intent(in), target :: st
    class(hysteretic_element_type), intent(in), target :: element
    real(wp), intent(in) :: f_min, f_max, F_E
    integer, intent(in) :: blades, engine_order
    type(dti_settings_type), intent(in) :: settings
    type(wheel_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f_center
    call wheel_dti(st, element, F_E, blades, engine_order, settings, point, error, &
      & f_min=f_min, f_max=f_max, f_center=f_center)
  end subroutine wheel_peak

  !> The wheel's response (f) or peak (f_min, f_max, f_center) by its runner.
  subroutine wheel_dti(st, element, F_E, blades, engine_order, settings, point, error, f, &
      & f_min, f_max, f_center)
    type(structure_type), intent(in), target :: st
    class(hysteretic_element_type), intent(in), target :: element
    real(wp), intent(in) :: F_E
    integer, intent(in) :: blades, engine_order
    type(dti_settings_type), intent(in) :: settings
    type(wheel_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: f, f_min, f_max, f_center
    type(wheel_runner_type) :: runner
    runner = wheel_runner_type(st=st, element=element, F_E=F_E, settings=settings, &
      & blades=blades, engine_order=engine_order, points=[wheel_point_type::])
    call runner%drive(error, f, f_min, f_max, f_center)
    if (runner%best > 0) point = runner%points(runner%best)
    call runner%stamp(point)
  end subroutine wheel_dti

  !> One run of the wheel (check_wheel has made sure of the asymmetric damper).
  subroutine wheel_run(self, f, gamma_1, error)
    class(wheel_runner_type), intent(inout) :: self
    real(wp), intent(in) :: f
    real(wp), intent(out) :: gamma_1
    type(error_type), allocatable, intent(out) :: error
    type(wheel_point_type) :: p
    select type (element => self%element)
    type is (contact_element_type)
      call integrate_wheel(self%st, element, 2.0_wp*pi*f, self%F_E, self%blades, &
        & self%engine_order, self%settings, p, error)
    end select
    gamma_1 = p%gamma_1
    self%points = [self%points, p]
  end subroutine wheel_run

  !> The single blade's input checks, then the wheel's own.
  subroutine check_wheel(self, error)
    class(wheel_runner_type), intent(in) :: self
    type(error_type), allocatable, intent(out) :: error
    call check_inputs(self%st, self%F_E, self%settings, error)
    if (allocated(error)) return
    if (self%blades < 2 .or. self%blades > MAX_BLADES) then
      call fatal_error(error, "dti: blades must be in 2.."//itoa(MAX_BLADES)//" for the "// &
        & "whole wheel in time, got "//itoa(self%blades), UDMAP_EINPUT)
      return
    end if
    if (self%engine_order < 0) then
      call fatal_error(error, "dti: engine_order must be >= 0, got "//itoa(self%engine_order), &
        & UDMAP_EINPUT)
      return
    end if
    select type (element => self%element)
    type is (contact_element_type)
    class default
      call fatal_error(error, "dti: the whole wheel needs the asymmetric damper (the jenkins "// &
        & "and table dampers act on gamma_P alone: the interblade phase does not change them)", &
        & UDMAP_EINPUT)
      return
    end select
    if (mod(self%engine_order, self%blades) /= 0) then
      if (.not. allocated(self%st%blade)) then
        call fatal_error(error, "dti: a traveling wave needs the blade's platform rows", &
          & UDMAP_EINPUT)
      else if (.not. platform_translations_known(self%st%blade)) then
        call fatal_error(error, "blade: the platform translations are unknown (traveling "// &
          & "waves need u_P: blade.u_dof on a matrices blade, platform.tangent on an fe "// &
          & "blade)", UDMAP_EINPUT)
      end if
    end if
  end subroutine check_wheel

  !> One time integration of the wheel from rest at omega [rad/s] to the steady state.
  subroutine integrate_wheel(st, element, omega, F_E, nb, eo, set, point, error)
    type(structure_type), intent(in) :: st
    type(contact_element_type), intent(in) :: element
    real(wp), intent(in) :: omega, F_E
    integer, intent(in) :: nb, eo
    type(dti_settings_type), intent(in) :: set
    type(wheel_point_type), intent(out) :: point
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: Bp(:,:), XB(:,:), q(:,:), v(:,:), a(:,:), qlin(:,:)
    real(wp), allocatable :: r(:), qn(:)
    real(wp), allocatable :: Pc(:,:), plin(:,:), Aw(:,:), Tg(:,:,:)
    type(damper_state_type), allocatable :: dam(:), trial(:)
    type(step_trace_type), allocatable :: tr(:)
    type(ss_tracker_type), allocatable :: ss(:)
    type(newmark_type) :: nm
    complex(wp) :: ratio
    real(wp) :: Cpp(3,3), Aref(3), Aload(3,2), phi, gmax, gmin, floor_p(3), pscale(3)
    logical :: held(3)
    integer :: n, j, per, good, g, b, k
    logical :: lifted

    point%F_E = F_E
    point%f = omega/(2.0_wp*pi)
    point%blades = nb
    point%engine_order = eo
    phi = 2.0_wp*pi*real(mod(eo, nb), wp)/real(nb, wp)
    point%phi = phi
    n = st%ndof
    g = st%gamma_dof
    call newmark_setup(st, omega, set, nm, error)
    if (allocated(error)) return
    allocate(Bp(n, 3), XB(n, 3))
    Bp = 0.0_wp
    if (allocated(st%blade)) then
      if (platform_translations_known(st%blade)) call platform_rows(st%blade, Bp)
    end if
    Bp(:, 3) = 0.0_wp
    Bp(g, 3) = 1.0_wp
    XB = Bp
    do k = 1, 3
      call keff_solve(st, nm%Keff, XB(:, k), error)
      if (allocated(error)) return
    end do
    Cpp = matmul(transpose(Bp), XB)
    held = [(all(Bp(:, k) == 0.0_wp), k = 1, 3)]
    allocate(q(n, 0:nb-1), v(n, 0:nb-1), a(n, 0:nb-1), qlin(n, 0:nb-1))
    allocate(r(n), qn(n))
    allocate(Pc(3, 0:nb-1), plin(3, 0:nb-1), Aw(3, 0:nb-1), Tg(6, 6, 0:nb-1))
    allocate(dam(0:nb-1), trial(0:nb-1), tr(0:nb-1), ss(0:nb-1))
    ! every damper virgin, CF ramped with the blades at rest: the element's loaded state
    dam = element%loaded
    Aload = platform_actions(element%geo, element%loaded)
    Aref = Aload(:, 1) + Aload(:, 2)
    ! the platform motion below which the residual is rounding of the contact forces
    floor_p = 0.15_wp*matmul(abs(Cpp), abs(Aload(:, 1)) + abs(Aload(:, 2)))
    Aw = 0.0_wp
    Pc = 0.0_wp
    do b = 0, nb - 1
      call damper_tangent(element%geo, dam(b), Tg(:, :, b))
    end do
    q = 0.0_wp; v = 0.0_wp; a = 0.0_wp
    good = 0
    do per = 1, set%max_periods
      do b = 0, nb - 1
        tr(b) = step_trace_type(sq=tr(b)%sq, sv=tr(b)%sv, sa=tr(b)%sa, sma=tr(b)%sma, &
          & gmax=q(g, b))
      end do
      lifted = .false.
      do j = 0, nm%Ns - 1
        do b = 0, nb - 1
          call newmark_load(st, nm, q(:, b), v(:, b), a(:, b), r)
          r(st%exc_dof) = r(st%exc_dof) + F_E*sin(2.0_wp*pi*real(j + 1, wp)/nm%Ns + b*phi)
          call keff_solve(st, nm%Keff, r, error)
          if (allocated(error)) return
          qlin(:, b) = r
          plin(:, b) = matmul(r, Bp)
        end do
        call solve_platforms()
        if (allocated(error)) return
        do b = 0, nb - 1
          qn = qlin(:, b) - matmul(XB, Aw(:, b))
          qn(g) = Pc(3, b)
          call newmark_commit(st, nm, j, tr(b), q(:, b), v(:, b), a(:, b), qn)
          lifted = lifted .or. any(trial(b)%mode == CONTACT_OPEN)
        end do
        dam = trial
        if (.not.all(abs(Pc(3, :)) <= set%gamma_limit)) then
          call fatal_error(error, "dti: |gamma_P| exceeds gamma_limit: the response is "// &
            & "unbounded (F_E at or above the limit force with little damping, or a force far "// &
            & "beyond the model)", UDMAP_EPHYSICS)
          return
        end if
      end do
      do b = 0, nb - 1
        tr(b)%G1 = 2.0_wp*tr(b)%G1/nm%T
        tr(b)%S1 = 2.0_wp*tr(b)%S1/nm%T
        call ss_track(ss(b), tr(b)%G1)
      end do
      if (per >= set%min_periods .and. &
          & all([(ss(b)%est <= set%ss_tol*abs(tr(b)%G1), b = 0, nb - 1)])) then
        good = good + 1
      else
        good = 0
      end if
      point%periods = per
      if (good >= 3) exit
    end do
    point%gamma_1 = abs(tr(0)%G1)
    point%sigma_1 = abs(tr(0)%S1)
    point%lift_off = lifted
    point%gamma_max = tr(0)%gmax
    point%gamma_0 = tr(0)%gmean/nm%T
    point%ss_error = maxval([(ss_relative(ss(b)%est, tr(b)%G1), b = 0, nb - 1)])
    point%gamma_b = [(tr(b)%G1, b = 0, nb - 1)]
    point%sigma_b = [(tr(b)%S1, b = 0, nb - 1)]
    gmax = maxval(abs(point%gamma_b)); gmin = minval(abs(point%gamma_b))
    if (gmax > 0.0_wp) point%gamma_spread = (gmax - gmin)/gmax
    gmax = maxval(abs(point%sigma_b)); gmin = minval(abs(point%sigma_b))
    if (gmax > 0.0_wp) point%sigma_spread = (gmax - gmin)/gmax
    do b = 0, nb - 1
      ratio = point%gamma_b(mod(b + 1, nb) + 1)/point%gamma_b(b + 1)
      if (abs(ratio) > 0.0_wp) point%phase_spread = max(point%phase_spread, &
        & abs(atan2(aimag(ratio*exp(cmplx(0.0_wp, -phi, wp))), &
        &           real(ratio*exp(cmplx(0.0_wp, -phi, wp)), wp))))
    end do
    if (good < 3) then
      call fatal_error(error, "dti: no steady state within max_periods = "// &
        & itoa(set%max_periods)//" periods (raise max_periods or ss_tol)", UDMAP_ENUMERIC)
      return
    end if
  contains
    !> Newton on the platforms' coordinates Pc (3, N) of the step: Pc - plin + C_pp Aw(Pc) = 0,
    !> Aw the blades' damper actions minus A_ref, the dampers traced from `dam` into `trial`.
    subroutine solve_platforms()
      real(wp) :: Rs(3, 0:nb-1), Rs_n(3, 0:nb-1), Pn(3, 0:nb-1), Awn(3, 0:nb-1)
      real(wp) :: Jac(3*nb, 3*nb), dP(3*nb), rnorm, rnorm_n, lam
      real(wp), allocatable :: Tn(:,:,:)
      type(damper_state_type), allocatable :: trn(:)
      integer :: it, ls, info, ipiv(3*nb), bp, bm, i0, ip, im
      allocate(Tn(6, 6, 0:nb-1), trn(0:nb-1))
      do k = 1, 3
        pscale(k) = max(maxval(abs(plin(k, :))), maxval(abs(Pc(k, :))), floor_p(k), tiny(1.0_wp))
      end do
      ! start: the committed dampers at the last step's coordinates
      trial = dam
      Rs = Pc - plin + matmul(Cpp, Aw)
      rnorm = residual_norm(Rs)
      do it = 1, 100
        if (rnorm <= 1.0e-13_wp) return
        Jac = 0.0_wp
        do b = 0, nb - 1
          bp = mod(b + 1, nb); bm = mod(b - 1 + nb, nb)
          i0 = 3*b; ip = 3*bp; im = 3*bm
          Jac(i0+1:i0+3, i0+1:i0+3) = Jac(i0+1:i0+3, i0+1:i0+3) + &
            & matmul(Cpp, Tg(1:3, 1:3, b) + Tg(4:6, 4:6, bm))
          Jac(i0+1:i0+3, ip+1:ip+3) = Jac(i0+1:i0+3, ip+1:ip+3) + matmul(Cpp, Tg(1:3, 4:6, b))
          Jac(i0+1:i0+3, im+1:im+3) = Jac(i0+1:i0+3, im+1:im+3) + matmul(Cpp, Tg(4:6, 1:3, bm))
          Jac(i0+1, i0+1) = Jac(i0+1, i0+1) + 1.0_wp
          Jac(i0+2, i0+2) = Jac(i0+2, i0+2) + 1.0_wp
          Jac(i0+3, i0+3) = Jac(i0+3, i0+3) + 1.0_wp
        end do
        dP = -reshape(Rs, [3*nb])
        call dgesv(3*nb, 1, Jac, 3*nb, ipiv, dP, 3*nb, info)
        ! a held coordinate (a zero row of B, the beam's v_P) stays at zero
        do k = 1, 3
          if (held(k)) dP(k::3) = 0.0_wp
        end do
        if (info /= 0) then
          call fatal_error(error, "dti: singular platform Jacobian of the wheel (dgesv info = "// &
            & itoa(info)//")", UDMAP_ENUMERIC)
          return
        end if
        lam = 1.0_wp
        do ls = 1, 30
          Pn = Pc + lam*reshape(dP, [3, nb])
          call evaluate(Pn, Awn, Tn, trn)
          if (allocated(error)) return
          Rs_n = Pn - plin + matmul(Cpp, Awn)
          rnorm_n = residual_norm(Rs_n)
          if (rnorm_n < rnorm .or. rnorm_n <= 1.0e-13_wp) exit
          lam = 0.5_wp*lam
        end do
        if (.not.(rnorm_n < rnorm .or. rnorm_n <= 1.0e-13_wp)) exit
        Pc = Pn; Aw = Awn; Tg = Tn; trial = trn; Rs = Rs_n; rnorm = rnorm_n
      end do
      if (rnorm > 1.0e-9_wp) call fatal_error(error, "dti: the wheel's damper equations did "// &
        & "not converge in a time step (relative residual "//trim(sci(rnorm))//")", UDMAP_ENUMERIC)
    end subroutine solve_platforms

    !> The dampers traced from `dam` to the coordinates Pt: the blades' actions minus A_ref,
    !> the tangents and the traced states.
    subroutine evaluate(Pt, Awt, Tt, st_out)
      real(wp), intent(in) :: Pt(3, 0:nb-1)
      real(wp), intent(out) :: Awt(3, 0:nb-1), Tt(6, 6, 0:nb-1)
      type(damper_state_type), intent(out) :: st_out(0:nb-1)
      real(wp) :: Ad(3, 2, 0:nb-1)
      integer :: d
      do d = 0, nb - 1
        st_out(d) = dam(d)
        call trace_path(element%geo, st_out(d), [Pt(:, d), Pt(:, mod(d + 1, nb))], error)
        if (allocated(error)) return
        Ad(:, :, d) = platform_actions(element%geo, st_out(d))
        call damper_tangent(element%geo, st_out(d), Tt(:, :, d))
      end do
      do d = 0, nb - 1
        Awt(:, d) = Ad(:, 1, d) + Ad(:, 2, mod(d - 1 + nb, nb)) - Aref
      end do
    end subroutine evaluate

    pure real(wp) function residual_norm(Rr)
      real(wp), intent(in) :: Rr(3, 0:nb-1)
      integer :: kk
      residual_norm = 0.0_wp
      do kk = 1, 3
        if (.not. held(kk)) residual_norm = max(residual_norm, maxval(abs(Rr(kk, :)))/pscale(kk))
      end do
    end function residual_norm
  end subroutine integrate_wheel

  !> The tangent T(6,6) = d(A(:,1); A(:,2))/dX of the damper's actions on its two platforms
  !> for its present contact states (exact between transitions: the equilibrium is linear).
  !> A singular damper equilibrium (no contact holds it) gives T = 0.
  pure subroutine damper_tangent(geo, state, T)
    type(damper_geometry_type), intent(in) :: geo
    type(damper_state_type), intent(in) :: state
    real(wp), intent(out) :: T(6, 6)
    real(wp) :: Ks(3,3), H(3,6), dq(3,6), vv(3), dN(6), dT(6)
    integer :: i, c, k, sg
    logical :: ok
    Ks = 0.0_wp; H = 0.0_wp; T = 0.0_wp
    do i = 1, 3
      k = 3*(geo%side(i) - 1)
      select case (state%mode(i))
      case (CONTACT_STICK)
        Ks = Ks + geo%kn(i)*outer(geo%bn(:,i), geo%bn(:,i)) + &
          & geo%kt(i)*outer(geo%bt(:,i), geo%bt(:,i))
        H(:, k+1:k+3) = H(:, k+1:k+3) + geo%kn(i)*outer(geo%bn(:,i), geo%pn(:,i)) + &
          & geo%kt(i)*outer(geo%bt(:,i), geo%pt(:,i))
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        sg = merge(1, -1, state%mode(i) == CONTACT_SLIP_POS)
        vv = geo%bn(:,i) + sg*geo%mu*geo%bt(:,i)
        Ks = Ks + geo%kn(i)*outer(vv, geo%bn(:,i))
        H(:, k+1:k+3) = H(:, k+1:k+3) + geo%kn(i)*outer(vv, geo%pn(:,i))
      end select
    end do
    do c = 1, 6
      call solve3(Ks, H(:, c), dq(:, c), ok)
      if (.not. ok) return
    end do
    do i = 1, 3
      if (state%mode(i) == CONTACT_OPEN) cycle
      k = 3*(geo%side(i) - 1)
      dN = -geo%kn(i)*matmul(geo%bn(:,i), dq)
      dN(k+1:k+3) = dN(k+1:k+3) + geo%kn(i)*geo%pn(:,i)
      if (state%mode(i) == CONTACT_STICK) then
        dT = -geo%kt(i)*matmul(geo%bt(:,i), dq)
        dT(k+1:k+3) = dT(k+1:k+3) + geo%kt(i)*geo%pt(:,i)
      else
        dT = merge(1.0_wp, -1.0_wp, state%mode(i) == CONTACT_SLIP_POS)*geo%mu*dN
      end if
      T(k+1:k+3, :) = T(k+1:k+3, :) + outer(geo%pn(:,i), dN) + outer(geo%pt(:,i), dT)
    end do
  contains
    pure function outer(x, y) result(o)
      real(wp), intent(in) :: x(:), y(:)
      real(wp) :: o(size(x), size(y))
      integer :: jj
      do jj = 1, size(y)
        o(:, jj) = x*y(jj)
      end do
    end function outer
  end subroutine damper_tangent

  function sci(x) result(s)
    real(wp), intent(in) :: x
    character(len=16) :: s
    write(s, '(es10.3)') x
  end function sci
end module udmap_baseline_wheel
