!> The receptances of the blade (the hot path of the mapping; the method is described in
!> blade/type.f90): the modal sums with the series of the dropped modes, their omega-derivatives,
!> and the direct solve with double-double refinement above omega_d/2 or with explicit C.
submodule (udmap_blade_type) udmap_blade_type_receptances
  implicit none

contains
  ! ------------------------------------------------------------------ evaluation

  !> Receptances at circular frequency omega [rad/s] (see the module documentation for the
  !> method); with `derivatives`, also d/d omega. Allocation-free in the modal path.
  module procedure receptances
    logical :: deriv
    deriv = .false.
    if (present(derivatives)) deriv = derivatives
    if (.not.ieee_is_finite(omega) .or. omega < 0.0_wp) then
      call fatal_error(error, "the frequency must be a non-negative finite number", UDMAP_EINPUT)
      return
    end if
    if (self%nmodes < 1) then
      call fatal_error(error, "the blade has not been built", UDMAP_EINPUT)
      return
    end if
    if (self%explicit_C .or. omega > self%omega_fast_max) then
      call direct_receptances(self, omega, deriv, r, error)
      if (allocated(error)) return
    else if (deriv) then
      call modal_receptances_deriv(self, omega, self%nfast, r)
    else
      call modal_receptances(self, omega, self%nfast, r)
    end if
    if (.not.(finite(r%gE) .and. finite(r%gg) .and. finite(r%EE) .and. finite(r%sE) &
        & .and. finite(r%sg) .and. finite(r%dgE) .and. finite(r%dgg) .and. finite(r%dEE) &
        & .and. finite(r%dsE) .and. finite(r%dsg))) then
      r = receptances_type()
      call fatal_error(error, "the receptances are unbounded at "//ftoa(omega/(2*pi))// &
        & " Hz (an undamped natural frequency)", UDMAP_EPHYSICS)
    end if
  end procedure receptances

  !> The modal sum, hot path. The seven products are accumulated in scalars (kept in registers;
  !> arrays would go through memory at every mode), then the series of the dropped modes.
  pure subroutine modal_receptances(self, omega, nsum, r)
    class(blade_type), intent(in) :: self
    real(wp), intent(in) :: omega
    integer, intent(in) :: nsum
    type(receptances_type), intent(out) :: r
    real(wp) :: om2, wb, a, b, t, tr, ti
    real(wp) :: r1, r2, r3, r4, r5, r6, r7, i1, i2, i3, i4, i5, i6, i7
    complex(wp) :: h(7)
    integer :: m
    om2 = omega*omega
    wb = omega*self%beta
    r1 = 0; r2 = 0; r3 = 0; r4 = 0; r5 = 0; r6 = 0; r7 = 0
    i1 = 0; i2 = 0; i3 = 0; i4 = 0; i5 = 0; i6 = 0; i7 = 0
    do m = 1, nsum
      ! 1/(w^2 (1 + i omega beta) - omega^2) = (a - i b)/(a^2 + b^2)
      a = self%w2(m) - om2
      b = wb*self%w2(m)
      t = 1.0_wp/(a*a + b*b)
      tr = a*t
      ti = -b*t
      r1 = r1 + self%coef(1, m)*tr; i1 = i1 + self%coef(1, m)*ti
      r2 = r2 + self%coef(2, m)*tr; i2 = i2 + self%coef(2, m)*ti
      r3 = r3 + self%coef(3, m)*tr; i3 = i3 + self%coef(3, m)*ti
      r4 = r4 + self%coef(4, m)*tr; i4 = i4 + self%coef(4, m)*ti
      r5 = r5 + self%coef(5, m)*tr; i5 = i5 + self%coef(5, m)*ti
      r6 = r6 + self%coef(6, m)*tr; i6 = i6 + self%coef(6, m)*ti
      r7 = r7 + self%coef(7, m)*tr; i7 = i7 + self%coef(7, m)*ti
    end do
    h = [cmplx(r1, i1, wp), cmplx(r2, i2, wp), cmplx(r3, i3, wp), cmplx(r4, i4, wp), &
      & cmplx(r5, i5, wp), cmplx(r6, i6, wp), cmplx(r7, i7, wp)]
    if (nsum < self%ndof) call add_series(self, omega, h)
    r%gE = h(1)
    r%gg = h(2)
    r%EE = h(3)
    r%sE = h(4) - om2*h(5)
    r%sg = h(6) - om2*h(7)
  end subroutine modal_receptances

  !> Adds the series of the modes above nfast (see add_residual), without derivatives.
  pure subroutine add_series(self, omega, h)
    class(blade_type), intent(in) :: self
    real(wp), intent(in) :: omega
    complex(wp), intent(inout) :: h(7)
    complex(wp) :: f, finv, zeta, p1, p2, p3, p4, p5, p6, p7
    integer :: n, nterms
    f = cmplx(1.0_wp, omega*self%beta, wp)
    finv = conjg(f)/(1.0_wp + (omega*self%beta)**2)
    zeta = (omega/self%omega_d)**2*finv
    nterms = series_terms(self, zeta)
    p1 = self%res(1, nterms); p2 = self%res(2, nterms); p3 = self%res(3, nterms)
    p4 = self%res(4, nterms); p5 = self%res(5, nterms); p6 = self%res(6, nterms)
    p7 = self%res(7, nterms)
    do n = nterms - 1, 1, -1
      p1 = p1*zeta + self%res(1, n); p2 = p2*zeta + self%res(2, n)
      p3 = p3*zeta + self%res(3, n); p4 = p4*zeta + self%res(4, n)
      p5 = p5*zeta + self%res(5, n); p6 = p6*zeta + self%res(6, n)
      p7 = p7*zeta + self%res(7, n)
    end do
    h = h + [p1, p2, p3, p4, p5, p6, p7]*finv
  end subroutine add_series

  !> Terms of the series for zeta: the tail after N terms is below |zeta|^N/(1 - |zeta|) of the
  !> dropped modes' part; N is the first with that below series_tol (|zeta| <= 1/4 on the modal
  !> path, so N <= blade_residual_terms).
  pure integer function series_terms(self, zeta) result(nterms)
    class(blade_type), intent(in) :: self
    complex(wp), intent(in) :: zeta
    real(wp) :: az, t, bound
    az = sqrt(zeta%re**2 + zeta%im**2)
    bound = series_tol*(1.0_wp - az)
    t = az
    nterms = 1
    do while (t > bound .and. nterms < self%nres)
      t = t*az
      nterms = nterms + 1
    end do
  end function series_terms

  !> The modal sum with derivatives: d/d omega of 1/d_m is -d_m'/d_m^2, d_m' = i beta w^2 - 2 omega.
  pure subroutine modal_receptances_deriv(self, omega, nsum, r)
    class(blade_type), intent(in) :: self
    real(wp), intent(in) :: omega
    integer, intent(in) :: nsum
    type(receptances_type), intent(out) :: r
    real(wp) :: om2, wb, a, b, t, tr, ti, sr, si, pr, pi_, dr, di
    real(wp) :: acc_re(8), acc_im(8), dacc_re(8), dacc_im(8)
    complex(wp) :: h(8), dh(8)
    integer :: m
    om2 = omega*omega
    wb = omega*self%beta
    acc_re = 0.0_wp
    acc_im = 0.0_wp
    dacc_re = 0.0_wp
    dacc_im = 0.0_wp
    do m = 1, nsum
      a = self%w2(m) - om2
      b = wb*self%w2(m)
      t = 1.0_wp/(a*a + b*b)
      tr = a*t
      ti = -b*t
      ! (1/d)^2
      sr = tr*tr - ti*ti
      si = 2*tr*ti
      ! d' = -2 omega + i beta w^2; derivative = -d' (1/d)^2
      pr = -2*omega
      pi_ = self%beta*self%w2(m)
      dr = -(pr*sr - pi_*si)
      di = -(pr*si + pi_*sr)
      acc_re = acc_re + self%coef(:, m)*tr
      acc_im = acc_im + self%coef(:, m)*ti
      dacc_re = dacc_re + self%coef(:, m)*dr
      dacc_im = dacc_im + self%coef(:, m)*di
    end do
    h = cmplx(acc_re, acc_im, wp)
    dh = cmplx(dacc_re, dacc_im, wp)
    if (nsum < self%ndof) call add_residual(self, omega, h, dh)
    r%gE = h(1)
    r%gg = h(2)
    r%EE = h(3)
    r%sE = h(4) - om2*h(5)
    r%sg = h(6) - om2*h(7)
    r%dgE = dh(1)
    r%dgg = dh(2)
    r%dEE = dh(3)
    r%dsE = dh(4) - 2*omega*h(5) - om2*dh(5)
    r%dsg = dh(6) - 2*omega*h(7) - om2*dh(7)
  end subroutine modal_receptances_deriv

  !> Adds the series of the modes above nfast, (1/f) sum_n Rt_n zeta^n with f = 1 + i omega beta,
  !> zeta = omega^2/(f omega_d^2) and the scaled moments Rt_n = res(:, n+1), and its derivative,
  !> taking the terms that |zeta| needs for series_tol (|zeta| <= 1/4 on the modal path).
  pure subroutine add_residual(self, omega, h, dh)
    class(blade_type), intent(in) :: self
    real(wp), intent(in) :: omega
    complex(wp), intent(inout) :: h(8), dh(8)
    complex(wp) :: f, zeta, p(8), dp(8), dzeta
    integer :: n, nterms
    f = cmplx(1.0_wp, omega*self%beta, wp)
    zeta = omega**2/(f*self%omega_d**2)
    nterms = series_terms(self, zeta)
    p = self%res(:, nterms)
    dp = 0.0_wp
    do n = nterms - 1, 1, -1
      dp = dp*zeta + p
      p = p*zeta + self%res(:, n)
    end do
    h = h + p/f
    dzeta = omega*cmplx(2.0_wp, omega*self%beta, wp)/(f*f*self%omega_d**2)
    dh = dh + dp*dzeta/f - p*cmplx(0.0_wp, self%beta, wp)/(f*f)
  end subroutine add_residual

  !> Direct solves of D(omega) q = e_E, e_g (and s for the stress derivative).
  subroutine direct_receptances(self, omega, deriv, r, error)
    class(blade_type), intent(in) :: self
    real(wp), intent(in) :: omega
    logical, intent(in) :: deriv
    type(receptances_type), intent(out) :: r
    type(error_type), allocatable, intent(out) :: error
    complex(wp), allocatable :: b(:, :), q(:, :), s(:)
    integer :: n, nrhs, g, e
    n = self%ndof
    g = self%gamma_dof
    e = self%exc_dof
    nrhs = 2
    if (deriv .and. self%has_stress) nrhs = 3
    allocate(b(n, nrhs), q(n, nrhs), source=(0.0_wp, 0.0_wp))
    b(e, 1) = 1.0_wp
    b(g, 2) = 1.0_wp
    if (self%has_stress) then
      s = cmplx(self%s_K - omega**2*self%s_M, 0.0_wp, wp)
      if (nrhs == 3) b(:, 3) = s
    end if
    call dynamic_solve(omega, self%beta, self%K, self%Kb, self%M, self%Mb, self%C, self%Cb, &
      & self%kd, b, q, error)
    if (allocated(error)) then
      error%message = error%message//" at "//ftoa(omega/(2*pi))//" Hz"
      return
    end if
    r%gE = q(g, 1)
    r%gg = q(g, 2)
    r%EE = q(e, 1)
    if (self%has_stress) then
      r%sE = stress_of(q(:, 1), b(:, 1))
      r%sg = stress_of(q(:, 2), b(:, 2))
    end if
    if (deriv) then
      ! dH_ab = -q_a^T D' q_b with D' = -2 omega M + i C (D symmetric).
      block
        complex(wp), allocatable :: dq_e(:), dq_g(:)
        dq_e = dprime(q(:, 1))
        dq_g = dprime(q(:, 2))
        r%dgE = -sum(q(:, 2)*dq_e)
        r%dgg = -sum(q(:, 2)*dq_g)
        r%dEE = -sum(q(:, 1)*dq_e)
        if (self%has_stress) then
          ! d(s^T D^-1 e_b) = s'^T q_b - (D^-1 s)^T D' q_b, s' = -2 omega s_M
          r%dsE = -2*omega*sum(self%s_M*q(:, 1)) - sum(q(:, 3)*dq_e)
          r%dsg = -2*omega*sum(self%s_M*q(:, 2)) - sum(q(:, 3)*dq_g)
        end if
      end block
    end if

  contains

    !> (s_K - omega^2 s_M)^T q with s_K^T q = r_K^T K q and K q = (b + omega^2 M q - i omega C q)
    !> (C explicit) or (b + omega^2 M q)/(1 + i omega beta).
    complex(wp) function stress_of(x, rhs) result(sigma)
      complex(wp), intent(in) :: x(:), rhs(:)
      real(wp), allocatable :: xr(:), xi(:), mr(:), mi(:), cr(:), ci(:)
      complex(wp), allocatable :: kx(:)
      allocate(xr(n), xi(n), mr(n), mi(n))
      xr = x%re
      xi = x%im
      call sym_matvec(self%M, self%Mb, self%kd, xr, mr)
      call sym_matvec(self%M, self%Mb, self%kd, xi, mi)
      kx = rhs + omega**2*cmplx(mr, mi, wp)
      if (self%explicit_C) then
        allocate(cr(n), ci(n))
        call sym_matvec(self%C, self%Cb, self%kd, xr, cr)
        call sym_matvec(self%C, self%Cb, self%kd, xi, ci)
        kx = kx - cmplx(0.0_wp, omega, wp)*cmplx(cr, ci, wp)
      else
        kx = kx/cmplx(1.0_wp, omega*self%beta, wp)
      end if
      sigma = sum(self%r_K*kx) - omega**2*sum(self%s_M*x)
    end function stress_of

    function dprime(x) result(y)
      complex(wp), intent(in) :: x(:)
      complex(wp), allocatable :: y(:)
      real(wp), allocatable :: xr(:), xi(:), mr(:), mi(:), cr(:), ci(:)
      allocate(xr(n), xi(n), mr(n), mi(n), cr(n), ci(n))
      xr = x%re
      xi = x%im
      call sym_matvec(self%M, self%Mb, self%kd, xr, mr)
      call sym_matvec(self%M, self%Mb, self%kd, xi, mi)
      if (self%explicit_C) then
        call sym_matvec(self%C, self%Cb, self%kd, xr, cr)
        call sym_matvec(self%C, self%Cb, self%kd, xi, ci)
      else
        call sym_matvec(self%K, self%Kb, self%kd, xr, cr)
        call sym_matvec(self%K, self%Kb, self%kd, xi, ci)
        cr = self%beta*cr
        ci = self%beta*ci
      end if
      ! (-2 omega M + i C)(xr + i xi)
      y = cmplx(-2*omega*mr - ci, -2*omega*mi + cr, wp)
    end function dprime
  end subroutine direct_receptances
end submodule udmap_blade_type_receptances
