!> Bracketed scalar root finding by reverse communication (Brent's zeroin), so that the
!> caller evaluates the function itself: no callbacks, no closures, no saved state.
!>
!> Usage:
!>   call brent_start(state, a, fa, b, fb, tol)      ! fa*fb <= 0
!>   do
!>     call brent_next(state, x, more)               ! x: next abscissa to evaluate
!>     if (.not.more) exit
!>     call brent_update(state, f(x))
!>   end do
!>   root = state%b                                  ! the best estimate, f(root) = state%fb
module udmap_core_root_finding
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: brent_type, brent_start, brent_next, brent_update, brent_bracket, &
    & brent_step
  public :: outward_type, outward_start, outward_next, outward_update

  !> State of one bracketed root search; b is always the best estimate so far.
  type :: brent_type
    real(wp) :: a = 0, b = 0, c = 0, fa = 0, fb = 0, fc = 0, d = 0, e = 0
    !> Absolute tolerance on the root.
    real(wp) :: tol = 0
    !> Function evaluations requested so far and the budget.
    integer :: evaluations = 0, max_evaluations = 200
    !> True once the root is located to tol (or the budget is spent).
    logical :: converged = .false.
  end type brent_type

  !> An outward search for a bracket, by reverse communication like Brent's: from x0 with
  !> f(x0), steps towards the root of an increasing f (x - sign(d, f)), doubling from d, inside
  !> (lo, hi). Ends with found ([a, b] holds a sign change, a /= b), or left (the next step
  !> would leave (lo, hi)), or neither after max_steps.
  type :: outward_type
    real(wp) :: a = 0, fa = 0, b = 0, fb = 0, d = 0, lo = 0, hi = 0
    integer :: steps = 0, max_steps = 60
    logical :: found = .false., left = .false.
  end type outward_type

contains

  pure subroutine outward_start(state, x0, f0, d, lo, hi)
    type(outward_type), intent(out) :: state
    real(wp), intent(in) :: x0, f0, d, lo, hi
    state%a = x0; state%fa = f0
    state%b = x0; state%fb = f0
    state%d = d; state%lo = lo; state%hi = hi
  end subroutine outward_start

  !> more = .true. with the next abscissa x to evaluate; .false. when the search has ended.
  pure subroutine outward_next(state, x, more)
    type(outward_type), intent(inout) :: state
    real(wp), intent(out) :: x
    logical, intent(out) :: more
    more = .false.
    x = state%b
    state%found = state%fa*state%fb <= 0 .and. state%a /= state%b
    if (state%found .or. state%steps >= state%max_steps) return
    state%a = state%b
    state%fa = state%fb
    x = state%a - sign(state%d, state%fa)
    state%left = .not. (x > state%lo .and. x < state%hi)
    if (state%left) return
    state%b = x
    state%d = 2*state%d
    state%steps = state%steps + 1
    more = .true.
  end subroutine outward_next

  pure subroutine outward_update(state, fx)
    type(outward_type), intent(inout) :: state
    real(wp), intent(in) :: fx
    state%fb = fx
  end subroutine outward_update

  !> Starts a search on the bracket [a, b] with function values fa, fb of opposite sign
  !> (or one of them zero); tol is the absolute tolerance on the root.
  pure subroutine brent_start(state, a, fa, b, fb, tol)
    type(brent_type), intent(out) :: state
    real(wp), intent(in) :: a, fa, b, fb, tol
    state%a = a; state%fa = fa
    state%b = b; state%fb = fb
    state%c = b; state%fc = fb
    state%d = b - a; state%e = state%d
    state%tol = tol
  end subroutine brent_start

  !> Advances the search: more = .true. with the next abscissa x to evaluate, or .false.
  !> when converged (state%b is the root).
  pure subroutine brent_next(state, x, more)
    type(brent_type), intent(inout) :: state
    real(wp), intent(out) :: x
    logical, intent(out) :: more
    real(wp) :: tol1, xm
    more = .false.
    x = state%b
    if (state%converged) return
    associate(a => state%a, b => state%b, c => state%c, fa => state%fa, fb => state%fb, &
        & fc => state%fc, d => state%d, e => state%e)
      call brent_bracket((fb > 0 .and. fc > 0) .or. (fb < 0 .and. fc < 0), a, b, c, fa, fb, &
        & fc, d, e)
      tol1 = 2*epsilon(1.0_wp)*abs(b) + 0.5_wp*state%tol
      xm = 0.5_wp*(c - b)
      if (abs(xm) <= tol1 .or. fb == 0 .or. state%evaluations >= state%max_evaluations) then
        state%converged = .true.
        x = b
        return
      end if
      call brent_step(a, b, c, fa, fb, fc, d, e, tol1, xm)
      x = b
    end associate
    state%evaluations = state%evaluations + 1
    more = .true.
  end subroutine brent_next

  !> Brent's zeroin before a step: with the new point b on the side of the contrapoint c
  !> (same_sign: fb and fc alike, by the caller's test) c takes the previous point a and the
  !> steps d, e restart from the bracket; then b becomes the end with the smaller |f|.
  pure subroutine brent_bracket(same_sign, a, b, c, fa, fb, fc, d, e)
    logical, intent(in) :: same_sign
    real(wp), intent(inout) :: a, b, c, fa, fb, fc, d, e
    if (same_sign) then
      c = a; fc = fa; d = b - a; e = d
    end if
    if (abs(fc) < abs(fb)) then
      a = b; b = c; c = a
      fa = fb; fb = fc; fc = fa
    end if
  end subroutine brent_bracket

  !> One step of Brent's zeroin (brent_next; also for callers with their own stopping test):
  !> from the last two points (a, fa), (b, fb), the contrapoint (c, fc) across the root, the
  !> tolerance tol at b and xm = (c - b)/2, inverse quadratic interpolation or a secant step
  !> where it stays well inside the bracket, else bisection; d and e hold the last two steps.
  !> (a, fa) take the old (b, fb) and b the next abscissa.
  pure subroutine brent_step(a, b, c, fa, fb, fc, d, e, tol, xm)
    real(wp), intent(inout) :: a, b, fa, d, e
    real(wp), intent(in) :: c, fb, fc, tol, xm
    real(wp) :: p, q, r, s
    if (abs(e) >= tol .and. abs(fa) > abs(fb)) then
      s = fb/fa
      if (a == c) then
        ! secant
        p = 2*xm*s
        q = 1 - s
      else
        ! inverse quadratic interpolation
        q = fa/fc
        r = fb/fc
        p = s*(2*xm*q*(q - r) - (b - a)*(r - 1))
        q = (q - 1)*(r - 1)*(s - 1)
      end if
      if (p > 0) q = -q
      p = abs(p)
      if (2*p < min(3*xm*q - abs(tol*q), abs(e*q))) then
        e = d
        d = p/q
      else
        d = xm
        e = d
      end if
    else
      d = xm
      e = d
    end if
    a = b
    fa = fb
    if (abs(d) > tol) then
      b = b + d
    else
      b = b + sign(tol, xm)
    end if
  end subroutine brent_step

  !> Gives the search the function value at the abscissa returned by brent_next.
  pure subroutine brent_update(state, fx)
    type(brent_type), intent(inout) :: state
    real(wp), intent(in) :: fx
    state%fb = fx
  end subroutine brent_update
end module udmap_core_root_finding
