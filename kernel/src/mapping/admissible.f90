!> The admissible force F_adm of a design (INTERFACES.md "Design of experiments output"): the
!> largest F_E <= F_lim/2 whose resonant stress is at most sigma_all, solved continuously. The
!> stress is sigma_a, or sigma_max with more than one harmonic (PHYSICS.md 4.1), infinite where
!> the response is unbounded; F_lim is the smaller of F_lim and F_lim_backbone (PHYSICS.md 5).
!>
!> - F_lim/2 when the stress there is admissible: the friction limit governs.
!> - Otherwise the highest crossing below F_lim/2: the stress is sampled at n_grid forces spaced
!>   geometrically over grid_decades below F_lim/2 (one backbone call), the highest admissible
!>   sample and the next one bracket the crossing, and Brent's method (in ln F, ln sigma) refines
!>   it to rtol. Where
!>   the stress is not monotone in F_E (it can dip when the damper starts to slip or lifts off)
!>   this is the upper end of the admissible set; a dip narrower than the grid spacing can go
!>   unseen.
!> - Below the smallest sample: with structural damping the stuck range's stress is
!>   proportional to F_E, so small forces are admissible. When even the smallest sample fails,
!>   the stress is taken tiny_ratio times lower: admissible there, that force and the smallest
!>   sample bracket the crossing (the first secant step is then the root); still above
!>   sigma_all (no structural damping: a stuck damper bounds nothing), F_adm = 0. F_adm is 0
!>   also when F_lim <= 0.
module udmap_mapping_admissible
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_mapping_model_data, only: model_type, point_type
  use udmap_mapping_traveling_dispatch, only: backbone
  use udmap_core_root_finding, only: brent_type, brent_start, brent_next, brent_update
  implicit none
  private
  public :: admissible_force, admissible_grid, admissible_search_type, admissible_start, &
    & admissible_next, admissible_update
  public :: n_grid, grid_decades, tiny_ratio

  !> Samples of the stress below F_lim/2 and the decades they span.
  integer, parameter :: n_grid = 16
  real(wp), parameter :: grid_decades = 3
  !> Below the smallest sample, the force (relative to it) where small forces are checked.
  real(wp), parameter :: tiny_ratio = 1.0e-6_wp
  !> Stands in for an unbounded stress inside the root search, which needs finite values.
  real(wp), parameter :: huge_stress = 1.0e300_wp

  integer, parameter :: STAGE_GRID = 1, STAGE_TINY = 2, STAGE_BRENT = 3, STAGE_DONE = 4

  !> The state of one search of F_adm (reverse communication, so that the search can be
  !> checked on known functions; admissible_force drives it with the model's backbone).
  type :: admissible_search_type
    real(wp) :: F_half = 0, sigma_all = 0, rtol = 0
    !> The answer once done [N].
    real(wp) :: F_adm = 0
    !> The stress at the smallest sample.
    real(wp) :: sig1 = 0
    integer :: stage = STAGE_DONE
    type(brent_type) :: brent
  end type admissible_search_type

contains

  !> The forces F_half 10^(-grid_decades (n_grid - i)/(n_grid - 1)), i = 1..n_grid (the last
  !> one F_half exactly).
  pure function admissible_grid(F_half) result(grid)
    real(wp), intent(in) :: F_half
    real(wp) :: grid(n_grid)
    integer :: i
    do i = 1, n_grid
      grid(i) = F_half*10.0_wp**(grid_decades*real(i - n_grid, wp)/real(n_grid - 1, wp))
    end do
    grid(n_grid) = F_half
  end function admissible_grid

  !> Starts the search of F_adm for the limit F_lim [N] and the allowable stress sigma_all
  !> [Pa], refined to the relative tolerance rtol (reverse communication: admissible_next asks
  !> for the stresses at some forces, admissible_update gives them).
  subroutine admissible_start(search, F_lim, sigma_all, rtol, error)
    type(admissible_search_type), intent(out) :: search
    real(wp), intent(in) :: F_lim, sigma_all, rtol
    type(error_type), allocatable, intent(out) :: error
    if (.not.(sigma_all > 0)) then
      call fatal_error(error, "admissible force: sigma_all must be positive", UDMAP_EINPUT)
      return
    end if
    search%F_half = 0.5_wp*F_lim
    if (.not.(abs(search%F_half) < huge(1.0_wp))) then
      call fatal_error(error, "admissible force: F_lim is not finite, no admissible force "// &
        & "can be defined", UDMAP_EPHYSICS)
      return
    end if
    search%sigma_all = sigma_all
    search%rtol = max(rtol, 1.0e-15_wp)
    search%stage = STAGE_GRID
    ! F_lim <= 0: nothing to search, F_adm = 0
    if (.not.(search%F_half > 0)) search%stage = STAGE_DONE
  end subroutine admissible_start

  !> The forces [N] whose stresses the search needs next; more = .false. when it is done
  !> (search%F_adm is the answer).
  subroutine admissible_next(search, forces, more)
    type(admissible_search_type), intent(inout) :: search
    real(wp), allocatable, intent(inout) :: forces(:)
    logical, intent(out) :: more
    real(wp) :: x, grid(n_grid)
    more = .true.
    select case (search%stage)
    case (STAGE_GRID)
      forces = admissible_grid(search%F_half)
    case (STAGE_TINY)
      grid = admissible_grid(search%F_half)
      forces = [tiny_ratio*grid(1)]
    case (STAGE_BRENT)
      call brent_next(search%brent, x, more)
      if (more) then
        forces = [exp(x)]
      else
        search%F_adm = exp(search%brent%b)
        search%stage = STAGE_DONE
      end if
    case default
      more = .false.
    end select
  end subroutine admissible_next

  !> The stresses [Pa] at the forces admissible_next asked for (+huge or +inf where the
  !> response is unbounded).
  subroutine admissible_update(search, sigma)
    type(admissible_search_type), intent(inout) :: search
    real(wp), intent(in) :: sigma(:)
    real(wp) :: grid(n_grid), sig(n_grid)
    integer :: k
    associate(s_all => search%sigma_all)
      select case (search%stage)
      case (STAGE_GRID)
        grid = admissible_grid(search%F_half)
        sig = min(sigma(1:n_grid), huge_stress)
        search%sig1 = sig(1)
        if (sig(n_grid) <= s_all) then
          ! the friction limit governs
          search%F_adm = search%F_half
          search%stage = STAGE_DONE
          return
        end if
        k = findloc(sig <= s_all, .true., 1, back=.true.)
        if (k > 0) then
          call start_brent(grid(k), sig(k), grid(k + 1), sig(k + 1))
        else
          search%stage = STAGE_TINY
        end if
      case (STAGE_TINY)
        if (min(sigma(1), huge_stress) > s_all) then
          ! small forces fail too: nothing is admissible
          search%F_adm = 0
          search%stage = STAGE_DONE
        else
          grid = admissible_grid(search%F_half)
          call start_brent(tiny_ratio*grid(1), min(sigma(1), huge_stress), grid(1), search%sig1)
        end if
      case (STAGE_BRENT)
        call brent_update(search%brent, excess(sigma(1)))
      end select
    end associate
  contains
    !> Brent's method on ln sigma - ln sigma_all against ln F (close to linear: the stress
    !> grows about as a power of the force, exactly so in the stuck range), so that the
    !> tolerance on ln F is rtol relative on F.
    subroutine start_brent(lo, s_lo, hi, s_hi)
      real(wp), intent(in) :: lo, s_lo, hi, s_hi
      call brent_start(search%brent, log(lo), excess(s_lo), log(hi), excess(s_hi), 2*search%rtol)
      search%stage = STAGE_BRENT
    end subroutine start_brent

    pure real(wp) function excess(stress)
      real(wp), intent(in) :: stress
      excess = log(max(min(stress, huge_stress), tiny(1.0_wp))) - log(search%sigma_all)
    end function excess
  end subroutine admissible_update

  !> F_adm [N] of the model for the limit F_lim [N] and the allowable stress sigma_all [Pa],
  !> refined to the relative tolerance rtol. The model needs stress rows.
  subroutine admissible_force(model, F_lim, sigma_all, rtol, F_adm, error)
    type(model_type), intent(inout) :: model
    real(wp), intent(in) :: F_lim, sigma_all, rtol
    real(wp), intent(out) :: F_adm
    type(error_type), allocatable, intent(out) :: error
    type(admissible_search_type) :: search
    type(point_type), allocatable :: p(:)
    real(wp), allocatable :: F(:), sigma(:)
    logical :: more
    integer :: i
    F_adm = 0
    if (.not.model%blade%has_stress) then
      call fatal_error(error, "admissible force: the blade has no stress rows", UDMAP_EINPUT)
      return
    end if
    call admissible_start(search, F_lim, sigma_all, rtol, error)
    if (allocated(error)) return
    do
      call admissible_next(search, F, more)
      if (.not.more) exit
      call backbone(model, F, p, error)
      if (allocated(error)) return
      sigma = [(stress(p(i)), i = 1, size(p))]
      call admissible_update(search, sigma)
    end do
    F_adm = search%F_adm
  contains
    !> The resonant stress of a point (huge where unbounded; sigma_max with more harmonics).
    pure real(wp) function stress(q)
      type(point_type), intent(in) :: q
      if (q%unbounded) then
        stress = huge(1.0_wp)
      else if (q%harmonics > 1) then
        stress = q%sigma_max
      else
        stress = q%sigma_a
      end if
    end function stress
  end subroutine admissible_force
end module udmap_mapping_admissible
