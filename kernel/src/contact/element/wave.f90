!> The asymmetric damper between two blades of a traveling wave (PHYSICS.md 2.6): its trace
!> along the periodic motion of both platforms and the Fourier projection of its action on
!> blade 0. Shared by the traveling-wave layers of the mapping and the standard method.
!>
!> Blade 0's platform moves as p(tau) = P_0 + Re(sum_h P_h e^{i h tau}), p = (u_P, v_P,
!> gamma_P); the damper's flat contacts follow p(tau), its curved contact p(tau + phi). The
!> action on blade 0 is the flat-side action plus the curved-side action delayed by phi,
!> A(tau) = A_flat(tau) + A_curved(tau - phi), so harmonic h of A is
!> A_flat,h + e^{-i h phi} A_curved,h. Loading history: virgin state, CF ramp with both platforms
!> at rest, a proportional ramp of both platforms to their values at tau = 0, then periods
!> until the state at the start of a period repeats.
!>
!> The path between `samples` equally spaced instants is a straight line in the platforms'
!> coordinates, traced exactly with its contact events (udmap_damper_tracer: trace_path); the
!> harmonics are the discrete Fourier transform of the action at the instants (the classical
!> AFT), corrected for the kinks: at an event the action's slope in time jumps, which the
!> transform of the samples sees as an error (h^2/2) jump(A') e^{-ik t_e} B2(delta) (h the
!> instants' spacing, delta the event's place between them, B2(x) = x^2 - x + 1/6: the
!> Euler-Maclaurin term of a kink). The correction adds it back, with the slope jump of the
!> smooth motion (the contact states' rates along the platforms' velocity at the event). Without
!> it every output kinks by O(h^2) whenever an event crosses an instant; with it they are
!> smooth to O(h^3), and closer to the smooth path's answer. Where no contact changes state
!> there is nothing to correct: the plain transform, to the last bit.
module udmap_contact_element_wave
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_damper_tracer_core, only: damper_geometry_type, damper_state_type, CONTACT_OPEN, &
    & mode_stiffness, equilibrium_cache_type, &
    & CONTACT_SLIP_POS, CONTACT_SLIP_NEG, compute_rates, rates_type, code_modes
  use udmap_damper_tracer, only: virgin_state, ramp_CF, trace_path, platform_actions, same_forces, &
    & path_events_type, along
  use udmap_damper_tracer_tangent, only: path_tangent_type, &
    & new_path_tangent, path_tangent_levers, path_tangent_segment, path_tangent_actions, &
    & contact_levers, mode_rates, invert3
  implicit none
  private
  public :: wave_aft, wave_settings_type, wave_result_type, wave_static_action, wave_samples

  !> How the trace is run.
  type :: wave_settings_type
    !> Instants per period.
    integer :: samples = 128
    !> Periods after the ramp: at least, at most.
    integer :: min_periods = 1, max_periods = 16
  end type wave_settings_type

  !> What a trace found besides the harmonics.
  type :: wave_result_type
    !> Energy dissipated per cycle in the damper [J], from the traced samples.
    real(wp) :: energy = 0
    !> A contact slipped / was open at some instant of the steady period.
    logical :: slipped = .false., lifted = .false.
    !> Each contact slipped at some instant of the steady period.
    logical :: contact_slipped(3) = .false.
    !> Periods traced after the ramp; the last one closed (the state repeated).
    integer :: periods = 0
    logical :: closed = .false.
  end type wave_result_type

