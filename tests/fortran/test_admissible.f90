!> The search of F_adm (kernel/src/mapping/admissible.f90) on stresses with known answers,
!> driven by reverse communication as admissible_force drives it with a model: a closed form
!> (F_lim/2 admissible, a crossing between samples, one below every sample), the stuck range's
!> proportional stress, no admissible force at all, the highest of several crossings, an
!> unbounded range, F_lim <= 0, and the errors.
module test_admissible
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use testing, only: test_suite, check_close, check_true, check_error, unittest_type, new_unittest
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_mapping_admissible, only: admissible_search_type, admissible_start, admissible_next, &
    & admissible_update, admissible_grid, n_grid, grid_decades
  implicit none
  private
  public :: collect_admissible

contains

  !> The F_adm search by reverse communication (mapping/admissible.f90).
  subroutine collect_admissible(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("admissible", run_admissible)]
  end subroutine collect_admissible

  !> F_adm searched on stresses with known answers: closed forms, offsets, several crossings.
  subroutine run_admissible(suite)
    type(test_suite), intent(inout) :: suite
    integer, parameter :: QUADRATIC = 1, PROPORTIONAL = 2, OFFSET = 3, SINE = 4, UNBOUNDED = 5, &
      & CONSTANT = 6
    real(wp), parameter :: cs(5) = [1e6_wp, 2e7_wp, 1e8_wp, 1e9_wp, 1e11_wp]
    real(wp) :: c, exact, got
    integer :: i, calls, grid_calls
    type(error_type), allocatable :: error

    ! sigma = c F (1 + F/F_lim) = sigma_all => F = F_lim (-1 + sqrt(1 + 4 sigma_all/(c F_lim)))/2;
    ! c = 1e6: F_lim/2 is admissible; c = 1e11: the crossing lies below the smallest sample
    do i = 1, size(cs)
      c = cs(i)
      got = search(QUADRATIC, c, 12.0_wp, 80e6_wp)
      exact = 12*(-1 + sqrt(1 + 4*80e6_wp/(c*12)))/2
      call check_close(suite, "closed form", got, min(exact, 6.0_wp), rtol=1e-11_wp)
      call check_true(suite, "one grid call, then at most 12 single forces", &
        & grid_calls == 1 .and. calls <= 1 + 12)
    end do
    ! the stuck range: sigma proportional to F, the crossing far below every sample
    c = 3e12_wp
    associate(g => admissible_grid(5.0_wp))
      call check_true(suite, "stuck: the crossing below the grid", g(1) > 80e6_wp/c)
    end associate
    call check_close(suite, "stuck: proportional", search(PROPORTIONAL, c, 10.0_wp, 80e6_wp), &
      & 80e6_wp/c, rtol=1e-14_wp)
    ! zeta = 0: a stuck damper bounds nothing, the stress tends to 67 MPa as F -> 0
    call check_true(suite, "nothing admissible", search(OFFSET, 0.0_wp, 20.0_wp, 60e6_wp) == 0)
    call check_close(suite, "offset crossing", search(OFFSET, 0.0_wp, 20.0_wp, 80e6_wp), 1.3_wp, &
      & rtol=1e-12_wp)
    ! 1 + sin(F)/2 against 1 up to F_lim/2 = 2.5 pi: admissible on (pi, 2 pi), the highest 2 pi
    call check_close(suite, "highest crossing", search(SINE, 0.0_wp, 5*pi, 1.0_wp), 2*pi, &
      & rtol=1e-12_wp)
    ! zeta = 0 with the backbone's asymptote at F = 3: infinite above, the admissible set ends
    call check_close(suite, "below an unbounded range", search(UNBOUNDED, 0.0_wp, 12.0_wp, &
      & 80e6_wp), 3.0_wp, rtol=1e-12_wp)
    call check_true(suite, "F_lim = 0", search(CONSTANT, 0.0_wp, 0.0_wp, 80e6_wp) == 0)
    ! the grid: geometric, ending at F_lim/2
    associate(g => admissible_grid(7.5_wp))
      call check_true(suite, "grid ends at F_lim/2", g(n_grid) == 7.5_wp)
      call check_close(suite, "grid starts decades below", g(1), 7.5_wp*10**(-grid_decades), &
        & rtol=1e-14_wp)
      call check_close(suite, "grid is geometric", maxval(g(2:)/g(:n_grid-1)), &
        & minval(g(2:)/g(:n_grid-1)), rtol=1e-14_wp)
    end associate
    ! errors
    block
      type(admissible_search_type) :: s
      call admissible_start(s, 10.0_wp, 0.0_wp, 1e-12_wp, error)
      call check_error(suite, "sigma_all = 0", error, UDMAP_EINPUT, "sigma_all")
      call admissible_start(s, ieee_value(1.0_wp, ieee_positive_inf), 80e6_wp, 1e-12_wp, error)
      call check_error(suite, "F_lim infinite", error, UDMAP_EPHYSICS, "F_lim")
    end block

  contains

    real(wp) function search(kind, c, F_lim, sigma_all) result(F_adm)
      integer, intent(in) :: kind
      real(wp), intent(in) :: c, F_lim, sigma_all
      type(admissible_search_type) :: s
      real(wp), allocatable :: F(:)
      logical :: more
      integer :: j
      calls = 0
      grid_calls = 0
      call admissible_start(s, F_lim, sigma_all, 1e-12_wp, error)
      if (allocated(error)) error stop "admissible_start failed"
      do
        call admissible_next(s, F, more)
        if (.not.more) exit
        calls = calls + 1
        if (size(F) == n_grid) grid_calls = grid_calls + 1
        call admissible_update(s, [(sigma(kind, c, F_lim, F(j)), j = 1, size(F))])
      end do
      F_adm = s%F_adm
    end function search

    real(wp) function sigma(kind, c, F_lim, F)
      integer, intent(in) :: kind
      real(wp), intent(in) :: c, F_lim, F
      select case (kind)
      case (QUADRATIC)
        sigma = c*F*(1 + F/F_lim)
      case (PROPORTIONAL)
        sigma = c*F
      case (OFFSET)
        sigma = 67e6_wp + 1e7_wp*F
      case (SINE)
        sigma = 1 + 0.5_wp*sin(F)
      case (UNBOUNDED)
        sigma = 1e7_wp*F
        if (F >= 3) sigma = ieee_value(1.0_wp, ieee_positive_inf)
      case default
        sigma = 1
      end select
    end function sigma
  end subroutine run_admissible
end module test_admissible
