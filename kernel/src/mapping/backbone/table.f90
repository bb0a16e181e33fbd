!> The table of the backbone F_bb(gamma) (PHYSICS.md 4; the method is described in
!> mapping/backbone.f90): the grid gamma_j = gamma_b 10^(j/grid_per_decade), one layer peak per
!> node started from the tracked eigenvalue, grown and covered as far as the requested forces
!> need, and F_bb with its slope between the nodes (inverse cubic Hermite interpolation, the
!> envelope theorem for the slope).
module udmap_mapping_backbone_table
  use udmap_core_kinds, only: wp
  use udmap_core_strings, only: rtoa
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, &
    & UDMAP_ENUMERIC
  use udmap_mapping_caches, only: layer_peak_type, PEAK_OK, PEAK_BELOW_BAND
  use udmap_mapping_layer, only: layer_peak
  use udmap_mapping_eigen_start, only: secular_root, direct_eigen_start
  use udmap_mapping_model_data, only: model_type, backbone_eval_type, damper_fingerprint, &
    & EIGEN_AUTO, EIGEN_DIRECT
  implicit none
  private
  public :: ensure_table, cover_table, eval_backbone, grid_gamma, max_decades, j_limit, j_rising, &
    & peak_rtol, layer_backbone, interp_offset

  !> How far above gamma_b the grid may grow (decades) before a root is declared out of reach.
  integer, parameter :: max_decades = 12
  !> Peak tolerance of the grid nodes (which only bracket roots and start searches).
  real(wp), parameter :: table_rtol = 1.0e-7_wp
  !> The end of the message where the grid would leave a measured table's stiffness range.
  character(len=*), parameter :: beyond_range = "beyond the damper's stiffness range (a "// &
    & "measured table without delta_M ends at its last row)"

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
    character(len=:), allocatable :: where
    if (peak%status == PEAK_BELOW_BAND) then
      where = "f_min; the resonance lies below the band"
    else
      where = "f_max; the resonance lies above the band"
    end if
    call fatal_error(error, "no resonance in the band ["//rtoa(model%analysis%f_min, "(g0.6)")// &
      & ", "//rtoa(model%analysis%f_max, "(g0.6)")//"] Hz: at gamma_P = "// &
      & rtoa(gamma, "(es11.4)")//" rad the layer response still grows at "// &
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
    gpd = model%analysis%grid_per_decade
    j_cap = j_limit(model)
    capped = j_cap < max_decades*gpd
    if (gamma_top > 0) then
      j_need = ceiling(gpd*log10(gamma_top/model%table%gamma_ref)) + 1
      if (capped .and. gamma_top <= model%damper%gamma_max) j_need = min(j_need, j_cap)
      if (j_need > j_cap) then
        if (capped) then
          call fatal_error(error, "backbone: gamma = "//rtoa(gamma_top, "(es11.4)")//" rad is "// &
            & beyond_range, UDMAP_EINPUT)
        else
          call fatal_error(error, "backbone: gamma = "//rtoa(gamma_top, "(es11.4)")// &
            & " rad is more than 1e12 gamma_b, out of the model's reach", UDMAP_EINPUT)
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
          if (capped) then
            call fatal_error(error, "backbone: the response to F_E = "// &
              & rtoa(F_max, "(es11.4)")//" N goes "//beyond_range, UDMAP_EINPUT)
          else if (present(reached)) then
            reached = .false.
          else
            call fatal_error(error, "backbone: F_E = "//rtoa(F_max, "(es11.4)")//" N is not "// &
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
end module udmap_mapping_backbone_table
