!> The backbone of the non-linear response curves (PHYSICS.md 4, paper section 4.2): the peak
!> of the response to F_E lies where the layer's linear response peaks, so
!>   F_bb(gamma) = gamma / max_omega |g~(omega; gamma)|
!> at the frequency of that maximum, and the peaks for F_E are the roots of F_bb(gamma) = F_E.
!>
!> F_bb is tabulated per damper revision on the grid gamma_j = gamma_b 10^(j/grid_per_decade)
!> from the last node at or below gamma_s (below it the damper is stuck, k is constant and F_bb
!> is exactly linear) up to wherever the requested forces need it. Each node is one layer peak
!> search started from the eigenvalue, which is tracked from node to node with the secular
!> equation (udmap_mapping_eigen_start). The nodes only bracket roots and start searches, so their
!> peaks are located to table_rtol; every result is refined to rtol.
!>
!> Roots of F_bb = F_E are bracketed on the grid, all of them, and refined by safeguarded
!> Newton iterations on v(u) = ln F_bb(e^u) - ln F_E, u = ln gamma, started by inverse cubic
!> Hermite interpolation between the nodes. The slope comes from the envelope theorem: at the
!> peak d|g~|/d omega = 0, so only k moves it,
!>   dv/du = 1 + Re( H_gg/(1 + k H_gg) dk/du ),
!> with dk/du from the damper's stiffness derivative (no receptance evaluation).
!> Two Newton steps usually reach rtol = 1e-12.
!>
!> Jumps of k(gamma) (PHYSICS.md 2.5): F_bb jumps with k at gamma_c. Grid intervals that hold
!> a jump are split there into continuous pieces, each bracketed and refined as above, and the
!> jump itself is a root when F_E lies between F_bb(gamma_c-) and F_bb(gamma_c+): gamma_P = gamma_c
!> with k = (1 - s) k- + s k+, s solved by safeguarded Newton (the envelope theorem again,
!> d ln F_bb/ds = Re(H_gg (k+ - k-)/(1 + k H_gg))). gamma_c is exact (the tracer's event
!> coincidence), so no answer depends on rtol beyond rtol itself.
!>
!> The peak frequency matters beyond rtol: the response curve is tangent to F_E there, and a
!> frequency error delta tilts it by delta/zeta^2 in d ln F/d ln omega. The layer peak search
!> returns its last (superlinear) secant estimate, which is good to far better than rtol.
module udmap_mapping_backbone
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_mapping_model_data, only: model_type, point_type, backbone_eval_type, &
    & limit_force_or_huge, fill_point, check_forces, limit_force_backbone, REGIME_LIMIT
  use udmap_mapping_backbone_table, only: ensure_table, cover_table, eval_backbone, peak_rtol, &
    & layer_backbone, interp_offset
  implicit none
  private
  public :: backbone_curve, backbone, backbone_roots

