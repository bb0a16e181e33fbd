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
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_mapping_layer, only: layer_peak_type, layer_peak, PEAK_OK, PEAK_BELOW_BAND
  use udmap_mapping_eigen_start, only: secular_root, direct_eigen_start
  use udmap_mapping_model_data, only: model_type, point_type, backbone_eval_type, limit_force_or_huge, &
    & fill_point, check_forces, damper_fingerprint, limit_force_backbone, EIGEN_AUTO, &
    & EIGEN_DIRECT, REGIME_LIMIT
  implicit none
  private
  public :: backbone_curve, backbone, ensure_table, cover_table, eval_backbone, backbone_roots
  public :: grid_gamma, max_decades, j_limit, j_rising

  !> How far above gamma_b the grid may grow (decades) before a root is declared out of reach.
  integer, parameter :: max_decades = 12
  !> Peak tolerance of the grid nodes (which only bracket roots and start searches).
  real(wp), parameter :: table_rtol = 1.0e-7_wp

contains

  !> Tolerance to which the peak frequency of a result is located.
  pure real(wp) function peak_rtol(model)
    type(model_type), intent(in) :: model
    peak_rtol = max(model%analysis%rtol, 4*epsilon(1.0_wp))
  end function peak_rtol

  !> Grid amplitude of node j [rad].
  pure real(wp) function grid_gamma(model, j) result(gamma)
    type(model_type), intent(in) :: model
    integer, intent(in) :: j
    gamma = model%table%gamma_ref*10.0_wp**(real(j, wp)/model%analysis%grid_per_decade)
  end function grid_gamma

  !> The backbone point of the layer gamma: the damper stiffness, the eigenvalue start, and
  !> the peak of |g~| located to rtol. The eigenvalue is tracked by the secular equation from
  !> start%lambda when a start is given (else lambda_start, else bracketed from the bare modes;
  !> the direct solver with eigen_method = EIGEN_DIRECT). The peak search starts at
  !> Re sqrt(lambda) + offset_guess when given (the offset omega_peak - Re sqrt(lambda) is smooth
  !> along the grid even where k(gamma) is not, and is interpolated there), else at
  !> start%peak%omega + Re sqrt(lambda) - Re sqrt(start%lambda), else at Re sqrt(lambda). With a
  !> start, its psi slope is the hint of the first Newton step and its peak gives the width.
  subroutine layer_backbone(model, gamma, rtol, e, error, start, lambda_start, loose, predict, &
      & offset_guess, k_fixed, dk_fixed)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: gamma, rtol
    type(backbone_eval_type), intent(out) :: e
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type), intent(in), optional :: start
    complex(wp), intent(in), optional :: lambda_start
    !> Only F_bb is needed (to rtol): the peak may be located to sqrt(rtol) of its
    !> relative width, since |g~| is stationary there.
    logical, intent(in), optional :: loose
    !> Accept a single-evaluation Newton step with the start's psi slope (grid nodes).
    logical, intent(in), optional :: predict
    !> Predicted omega_peak - Re sqrt(lambda) [rad/s].
    real(wp), intent(in), optional :: offset_guess
    !> The damper stiffness and dk/dgamma to use instead of the damper's at gamma (the
    !> one-sided or interpolated values at a jump).
    complex(wp), intent(in), optional :: k_fixed, dk_fixed
    real(wp) :: omega0, width, tol, dpsi
    logical :: ok
    e%gamma = gamma
    if (present(k_fixed)) then
      e%k = k_fixed
    else
      e%k = model%damper%stiffness(gamma)
    end if
    if (model%analysis%eigen_method == EIGEN_DIRECT) then
      call direct_eigen_start(model%blade, e%k, model%analysis%dense_max, e%lambda, error)
      if (allocated(error)) return
    else
      if (present(start)) then
        call secular_root(model%secular, e%k, e%lambda, ok, start%lambda)
      else if (present(lambda_start)) then
        call secular_root(model%secular, e%k, e%lambda, ok, lambda_start)
      else
        call secular_root(model%secular, e%k, e%lambda, ok)
      end if
      if (.not.ok) then
        call fatal_error(error, "backbone: the eigenvalue start (secular equation) did not "// &
          & "converge", UDMAP_ENUMERIC)
        return
      end if
    end if
    if (present(offset_guess)) then
      omega0 = re_sqrt(e%lambda) + offset_guess
    else if (present(start)) then
      omega0 = start%peak%omega + re_sqrt(e%lambda) - re_sqrt(start%lambda)
    else
      omega0 = re_sqrt(e%lambda)
    end if
    width = abs(aimag(e%lambda)) + model%c1*omega0
    if (present(start)) then
      if (peak_width(start%peak) > 0) width = peak_width(start%peak)
    end if
    tol = rtol
    if (present(loose)) then
      if (loose) tol = max(rtol, 0.1_wp*sqrt(model%analysis%rtol)*width/omega0**2)
    end if
    dpsi = 0
    if (present(start)) dpsi = start%peak%dpsi
    if (dpsi > 0) then
      call layer_peak(model%bare, e%k, omega0, width, model%omega_lo, model%omega_hi, tol, &
        & e%peak, error, dpsi=dpsi, predict=predict)
    else
      call layer_peak(model%bare, e%k, omega0, width, model%omega_lo, model%omega_hi, tol, &
        & e%peak, error)
    end if
    if (allocated(error)) return
    if (e%peak%status /= PEAK_OK) then
      call band_error(model, gamma, e%peak, error)
      return
    end if
    e%F_bb = gamma/e%peak%amplitude
    if (present(dk_fixed)) then
      e%slope = 1 + real(e%peak%r%gg*gamma*dk_fixed/(1 + e%k*e%peak%r%gg), wp)
    else
      e%slope = backbone_slope(model, e)
    end if
  end subroutine layer_backbone

  !> Re sqrt(lambda) in real arithmetic.
  elemental real(wp) function re_sqrt(lambda)
    complex(wp), intent(in) :: lambda
    re_sqrt = sqrt(0.5_wp*(sqrt(real(lambda, wp)**2 + aimag(lambda)**2) + real(lambda, wp)))
  end function re_sqrt

  !> Half-width W (in omega^2) of a peak from its data: for one mode P = ((s - s*)^2 + W^2)/A^2,
  !> so W^2 = 2 P*/P'' = 2/(|g~|^2 dpsi). 0 when the slope is unknown.
  elemental real(wp) function peak_width(peak)
    type(layer_peak_type), intent(in) :: peak
    peak_width = 0
    if (peak%dpsi > 0) peak_width = sqrt(2/(peak%amplitude**2*peak%dpsi))
  end function peak_width

  !> omega_peak - Re sqrt(lambda) of a backbone point.
  elemental real(wp) function offset(e)
    type(backbone_eval_type), intent(in) :: e
    offset = e%peak%omega - re_sqrt(e%lambda)
  end function offset

  !> The offset omega_peak - Re sqrt(lambda) at gamma [rad/s] interpolated along the grid nodes
  !> (cubic Lagrange in ln gamma through the four nearest nodes).
  real(wp) function interp_offset(model, gamma) result(omega)
    type(model_type), intent(in) :: model
    real(wp), intent(in) :: gamma
    real(wp) :: x, xs(4), ys(4), l
    integer :: j0, a, b
    associate(t => model%table)
      x = model%analysis%grid_per_decade*log10(gamma/t%gamma_ref)
      if (t%j_hi - t%j_lo < 3) then
        j0 = min(max(nint(x), t%j_lo), t%j_hi)
        omega = offset(t%node(j0))
        return
      end if
      j0 = min(max(floor(x) - 1, t%j_lo), t%j_hi - 3)
      xs = [(real(j0 + a, wp), a = 0, 3)]
      ys = offset(t%node(j0:j0 + 3))
    end associate
    omega = 0
    do a = 1, 4
      l = 1
      do b = 1, 4
        if (b /= a) l = l*(x - xs(b))/(xs(a) - xs(b))
      end do
      omega = omega + l*ys(a)
    end do
  end function interp_offset

  !> d ln F_bb / d ln gamma at a layer peak (envelope theorem, see the module doc), with
  !> dk/d ln gamma = gamma dk/dgamma from the damper.
  real(wp) function backbone_slope(model, e) result(slope)
    type(model_type), intent(in) :: model
    type(backbone_eval_type), intent(in) :: e
    complex(wp) :: dk
    dk = e%gamma*model%damper%stiffness_derivative(e%gamma)
    slope = 1 + real(e%peak%r%gg*dk/(1 + e%k*e%peak%r%gg), wp)
  end function backbone_slope

  !> Error for a layer whose peak is not inside the band.
  subroutine band_error(model, gamma, peak, error)
    type(model_type), intent(in) :: model
    real(wp), intent(in) :: gamma
    type(layer_peak_type), intent(in) :: peak
    type(error_type), allocatable, intent(out) :: error
    character(len=32) :: bg, bl, bh
    character(len=:), allocatable :: where
    write(bg, '(es11.4)') gamma
    write(bl, '(g0.6)') model%analysis%f_min
    write(bh, '(g0.6)') model%analysis%f_max
    if (peak%status == PEAK_BELOW_BAND) then
      where = "f_min; the resonance lies below the band"
    else
      where = "f_max; the resonance lies above the band"
    end if
    call fatal_error(error, "no resonance in the band ["//trim(bl)//", "//trim(bh)// &
      & "] Hz: at gamma_P = "//trim(adjustl(bg))//" rad the layer response still grows at "// &
      & where, UDMAP_EPHYSICS)
  end subroutine band_error

  !> Builds the backbone table for the damper's current revision (nodes from the stuck
  !> range up to the rising range above gamma_b), unless it is up to date.
  subroutine ensure_table(model, error)
    type(model_type), intent(inout) :: model
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: gamma_lin
    integer :: gpd, j_lo
    if (model%table%revision == model%damper%revision .and. model%table%j_hi >= model%table%j_lo &
      & .and. all(model%table%fingerprint == damper_fingerprint(model%damper)) .and. &
      & model%table%eigen_method == model%analysis%eigen_method) return
    gpd = model%analysis%grid_per_decade
    model%table%gamma_ref = model%damper%gamma_b
    if (model%damper%gamma_s > 0 .and. model%damper%gamma_s <= model%damper%gamma_b) then
      gamma_lin = model%damper%gamma_s
    else
      ! no stuck amplitude given: assume k constant six decades below gamma_b
      gamma_lin = 1.0e-6_wp*model%damper%gamma_b
    end if
    j_lo = floor(gpd*log10(gamma_lin/model%table%gamma_ref))
    if (grid_gamma(model, j_lo) > gamma_lin) j_lo = j_lo - 1
    if (grid_gamma(model, j_lo + 1) <= gamma_lin) j_lo = j_lo + 1
    model%table%j_lo = j_lo
    model%table%j_hi = j_lo - 1
    model%table%n_side = 0
    model%table%revision = model%damper%revision
    model%table%fingerprint = damper_fingerprint(model%damper)
    model%table%eigen_method = model%analysis%eigen_method
    if (j_limit(model) <= j_lo) then
      call fatal_error(error, "backbone: the damper's stiffness is defined only up to its stuck "// &
        & "amplitude (a measured table without slip rows and delta_M)", UDMAP_EINPUT)
      model%table%revision = -huge(1)
      return
    end if
    call grow_table(model, min(j_rising(model), j_limit(model)), error)
    if (allocated(error)) model%table%revision = -huge(1)
  end subroutine ensure_table

  !> Computes the table nodes j_hi+1 .. j_new.
  subroutine grow_table(model, j_new, error)
    type(model_type), intent(inout) :: model
    integer, intent(in) :: j_new
    type(error_type), allocatable, intent(out) :: error
    type(error_type), allocatable :: direct_error
    type(backbone_eval_type), allocatable :: grown(:)
    complex(wp) :: lambda_direct
    integer :: j, j_old, lo
    lo = model%table%j_lo
    j_old = model%table%j_hi
    if (j_new <= j_old) return
    allocate(grown(lo:j_new))
    if (j_old >= lo) grown(lo:j_old) = model%table%node(lo:j_old)
    call move_alloc(grown, model%table%node)
    associate(node => model%table%node)
      do j = j_old + 1, j_new
        if (j == lo) then
          ! the first node is where stuck roots are read off: full tolerance
          if (model%analysis%eigen_method == EIGEN_AUTO .and. .not.model%have_direct) then
            ! once per model: the direct eigen-solve, the secular equation continues from it
            model%have_direct = .true.
            call direct_eigen_start(model%blade, model%damper%stiffness(grid_gamma(model, j)), &
              & model%analysis%dense_max, lambda_direct, direct_error)
            if (.not.allocated(direct_error)) then
              model%lambda_direct = lambda_direct
              call layer_backbone(model, grid_gamma(model, j), peak_rtol(model), node(j), &
                & error, lambda_start=lambda_direct)
            else
              call layer_backbone(model, grid_gamma(model, j), peak_rtol(model), node(j), error)
            end if
          else
            call layer_backbone(model, grid_gamma(model, j), peak_rtol(model), node(j), error)
          end if
        else if (j >= lo + 3) then
          ! start at the peak offset from the eigenvalue extrapolated along the grid
          call layer_backbone(model, grid_gamma(model, j), max(table_rtol, model%analysis%rtol), &
            & node(j), error, start=node(j - 1), predict=.true., &
            & offset_guess=3*offset(node(j - 1)) - 3*offset(node(j - 2)) + offset(node(j - 3)))
        else
          call layer_backbone(model, grid_gamma(model, j), max(table_rtol, model%analysis%rtol), &
            & node(j), error, start=node(j - 1), predict=.true.)
        end if
        if (allocated(error)) return
        model%table%j_hi = j
      end do
    end associate
  end subroutine grow_table

  !> The last grid node the damper's stiffness is defined at: 1e12 gamma_b, or the damper's
  !> gamma_max (a measured table without delta_M ends at its last row).
  integer function j_limit(model)
    type(model_type), intent(in) :: model
    integer :: gpd
    gpd = model%analysis%grid_per_decade
    j_limit = max_decades*gpd
    if (model%damper%gamma_max < huge(1.0_wp)) then
      j_limit = min(j_limit, floor(gpd*log10(model%damper%gamma_max/model%table%gamma_ref)) + 1)
      do while (grid_gamma(model, j_limit) > model%damper%gamma_max*(1 + 1e-12_wp))
        j_limit = j_limit - 1
      end do
    end if
  end function j_limit

  !> First grid node of the range where F_bb rises monotonically: a quarter decade above
  !> gamma_b. Above gamma_b the loop is the base cycle with lengthened plateaus,
  !> E = E_b + 2 Delta_M (gamma - gamma_b) with E_b <= 2 Delta_M gamma_b (the base cycle fits
  !> in its 2 gamma_b x Delta_M box), so gamma k_Im = E/(pi gamma) rises with gamma; for the
  !> resonant mode F_bb ~ gamma (omega_1^2 omega beta + phi_g^2 k_Im)/|phi_g phi_E| rises too.
  pure integer function j_rising(model)
    type(model_type), intent(in) :: model
    j_rising = (model%analysis%grid_per_decade + 3)/4
  end function j_rising

  !> Grows the table until it reaches gamma_top and, if F_max > 0, until F_bb exceeds F_max
  !> at a node of the rising range above gamma_b (j_rising) where it rises: no root lies above.
  !> A damper whose k(gamma) ends at gamma_max (measured table without delta_M) caps the grid
  !> there: the grid then runs to the last node, where F_bb must exceed F_max, and roots are
  !> sought below it only.
  subroutine cover_table(model, F_max, gamma_top, error, reached)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_max, gamma_top
    type(error_type), allocatable, intent(out) :: error
    !> When present, F_max not reached below 1e12 gamma_b is reported here (.false.) instead
    !> of as an error (the table then ends at the cap).
    logical, intent(out), optional :: reached
    integer :: gpd, j_cap, j_need
    logical :: capped
    character(len=32) :: buf
    gpd = model%analysis%grid_per_decade
    j_cap = j_limit(model)
    capped = j_cap < max_decades*gpd
    if (gamma_top > 0) then
      j_need = ceiling(gpd*log10(gamma_top/model%table%gamma_ref)) + 1
      if (capped .and. gamma_top <= model%damper%gamma_max) j_need = min(j_need, j_cap)
      if (j_need > j_cap) then
        write(buf, '(es11.4)') gamma_top
        if (capped) then
          call fatal_error(error, "backbone: gamma = "//trim(adjustl(buf))//" rad is beyond "// &
            & "the damper's stiffness range (a measured table without delta_M ends at its "// &
            & "last row)", UDMAP_EINPUT)
        else
          call fatal_error(error, "backbone: gamma = "//trim(adjustl(buf))//" rad is more "// &
            & "than 1e12 gamma_b, out of the model's reach", UDMAP_EINPUT)
        end if
        return
      end if
      call grow_table(model, j_need, error)
      if (allocated(error)) return
    end if
    if (present(reached)) reached = .true.
    if (F_max <= 0) return
    associate(t => model%table)
      do while (.not.(t%node(t%j_hi)%F_bb > F_max .and. ((capped .and. t%j_hi == j_cap) .or. &
          & (.not.capped .and. t%j_hi >= j_rising(model) .and. &
          & t%node(t%j_hi)%F_bb >= t%node(t%j_hi - 1)%F_bb))))
        if (t%j_hi >= j_cap) then
          write(buf, '(es11.4)') F_max
          if (capped) then
            call fatal_error(error, "backbone: the response to F_E = "//trim(adjustl(buf))// &
              & " N goes beyond the damper's stiffness range (a measured table without "// &
              & "delta_M ends at its last row)", UDMAP_EINPUT)
          else if (present(reached)) then
            reached = .false.
          else
            call fatal_error(error, "backbone: F_E = "//trim(adjustl(buf))//" N is not "// &
              & "reached below 1e12 gamma_b", UDMAP_EPHYSICS)
          end if
          return
        end if
        call grow_table(model, min(t%j_hi + j_rising(model), j_cap), error)
        if (allocated(error)) return
      end do
    end associate
  end subroutine cover_table

  !> F_bb at gamma [rad] with its layer peak to peak_rtol: linear below the grid, else a peak
  !> search warm-started from `start` or the nearest node (the table must cover gamma).
  subroutine eval_backbone(model, gamma, e, error, start, loose)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: gamma
    type(backbone_eval_type), intent(out) :: e
    type(error_type), allocatable, intent(out) :: error
    type(backbone_eval_type), intent(in), optional :: start
    !> Only F_bb is needed (see layer_backbone).
    logical, intent(in), optional :: loose
    integer :: j
    associate(t => model%table)
      if (gamma <= t%node(t%j_lo)%gamma) then
        e = t%node(t%j_lo)
        e%gamma = gamma
        e%F_bb = gamma*t%node(t%j_lo)%F_bb/t%node(t%j_lo)%gamma
        e%slope = 1
        return
      end if
      ! the eigenvalue tracked from the given start (the previous iterate) or the nearest node,
      ! the peak offset interpolated along the grid
      if (present(start)) then
        call layer_backbone(model, gamma, peak_rtol(model), e, error, start=start, loose=loose, &
          & offset_guess=interp_offset(model, gamma))
      else
        j = nint(model%analysis%grid_per_decade*log10(gamma/t%gamma_ref))
        j = min(max(j, t%j_lo), t%j_hi)
        call layer_backbone(model, gamma, peak_rtol(model), e, error, start=t%node(j), &
          & loose=loose, offset_guess=interp_offset(model, gamma))
      end if
    end associate
  end subroutine eval_backbone

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
