!> Brent's minimisation of a function of one variable (Numerical Recipes' brent: parabolic
!> steps, golden sections where they fail) by reverse communication, like the root finding of
!> udmap_core_root_finding: the caller evaluates the function itself (a time integration, a
!> harmonic balance) and handles its errors; no callbacks, no saved state.
!>
!> Usage:
!>   call brent_min_start(state, lo, hi, x, fx, rtol, max_steps)   ! lo < x < hi, fx = f(x)
!>   do
!>     call brent_min_next(state, u, more)      ! u: next abscissa to evaluate
!>     if (.not. more) exit
!>     call brent_min_update(state, f(u))       ! state%better: u is the new state%x
!>   end do
!>   ! state%x: the minimum found, f(state%x) = state%fx
module udmap_core_minimise
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: brent_min_type, brent_min_start, brent_min_next, brent_min_update, golden_section

  !> (3 - sqrt(5))/2: the golden section's step, as a fraction of the bracket.
  real(wp), parameter :: golden_section = 0.3819660112501051_wp

  !> State of one minimisation; x is always the best point so far.
  type :: brent_min_type
    real(wp) :: lo = 0, hi = 0              !< the bracket
    real(wp) :: x = 0, fx = 0               !< the best point
    real(wp) :: w = 0, fw = 0, v = 0, fv = 0  !< the second best, the previous w
    real(wp) :: u = 0                       !< the abscissa last asked for
    real(wp) :: d = 0, e = 0                !< the last step and the one before
    real(wp) :: rtol = 0                    !< tolerance on x, relative to |x|
    integer :: steps = 0, max_steps = 0     !< steps asked for so far and the budget
    logical :: better = .false.             !< the last update moved x to u
  end type brent_min_type

contains

  !> Starts on the bracket [lo, hi] from x inside it with fx = f(x).
  pure subroutine brent_min_start(state, lo, hi, x, fx, rtol, max_steps)
    type(brent_min_type), intent(out) :: state
    real(wp), intent(in) :: lo, hi, x, fx, rtol
    integer, intent(in) :: max_steps
    state%lo = lo; state%hi = hi
    state%x = x; state%w = x; state%v = x
    state%fx = fx; state%fw = fx; state%fv = fx
    state%rtol = rtol
    state%max_steps = max_steps
  end subroutine brent_min_start

  !> more = .true. with the next abscissa u to evaluate; .false. when x is located to rtol or
  !> the budget is spent.
  pure subroutine brent_min_next(state, u, more)
    type(brent_min_type), intent(inout) :: state
    real(wp), intent(out) :: u
    logical, intent(out) :: more
    real(wp) :: xm, tol1, tol2, r, q, p, etemp
    more = .false.
    u = state%x
    if (state%steps >= state%max_steps) return
    state%steps = state%steps + 1
    associate(lo => state%lo, hi => state%hi, x => state%x, fx => state%fx, w => state%w, &
        & fw => state%fw, v => state%v, fv => state%fv, d => state%d, e => state%e)
      xm = 0.5_wp*(lo + hi)
      tol1 = state%rtol*abs(x)
      tol2 = 2.0_wp*tol1
      if (abs(x - xm) <= tol2 - 0.5_wp*(hi - lo)) return
      if (abs(e) > tol1) then
        r = (x - w)*(fx - fv)
        q = (x - v)*(fx - fw)
        p = (x - v)*q - (x - w)*r
        q = 2.0_wp*(q - r)
        if (q > 0.0_wp) p = -p
        q = abs(q)
        etemp = e
        e = d
        if (abs(p) >= abs(0.5_wp*q*etemp) .or. p <= q*(lo - x) .or. p >= q*(hi - x)) then
          e = merge(lo - x, hi - x, x >= xm)
          d = golden_section*e
        else
          d = p/q
          u = x + d
          if (u - lo < tol2 .or. hi - u < tol2) d = sign(tol1, xm - x)
        end if
      else
        e = merge(lo - x, hi - x, x >= xm)
        d = golden_section*e
      end if
      if (abs(d) >= tol1) then
        u = x + d
      else
        u = x + sign(tol1, d)
      end if
    end associate
    state%u = u
    more = .true.
  end subroutine brent_min_next

  !> Gives the search fu = f(u) at the abscissa u of brent_min_next.
  pure subroutine brent_min_update(state, fu)
    type(brent_min_type), intent(inout) :: state
    real(wp), intent(in) :: fu
    associate(lo => state%lo, hi => state%hi, x => state%x, fx => state%fx, w => state%w, &
        & fw => state%fw, v => state%v, fv => state%fv, u => state%u)
      state%better = fu <= fx
      if (fu <= fx) then
        if (u >= x) then
          lo = x
        else
          hi = x
        end if
        v = w; fv = fw
        w = x; fw = fx
        x = u; fx = fu
      else
        if (u < x) then
          lo = u
        else
          hi = u
        end if
        if (fu <= fw .or. w == x) then
          v = w; fv = fw
          w = u; fw = fu
        else if (fu <= fv .or. v == x .or. v == w) then
          v = u; fv = fu
        end if
      end if
    end associate
  end subroutine brent_min_update
end module udmap_core_minimise
