!> Resonance peaks and the limit force of a traveling wave (PHYSICS.md 2.6, sections 4 and 5
!> at the interblade phase phi).
!>
!> F_bb(gamma) is the minimum over omega of the force of the layer gamma
!> (udmap_mapping_traveling_layer); a requested F_E is the root of F_bb(gamma) = F_E. It is
!> solved first as one point (udmap_mapping_traveling_point: wave_point), and where that does
!> not converge by bracketing outward from the in-phase answer and Brent's method on ln gamma.
!> A force inside a jump of F_bb (a contact that starts to lift off) takes the set-valued
!> point of PHYSICS.md 2.5 (wave_jump_point), flagged jump. The outputs
!> follow from the solved layer at its peak: gamma_P (first harmonic), f_res, sigma_a and u_E
!> (first-harmonic amplitudes), k = A_gamma,1/gamma_P, the largest excursions at H > 1.
!>
!> F_lim(phi): the supremum of F_bb with zeta = 0 is the energy balance of the bare first
!> mode at large amplitude: the work that friction takes from blade 0 per cycle grows as
!> W(a) ~ W' a, the work of the force F along the mode as pi F a |psi_E/psi_g|, so
!> F_lim = W'/(pi |psi_E/psi_g|) (at phi = 0: 2 Delta_M/(pi |phi_E/phi_g|), section 5).
module udmap_mapping_traveling_backbone
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS, &
    & UDMAP_ENUMERIC
  use udmap_core_strings, only: ftoa
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update
  use udmap_blade_platform, only: platform_rows
  use udmap_damper_type, only: DAMPER_ASYMMETRIC
  use udmap_contact_element_wave, only: wave_aft, wave_settings_type
  use udmap_mapping_model_data, only: model_type, point_type, REGIME_STUCK, &
    & REGIME_PARTIAL_SLIP, REGIME_FULL_SLIP, REGIME_LIMIT, check_response_frequency
  use udmap_mapping_backbone, only: inphase_backbone => backbone
  use udmap_mapping_harmonic_layer, only: largest_excursion
  use udmap_mapping_harmonic_table_points, only: table_usable, table_backbone_point, &
    & cover_table, reset_table
  use udmap_mapping_traveling_layer, only: traveling_type, wave_layer_type, new_traveling, &
    & wave_peak, wave_layer_solve, wave_layer_slope
  use udmap_mapping_traveling_point, only: wave_point, wave_jump_point
  implicit none
  private
  public :: wave_backbone, wave_response, wave_limit_force, interblade_phase, new_model_traveling, &
    & wave_backbone_curve, wave_cover_forces

  !> Relative tolerance of the backbone roots in gamma (the layers are solved to ~1e-11).
  real(wp), parameter :: root_rtol = 1.0e-10_wp
  !> A bracket that closes with ln F_bb off the force by more than this holds a jump of F_bb.
  real(wp), parameter :: jump_misfit = 1.0e-6_wp