contains

  !> Instants per period for harmonics 1..H: 64, or 8 H beyond H = 8. With the kink
  !> correction, 64 instants put k within 4e-5 of the smooth path's (blade A's damper, in
  !> phase, gamma 6e-4 to 4e-3 rad; 128: within 7e-6), at half the cost of 128.
  pure integer function wave_samples(H)
    integer, intent(in) :: H
    wave_samples = max(64, 8*H)
  end function wave_samples

  !> The static action on blade 0 of the damper loaded by CF with both platforms at rest.
  subroutine wave_static_action(geo, CF, A_ref, error)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF
    real(wp), intent(out) :: A_ref(3)
    type(error_type), allocatable, intent(out) :: error
    type(damper_state_type) :: st
    real(wp) :: A(3,2)
    A_ref = 0
    call virgin_state(geo, st)
    call ramp_CF(geo, st, CF, error)
    if (allocated(error)) return
    A = platform_actions(geo, st)
    A_ref = A(:,1) + A(:,2)
  end subroutine wave_static_action

  !> Harmonics A0 (static) and A(:,h), h = 1..size(P,2), of the damper's restoring action on
  !> blade 0 for blade 0's platform harmonics P0 (static) and P(:,h), at the interblade phase
  !> phi [rad]. With dP0 and dP (P's derivatives with respect to np parameters, P(3,1) real and
  !> positive), also their derivatives dA0 and dA: the traced function's, exactly
  !> (udmap_damper_tracer_tangent, and the kink corrections' derivatives).
  subroutine wave_aft(geo, CF, phi, P0, P, settings, A0, A, error, res, dP0, dP, dA0, dA)
    type(damper_geometry_type), intent(in) :: geo
    real(wp), intent(in) :: CF, phi, P0(3)
    complex(wp), intent(in) :: P(:, :)
    type(wave_settings_type), intent(in) :: settings
    real(wp), intent(out) :: A0(3)
    complex(wp), intent(out) :: A(:, :)
    type(error_type), allocatable, intent(out) :: error
    type(wave_result_type), intent(out), optional :: res
    real(wp), intent(in), optional :: dP0(:, :)
    complex(wp), intent(in), optional :: dP(:, :, :)
    real(wp), intent(out), optional :: dA0(:, :)
    complex(wp), intent(out), optional :: dA(:, :, :)
    type(damper_state_type) :: st, start
    type(path_events_type) :: ev
    type(path_tangent_type) :: tan
    type(equilibrium_cache_type) :: eqc
    real(wp), allocatable :: lvn(:, :, :), lvt(:, :, :)
    real(wp), allocatable :: X(:, :), AL(:, :), AR(:, :), Xp(:, :, :), ALp(:, :), ARp(:, :)
    complex(wp), allocatable :: e(:, :), CL(:, :), CR(:, :), root(:), CLp(:, :, :), CRp(:, :, :)
    real(wp) :: Ak(3,2), energy, F_scale, theta
    real(wp), allocatable :: Akp(:, :, :), Er(:, :), Ei(:, :), SL(:, :, :), SR(:, :, :)
    integer, allocatable :: mlo(:), mhi(:)
    complex(wp), allocatable :: Pr(:, :), Pphi(:, :), Prp(:, :, :), Pphip(:, :, :)
    integer :: ns, j, k, per, H, np, kp
    logical :: closed, slipped, lifted, cs(3), tangent

    ns = settings%samples
    H = size(P, 2)
    A0 = 0
    A = (0.0_wp, 0.0_wp)
    if (ns < 2*H + 2) then
      call fatal_error(error, "wave_aft: too few samples for the harmonics", UDMAP_EINPUT)
      return
    end if
    allocate(X(6, 0:ns-1), AL(3, ns), AR(3, ns), e(H, ns), Pr(3, H), Pphi(3, H), CL(3, 0:H), &
      & CR(3, 0:H), root(0:ns-1))
    ! time origin where gamma_P's first harmonic is real: the sampled trace then depends on
    ! the motion alone, not on its phase against the force (every caller solves the same
    ! equations whatever it holds fixed)
    theta = 0
    if (P(3, 1) /= 0) theta = atan2(aimag(P(3, 1)), real(P(3, 1), wp))
    do k = 1, H
      Pr(:, k) = P(:, k)*exp(cmplx(0.0_wp, -k*theta, wp))
      Pphi(:, k) = Pr(:, k)*exp(cmplx(0.0_wp, k*phi, wp))
    end do
    ! e^{-i m tau_j} = root(m j mod ns): ns exponentials instead of H ns (and H ns more for
    ! the transform), which dominated the trace at high H
    do j = 0, ns - 1
      root(j) = exp(cmplx(0.0_wp, -2*pi*j/ns, wp))
    end do
    do j = 0, ns - 1
      X(1:3, j) = sampled(Pr, P0, j, 1, H)
      X(4:6, j) = sampled(Pphi, P0, j, 1, H)
    end do
    tangent = present(dP0) .and. present(dP) .and. present(dA0) .and. present(dA)
    np = 0
    if (tangent) then
      if (theta /= 0) then
        call fatal_error(error, "wave_aft: derivatives need a real positive first harmonic "// &
          & "of gamma_P", UDMAP_EINPUT)
        return
      end if
      np = size(dP, 3)
      allocate(Xp(6, np, 0:ns-1), ALp(3*np, ns), ARp(3*np, ns), Akp(3, 2, np), mlo(np), mhi(np), &
        & CLp(3, 0:H, np), CRp(3, 0:H, np), Prp(3, H, np), Pphip(3, H, np))
      do kp = 1, np
        ! the harmonics a direction moves (mostly one: the unknowns' unit vectors)
        mlo(kp) = H + 1
        mhi(kp) = 0
        do k = 1, H
          if (any(dP(:, k, kp) /= 0)) then
            mlo(kp) = min(mlo(kp), k)
            mhi(kp) = k
          end if
        end do
        do k = 1, H
          Prp(:, k, kp) = dP(:, k, kp)
          Pphip(:, k, kp) = dP(:, k, kp)*exp(cmplx(0.0_wp, k*phi, wp))
        end do
        do j = 0, ns - 1
          Xp(1:3, kp, j) = sampled(Prp(:, :, kp), dP0(:, kp), j, mlo(kp), mhi(kp))
          Xp(4:6, kp, j) = sampled(Pphip(:, :, kp), dP0(:, kp), j, mlo(kp), mhi(kp))
        end do
      end do
      call new_path_tangent(tan, np)
      ! the contacts' travel for the derivatives at every instant (ns: at rest)
      allocate(lvn(3, np, 0:ns), lvt(3, np, 0:ns))
      do j = 0, ns - 1
        call path_tangent_levers(geo, Xp(:, :, j), lvn(:, :, j), lvt(:, :, j))
      end do
      lvn(:, :, ns) = 0
      lvt(:, :, ns) = 0
    end if
    call virgin_state(geo, st)
    call ramp_CF(geo, st, CF, error)
    if (allocated(error)) return
    F_scale = max(CF, 1e-300_wp)
    if (tangent) then
      ! the ramp from rest to the first instant: its start does not move with the parameters
      call trace_path(geo, st, X(:, 0), error, ev, eqc)
      if (allocated(error)) return
      call path_tangent_segment(geo, tan, [(0.0_wp, j = 1, 6)], X(:, 0), lvn(:, :, ns), &
        & lvt(:, :, ns), lvn(:, :, 0), lvt(:, :, 0), ev%entry, ev%log)
    else
      call trace_path(geo, st, X(:, 0), error, cache=eqc)
      if (allocated(error)) return
    end if
    closed = .false.
    do per = 1, settings%max_periods
      start = st
      slipped = .false.
      lifted = .false.
      cs = .false.
      energy = 0
      CL = 0
      CR = 0
      if (tangent) then
        CLp = 0
        CRp = 0
      end if
      do j = 1, ns
        call trace_path(geo, st, X(:, mod(j, ns)), error, ev, eqc)
        if (allocated(error)) return
        if (tangent) then
          call path_tangent_segment(geo, tan, X(:, j-1), X(:, mod(j, ns)), lvn(:, :, j-1), &
            & lvt(:, :, j-1), lvn(:, :, mod(j, ns)), lvt(:, :, mod(j, ns)), ev%entry, ev%log)
          call path_tangent_actions(geo, tan, st%mode, lvn(:, :, mod(j, ns)), &
            & lvt(:, :, mod(j, ns)), Akp)
          do kp = 1, np
            ALp(3*kp-2:3*kp, j) = Akp(:, 1, kp)
            ARp(3*kp-2:3*kp, j) = Akp(:, 2, kp)
          end do
        end if
        do k = 1, ev%n
          call correct_kink((j - 1 + ev%s(k))*2*pi/ns, ev%s(k), code_modes(ev%before(k)), &
            & code_modes(ev%after(k)), ev%vertex(k))
        end do
        Ak = platform_actions(geo, st)
        ! trapezoid on the samples: the work of the actions on their platforms
        if (j > 1) energy = energy + 0.5_wp*(dot_product(AL(:, j-1) + Ak(:,1), &
          & X(1:3, mod(j, ns)) - X(1:3, j-1)) + dot_product(AR(:, j-1) + Ak(:,2), &
          & X(4:6, mod(j, ns)) - X(4:6, j-1)))
        AL(:, j) = Ak(:,1)
        AR(:, j) = Ak(:,2)
        cs = cs .or. st%mode == CONTACT_SLIP_POS .or. st%mode == CONTACT_SLIP_NEG
        slipped = any(cs)
        lifted = lifted .or. any(st%mode == CONTACT_OPEN)
      end do
      ! the first segment of the period closes the trapezoid sum
      energy = energy + 0.5_wp*(dot_product(AL(:, ns) + AL(:, 1), X(1:3, 1) - X(1:3, 0)) + &
        & dot_product(AR(:, ns) + AR(:, 1), X(4:6, 1) - X(4:6, 0)))
      closed = same_forces(geo, start, st, F_scale)
      if (per >= settings%min_periods .and. closed) exit
    end do
    ! harmonics of the action on blade 0 (instants tau_j = 2 pi j/ns, j = 1..ns)
    do j = 1, ns
      do k = 1, H
        e(k, j) = root(mod(k*j, ns))
      end do
    end do
    A0 = (sum(AL, dim=2) + sum(AR, dim=2))/ns + real(CL(:, 0) + CR(:, 0), wp)/(2*pi)
    do k = 1, H
      A(:, k) = (matmul(AL, e(k, :)) + &
        & exp(cmplx(0.0_wp, -k*phi, wp))*matmul(AR, e(k, :)))*(2.0_wp/ns) &
        & + (CL(:, k) + exp(cmplx(0.0_wp, -k*phi, wp))*CR(:, k))/pi
      if (theta /= 0) A(:, k) = A(:, k)*exp(cmplx(0.0_wp, k*theta, wp))
    end do
    if (tangent) then
      ! the derivatives' transform as real matrix products over all directions at once:
      ! (3 np, ns) samples times the instants' cosines and sines (ns, H)
      allocate(Er(ns, H), Ei(ns, H), SL(3*np, H, 2), SR(3*np, H, 2))
      do k = 1, H
        do j = 1, ns
          Er(j, k) = real(root(mod(k*j, ns)), wp)
          Ei(j, k) = aimag(root(mod(k*j, ns)))
        end do
      end do
      SL(:, :, 1) = matmul(ALp, Er)
      SL(:, :, 2) = matmul(ALp, Ei)
      SR(:, :, 1) = matmul(ARp, Er)
      SR(:, :, 2) = matmul(ARp, Ei)
      do kp = 1, np
        dA0(:, kp) = (sum(ALp(3*kp-2:3*kp, :), dim=2) + sum(ARp(3*kp-2:3*kp, :), dim=2))/ns + &
          & real(CLp(:, 0, kp) + CRp(:, 0, kp), wp)/(2*pi)
        do k = 1, H
          dA(:, k, kp) = (cmplx(SL(3*kp-2:3*kp, k, 1), SL(3*kp-2:3*kp, k, 2), wp) + &
            & exp(cmplx(0.0_wp, -k*phi, wp))*cmplx(SR(3*kp-2:3*kp, k, 1), &
            & SR(3*kp-2:3*kp, k, 2), wp))*(2.0_wp/ns) &
            & + (CLp(:, k, kp) + exp(cmplx(0.0_wp, -k*phi, wp))*CRp(:, k, kp))/pi
        end do
      end do
    end if
    if (present(res)) then
      res%energy = energy
      res%slipped = slipped
      res%contact_slipped = cs
      res%lifted = lifted
      res%periods = min(per, settings%max_periods)
      res%closed = closed
    end if

  contains

    !> The kink of an event at time t_e (at delta of its interval), contact states from
    !> m_before to m_after: (h^2/2) jump(A') e^{-ik t_e} B2(delta) added to the Fourier
    !> integrals CL, CR (k = 0..H) and the same for the work, A' the actions' rates along
    !> the platforms' velocity at t_e.
    subroutine correct_kink(t_e, delta, m_before, m_after, vertex)
      real(wp), intent(in) :: t_e, delta
      integer, intent(in) :: m_before(3), m_after(3), vertex
      real(wp) :: V(6), dA(3, 2), c, V_p(6), dA_p(3, 2), d_p, c_p
      real(wp) :: K0(3, 3), K0i(3, 3), K1(3, 3), K1i(3, 3), cn(3), ct(3), dN0(3), dT0(3), &
        & dN1(3), dT1(3), a_L(3), a_R(3)
      complex(wp) :: z(0:H)
      logical :: ok
      integer :: kk, q, i
      ! z(m) = e^{-i m t_e} by powers (their rounding, m eps, is far below the kink's size)
      z(0) = 1
      if (H >= 1) z(1) = exp(cmplx(0.0_wp, -t_e, wp))
      do kk = 2, H
        z(kk) = z(kk - 1)*z(1)
      end do
      V(1:3) = motion_rate(Pr, z, 1, H)
      V(4:6) = motion_rate(Pphi, z, 1, H)
      call slope_jump(V, m_before, m_after, dA, ok)
      if (.not. ok) return
      c = 0.5_wp*(2*pi/ns)**2*(delta*delta - delta + 1/6.0_wp)
      do kk = 0, H
        CL(:, kk) = CL(:, kk) + c*dA(:, 1)*z(kk)
        CR(:, kk) = CR(:, kk) + c*dA(:, 2)*z(kk)
      end do
      energy = energy + c*(dot_product(dA(:, 1), V(1:3)) + dot_product(dA(:, 2), V(4:6)))
      if (.not. tangent) return
      ! the correction's derivatives: the event's place delta moves (t_e with it), and so do
      ! the velocity there and the slope jump, linear in the velocity (both states'
      ! equilibrium matrices inverted once for every derivative)
      a_L = motion_accel(Pr, z)
      a_R = motion_accel(Pphi, z)
      call mode_stiffness(geo, m_before, K0)
      call invert3(K0, K0i, ok)
      if (.not. ok) return
      call mode_stiffness(geo, m_after, K1)
      call invert3(K1, K1i, ok)
      if (.not. ok) return
      do q = 1, np
        d_p = 0
        if (vertex > 0) d_p = tan%s_p(q, vertex)
        c_p = 0.5_wp*(2*pi/ns)**2*(2*delta - 1)*d_p
        V_p(1:3) = motion_rate(Prp(:, :, q), z, mlo(q), mhi(q)) + a_L*d_p*2*pi/ns
        V_p(4:6) = motion_rate(Pphip(:, :, q), z, mlo(q), mhi(q)) + a_R*d_p*2*pi/ns
        call contact_levers(geo, V_p, cn, ct)
        call mode_rates(geo, m_before, K0i, cn, ct, dN0, dT0)
        call mode_rates(geo, m_after, K1i, cn, ct, dN1, dT1)
        dA_p = 0
        do i = 1, 3
          dA_p(:, geo%side(i)) = dA_p(:, geo%side(i)) + (dN1(i) - dN0(i))*geo%pn(:, i) + &
            & (dT1(i) - dT0(i))*geo%pt(:, i)
        end do
        do kk = 0, H
          CLp(:, kk, q) = CLp(:, kk, q) + (c_p*dA(:, 1) + c*dA_p(:, 1))*z(kk) + &
            & c*dA(:, 1)*z(kk)*cmplx(0.0_wp, -kk*d_p*2*pi/ns, wp)
          CRp(:, kk, q) = CRp(:, kk, q) + (c_p*dA(:, 2) + c*dA_p(:, 2))*z(kk) + &
            & c*dA(:, 2)*z(kk)*cmplx(0.0_wp, -kk*d_p*2*pi/ns, wp)
        end do
      end do

    end subroutine correct_kink

    !> The jump dJ of the actions' rates at an event from the contact states m_before to
    !> m_after, for the platforms' velocity W (ok: both states' equilibrium is regular).
    subroutine slope_jump(W, m_before, m_after, dJ, ok)
      real(wp), intent(in) :: W(6)
      integer, intent(in) :: m_before(3), m_after(3)
      real(wp), intent(out) :: dJ(3, 2)
      logical, intent(out) :: ok
      type(damper_geometry_type) :: arc
      type(rates_type) :: r0, r1
      logical :: ok0, ok1
      integer :: i
      arc = along(geo, W)
      call compute_rates(arc, m_before, 1.0_wp, 0.0_wp, r0, ok0)
      call compute_rates(arc, m_after, 1.0_wp, 0.0_wp, r1, ok1)
      ok = ok0 .and. ok1
      dJ = 0
      if (.not. ok) return
      do i = 1, 3
        dJ(:, geo%side(i)) = dJ(:, geo%side(i)) + (r1%dN(i) - r0%dN(i))*geo%pn(:, i) + &
          & (r1%dT(i) - r0%dT(i))*geo%pt(:, i)
      end do
    end subroutine slope_jump

    !> The platform's velocity for the harmonics Q at the time t with z(m) = e^{-i m t}, from
    !> harmonics m1..m2 (1..H; a derivative's: those it moves).
    pure function motion_rate(Q, z, m1, m2) result(v_t)
      complex(wp), intent(in) :: Q(:, :), z(0:)
      integer, intent(in) :: m1, m2
      real(wp) :: v_t(3)
      integer :: m
      v_t = 0
      do m = m1, m2
        v_t = v_t + real(cmplx(0.0_wp, real(m, wp), wp)*Q(:, m)*conjg(z(m)), wp)
      end do
    end function motion_rate

    !> The platform's acceleration for the harmonics Q at the time t with z(m) = e^{-i m t}.
    pure function motion_accel(Q, z) result(a_t)
      complex(wp), intent(in) :: Q(:, :), z(0:)
      real(wp) :: a_t(3)
      integer :: m
      a_t = 0
      do m = 1, H
        a_t = a_t - real(m, wp)**2*real(Q(:, m)*conjg(z(m)), wp)
      end do
    end function motion_accel

    !> The platform's coordinates for the static part Q0 and the harmonics Q at the instant
    !> tau_j = 2 pi j/ns, from harmonics m1..m2 (1..H; a derivative's: those it moves).
    pure function sampled(Q, Q0, jj, m1, m2) result(x_t)
      complex(wp), intent(in) :: Q(:, :)
      real(wp), intent(in) :: Q0(3)
      integer, intent(in) :: jj, m1, m2
      real(wp) :: x_t(3)
      integer :: m
      x_t = Q0
      do m = m1, m2
        x_t = x_t + real(Q(:, m)*conjg(root(mod(m*jj, ns))), wp)
      end do
    end function sampled
  end subroutine wave_aft
end module udmap_contact_element_wave
