!> The periodic waveform of the alternating frequency-time method: gamma(tau) = Gamma_0 +
!> Re(sum_h Gamma_h e^{i h tau}), tau = omega t, its slope, its extrema over a period (the roots
!> of gamma', where the exact AFT splits the path into monotone stretches), the instant at which
!> it reaches a value on a monotone stretch, and the powers e^{i h tau} of the Fourier integrals.
module udmap_contact_aft_waveform
  use udmap_core_kinds, only: wp, pi
  use udmap_core_sorting, only: sort_ascending
  implicit none
  private
  public :: waveform_value, waveform_slope, waveform_extrema, solve_time, powers, two_pi

  !> One period of tau [rad].
  real(wp), parameter :: two_pi = 2.0_wp*pi

contains

  !> gamma(tau) for the coefficients G0 (static) and G(1:H).
  pure real(wp) function waveform_value(G0, G, tau) result(val)
    real(wp), intent(in) :: G0, tau
    complex(wp), intent(in) :: G(:)
    complex(wp) :: z, zh
    integer :: h
    z = cmplx(cos(tau), sin(tau), wp)
    zh = (1.0_wp, 0.0_wp)
    val = G0
    do h = 1, size(G)
      zh = zh*z
      val = val + real(G(h)*zh, wp)
    end do
  end function waveform_value

  !> d^order gamma / dtau^order at tau (order 1 or 2).
  pure real(wp) function waveform_slope(G, tau, order) result(val)
    complex(wp), intent(in) :: G(:)
    real(wp), intent(in) :: tau
    integer, intent(in) :: order
    complex(wp) :: z, zh
    integer :: h
    z = cmplx(cos(tau), sin(tau), wp)
    zh = (1.0_wp, 0.0_wp)
    val = 0.0_wp
    ! (i h)^1 = i h, (i h)^2 = -h^2 (no complex power in the inner loop)
    if (order == 1) then
      do h = 1, size(G)
        zh = zh*z
        val = val - h*aimag(G(h)*zh)
      end do
    else
      do h = 1, size(G)
        zh = zh*z
        val = val - real(h, wp)**2*real(G(h)*zh, wp)
      end do
    end if
  end function waveform_slope

  !> gamma(tau) - Gamma_0 + G0 (val) and gamma'(tau) (d1) in one pass: the values of
  !> waveform_value and waveform_slope, bit for bit, for the Newton steps that need both.
  pure subroutine waveform_value_slope(G0, G, tau, val, d1)
    real(wp), intent(in) :: G0, tau
    complex(wp), intent(in) :: G(:)
    real(wp), intent(out) :: val, d1
    complex(wp) :: z, zh, gz
    integer :: h
    z = cmplx(cos(tau), sin(tau), wp)
    zh = (1.0_wp, 0.0_wp)
    val = G0
    d1 = 0.0_wp
    do h = 1, size(G)
      zh = zh*z
      gz = G(h)*zh
      val = val + real(gz, wp)
      d1 = d1 - h*aimag(gz)
    end do
  end subroutine waveform_value_slope

  !> gamma'(tau) (d1) and gamma''(tau) (d2) in one pass, bit for bit waveform_slope's.
  pure subroutine waveform_slopes(G, tau, d1, d2)
    complex(wp), intent(in) :: G(:)
    real(wp), intent(in) :: tau
    real(wp), intent(out) :: d1, d2
    complex(wp) :: z, zh, gz
    integer :: h
    z = cmplx(cos(tau), sin(tau), wp)
    zh = (1.0_wp, 0.0_wp)
    d1 = 0.0_wp
    d2 = 0.0_wp
    do h = 1, size(G)
      zh = zh*z
      gz = G(h)*zh
      d1 = d1 - h*aimag(gz)
      d2 = d2 - real(h, wp)**2*real(gz, wp)
    end do
  end subroutine waveform_slopes

  !> The extrema of gamma(tau) over one period, in order, starting at the global maximum:
  !> tau(1) is the maximum, tau(2), ... alternate minimum/maximum, tau(n+1) = tau(1) + 2 pi.
  !> n = 0 for a constant waveform.
  pure subroutine waveform_extrema(G, tau, n)
    complex(wp), intent(in) :: G(:)
    real(wp), allocatable, intent(out) :: tau(:)
    integer, intent(out) :: n
    integer :: H, ns, j, k, imax, h1, nh, i, nj, jj, nc, nn, m, w
    real(wp), allocatable :: ts(:), ds(:), roots(:), c1(:), s1(:), sa(:), cb(:)
    integer, allocatable :: js(:), cells(:), next(:)
    logical, allocatable :: done(:)
    complex(wp) :: z, zs
    real(wp) :: a, b, fa, fb, x, fx, d2, best, v, scale, xn, B2, reach, err
    H = size(G)
    n = 0
    scale = sum(abs(G))
    if (scale <= 0.0_wp) then
      allocate(tau(1))
      tau = 0.0_wp
      return
    end if
    ! only one harmonic present: extrema in closed form
    h1 = 0
    do k = 1, H
      if (abs(G(k)) > 0.0_wp) then
        if (h1 /= 0) then
          h1 = -1
          exit
        end if
        h1 = k
      end if
    end do
    if (h1 > 0) then
      n = 2*h1
      allocate(tau(n+1))
      do k = 1, n
        tau(k) = (-atan2(aimag(G(h1)), real(G(h1), wp)) + (k - 1)*pi)/h1
      end do
      tau(n+1) = tau(1) + two_pi
      return
    end if
    ! general waveform: sign changes of gamma' on a grid fine enough for H harmonics
    ns = max(64, 16*H)
    allocate(ts(0:ns), ds(0:ns), roots(ns))
    do j = 0, ns
      ts(j) = two_pi*j/ns
    end do
    ! gamma'(tau_j) = -(sa_j + cb_j), sa_j = sum_h h Re G_h sin(h tau_j), cb_j = sum_h h Im G_h
    ! cos(h tau_j); at tau_{ns-j} = 2 pi - tau_j the sines change sign: sa_j - cb_j. So only
    ! j = 0..ns/2, cos/sin(h tau_j) by the angle-addition recurrence (grid_slopes), cos/sin(tau_j)
    ! exact every 8th point and rotated in between.
    nh = ns/2
    allocate(c1(0:nh), s1(0:nh), sa(0:nh), cb(0:nh), js(nh + 1))
    zs = cmplx(cos(two_pi/ns), sin(two_pi/ns), wp)
    do j = 0, nh
      if (mod(j, 8) == 0) then
        z = cmplx(cos(ts(j)), sin(ts(j)), wp)
      else
        z = z*zs
      end if
      c1(j) = real(z, wp)
      s1(j) = aimag(z)
    end do
    ! gamma' on the coarse grid (every 8th point) first, then in the middle of each cell where
    ! it may vanish, halving the cells down to the fine grid. A cell of width w where gamma'
    ! keeps away from zero (|gamma''| <= B2 = sum h^2 |G_h| cannot bring it there over w, with
    ! a margin for the rounding of the sums) holds no sign change on the fine grid: its inner
    ! points are not computed. The values computed, and so the roots, are those of the whole
    ! fine grid (each point's recurrence is its own).
    nj = nh/8 + 1
    js(1:nj) = [(j, j = 0, nh, 8)]
    call grid_slopes(G, c1, s1, js(1:nj), sa, cb)
    do i = 0, ns - 1, 8
      ds(i) = slope_at(i)
    end do
    ds(ns) = ds(0)
    B2 = 0
    do k = 1, H
      B2 = B2 + real(k, wp)**2*abs(G(k))
    end do
    err = 100.0_wp*H*epsilon(1.0_wp)*B2
    allocate(done(0:nh), cells(ns), next(ns))
    done = .false.
    done(0:nh:8) = .true.
    nc = ns/8
    cells(1:nc) = [(i, i = 0, ns - 8, 8)]
    w = 8
    do while (w > 1)
      ! the cells [i, i + w] that may hold a zero, and their middles to compute
      reach = B2*(w*two_pi/ns) + 4*err
      nj = 0
      nn = 0
      do m = 1, nc
        i = cells(m)
        if (abs(ds(i)) + abs(ds(i+w)) > reach) cycle
        nn = nn + 1
        next(nn) = i
        jj = i + w/2
        if (jj > nh) jj = ns - jj
        if (done(jj)) cycle
        done(jj) = .true.
        nj = nj + 1
        js(nj) = jj
      end do
      call grid_slopes(G, c1, s1, js(1:nj), sa, cb)
      w = w/2
      nc = 0
      do m = 1, nn
        i = next(m)
        ds(i+w) = slope_at(i+w)
        cells(nc+1:nc+2) = [i, i + w]
        nc = nc + 2
      end do
    end do
    ts(ns) = two_pi
    ! zero counts as positive, so a touching zero (inflection) is not an extremum; the fine
    ! cells left, in order
    do m = 1, nc
      j = cells(m)
      if ((ds(j) >= 0.0_wp) .eqv. (ds(j+1) >= 0.0_wp)) cycle
      a = ts(j); b = ts(j+1); fa = ds(j); fb = ds(j+1)
      if (fa == 0.0_wp) then
        x = a
      else if (fb == 0.0_wp) then
        x = b
      else
        ! safeguarded Newton on gamma' inside the bracket
        x = a - fa*(b - a)/(fb - fa)
        do k = 1, 100
          call waveform_slopes(G, x, fx, d2)
          if (abs(fx) <= 8.0_wp*epsilon(1.0_wp)*scale*H) exit
          call newton_step(x, fx, d2, a, fa, b, fb, xn)
          if (xn == x .or. b - a <= 4.0_wp*epsilon(1.0_wp)*two_pi) exit
          x = xn
        end do
      end if
      if (x >= two_pi) x = x - two_pi
      if (n > 0) then
        if (abs(x - roots(n)) <= 4.0_wp*epsilon(1.0_wp)*two_pi .or. &
            & abs(x - roots(1)) <= 4.0_wp*epsilon(1.0_wp)*two_pi) cycle
      end if
      n = n + 1
      roots(n) = x
    end do
    if (n < 2) then
      ! degenerate (extrema closer than the grid resolves): grid maximum and minimum
      n = 2
      roots(1) = ts(maxloc(waveform_grid(G, ts(0:ns-1)), 1) - 1)
      roots(2) = ts(minloc(waveform_grid(G, ts(0:ns-1)), 1) - 1)
    end if
    call sort_ascending(roots(1:n))
    ! start at the global maximum
    imax = 1
    best = -huge(1.0_wp)
    do k = 1, n
      v = waveform_value(0.0_wp, G, roots(k))
      if (v > best) then
        best = v
        imax = k
      end if
    end do
    allocate(tau(n+1))
    do k = 1, n
      j = imax + k - 1
      if (j <= n) then
        tau(k) = roots(j)
      else
        tau(k) = roots(j - n) + two_pi
      end if
    end do
    tau(n+1) = tau(1) + two_pi
  contains
    !> gamma'(tau_i), i = 0..ns-1, from the sums at i or at its mirror ns - i.
    pure real(wp) function slope_at(i) result(d)
      integer, intent(in) :: i
      if (i <= nh) then
        d = -(sa(i) + cb(i))
      else
        d = sa(ns-i) - cb(ns-i)
      end if
    end function slope_at

    pure function waveform_grid(G, t) result(v)
      complex(wp), intent(in) :: G(:)
      real(wp), intent(in) :: t(:)
      real(wp) :: v(size(t))
      integer :: i
      do i = 1, size(t)
        v(i) = waveform_value(0.0_wp, G, t(i))
      end do
    end function waveform_grid
  end subroutine waveform_extrema

  !> sa_j = sum_h h Re G_h sin(h tau_j) and cb_j = sum_h h Im G_h cos(h tau_j) at the grid
  !> points js, cos/sin(h tau_j) by the angle-addition recurrence from c1, s1 = cos/sin(tau_j).
  pure subroutine grid_slopes(G, c1, s1, js, sa, cb)
    complex(wp), intent(in) :: G(:)
    real(wp), intent(in) :: c1(0:), s1(0:)
    integer, intent(in) :: js(:)
    real(wp), intent(inout) :: sa(0:), cb(0:)
    real(wp), dimension(size(js)) :: cc, ss, ch, sh, a, b
    real(wp) :: gr, gi, cn
    integer :: m, k
    ! gathered, so that the inner loop runs over contiguous points
    cc = c1(js)
    ss = s1(js)
    ch = cc
    sh = ss
    a = real(G(1), wp)*ss
    b = aimag(G(1))*cc
    do k = 2, size(G)
      gr = k*real(G(k), wp)
      gi = k*aimag(G(k))
      do m = 1, size(js)
        cn = ch(m)*cc(m) - sh(m)*ss(m)
        sh(m) = sh(m)*cc(m) + ch(m)*ss(m)
        ch(m) = cn
        a(m) = a(m) + gr*sh(m)
        b(m) = b(m) + gi*cn
      end do
    end do
    sa(js) = a
    cb(js) = b
  end subroutine grid_slopes

  !> e^{i m t} for m = -2H..H.
  pure subroutine powers(t, H, P)
    real(wp), intent(in) :: t
    integer, intent(in) :: H
    complex(wp), intent(out) :: P(-2*H:H)
    complex(wp) :: z
    integer :: m
    z = cmplx(cos(t), sin(t), wp)
    P(0) = (1.0_wp, 0.0_wp)
    do m = 1, H
      P(m) = P(m-1)*z
    end do
    do m = 1, 2*H
      P(-m) = P(-m+1)*conjg(z)
    end do
  end subroutine powers

  !> The instant in [ta, tb] where the monotone waveform reaches gt (gb = gamma(tb));
  !> G_abs = sum |G_h| (the scale of the rounding, once a waveform).
  pure real(wp) function solve_time(G0, G, G_abs, gt, ta, tb, gb) result(t)
    real(wp), intent(in) :: G0, G_abs, gt, ta, tb, gb
    complex(wp), intent(in) :: G(:)
    real(wp) :: a, b, fa, fb, ft, tn, tolf, v, d1
    integer :: it
    a = ta; b = tb
    fa = G0 + waveform_value(0.0_wp, G, a) - gt
    fb = gb - gt
    if (fa == 0.0_wp) then
      t = a; return
    end if
    if (fb == 0.0_wp .or. (fa > 0.0_wp .eqv. fb > 0.0_wp)) then
      ! rounding put g at (or just past) the end of the stretch
      if (abs(fa) < abs(fb)) then
        t = a
      else
        t = b
      end if
      return
    end if
    tolf = 4.0_wp*epsilon(1.0_wp)*(abs(G0) + G_abs + abs(gt))
    t = a - fa*(b - a)/(fb - fa)
    do it = 1, 100
      call waveform_value_slope(0.0_wp, G, t, v, d1)
      ft = G0 + v - gt
      if (abs(ft) <= tolf) return
      call newton_step(t, ft, d1, a, fa, b, fb, tn)
      if (tn == t .or. b - a <= 2.0_wp*epsilon(1.0_wp)*max(abs(a), abs(b), 1.0_wp)) return
      t = tn
    end do
  end function solve_time

  !> One safeguarded Newton step on f inside the bracket [a, b] (f(a), f(b) of opposite
  !> signs): the bracket shrunk to x (f(x) = fx) keeping the sign change, then the Newton
  !> step from x with slope dfx, or the midpoint when there is no slope or the step leaves it.
  pure subroutine newton_step(x, fx, dfx, a, fa, b, fb, xn)
    real(wp), intent(in) :: x, fx, dfx
    real(wp), intent(inout) :: a, fa, b, fb
    real(wp), intent(out) :: xn
    if ((fx > 0.0_wp) .eqv. (fa > 0.0_wp)) then
      a = x; fa = fx
    else
      b = x; fb = fx
    end if
    xn = 0.5_wp*(a + b)
    if (dfx /= 0.0_wp) xn = x - fx/dfx
    if (.not.(xn > a .and. xn < b)) xn = 0.5_wp*(a + b)
  end subroutine newton_step
end module udmap_contact_aft_waveform