contains

  !> The root of F_bb = F_E between the backbone points na and nb (grid nodes or the sides of a
  !> jump, which bracket it, F_bb continuous between them) to rtol in gamma, with the layer
  !> peak there.
  subroutine refine_root(model, F_E, na, nb, e, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E
    type(backbone_eval_type), intent(in) :: na, nb
    type(backbone_eval_type), intent(out) :: e
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type) :: prev
    real(wp) :: ua, ub, fa, fb, sa, sb, du, t, p, dp, lo, hi, x, f, dx, tol
    integer :: it
    logical :: have_prev, rising, full
    ua = log(na%gamma)
    ub = log(nb%gamma)
    fa = log(na%F_bb/F_E)
    fb = log(nb%F_bb/F_E)
    sa = na%slope
    sb = nb%slope
    if (fb == 0) then
      if (.not.(abs(nb%k - model%damper%stiffness(nb%gamma)) > 0)) then
        call eval_backbone(model, nb%gamma, e, error, start=nb)
      else
        ! the upper side of a jump: its own k
        call layer_backbone(model, nb%gamma, peak_rtol(model), e, error, start=nb, &
          & k_fixed=nb%k, dk_fixed=model%damper%stiffness_derivative(nb%gamma))
      end if
      return
    end if
    du = ub - ua
    rising = fb > fa
    tol = model%analysis%rtol
    ! start: root of the cubic Hermite interpolant of v on [ua, ub] (linear if that fails)
    t = fa/(fa - fb)
    do it = 1, 20
      p = (2*t**3 - 3*t**2 + 1)*fa + (t**3 - 2*t**2 + t)*du*sa + (-2*t**3 + 3*t**2)*fb + &
        & (t**3 - t**2)*du*sb
      dp = (6*t**2 - 6*t)*fa + (3*t**2 - 4*t + 1)*du*sa + (-6*t**2 + 6*t)*fb + (3*t**2 - 2*t)*du*sb
      if (dp == 0) exit
      t = t - p/dp
      if (.not.(t > 0 .and. t < 1)) exit
      if (abs(p/dp) < 1e-14_wp) exit
    end do
    if (.not.(t > 0 .and. t < 1)) t = fa/(fa - fb)
    lo = ua
    hi = ub
    x = ua + t*du
    have_prev = .false.
    ! Newton with F_bb from loosely located peaks; once the step is small the next iterate is
    ! the answer to rtol (quadratic convergence) and gets the fully located peak
    full = .false.
    do it = 1, 100
      if (have_prev) then
        call eval_backbone(model, exp(x), e, error, start=prev, loose=.not.full)
      else if (t < 0.5_wp) then
        call eval_backbone(model, exp(x), e, error, start=na, loose=.not.full)
      else
        call eval_backbone(model, exp(x), e, error, start=nb, loose=.not.full)
      end if
      if (allocated(error)) return
      f = log(e%F_bb/F_E)
      if ((f > 0) .eqv. rising) then
        hi = x
      else
        lo = x
      end if
      dx = -f/e%slope
      if (f == 0 .or. abs(dx) <= tol .or. hi - lo <= tol) then
        if (full) return
        ! the root is x: locate its peak fully
        full = .true.
        prev = e
        have_prev = .true.
        cycle
      end if
      prev = e
      have_prev = .true.
      if (.not.(x + dx > lo .and. x + dx < hi)) then
        x = 0.5_wp*(lo + hi)
      else
        x = x + dx
        full = abs(dx) <= 1e-4_wp
      end if
    end do
    call fatal_error(error, "backbone: the root refinement did not converge", UDMAP_ENUMERIC)
  end subroutine refine_root

  !> Every root of F_bb(gamma) = F_E (ascending) and, at the largest, the backbone point.
  !> The table must already cover F_E (cover_table). A root in a jump of k (PHYSICS.md 2.5)
  !> is gamma_c; `jump` says whether the largest root is one.
  subroutine backbone_roots(model, F_E, roots, e, error, jump)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E
    real(wp), allocatable, intent(out) :: roots(:)
    type(backbone_eval_type), intent(out) :: e
    type(error_type), allocatable, intent(out) :: error
    logical, intent(out), optional :: jump
    type(backbone_eval_type) :: left, last
    real(wp) :: found(256)
    integer :: j, n, i, i_next
    logical :: last_jump, have_last
    n = 0
    last_jump = .false.
    have_last = .false.
    if (present(jump)) jump = .false.
    call ensure_sides(model, error)
    if (allocated(error)) return
    i_next = 1
    associate(t => model%table)
      if (F_E <= t%node(t%j_lo)%F_bb) then
        ! stuck: F_bb is linear through the origin below the first node
        n = 1
        found(1) = F_E*t%node(t%j_lo)%gamma/t%node(t%j_lo)%F_bb
        call eval_backbone(model, found(1), e, error)
        if (allocated(error)) return
      end if
      if (n == 1) then
        last = e
        have_last = .true.
      end if
      do while (i_next <= t%n_side)
        if (t%side(1, i_next)%gamma >= t%node(t%j_lo)%gamma) exit
        i_next = i_next + 1
      end do
      do j = t%j_lo, t%j_hi - 1
        ! jumps at gamma_c in [gamma_j, gamma_j+1) split the interval into continuous pieces
        left = t%node(j)
        do i = i_next, t%n_side
          if (t%side(1, i)%gamma >= t%node(j + 1)%gamma) exit
          i_next = i + 1
          if (t%side(1, i)%gamma > left%gamma) call piece(left, t%side(1, i))
          if (allocated(error)) return
          ! the jump: F_bb takes every value between its sides at gamma_c
          if (brackets(t%side(1, i)%F_bb, t%side(2, i)%F_bb) .and. n < size(found)) then
            call jump_root(model, F_E, t%side(1, i), t%side(2, i), last, error)
            if (allocated(error)) return
            n = n + 1
            found(n) = last%gamma
            last_jump = .true.
            have_last = .true.
          end if
          left = t%side(2, i)
        end do
        call piece(left, t%node(j + 1))
        if (allocated(error)) return
      end do
    end associate
    if (have_last) e = last
    if (present(jump)) jump = last_jump
    if (n == 0) then
      call fatal_error(error, "backbone: no amplitude found for the force (internal: the "// &
        & "table does not cover it)", UDMAP_ENUMERIC)
      return
    end if
    roots = found(1:n)

  contains

    !> A root in (F_a, F_b]: a sign change, or a zero at the upper end.
    logical function brackets(Fa, Fb)
      real(wp), intent(in) :: Fa, Fb
      brackets = (Fa < F_E .and. Fb >= F_E) .or. (Fa > F_E .and. Fb <= F_E)
    end function brackets

    !> The root on the continuous piece from a to b, if they bracket one.
    subroutine piece(a, b)
      type(backbone_eval_type), intent(in) :: a, b
      if (.not.brackets(a%F_bb, b%F_bb) .or. n >= size(found)) return
      call refine_root(model, F_E, a, b, last, error)
      if (allocated(error)) return
      n = n + 1
      found(n) = last%gamma
      last_jump = .false.
      have_last = .true.
    end subroutine piece
  end subroutine backbone_roots

  !> The backbone points at both sides of every jump of k (PHYSICS.md 2.5) that the grid
  !> reaches, each computed once per table.
  subroutine ensure_sides(model, error)
    type(model_type), intent(inout) :: model
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type), allocatable :: grown(:,:)
    real(wp) :: gamma_c
    complex(wp) :: km, kp, dkm, dkp
    integer :: i, j, n
    associate(t => model%table)
      n = model%damper%jump_count()
      if (n == 0 .or. t%n_side == n) return
      if (.not.allocated(t%side)) then
        allocate(t%side(2, n))
      else if (size(t%side, 2) /= n) then
        allocate(grown(2, n))
        call move_alloc(grown, t%side)
        t%n_side = 0
      end if
      do i = t%n_side + 1, n
        call model%damper%jump(i, gamma_c, km, kp, dkm, dkp)
        if (gamma_c >= t%node(t%j_hi)%gamma) exit
        if (gamma_c <= t%node(t%j_lo)%gamma) then
          ! below the grid k is constant: no jump can lie there; keep the bookkeeping simple
          t%side(1, i) = t%node(t%j_lo)
          t%side(2, i) = t%node(t%j_lo)
          t%n_side = i
          cycle
        end if
        j = nint(model%analysis%grid_per_decade*log10(gamma_c/t%gamma_ref))
        j = min(max(j, t%j_lo), t%j_hi)
        call layer_backbone(model, gamma_c, peak_rtol(model), t%side(1, i), error, &
          & start=t%node(j), offset_guess=interp_offset(model, gamma_c), k_fixed=km, &
          & dk_fixed=dkm)
        if (allocated(error)) return
        call layer_backbone(model, gamma_c, peak_rtol(model), t%side(2, i), error, &
          & start=t%side(1, i), k_fixed=kp, dk_fixed=dkp)
        if (allocated(error)) return
        t%n_side = i
      end do
    end associate
  end subroutine ensure_sides

  !> The root of F_bb = F_E inside the jump between the sides a (k-) and b (k+) at gamma_c:
  !> the layer with k = (1 - s) k- + s k+ whose peak is F_E (PHYSICS.md 2.5). ln F_bb(s) is
  !> smooth in s with the slope Re(H_gg (k+ - k-)/(1 + k H_gg)) at the peak (envelope
  !> theorem); safeguarded Newton in the bracket [0, 1] to rtol.
  subroutine jump_root(model, F_E, a, b, e, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E
    type(backbone_eval_type), intent(in) :: a, b
    type(backbone_eval_type), intent(out) :: e
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type) :: prev
    complex(wp) :: dk
    real(wp) :: s, lo, hi, f, fa, fb, df, ds
    integer :: it
    logical :: rising
    dk = b%k - a%k
    fa = log(a%F_bb/F_E)
    fb = log(b%F_bb/F_E)
    if (fb == 0) then
      e = b
      return
    end if
    rising = fb > fa
    lo = 0
    hi = 1
    s = fa/(fa - fb)
    prev = a
    if (s > 0.5_wp) prev = b
    do it = 1, 100
      call layer_backbone(model, a%gamma, peak_rtol(model), e, error, start=prev, &
        & k_fixed=a%k + s*dk, dk_fixed=(1 - s)*model%damper%stiffness_derivative(a%gamma))
      if (allocated(error)) return
      f = log(e%F_bb/F_E)
      if ((f > 0) .eqv. rising) then
        hi = s
      else
        lo = s
      end if
      df = real(e%peak%r%gg*dk/(1 + e%k*e%peak%r%gg), wp)
      ds = 0
      if (df /= 0) ds = -f/df
      if (f == 0 .or. abs(f) <= 0.1_wp*model%analysis%rtol .or. hi - lo <= 1e-15_wp) return
      prev = e
      if (.not.(s + ds > lo .and. s + ds < hi)) then
        s = 0.5_wp*(lo + hi)
      else
        s = s + ds
      end if
    end do
    call fatal_error(error, "backbone: the root inside a jump of k(gamma) did not converge", &
      & UDMAP_ENUMERIC)
  end subroutine jump_root

  !> F_bb(gamma) [N] and the peak frequency f_res [Hz] for amplitudes gamma [rad].
  subroutine backbone_curve(model, gamma, F_bb, f_res, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: gamma(:)
    real(wp), intent(out) :: F_bb(:), f_res(:)
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type) :: e
    integer :: i
    character(len=12) :: buf
    F_bb = 0
    f_res = 0
    if (size(F_bb) < size(gamma) .or. size(f_res) < size(gamma)) then
      call fatal_error(error, "backbone_curve: F_bb and f_res must be as long as gamma", UDMAP_EINPUT)
      return
    end if
    do i = 1, size(gamma)
      if (.not.(gamma(i) > 0 .and. gamma(i) < huge(1.0_wp))) then
        write(buf, '(i0)') i
        call fatal_error(error, "backbone_curve: gamma("//trim(buf)//") must be a positive "// &
          & "number [rad]", UDMAP_EINPUT)
        return
      end if
    end do
    if (size(gamma) == 0) return
    call ensure_table(model, error)
    if (allocated(error)) return
    call cover_table(model, 0.0_wp, maxval(gamma), error)
    if (allocated(error)) return
    do i = 1, size(gamma)
      call eval_backbone(model, gamma(i), e, error)
      if (allocated(error)) return
      F_bb(i) = e%F_bb
      f_res(i) = e%peak%omega/(2*pi)
    end do
  end subroutine backbone_curve

  !> The peaks of the non-linear response for the forces F_E [N] (PHYSICS.md 4): every root
  !> of F_bb(gamma) = F_E, the largest giving gamma_P and the outputs at its frequency. Without
  !> structural damping a force at or above F_lim, or one that F_bb does not reach below
  !> 1e12 gamma_b, gives an unbounded point (regime REGIME_LIMIT, numbers 0, no roots).
  subroutine backbone(model, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type) :: e
    real(wp), allocatable :: roots(:)
    real(wp) :: F_lim, F_max, F_reach
    logical :: reached, jump
    integer :: i
    allocate(points(size(F_E)))
    call check_forces(F_E, "backbone", error)
    if (allocated(error)) return
    if (size(F_E) == 0) return
    call ensure_table(model, error)
    if (allocated(error)) return
    ! without structural damping friction bounds the response only below the asymptote of
    ! F_bb: F_lim in theory, lower when the damper dissipates less than 2 Delta_M per unit
    ! rotation at large amplitude (e.g. with lift-off, F_lim_backbone of PHYSICS.md 5); forces
    ! F_bb never reaches are unbounded
    F_lim = min(limit_force_or_huge(model), limit_force_backbone(model))
    F_max = 0
    do i = 1, size(F_E)
      if (.not.(model%undamped .and. F_E(i) >= F_lim)) F_max = max(F_max, F_E(i))
    end do
    F_reach = huge(1.0_wp)
    if (model%undamped) then
      call cover_table(model, F_max, 0.0_wp, error, reached)
      if (allocated(error)) return
      if (.not.reached) F_reach = model%table%node(model%table%j_hi)%F_bb
    else
      call cover_table(model, F_max, 0.0_wp, error)
      if (allocated(error)) return
    end if
    do i = 1, size(F_E)
      if (model%undamped .and. (F_E(i) >= F_lim .or. F_E(i) >= F_reach)) then
        points(i)%F_E = F_E(i)
        points(i)%regime = REGIME_LIMIT
        points(i)%unbounded = .true.
        points(i)%hcf_ok = .false.
        allocate(points(i)%roots(0))
        cycle
      end if
      call backbone_roots(model, F_E(i), roots, e, error, jump)
      if (allocated(error)) return
      call fill_point(model, points(i), F_E(i), F_lim, e%peak%omega, e%peak%r, e%k, roots)
      points(i)%jump = jump
    end do
  end subroutine backbone
end module udmap_mapping_backbone
