!> One multi-harmonic amplitude layer (PHYSICS.md 4.1). The first harmonic of the platform
!> rotation is fixed, Gamma_1 = gamma (real: it is the phase reference), and so is omega; the
!> blade is condensed onto the damper DOF through its receptances at h omega, and only the other
!> harmonics are solved for:
!>
!>   R_0 = Gamma_0 + H_gg(0) (M_0 - M_ref) = 0,   R_h = Gamma_h + H_gg(h omega) M_h = 0 (h = 2..H),
!>
!> M_h the harmonics of the damper moment over the periodic gamma(t), traced exactly through
!> the contact model with its loading history (udmap_contact_aft_moment, shared with the standard
!> method), and M_ref the static moment of the loaded damper (the blade's reference state). Newton
!> with the
!> damper Jacobian dM/dGamma in closed form from one trace (aft_moment_jacobian; finite
!> differences, 2H traces, where the events change within the perturbation), reused while
!> Newton contracts, and a backtracking line search. The force that puts the blade on the
!> layer then follows explicitly, P(omega) = (gamma + H_gg(omega) M_1)/H_gE(omega), and the
!> layer's peak is the minimum of |P| over omega: the root of psi = d|P|^2/domega, whose total
!> derivative carries dGamma/domega = -J^-1 dR/domega (the implicit function theorem; no extra
!> trace). dGamma/dgamma likewise gives the Jacobian of the backbone root search (s%Jroot) and,
!> with dGamma/domega, the first-order prediction that starts a neighbouring layer.
!>
!> Nothing here depends on neighbouring layers: a warm start only saves iterations (a cold
!> start, all other harmonics 0, converges to the same solution).
module udmap_mapping_harmonic_layer
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_blade_type, only: blade_type, receptances_type
  use udmap_core_dense_lu, only: lu_factor, lu_solve
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_aft_moment, only: aft_workspace_type, aft_moment, aft_moment_jacobian
  use udmap_contact_aft_waveform, only: waveform_value, waveform_extrema
  use udmap_mapping_harmonic_types, only: harmonic_state_type, harmonic_workspace_type, &
    & harmonic_outputs_type
  implicit none
  private
  public :: harmonic_setup, harmonic_solve, harmonic_outputs, harmonic_resize, largest_excursion

  !> Exact AFT: periods after the ramp (at least, at most) and the loop-closure tolerance (the
  !> standard method's defaults, so that both solve the same equations).
  integer, parameter :: aft_min_periods = 1, aft_max_periods = 8
  real(wp), parameter :: aft_loop_rtol = 1.0e-12_wp
  !> Relative finite-difference step of the damper Jacobian.
  real(wp), parameter :: fd_step = 1.0e-7_wp
  !> Newton: relative step tolerance (to the layer amplitude) and iteration cap.
  real(wp), parameter :: newton_tol = 1.0e-12_wp
  integer, parameter :: newton_max = 60

contains

  !> Takes the element (a copy) and the blade's static receptances; call again after a change.
  subroutine harmonic_setup(ws, element, blade, error)
    type(harmonic_workspace_type), intent(inout) :: ws
    class(hysteretic_element_type), intent(in) :: element
    type(blade_type), intent(in) :: blade
    type(error_type), allocatable, intent(out) :: error
    type(receptances_type) :: r0
    if (allocated(ws%element)) deallocate(ws%element)
    allocate(ws%element, source=element)
    call ws%element%load(error)
    if (allocated(error)) return
    ws%M_ref = ws%element%moment()
    call blade%receptances(0.0_wp, r0, error)
    if (allocated(error)) return
    ws%gg0 = r0%gg
    ws%sg0 = r0%sg
  end subroutine harmonic_setup

  !> Gives the state H harmonics, keeping the ones it has (warm start) and zeroing the others.
  subroutine harmonic_resize(s, H)
    type(harmonic_state_type), intent(inout) :: s
    integer, intent(in) :: H
    complex(wp), allocatable :: G(:)
    integer :: m
    if (s%H == H .and. allocated(s%G)) return
    allocate(G(H))
    G = (0.0_wp, 0.0_wp)
    if (allocated(s%G)) then
      m = min(H, size(s%G))
      G(1:m) = s%G(1:m)
    end if
    call move_alloc(G, s%G)
    s%H = H
    if (allocated(s%M)) deallocate(s%M)
    if (allocated(s%r)) deallocate(s%r)
    if (allocated(s%JM)) deallocate(s%JM)
    if (allocated(s%x_jm)) deallocate(s%x_jm)
    if (allocated(s%JM1)) deallocate(s%JM1)
    if (allocated(s%dx_dg)) deallocate(s%dx_dg)
    if (allocated(s%dx_dw)) deallocate(s%dx_dw)
    allocate(s%M(H), s%r(H), s%JM(2*H+1, 2*H-1), s%x_jm(2*H-1), s%JM1(2*H+1), &
      & s%dx_dg(2*H-1), s%dx_dw(2*H-1))
    s%dx_valid = .false.
    s%jm_valid = .false.
  end subroutine harmonic_resize

  !> Solves the layer (gamma, omega) for Gamma_0, Gamma_2..Gamma_H, starting from what s holds
  !> (its G(2:H), G0: a neighbouring layer's solution, or zeros for a cold start), and computes
  !> P and psi. s%H must be set (harmonic_resize).
  subroutine harmonic_solve(ws, blade, gamma, omega, s, error)
    type(harmonic_workspace_type), intent(inout) :: ws
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: gamma, omega
    type(harmonic_state_type), intent(inout) :: s
    type(error_type), allocatable, intent(out) :: error
    integer :: H, n, h1, it, ls, info, attempt
    character(len=64) :: what
    real(wp), allocatable :: x(:), R(:), xt(:), Rt(:), J(:,:), dx(:), dRw(:)
    integer, allocatable :: ipiv(:)
    real(wp) :: rn, rnt, t, step, step_prev
    logical :: fresh, accepted, predict
    real(wp) :: dg_old, dw_old
    !> J holds the LU factors of the layer Jacobian for the current s%JM (the receptances are
    !> fixed within a solve): one factorization per damper Jacobian
    logical :: lu_ok
    complex(wp) :: dM1, dP
    character(len=64) :: buf

    H = s%H
    n = 2*H - 1
    ws%solves = ws%solves + 1
    if (.not.(gamma > 0 .and. gamma < huge(1.0_wp)) .or. .not.(omega > 0)) then
      call fatal_error(error, "harmonic layer: gamma and omega must be positive", UDMAP_EINPUT)
      return
    end if
    ! a neighbouring layer close by: first-order prediction of its harmonics from this one's
    ! derivatives; farther: the other harmonics scale roughly with the first
    predict = s%dx_valid .and. s%gamma > 0 .and. abs(gamma/s%gamma - 1) <= 0.1_wp .and. &
      & abs(omega/s%omega - 1) <= 0.02_wp
    dg_old = gamma - s%gamma
    dw_old = omega - s%omega
    if (.not.predict .and. gamma /= s%gamma .and. s%gamma > 0 .and. allocated(s%G)) then
      s%G(2:H) = s%G(2:H)*(gamma/s%gamma)
    end if
    s%dx_valid = .false.
    s%gamma = gamma
    s%omega = omega
    s%G(1) = cmplx(gamma, 0.0_wp, wp)
    do h1 = 1, H
      call blade%receptances(h1*omega, s%r(h1), error, derivatives=.true.)
      if (allocated(error)) then
        write(buf, '(a, i0, a, es10.3)') "harmonic ", h1, " of the layer gamma = ", gamma
        error%message = trim(buf)//": "//error%message
        return
      end if
    end do
    allocate(x(n), R(n), xt(n), Rt(n), J(n, n), dx(n), ipiv(n), dRw(n))
    lu_ok = .false.
    call pack_x(s, x)
    if (predict) x = x + s%dx_dg*dg_old + s%dx_dw*dw_old
    ! a warm start that leads Newton astray (e.g. across a change of the contact topology) is
    ! dropped for a cold one (all other harmonics 0), which is then the answer
    do attempt = 1, 2
      if (attempt == 2) then
        if (all(x == 0)) exit
        x = 0
        s%jm_valid = .false.
      end if
      call newton(x, what)
      if (allocated(error)) return
      if (len_trim(what) == 0) exit
    end do
    if (len_trim(what) > 0) then
      call fail(trim(what))
      return
    end if
    ! s holds the moments at the solution (newton leaves them there)
    call unpack_x(x, s)
    s%lift_off = ws%aft%lift_off
    ! psi needs dM/dGamma at the solution: renew a Jacobian taken far from it
    if (maxval(abs(x - s%x_jm)) > 1.0e-4_wp*gamma) then
      call jacobian(x, error)
      if (allocated(error)) return
    end if
    s%P = (gamma + s%r(1)%gg*s%M(1))/s%r(1)%gE
    ! dGamma/domega = -J^-1 dR/domega, dR_h/domega = h H_gg'(h omega) M_h
    if (.not.factorize()) then
      call fail("the layer's Jacobian is singular")
      return
    end if
    dRw = 0
    do h1 = 2, H
      dRw(2*h1-2) = real(h1*s%r(h1)%dgg*s%M(h1), wp)
      dRw(2*h1-1) = aimag(h1*s%r(h1)%dgg*s%M(h1))
    end do
    dx = -dRw
    call lu_solve(n, J, ipiv, dx)
    dM1 = cmplx(dot_product(s%JM(2, :), dx), dot_product(s%JM(3, :), dx), wp)
    dP = (s%r(1)%dgg*s%M(1) + s%r(1)%gg*dM1)/s%r(1)%gE - s%P*s%r(1)%dgE/s%r(1)%gE
    s%psi = 2*real(conjg(s%P)*dP, wp)
    s%dx_dw = dx
    call root_jacobian(dP, dM1)
    if (allocated(error)) return
  contains
    !> s%Jroot from dP/domega (Pw) and dM_1/domega (M1w) of the solved layer.
    subroutine root_jacobian(Pw, M1w)
      complex(wp), intent(in) :: Pw, M1w
      type(receptances_type) :: rp
      complex(wp) :: M1g, Pg, Pww, Pwg, z, gg2, gE2
      real(wp) :: dxg(n), P2, a, dw
      integer :: k
      ! dGamma/dgamma = -J^-1 dR/dgamma (the factors of J are in J)
      dxg(1) = real(ws%gg0, wp)*s%JM1(1)
      do k = 2, H
        z = s%r(k)%gg*cmplx(s%JM1(2*k), s%JM1(2*k+1), wp)
        dxg(2*k-2) = real(z, wp)
        dxg(2*k-1) = aimag(z)
      end do
      dxg = -dxg
      call lu_solve(n, J, ipiv, dxg)
      M1g = cmplx(s%JM1(2) + dot_product(s%JM(2, :), dxg), &
        & s%JM1(3) + dot_product(s%JM(3, :), dxg), wp)
      s%dx_dg = dxg
      s%dx_valid = .true.
      ! second derivatives of the receptances at omega by a difference of the first ones
      dw = 1.0e-6_wp*omega
      call blade%receptances(omega + dw, rp, error, derivatives=.true.)
      if (allocated(error)) return
      gg2 = (rp%dgg - s%r(1)%dgg)/dw
      gE2 = (rp%dgE - s%r(1)%dgE)/dw
      associate(P => s%P, gg => s%r(1)%gg, dgg => s%r(1)%dgg, gE => s%r(1)%gE, &
          & dgE => s%r(1)%dgE, M1 => s%M(1))
        Pg = (1 + gg*M1g)/gE
        Pww = (gg2*M1 + 2*dgg*M1w)/gE - 2*Pw*dgE/gE - P*gE2/gE
        Pwg = dgg*M1g/gE - Pg*dgE/gE
        P2 = abs(P)**2
        a = real(conjg(P)*Pw, wp)
        s%Jroot(1, 1) = gamma*real(conjg(P)*Pg, wp)/P2
        s%Jroot(1, 2) = omega*a/P2
        s%Jroot(2, 1) = gamma*omega*(real(conjg(Pg)*Pw + conjg(P)*Pwg, wp)/P2 &
          & - 2*a*real(conjg(P)*Pg, wp)/P2**2)
        s%Jroot(2, 2) = s%Jroot(1, 2) + omega**2*((abs(Pw)**2 + real(conjg(P)*Pww, wp))/P2 &
          & - 2*a**2/P2**2)
      end associate
    end subroutine root_jacobian

    !> Newton from x; what: empty on convergence, else why it stopped (error: a failed trace).
    subroutine newton(x, what)
      real(wp), intent(inout) :: x(:)
      character(len=*), intent(out) :: what
      what = ""
      call residual(x, R, error)
      if (allocated(error)) return
      rn = norm2(R)
      step_prev = huge(1.0_wp)
      do it = 1, newton_max
        fresh = .false.
        if (.not.s%jm_valid) then
          call jacobian(x, error)
          if (allocated(error)) return
          fresh = .true.
        end if
        if (.not.factorize()) then
          what = "the layer's Jacobian is singular"
          return
        end if
        dx = -R
        call lu_solve(n, J, ipiv, dx)
        ! backtracking on |R|; a stale Jacobian that fails to descend is renewed first
        t = 1
        accepted = .false.
        do ls = 1, 30
          xt = x + t*dx
          call residual(xt, Rt, error)
          if (allocated(error)) return
          rnt = norm2(Rt)
          if (rnt <= (1 - 1.0e-4_wp*t)*rn .or. maxval(abs(t*dx)) <= newton_tol*xscale(x)) then
            accepted = .true.
            exit
          end if
          if (.not.fresh) exit
          t = 0.5_wp*t
        end do
        if (.not.accepted) then
          if (.not.fresh) then
            s%jm_valid = .false.
            call residual(x, R, error)
            if (allocated(error)) return
            cycle
          end if
          ! no descent even with a fresh Jacobian: accept at the rounding level of the
          ! piecewise-linear contact (far below what the outputs need)
          if (rn <= 1.0e-11_wp*xscale(x)) then
            ! the moments of x again (the line search left those of its last trial)
            call residual(x, R, error)
            return
          end if
          what = "Newton found no descent direction"
          return
        end if
        step = maxval(abs(t*dx))
        x = xt
        R = Rt
        rn = rnt
        if (step <= newton_tol*xscale(x)) return
        ! slow contraction with a reused Jacobian (contacts changed state): renew it
        if (.not.fresh .and. (t < 1 .or. step > 0.1_wp*step_prev)) s%jm_valid = .false.
        step_prev = step
      end do
      what = "Newton did not converge"
    end subroutine newton

    !> Scale of the unknowns: the layer amplitude, or a larger static offset.
    pure real(wp) function xscale(xv)
      real(wp), intent(in) :: xv(:)
      xscale = max(gamma, maxval(abs(xv)))
    end function xscale

    subroutine fail(what)
      character(len=*), intent(in) :: what
      character(len=160) :: b
      write(b, '(a, i0, a, es12.5, a, g0.8, a)') " (H = ", H, ", layer gamma = ", gamma, &
        & " rad, f = ", omega/(2*pi), " Hz)"
      if (ws%aft%lift_off) then
        ! the loop changes shape abruptly with the waveform: M_h(Gamma) jumps (PHYSICS.md 2.5)
        call fatal_error(error, "harmonic layer: "//what//trim(b)//"; a damper contact lifts "// &
          & "off on this layer and the damper moment jumps with the waveform, so the layer "// &
          & "equations may have no solution: try fewer harmonics", UDMAP_ENUMERIC)
      else
        call fatal_error(error, "harmonic layer: "//what//trim(b), UDMAP_ENUMERIC)
      end if
    end subroutine fail

    !> The damper moments for the unknowns x (stored in s%M0, s%M) and the residual.
    subroutine residual(xv, Rv, err)
      real(wp), intent(in) :: xv(:)
      real(wp), intent(out) :: Rv(:)
      type(error_type), allocatable, intent(out) :: err
      integer :: k
      complex(wp) :: z
      call moments(xv, err)
      if (allocated(err)) return
      Rv(1) = xv(1) + real(ws%gg0, wp)*(s%M0 - ws%M_ref)
      do k = 2, H
        z = cmplx(xv(2*k-2), xv(2*k-1), wp) + s%r(k)%gg*s%M(k)
        Rv(2*k-2) = real(z, wp)
        Rv(2*k-1) = aimag(z)
      end do
    end subroutine residual

    !> The moments for xv (Gamma_1 = gamma, or gamma1 when given).
    subroutine moments(xv, err, gamma1)
      real(wp), intent(in) :: xv(:)
      type(error_type), allocatable, intent(out) :: err
      real(wp), intent(in), optional :: gamma1
      if (present(gamma1)) then
        call set_G(gamma1, xv, H, s%G)
      else
        call set_G(gamma, xv, H, s%G)
      end if
      call aft_moment(ws%element, ws%aft, xv(1), s%G, 0, aft_min_periods, aft_max_periods, &
        & aft_loop_rtol, s%M0, s%M, err)
      ws%traces = ws%traces + 1
      if (allocated(err)) err%message = "harmonic layer: "//err%message
    end subroutine moments

    !> dM/dGamma about xv, whose moments s%M0, s%M hold (and hold again on return): in closed
    !> form from one trace (aft_moment_jacobian), or by forward differences (2H - 1 traces)
    !> where the sequence of contact events changes within the perturbation.
    subroutine jacobian(xv, err)
      real(wp), intent(in) :: xv(:)
      type(error_type), allocatable, intent(out) :: err
      real(wp) :: m_base(2*H+1), m_pert(2*H+1), xp(size(xv)), d, M0_base, JA(2*H+1, 2*H+1)
      real(wp) :: M0_a
      complex(wp) :: Mc_base(H), Mc_a(H)
      logical :: lift_base, ok
      integer :: k
      lift_base = ws%aft%lift_off
      call set_G(gamma, xv, H, s%G)
      call aft_moment_jacobian(ws%element, ws%aft, xv(1), s%G, aft_min_periods, &
        & aft_max_periods, aft_loop_rtol, M0_a, Mc_a, JA, ok, err)
      ws%traces = ws%traces + 1
      if (allocated(err)) then
        err%message = "harmonic layer: "//err%message
        return
      end if
      ws%aft%lift_off = lift_base
      if (ok) then
        ! columns Gamma_0, Re/Im Gamma_2.. (Gamma_1 is fixed)
        s%JM(:, 1) = JA(:, 1)
        s%JM(:, 2:n) = JA(:, 4:2*H+1)
        s%JM1 = JA(:, 2)
        s%x_jm = xv
        s%jm_valid = .true.
        lu_ok = .false.
        return
      end if
      call pack_m(m_base)
      M0_base = s%M0
      Mc_base = s%M
      do k = 1, n
        xp = xv
        d = fd_step*max(gamma, abs(xv(k)))
        xp(k) = xv(k) + d
        call moments(xp, err)
        if (allocated(err)) return
        call pack_m(m_pert)
        s%JM(:, k) = (m_pert - m_base)/d
      end do
      ! and against Gamma_1
      d = fd_step*gamma
      call moments(xv, err, gamma + d)
      if (allocated(err)) return
      call pack_m(m_pert)
      s%JM1 = (m_pert - m_base)/d
      s%M0 = M0_base
      s%M = Mc_base
      call set_G(gamma, xv, H, s%G)
      ws%aft%lift_off = lift_base
      s%x_jm = xv
      s%jm_valid = .true.
      lu_ok = .false.
    end subroutine jacobian

    !> The LU factors of J for the current s%JM in J (false: singular).
    logical function factorize()
      factorize = .true.
      if (lu_ok) return
      call build_J(J)
      call lu_factor(n, J, ipiv, info)
      factorize = info == 0
      lu_ok = factorize
    end function factorize

    subroutine pack_m(m)
      real(wp), intent(out) :: m(:)
      integer :: k
      m(1) = s%M0
      do k = 1, H
        m(2*k) = real(s%M(k), wp)
        m(2*k+1) = aimag(s%M(k))
      end do
    end subroutine pack_m

    !> J = I + diag(receptances) dM/dGamma (rows of M_1 skipped: Gamma_1 is fixed).
    subroutine build_J(Jm)
      real(wp), intent(out) :: Jm(:,:)
      integer :: k, c
      real(wp) :: a, b
      Jm = 0
      do c = 1, n
        Jm(c, c) = 1
      end do
      Jm(1, :) = Jm(1, :) + real(ws%gg0, wp)*s%JM(1, :)
      do k = 2, H
        a = real(s%r(k)%gg, wp)
        b = aimag(s%r(k)%gg)
        Jm(2*k-2, :) = Jm(2*k-2, :) + a*s%JM(2*k, :) - b*s%JM(2*k+1, :)
        Jm(2*k-1, :) = Jm(2*k-1, :) + b*s%JM(2*k, :) + a*s%JM(2*k+1, :)
      end do
    end subroutine build_J
  end subroutine harmonic_solve

  pure subroutine pack_x(s, x)
    type(harmonic_state_type), intent(in) :: s
    real(wp), intent(out) :: x(:)
    integer :: k
    x(1) = s%G0
    do k = 2, s%H
      x(2*k-2) = real(s%G(k), wp)
      x(2*k-1) = aimag(s%G(k))
    end do
  end subroutine pack_x

  pure subroutine unpack_x(x, s)
    real(wp), intent(in) :: x(:)
    type(harmonic_state_type), intent(inout) :: s
    s%G0 = x(1)
    call set_G(s%gamma, x, s%H, s%G)
  end subroutine unpack_x

  !> The harmonics G(1:H) of gamma(t): Gamma_1 = g1 (real) and Gamma_k from the unknowns x
  !> (Re, Im at 2k-2, 2k-1).
  pure subroutine set_G(g1, x, H, G)
    real(wp), intent(in) :: g1, x(:)
    integer, intent(in) :: H
    complex(wp), intent(inout) :: G(:)
    integer :: k
    G(1) = cmplx(g1, 0.0_wp, wp)
    do k = 2, H
      G(k) = cmplx(x(2*k-2), x(2*k-1), wp)
    end do
  end subroutine set_G

  !> Stress and displacement harmonics of a solved layer (force s%P), and the largest
  !> excursions of gamma(t) and sigma(t) from their means.
  subroutine harmonic_outputs(ws, s, has_stress, out)
    type(harmonic_workspace_type), intent(in) :: ws
    type(harmonic_state_type), intent(in) :: s
    logical, intent(in) :: has_stress
    type(harmonic_outputs_type), intent(out) :: out
    complex(wp) :: Sh(s%H)
    integer :: k
    out%S1 = s%r(1)%sE*s%P - s%r(1)%sg*s%M(1)
    out%U1 = s%r(1)%EE*s%P - s%r(1)%gE*s%M(1)
    Sh(1) = out%S1
    do k = 2, s%H
      Sh(k) = -s%r(k)%sg*s%M(k)
    end do
    allocate(out%gamma_h(0:s%H), out%sigma_h(0:s%H))
    out%gamma_h(0) = abs(s%G0)
    out%gamma_h(1:) = abs(s%G)
    out%sigma_h(0) = abs(real(ws%sg0, wp)*(s%M0 - ws%M_ref))
    out%sigma_h(1:) = abs(Sh)
    out%gamma_max = largest_excursion(s%G)
    out%sigma_max = 0
    if (has_stress) then
      out%sigma_max = largest_excursion(Sh)
    else
      out%sigma_h = 0
      out%S1 = 0
    end if
  end subroutine harmonic_outputs

  !> max_tau |Re sum_h Z_h e^{i h tau}|: the largest excursion of a periodic signal from its
  !> mean (at the extrema, located exactly).
  real(wp) function largest_excursion(Z) result(v)
    complex(wp), intent(in) :: Z(:)
    real(wp), allocatable :: tau(:)
    integer :: n, k
    call waveform_extrema(Z, tau, n)
    v = 0
    do k = 1, max(n, 1)
      v = max(v, abs(waveform_value(0.0_wp, Z, tau(k))))
    end do
  end function largest_excursion
end module udmap_mapping_harmonic_layer
