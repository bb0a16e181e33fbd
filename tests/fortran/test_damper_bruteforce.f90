!> Cross-check of the event-driven tracer on blade_a against an independent brute-force
!> tracing: small load steps, each solved by Newton with a return mapping per contact, written
!> from PHYSICS.md 2.1 directly (own kinematics, own linear algebra). Step refinement shows
!> convergence to the exact values.
module test_damper_bruteforce
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_damper_bruteforce

  !> One contact as PHYSICS.md 2.1 states it.
  type :: contact
    real(wp) :: r(2), n(2), t(2), P(2), kn, kt
  end type contact

contains

  !> Brute force: Newton load steps against the event-driven tracer.
  subroutine collect_damper_bruteforce(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("damper_bruteforce", run_damper_bruteforce)]
  end subroutine collect_damper_bruteforce

  !> The event-driven tracer against small Newton load steps with return mapping.
  subroutine run_damper_bruteforce(suite)
    type(test_suite), intent(inout) :: suite

    type(damper_type) :: d
    type(asymmetric_params_type) :: params
    type(error_type), allocatable :: error
    type(contact) :: c(3)
    real(wp) :: mu, CF, gb, Mmax, Mmin, gb_bf, k_bf, h, err_coarse, err_fine
    real(wp), allocatable :: gam(:), Mr(:)
    complex(wp) :: kk(2), kx
    integer :: i, nsteps(2), newton_failures = 0

    params = blade_a_damper_params()
    call new_asymmetric_damper(d, params, error)
    call check_no_error(suite, "blade_a damper", error)
    if (allocated(error)) return
    gb = d%gamma_b
    call setup(params)

    ! Plateau moments and gamma_b from a loop at 3 gamma_b; the travel to the plateau is
    ! resolved to one step h.
    nsteps = [4000, 40000]
    do i = 1, 2
      call brute_loop(3*gb, nsteps(i), gam, Mr)
      h = 6*gb/nsteps(i)
      Mmax = maxval(Mr)
      Mmin = minval(Mr)
      gb_bf = max(travel_to(Mmin, -1), travel_to(Mmax, 1))/2
      write(*, '(a, i0, a, 3es22.14)') "brute force, ", nsteps(i), " steps per half cycle: "// &
        & "M_max, M_min, gamma_b = ", Mmax, Mmin, gb_bf
      call check_close(suite, "brute force M_max", Mmax, d%M_max, 1e-9_wp)
      call check_close(suite, "brute force M_min", Mmin, d%M_min, 1e-9_wp)
      call check_close(suite, "brute force gamma_b within a step", gb_bf, gb, 0.0_wp, h)
      kk(i) = describing(3*gb, gam, Mr)
    end do
    kx = d%stiffness(3*gb)
    err_coarse = abs(kk(1) - kx)/abs(kx)
    err_fine = abs(kk(2) - kx)/abs(kx)
    write(*, '(a, 2es10.3)') "k(3 gamma_b) brute force rel. errors (coarse, fine): ", err_coarse, err_fine
    call check_true(suite, "k(3 gamma_b) brute force converges", err_fine < err_coarse/10 .and. err_fine < 1e-5_wp)

    ! Partial slip: k(0.9 gamma_b), history from the virgin state.
    do i = 1, 2
      call brute_loop(0.9_wp*gb, nsteps(i), gam, Mr)
      kk(i) = describing(0.9_wp*gb, gam, Mr)
    end do
    kx = d%stiffness(0.9_wp*gb)
    err_coarse = abs(kk(1) - kx)/abs(kx)
    err_fine = abs(kk(2) - kx)/abs(kx)
    write(*, '(a, 2es10.3)') "k(0.9 gamma_b) brute force rel. errors (coarse, fine): ", err_coarse, err_fine
    call check_true(suite, "k(0.9 gamma_b) brute force converges", err_fine < err_coarse/10 .and. err_fine < 1e-5_wp)

    ! Stuck stiffness: a small loop is elastic after the ramp.
    call brute_loop(1e-5_wp, 200, gam, Mr)
    k_bf = (Mr(1) - Mr(size(Mr)/2 + 1))/(2e-5_wp)
    write(*, '(a, es22.14)') "brute force k_stuck = ", k_bf
    call check_close(suite, "brute force k_stuck", k_bf, d%k_stuck, 1e-9_wp)

    call check_true(suite, "brute force Newton converged at every step", newton_failures == 0)

  contains

    subroutine setup(p)
      type(asymmetric_params_type), intent(in) :: p
      real(wp) :: bL, bR
      integer :: j
      bL = p%beta_L_deg*pi/180
      bR = p%beta_R_deg*pi/180
      do j = 1, 2
        c(j)%r = p%flat(:,j)
        c(j)%n = [sin(bL), -cos(bL)]
        c(j)%P = [-p%pitch/2, p%y_P]
        c(j)%kn = p%kn_flat
        c(j)%kt = p%kt_flat
      end do
      c(3)%r = p%curved
      c(3)%n = [-sin(bR), -cos(bR)]
      c(3)%P = [p%pitch/2, p%y_P]
      c(3)%kn = p%kn_curved
      c(3)%kt = p%kt_curved
      do j = 1, 3
        c(j)%t = [-c(j)%n(2), c(j)%n(1)]
      end do
      mu = p%mu
      CF = p%CF
    end subroutine setup

    pure real(wp) function cross(a, b)
      real(wp), intent(in) :: a(2), b(2)
      cross = a(1)*b(2) - a(2)*b(1)
    end function cross

    !> Contact forces on the damper for DOFs q at (gamma, CF) with sliders w_old (return mapping),
    !> their Jacobian, the new sliders and the restoring moment.
    subroutine forces(q, gamma, load, w_old, R, J, w_new, M)
      real(wp), intent(in) :: q(3), gamma, load, w_old(3)
      real(wp), intent(out) :: R(3), J(3,3), w_new(3), M
      real(wp) :: uD(2), uP(2), dd(2), g, Nf, Tf, Ttr, B(2,3), dNf(3), dTf(3), F(2), dF(2,3)
      integer :: i
      R = [0.0_wp, load, 0.0_wp]
      J = 0
      M = 0
      do i = 1, 3
        associate (rc => c(i)%r, nc => c(i)%n, tc => c(i)%t, Pc => c(i)%P)
          B(1,:) = [1.0_wp, 0.0_wp, -rc(2)]
          B(2,:) = [0.0_wp, 1.0_wp, rc(1)]
          uD = matmul(B, q)
          uP = gamma*[-(rc(2) - Pc(2)), rc(1) - Pc(1)]
          dd = uD - uP
          g = -dot_product(nc, dd)
          if (g <= 0) then
            Nf = 0
            Tf = 0
            dNf = 0
            dTf = 0
            w_new(i) = dot_product(tc, dd)
          else
            Nf = c(i)%kn*g
            dNf = -c(i)%kn*matmul(nc, B)
            Ttr = -c(i)%kt*(dot_product(tc, dd) - w_old(i))
            if (abs(Ttr) <= mu*Nf) then
              Tf = Ttr
              dTf = -c(i)%kt*matmul(tc, B)
            else
              Tf = sign(mu*Nf, Ttr)
              dTf = sign(mu, Ttr)*dNf
            end if
            w_new(i) = dot_product(tc, dd) + Tf/c(i)%kt
          end if
          F = Nf*nc + Tf*tc
          dF(1,:) = nc(1)*dNf + tc(1)*dTf
          dF(2,:) = nc(2)*dNf + tc(2)*dTf
          R(1:2) = R(1:2) + F
          R(3) = R(3) + cross(rc, F)
          J(1:2,:) = J(1:2,:) + dF
          J(3,:) = J(3,:) + rc(1)*dF(2,:) - rc(2)*dF(1,:)
          M = M + cross(rc - Pc, F)
        end associate
      end do
    end subroutine forces

    !> One load step: Newton on the equilibrium from the previous q, with a backtracking line
    !> search on |R| (the return mapping makes the residual only piecewise smooth).
    subroutine step(q, w, gamma, load, M)
      real(wp), intent(inout) :: q(3), w(3)
      real(wp), intent(in) :: gamma, load
      real(wp), intent(out) :: M
      real(wp) :: R(3), J(3,3), w_new(3), dq(3), R1(3), J1(3,3), lam
      integer :: it, ls
      do it = 1, 60
        call forces(q, gamma, load, w, R, J, w_new, M)
        if (maxval(abs(R)) <= 1e-11_wp*max(load, 1.0_wp) .and. it > 1) exit
        if (all(J == 0)) then
          ! No contact closed: the load pushes the damper outwards onto the platforms.
          q = q + [0.0_wp, 2*load/sum(c%kn), 0.0_wp]
          cycle
        end if
        dq = gauss(J, -R)
        lam = 1
        do ls = 1, 40
          call forces(q + lam*dq, gamma, load, w, R1, J1, w_new, M)
          if (norm2(R1) < norm2(R)) exit
          lam = lam/2
        end do
        q = q + lam*dq
      end do
      if (it > 60) then
        newton_failures = newton_failures + 1
        if (newton_failures == 1) write(*, '(a, 3es12.4, a, 3es12.4)') "Newton failed at gamma, CF, |R| = ", &
          & gamma, load, maxval(abs(R)), " q = ", q
      end if
      call forces(q, gamma, load, w, R, J, w_new, M)
      w = w_new
    end subroutine step

    function gauss(A0, b0) result(x)
      real(wp), intent(in) :: A0(3,3), b0(3)
      real(wp) :: x(3), A(3,3), b(3), f, tmp(3), tb
      integer :: i, k, piv
      A = A0
      b = b0
      do k = 1, 3
        piv = k - 1 + maxloc(abs(A(k:3,k)), 1)
        tmp = A(k,:); A(k,:) = A(piv,:); A(piv,:) = tmp
        tb = b(k); b(k) = b(piv); b(piv) = tb
        do i = k + 1, 3
          f = A(i,k)/A(k,k)
          A(i,:) = A(i,:) - f*A(k,:)
          b(i) = b(i) - f*b(k)
        end do
      end do
      do i = 3, 1, -1
        x(i) = (b(i) - dot_product(A(i,i+1:3), x(i+1:3)))/A(i,i)
      end do
    end function gauss

    !> The history of PHYSICS.md 2.1 in small steps: CF ramp, gamma ramp to +a, three cycles
    !> with uniform steps of gamma (the model is rate-independent, only the path matters).
    !> Returns the last cycle: gam(1) = a down to -a and back to a.
    subroutine brute_loop(a, n, gam, Mr)
      real(wp), intent(in) :: a
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: gam(:), Mr(:)
      real(wp) :: q(3), w(3), M
      integer :: i, cyc
      allocate(gam(2*n + 1), Mr(2*n + 1))
      q = 0
      w = 0
      do i = 1, 100
        call step(q, w, 0.0_wp, CF*i/100, M)
      end do
      do i = 1, n
        call step(q, w, a*i/n, CF, M)
      end do
      do cyc = 1, 3
        do i = 0, 2*n
          if (i <= n) then
            gam(i+1) = a*(1 - 2*real(i, wp)/n)
          else
            gam(i+1) = a*(-1 + 2*real(i - n, wp)/n)
          end if
          if (i > 0) call step(q, w, gam(i+1), CF, M)
          if (i == 0) call step(q, w, a, CF, M)
          Mr(i+1) = M
        end do
      end do
    end subroutine brute_loop

    !> Travel from the reversal to the first step on the plateau M_p (sgn -1: descending).
    real(wp) function travel_to(Mp, sgn) result(s)
      real(wp), intent(in) :: Mp
      integer, intent(in) :: sgn
      integer :: n, i, i0
      n = (size(gam) - 1)/2
      i0 = merge(1, n + 1, sgn < 0)
      s = 0
      do i = i0, i0 + n
        if (abs(Mr(i) - Mp) <= 1e-9_wp*abs(Mp)) then
          s = abs(gam(i) - gam(i0))
          return
        end if
      end do
    end function travel_to

    !> Describing function of a sampled loop: k_Im from the enclosed area (trapezoids in gamma),
    !> k_Re = 1/(pi a) int M cos(tau) dtau (trapezoids in tau).
    complex(wp) function describing(a, gam, Mr) result(k)
      real(wp), intent(in) :: a, gam(:), Mr(:)
      real(wp) :: E, kre, tau(size(gam))
      integer :: i, n
      n = (size(gam) - 1)/2
      do i = 1, size(gam)
        tau(i) = acos(max(-1.0_wp, min(1.0_wp, gam(i)/a)))
        if (i > n + 1) tau(i) = 2*pi - tau(i)
      end do
      E = 0
      kre = 0
      do i = 2, size(gam)
        E = E + (gam(i) - gam(i-1))*(Mr(i) + Mr(i-1))/2
        kre = kre + (tau(i) - tau(i-1))*(Mr(i)*cos(tau(i)) + Mr(i-1)*cos(tau(i-1)))/2
      end do
      k = cmplx(kre/(pi*a), E/(pi*a**2), wp)
    end function describing
  end subroutine run_damper_bruteforce
end module test_damper_bruteforce