contains

  !> The interblade phase angle of the model's analysis [rad], in (-pi, pi].
  pure real(wp) function interblade_phase(model) result(phi)
    type(model_type), intent(in) :: model
    phi = modulo(model%analysis%ibpa_deg + 180.0_wp, 360.0_wp) - 180.0_wp
    if (phi == -180.0_wp) phi = 180.0_wp
    phi = phi*pi/180
  end function interblade_phase

  !> The traveling-wave coupling of the model's blade and (asymmetric) damper.
  subroutine new_model_traveling(model, tw, error, H)
    type(model_type), intent(in) :: model
    type(traveling_type), intent(out) :: tw
    type(error_type), allocatable, intent(out) :: error
    !> Harmonics (default: the analysis', 1 for auto).
    integer, intent(in), optional :: H
    integer :: nh
    if (model%damper%kind /= DAMPER_ASYMMETRIC) then
      call fatal_error(error, "traveling wave: only the asymmetric damper depends on phi", &
        & UDMAP_EINPUT)
      return
    end if
    nh = max(model%analysis%harmonics, 1)
    if (present(H)) nh = H
    call new_traveling(tw, model%blade, model%damper%geometry, model%damper%params%CF, &
      & interblade_phase(model), nh, model%omega_lo, model%omega_hi, error)
  end subroutine new_model_traveling

  !> F_lim(phi) [N] (see the module's header).
  subroutine wave_limit_force(model, F_lim, error)
    type(model_type), intent(in) :: model
    real(wp), intent(out) :: F_lim
    type(error_type), allocatable, intent(out) :: error
    type(traveling_type) :: tw
    real(wp), allocatable :: B(:, :)
    real(wp) :: psi(3), psi_E, a_c, W(2), amp(2), A0(3)
    complex(wp) :: P(3, 1), A(3, 1)
    type(wave_settings_type) :: settings
    integer :: k
    F_lim = 0
    call new_model_traveling(model, tw, error)
    if (allocated(error)) return
    allocate(B(model%blade%ndof, 3))
    call platform_rows(model%blade, B)
    psi = matmul(model%blade%phi(:, 1), B)
    psi_E = model%blade%phi(model%blade%exc_dof, 1)
    psi = psi/psi(3)
    psi_E = psi_E/model%blade%phi(model%blade%gamma_dof, 1)
    ! far beyond the rotation that CF deflects the contacts by: the plateaus dominate
    a_c = max(tw%CF, 1e-300_wp)/tw%geo%rate_scale
    amp = [1e4_wp, 2e4_wp]*a_c
    settings%samples = tw%settings%samples
    do k = 1, 2
      P(:, 1) = cmplx(amp(k)*psi, 0.0_wp, wp)
      call wave_aft(tw%geo, tw%CF, tw%phi, [0.0_wp, 0.0_wp, 0.0_wp], P, settings, A0, A, error)
      if (allocated(error)) return
      W(k) = pi*sum(aimag(A(:, 1)*conjg(P(:, 1))))
    end do
    if (.not. ((W(2) - W(1)) > 0)) then
      call fatal_error(error, "traveling wave: the damper dissipates no energy at large "// &
        & "amplitude (no limit force)", UDMAP_EPHYSICS)
      return
    end if
    F_lim = (W(2) - W(1))/(amp(2) - amp(1))/(pi*abs(psi_E))
  end subroutine wave_limit_force

  !> The peaks of the traveling wave for the forces F_E [N]: from the force table where it is
  !> on (model%force_table, the FMU's F_E-only steps; udmap_mapping_harmonic_table_points, at
  !> every H, H = 1 included: a traveling point costs a root of layer solves), interpolated
  !> where a verified panel holds F_E; else, and for every force where none does, exact.
  subroutine wave_backbone(model, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(point_type), allocatable :: p(:)
    real(wp) :: F_lim
    logical :: found
    integer :: i
    if (.not. table_usable(model)) then
      call wave_backbone_exact(model, F_E, points, error)
      return
    end if
    ! F_lim(phi) is kept with the table (a trace of its own: most of a step from the table)
    call reset_table(model)
    if (model%ftable%F_lim < 0) then
      call wave_limit_force(model, F_lim, error)
      if (allocated(error)) return
      model%ftable%F_lim = F_lim
    end if
    F_lim = model%ftable%F_lim
    allocate(points(size(F_E)))
    do i = 1, size(F_E)
      found = .false.
      if (F_E(i) > 0 .and. .not.(model%undamped .and. F_E(i) >= F_lim)) &
        & call table_backbone_point(model, F_E(i), wave_exact, .true., F_lim, points(i), found)
      if (found) cycle
      call wave_backbone_exact(model, F_E(i:i), p, error)
      if (allocated(error)) return
      points(i) = p(1)
    end do
  end subroutine wave_backbone

  !> The exact traveling-wave backbone point at F [N] (the force table's solver at phi).
  subroutine wave_exact(model, F, q, ok)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F
    type(point_type), intent(out) :: q
    logical, intent(out) :: ok
    type(point_type), allocatable :: p(:)
    type(error_type), allocatable :: err
    call wave_backbone_exact(model, [F], p, err)
    ok = .not.allocated(err)
    if (ok) ok = .not.p(1)%unbounded
    if (ok) q = p(1)
  end subroutine wave_exact

  !> Covers the forces [F_min, F_max] in advance (the FMU's F_E_min..F_E_max), as
  !> udmap_mapping_harmonic_mapping's cover_forces does in phase: every force of the range gets
  !> its leaf of the force table, at every H (H = 1 included). Unbounded forces are left out.
  subroutine wave_cover_forces(model, F_min, F_max, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_min, F_max
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: F_lim, F_hi
    if (.not.(F_min > 0 .and. F_min <= F_max .and. F_max < huge(1.0_wp))) then
      call fatal_error(error, "cover_forces: the range must satisfy 0 < F_min <= F_max < inf", &
        & UDMAP_EINPUT)
      return
    end if
    if (.not. table_usable(model)) return
    call wave_limit_force(model, F_lim, error)
    if (allocated(error)) return
    F_hi = F_max
    if (model%undamped) F_hi = min(F_hi, F_lim)
    if (.not.(F_hi >= F_min)) return
    call cover_table(model, F_min, F_hi, wave_exact, .true.)
  end subroutine wave_cover_forces

  !> The exact peaks of the traveling wave for the forces F_E [N]. analysis%harmonics = 0
  !> (auto): H = 1, 3, 5, ... until gamma_P, sigma_a and f_res change by less than harmonic_tol.
  subroutine wave_backbone_exact(model, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(traveling_type) :: tw
    !> The layer of the search; the latest solved below and above the force (nested search).
    type(wave_layer_type) :: L, below, above
    type(point_type), allocatable :: guess(:)
    real(wp) :: F_lim, omega_g, F_cur, w, change, ratio, shift
    integer :: i, H_saved, ih, nH
    integer, parameter :: auto_H(7) = [1, 3, 5, 9, 17, 33, 64]
    !> The last two points (predict, remember): ln F_E, ln ratio, ln shift, L's harmonics
    !> to gamma.
    integer :: n_hist
    !> A force of this rung kept from the rung below (its own did not solve).
    logical :: skipped
    real(wp) :: h_lnF(2), h_lnr(2), h_lns(2), h_P0(3, 2)
    complex(wp), allocatable :: h_P(:, :, :)

    call wave_limit_force(model, F_lim, error)
    if (allocated(error)) return
    ! the in-phase single-harmonic peaks start the search (that method reads neither the
    ! harmonics nor the phase)
    call inphase_backbone(model, F_E, guess, error)
    if (allocated(error)) return
    H_saved = model%analysis%harmonics
    nH = merge(size(auto_H), 1, H_saved == 0)
    do ih = 1, nH
      call new_model_traveling(model, tw, error, merge(auto_H(ih), H_saved, H_saved == 0))
      if (allocated(error)) return
      L = wave_layer_type()
      ratio = 1
      shift = 1
      n_hist = 0
      skipped = .false.
      if (allocated(points)) call move_alloc(points, guess)
      allocate(points(size(F_E)))
      omega_g = 0
      do i = 1, size(F_E)
        points(i)%F_E = F_E(i)
        points(i)%harmonics = tw%H
        if (model%undamped .and. F_E(i) >= F_lim) then
          points(i)%regime = REGIME_LIMIT
          points(i)%unbounded = .true.
          allocate(points(i)%roots(0))
          cycle
        end if
        ! the start: the guess corrected as the previous force's was (the phase moves the
        ! peaks of neighbouring forces alike), at the previous force's frequency shift; after
        ! two points, the corrections and the platform's harmonics (to gamma) extrapolated in
        ! ln F_E from them
        call predict(F_E(i))
        if (guess(i)%f_res > 0) omega_g = 2*pi*guess(i)%f_res*shift
        call peak_of_force(F_E(i), max(guess(i)%gamma_P*ratio, tiny(1.0_wp)), omega_g, &
          & points(i), error)
        if (allocated(error) .and. ih > 1 .and. ih < nH) then
          ! a rung on the way up (auto) that does not solve at this force (e.g. two peaks
          ! folding into each other at that H): the force goes on from the rung below, and the
          ! harmonics are raised again whatever the others' change
          deallocate(error)
          points(i) = guess(i)
          skipped = .true.
          n_hist = 0
          cycle
        end if
        if (allocated(error)) return
        omega_g = 2*pi*points(i)%f_res
        if (guess(i)%gamma_P > 0 .and. guess(i)%f_res > 0) then
          ratio = points(i)%gamma_P/guess(i)%gamma_P
          shift = points(i)%f_res/guess(i)%f_res
        end if
        call remember(F_E(i), points(i))
      end do
      if (ih == 1 .or. skipped) cycle
      change = 0
      do i = 1, size(F_E)
        if (points(i)%unbounded) cycle
        change = max(change, abs(points(i)%gamma_P/guess(i)%gamma_P - 1), &
          & abs(points(i)%f_res/guess(i)%f_res - 1))
        if (guess(i)%sigma_a > 0) change = max(change, abs(points(i)%sigma_a/guess(i)%sigma_a - 1))
      end do
      if (change < model%analysis%harmonic_tol) exit
    end do

  contains

    !> The start of the force F from the last two points (hist), where their forces bracket
    !> no more than F's distance twice over: ratio, shift and the shape of L's harmonics.
    subroutine predict(F)
      real(wp), intent(in) :: F
      real(wp) :: t
      if (n_hist < 2 .or. .not. allocated(L%P)) return
      if (.not. (L%gamma > 0)) return
      t = (log(F) - h_lnF(2))/(h_lnF(2) - h_lnF(1))
      if (.not. (t > 0 .and. t <= 2)) return
      ratio = exp(h_lnr(2) + t*(h_lnr(2) - h_lnr(1)))
      shift = exp(h_lns(2) + t*(h_lns(2) - h_lns(1)))
      L%P = (h_P(:, :, 2) + t*(h_P(:, :, 2) - h_P(:, :, 1)))*L%gamma
      L%P0 = (h_P0(:, 2) + t*(h_P0(:, 2) - h_P0(:, 1)))*L%gamma
    end subroutine predict

    !> Keeps the point pt of the force F for predict (a jump, a failure or an unbounded
    !> point starts the history again).
    subroutine remember(F, pt)
      real(wp), intent(in) :: F
      type(point_type), intent(in) :: pt
      if (pt%jump .or. pt%unbounded .or. .not. allocated(L%P) .or. .not. (L%gamma > 0) .or. &
        & .not. (guess(i)%gamma_P > 0 .and. guess(i)%f_res > 0)) then
        n_hist = 0
        return
      end if
      if (allocated(h_P)) then
        if (size(h_P, 2) /= tw%H) deallocate(h_P)
      end if
      if (.not. allocated(h_P)) allocate(h_P(3, tw%H, 2))
      if (n_hist == 2) then
        h_lnF(1) = h_lnF(2)
        h_lnr(1) = h_lnr(2)
        h_lns(1) = h_lns(2)
        h_P(:, :, 1) = h_P(:, :, 2)
        h_P0(:, 1) = h_P0(:, 2)
      end if
      n_hist = min(n_hist + 1, 2)
      h_lnF(n_hist) = log(F)
      h_lnr(n_hist) = log(ratio)
      h_lns(n_hist) = log(shift)
      h_P(:, :, n_hist) = L%P/L%gamma
      h_P0(:, n_hist) = L%P0/L%gamma
    end subroutine remember

    !> Root gamma of F_bb(gamma) = F and the outputs there.
    subroutine peak_of_force(F, gamma0, omega0, pt, err)
      real(wp), intent(in) :: F, gamma0, omega0
      type(point_type), intent(inout) :: pt
      type(error_type), allocatable, intent(out) :: err
      type(brent_type) :: bs
      real(wp) :: lo, hi, glo, ghi, g, x, slope, step
      logical :: more, ok
      integer :: k
      ! the whole point at once; the nested search below where that does not converge
      call wave_point(tw, F, gamma0, omega0, L, ok)
      if (ok) then
        call fill_point(tw, L, L%gamma, F, F_lim, model%analysis%sigma_all, pt)
        return
      end if
      L = wave_layer_type()
      below = wave_layer_type()
      above = wave_layer_type()
      w = omega0
      F_cur = F
      lo = log(gamma0)
      glo = excess(lo, err)
      ! a start next to a jump (the previous force's gamma_c) may have no layer: a little
      ! below or above it has
      do k = 1, 4
        if (.not. allocated(err)) exit
        deallocate(err)
        lo = log(gamma0) + merge(-1, 1, mod(k, 2) == 1)*1e-5_wp*4**((k - 1)/2)
        L = wave_layer_type()
        glo = excess(lo, err)
      end do
      if (allocated(err)) return
      ! Newton in (ln gamma, ln F_bb) with the layer's own slope (one trace more per step);
      ! a step that does not reduce the misfit hands over to the bracketing below
      x = lo
      g = glo
      do k = 1, 12
        call wave_layer_slope(tw, L, slope, err)
        if (allocated(err)) return
        if (.not. (slope > 0.02_wp)) exit
        step = -g/slope
        step = sign(min(abs(step), log(4.0_wp)), step)
        if (abs(step) <= root_rtol) then
          call fill_point(tw, L, exp(x), F, F_lim, model%analysis%sigma_all, pt)
          return
        end if
        lo = x
        glo = g
        x = x + step
        g = excess(x, err)
        if (allocated(err)) then
          ! a layer without a solution: next to a jump of F_bb
          call jump_point(x, pt, err)
          return
        end if
        if (abs(g) >= abs(glo)) exit
      end do
      ! the bracket starts from the last two points of Newton (or the first alone)
      if (g*glo <= 0 .and. x /= lo) then
        hi = x
        ghi = g
      else
        lo = x
        glo = g
        hi = lo
        ghi = glo
      end if
      ! secant steps in (ln gamma, ln F_bb) (slope 1 to start: F_bb grows like gamma in stick
      ! and towards the limit), capped at a factor 4, until the root is bracketed
      slope = 1
      do k = 1, 80
        if (glo*ghi <= 0 .and. lo /= hi) exit
        step = -ghi/max(slope, 0.05_wp)
        step = sign(min(abs(step), log(4.0_wp)), step)
        if (abs(step) < 1e-6_wp) step = sign(1e-6_wp, step)
        x = hi + step
        g = excess(x, err)
        if (allocated(err)) then
          call jump_point(x, pt, err)
          return
        end if
        if (x /= hi .and. g /= ghi) slope = (g - ghi)/(x - hi)
        lo = hi
        glo = ghi
        hi = x
        ghi = g
      end do
      if (lo > hi) then
        x = lo
        lo = hi
        hi = x
        g = glo
        glo = ghi
        ghi = g
      end if
      if (glo*ghi > 0) then
        call fatal_error(err, "traveling wave: no peak found for F_E = "//ftoa(F)//" N at phi = "// &
          & ftoa(tw%phi)//" rad", UDMAP_EPHYSICS)
        return
      end if
      call brent_start(bs, lo, glo, hi, ghi, root_rtol)
      do
        call brent_next(bs, x, more)
        if (.not. more) exit
        g = excess(x, err)
        if (allocated(err)) then
          call jump_point(x, pt, err)
          return
        end if
        call brent_update(bs, g)
      end do
      g = excess(x, err)
      if (allocated(err)) return
      if (abs(g) > jump_misfit) then
        ! the bracket closed without a root: F_bb jumps across F there (PHYSICS.md 2.5)
        call jump_point(x, pt, err)
        return
      end if
      call fill_point(tw, L, exp(x), F, F_lim, model%analysis%sigma_all, pt)
    end subroutine peak_of_force

    !> The set-valued point of a jump of F_bb at about e^xg (udmap_mapping_traveling_point's
    !> wave_jump_point); else the error err (kept, or a new one).
    subroutine jump_point(xg, pt, err)
      real(wp), intent(in) :: xg
      type(point_type), intent(inout) :: pt
      type(error_type), allocatable, intent(inout) :: err
      logical :: ok
      ok = below%solved .and. above%solved
      if (ok) call wave_jump_point(tw, F_cur, exp(xg), below, above, L, ok)
      if (.not. ok) then
        if (.not. allocated(err)) call fatal_error(err, "traveling wave: F_bb jumps across "// &
          & "F_E = "//ftoa(F_cur)//" N at gamma = "//ftoa(exp(xg))//" rad, phi = "// &
          & ftoa(tw%phi)//" rad, and no one-sided layer was found next to it", UDMAP_ENUMERIC)
        return
      end if
      if (allocated(err)) deallocate(err)
      call fill_point(tw, L, L%gamma, F_cur, F_lim, model%analysis%sigma_all, pt)
      pt%jump = .true.
    end subroutine jump_point

    !> ln F_bb(e^x) - ln F_cur at the layer e^x (leaves L at its peak, w at its frequency).
    real(wp) function excess(xg, err)
      real(wp), intent(in) :: xg
      type(error_type), allocatable, intent(out) :: err
      real(wp) :: Fbb
      excess = 0
      call wave_peak(tw, exp(xg), w, L, Fbb, err)
      if (allocated(err)) return
      w = L%omega
      excess = log(Fbb) - log(F_cur)
      ! the latest layers on either side of the force (the sides of a jump, if one is met)
      if (excess < 0) then
        below = L
      else
        above = L
      end if
    end function excess

  end subroutine wave_backbone_exact

  !> The outputs of the solved layer L (amplitude gamma) scaled to the force F [N].
  subroutine fill_point(tw, L, gamma, F, F_lim, sigma_all, pt)
    type(traveling_type), intent(in) :: tw
    type(wave_layer_type), intent(in) :: L
    real(wp), intent(in) :: gamma, F, F_lim, sigma_all
    type(point_type), intent(inout) :: pt
    complex(wp), allocatable :: Z(:)
    real(wp) :: s
    integer :: h
    s = F/abs(L%F)
    pt%gamma_P = gamma
    pt%f_res = L%omega/(2*pi)
    pt%sigma_a = s*abs(L%sigma(1))
    pt%u_E = s*abs(L%uE(1))
    pt%k = L%A(3, 1)/gamma
    pt%roots = [gamma]
    if (.not. L%trace%slipped) then
      pt%regime = REGIME_STUCK
    else if (all(L%trace%contact_slipped)) then
      pt%regime = REGIME_FULL_SLIP
    else
      pt%regime = REGIME_PARTIAL_SLIP
    end if
    if (F >= F_lim) pt%regime = REGIME_LIMIT
    pt%gamma_max = gamma
    pt%sigma_max = pt%sigma_a
    if (tw%H > 1) then
      Z = L%P(3, :)
      pt%gamma_max = largest_excursion(Z)
      Z = L%sigma*s
      pt%sigma_max = largest_excursion(Z)
      allocate(pt%gamma_h(0:tw%H), pt%sigma_h(0:tw%H))
      pt%gamma_h(0) = abs(L%P0(3))
      pt%sigma_h(0) = 0
      do h = 1, tw%H
        pt%gamma_h(h) = abs(L%P(3, h))
        pt%sigma_h(h) = s*abs(L%sigma(h))
      end do
    end if
    ! as in phase: with H > 1 the criterion takes the largest excursion sigma_max
    pt%hcf_ok = F <= 0.5_wp*F_lim .and. pt%sigma_max <= sigma_all .and. F_lim < huge(1.0_wp)
  end subroutine fill_point

  !> The response of the traveling wave at the excitation frequency f_exc [Hz] for the forces
  !> F_E [N]: the layers gamma whose force at omega is F_E (|F(gamma, omega)| = F_E), found on
  !> a grid in ln gamma from the stuck range upwards and refined by Brent's method; every root
  !> is kept (ascending), the largest is the point.
  subroutine wave_response(model, f_exc, F_E, points, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: f_exc
    real(wp), intent(in) :: F_E(:)
    type(point_type), allocatable, intent(out) :: points(:)
    type(error_type), allocatable, intent(out) :: error
    type(traveling_type) :: tw
    type(wave_layer_type) :: L
    type(brent_type) :: bs
    real(wp) :: F_lim, omega, x, x0, dx, g, gprev, xprev, lo, hi, glo, ghi
    real(wp), allocatable :: roots(:)
    logical :: more
    integer :: i, k
    omega = 2*pi*f_exc
    call check_response_frequency(model%analysis, f_exc, error)
    if (allocated(error)) return
    call new_model_traveling(model, tw, error)
    if (allocated(error)) return
    call wave_limit_force(model, F_lim, error)
    if (allocated(error)) return
    allocate(points(size(F_E)))
    dx = log(10.0_wp)/model%analysis%grid_per_decade
    do i = 1, size(F_E)
      points(i)%F_E = F_E(i)
      points(i)%f_res = f_exc
      points(i)%harmonics = tw%H
      ! stuck range: a layer far below the rotation that CF deflects the contacts by, where
      ! |F| grows like gamma; the first grid point puts |F| at 1e-3 F_E
      x0 = log(1e-3_wp*tw%CF/tw%geo%rate_scale)
      L = wave_layer_type()
      g = misfit(x0, F_E(i))
      if (allocated(error)) return
      x0 = x0 - g + log(1e-3_wp)
      L = wave_layer_type()
      x = x0
      gprev = misfit(x, F_E(i))
      if (allocated(error)) return
      allocate(roots(0))
      do k = 1, 100000
        xprev = x
        x = x + dx
        g = misfit(x, F_E(i))
        if (allocated(error)) return
        if (g*gprev <= 0 .and. g /= gprev) then
          lo = xprev
          hi = x
          glo = gprev
          ghi = g
          call brent_start(bs, lo, glo, hi, ghi, root_rtol)
          do
            call brent_next(bs, x, more)
            if (.not. more) exit
            g = misfit(x, F_E(i))
            if (allocated(error)) return
            call brent_update(bs, g)
          end do
          roots = [roots, exp(x)]
          x = hi
          g = misfit(x, F_E(i))
          if (allocated(error)) return
        end if
        gprev = g
        ! beyond the last root |F| keeps growing: three decades past F_E end the scan
        if (g > log(1e3_wp) .and. size(roots) > 0) exit
        if (g > log(1e6_wp)) exit
      end do
      if (size(roots) == 0) then
        call fatal_error(error, "traveling wave: no response found for F_E = "//ftoa(F_E(i))// &
          & " N at "//ftoa(f_exc)//" Hz, phi = "//ftoa(tw%phi)//" rad", UDMAP_EPHYSICS)
        return
      end if
      g = misfit(log(roots(size(roots))), F_E(i))
      if (allocated(error)) return
      call fill_point(tw, L, roots(size(roots)), F_E(i), F_lim, model%analysis%sigma_all, &
        & points(i))
      points(i)%f_res = f_exc
      points(i)%roots = roots
      deallocate(roots)
    end do

  contains

    !> ln |F(e^xg, omega)| - ln F (leaves L solved at e^xg).
    real(wp) function misfit(xg, F)
      real(wp), intent(in) :: xg, F
      misfit = 0
      call wave_layer_solve(tw, exp(xg), omega, L, error)
      if (allocated(error)) return
      misfit = log(abs(L%F)) - log(F)
    end function misfit
  end subroutine wave_response

  !> F_bb(gamma) [N] and the frequency of each layer's peak [Hz] of the traveling wave, the
  !> layers in the order given (each started from the previous one's peak).
  subroutine wave_backbone_curve(model, gamma, F_bb, f_res, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: gamma(:)
    real(wp), intent(out) :: F_bb(:), f_res(:)
    type(error_type), allocatable, intent(out) :: error
    type(traveling_type) :: tw
    type(wave_layer_type) :: L
    real(wp) :: w
    integer :: i
    F_bb = 0
    f_res = 0
    if (size(F_bb) < size(gamma) .or. size(f_res) < size(gamma)) then
      call fatal_error(error, "backbone_curve: the output arrays are too short", UDMAP_EINPUT)
      return
    end if
    call new_model_traveling(model, tw, error)
    if (allocated(error)) return
    w = 0
    do i = 1, size(gamma)
      if (.not. (gamma(i) > 0 .and. gamma(i) < huge(1.0_wp))) then
        call fatal_error(error, "backbone_curve: gamma must be positive numbers", UDMAP_EINPUT)
        return
      end if
      call wave_peak(tw, gamma(i), w, L, F_bb(i), error)
      if (allocated(error)) return
      w = L%omega
      f_res(i) = w/(2*pi)
    end do
  end subroutine wave_backbone_curve
end module udmap_mapping_traveling_backbone
