!> Double-double arithmetic (a value is hi + lo, |lo| <= ulp(hi)/2, ~106 bits) from error-free
!> transformations in plain double precision: Knuth's two-sum and Dekker's two-product (with
!> Veltkamp splitting, no FMA needed). Used for the residuals of iterative refinement and for
!> products of the stiff blade matrices, where double precision cancels digits; several times
!> faster than quadruple precision, which is emulated in software.
!> The formulas rely on IEEE double arithmetic evaluated as written (no -ffast-math: Fortran
!> honours the parentheses).
module udmap_blade_dd
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: two_sum, two_prod, dd_add, dd_add_d, dd_mul_d, sym_matvec_dd, dot_dd

  !> Veltkamp's splitting constant 2^27 + 1.
  real(wp), parameter :: splitter = 134217729.0_wp

contains

  !> s + e = a + b exactly, s = fl(a + b).
  elemental subroutine two_sum(a, b, s, e)
    real(wp), intent(in) :: a, b
    real(wp), intent(out) :: s, e
    call fast_two_sum(a, b, s, e)
  end subroutine two_sum

  !> p + e = a b exactly, p = fl(a b) (Dekker; assumes no overflow in the splitting).
  elemental subroutine two_prod(a, b, p, e)
    real(wp), intent(in) :: a, b
    real(wp), intent(out) :: p, e
    call fast_two_prod(a, b, p, e)
  end subroutine two_prod

  ! The private versions below are what this module calls: private procedures are not
  ! interposable in the shared library, so the compiler can inline them.

  elemental subroutine fast_two_sum(a, b, s, e)
    real(wp), intent(in) :: a, b
    real(wp), intent(out) :: s, e
    real(wp) :: v
    s = a + b
    v = s - a
    e = (a - (s - v)) + (b - v)
  end subroutine fast_two_sum

  elemental subroutine fast_two_prod(a, b, p, e)
    real(wp), intent(in) :: a, b
    real(wp), intent(out) :: p, e
    real(wp) :: t, ah, al, bh, bl
    p = a*b
    t = splitter*a
    ah = t - (t - a)
    al = a - ah
    t = splitter*b
    bh = t - (t - b)
    bl = b - bh
    e = ((ah*bh - p) + ah*bl + al*bh) + al*bl
  end subroutine fast_two_prod

  !> (zh, zl) = (xh, xl) + (yh, yl), renormalised.
  elemental subroutine dd_add(xh, xl, yh, yl, zh, zl)
    real(wp), intent(in) :: xh, xl, yh, yl
    real(wp), intent(out) :: zh, zl
    real(wp) :: s, e
    call fast_two_sum(xh, yh, s, e)
    e = e + (xl + yl)
    zh = s + e
    zl = e - (zh - s)
  end subroutine dd_add

  !> (zh, zl) = (xh, xl) + y, renormalised.
  elemental subroutine dd_add_d(xh, xl, y, zh, zl)
    real(wp), intent(in) :: xh, xl, y
    real(wp), intent(out) :: zh, zl
    real(wp) :: s, e
    call fast_two_sum(xh, y, s, e)
    e = e + xl
    zh = s + e
    zl = e - (zh - s)
  end subroutine dd_add_d

  !> (zh, zl) = (xh, xl) y, renormalised.
  elemental subroutine dd_mul_d(xh, xl, y, zh, zl)
    real(wp), intent(in) :: xh, xl, y
    real(wp), intent(out) :: zh, zl
    real(wp) :: p, e
    call fast_two_prod(xh, y, p, e)
    e = e + xl*y
    zh = p + e
    zl = e - (zh - p)
  end subroutine dd_mul_d

  !> y = A x in double-double for the symmetric A (dense `a`, or band `ab` with half-bandwidth
  !> kd, uplo = 'U'; the band form is used when allocated) and x = xh + xl. Each product is
  !> exact (two_prod), the sums are compensated: the error is ~eps^2 sum |a_ij x_j|.
  pure subroutine sym_matvec_dd(a, ab, kd, xh, xl, yh, yl)
    real(wp), allocatable, intent(in) :: a(:, :), ab(:, :)
    integer, intent(in) :: kd
    real(wp), intent(in) :: xh(:), xl(:)
    real(wp), intent(out) :: yh(:), yl(:)
    real(wp) :: s, e
    integer :: i, j, n
    n = size(xh)
    yh = 0.0_wp
    yl = 0.0_wp
    if (allocated(ab)) then
      do j = 1, n
        ! Column j of the upper band, mirrored for the lower part.
        do i = max(1, j-kd), j - 1
          call accumulate(yh(i), yl(i), ab(kd+1+i-j, j), xh(j), xl(j))
          call accumulate(yh(j), yl(j), ab(kd+1+i-j, j), xh(i), xl(i))
        end do
        call accumulate(yh(j), yl(j), ab(kd+1, j), xh(j), xl(j))
      end do
    else
      do i = 1, n
        do j = 1, n
          call accumulate(yh(i), yl(i), a(j, i), xh(j), xl(j))
        end do
      end do
    end if
    ! Renormalise.
    do i = 1, n
      call fast_two_sum(yh(i), yl(i), s, e)
      yh(i) = s
      yl(i) = e
    end do
  end subroutine sym_matvec_dd

  !> sh + sl += aij (xh + xl): the product exactly, its sum compensated (sl collects the
  !> errors; renormalised by the caller at the end).
  elemental subroutine accumulate(sh, sl, aij, xh, xl)
    real(wp), intent(inout) :: sh, sl
    real(wp), intent(in) :: aij, xh, xl
    real(wp) :: p, e, s, t
    call fast_two_prod(aij, xh, p, e)
    call fast_two_sum(sh, p, s, t)
    sh = s
    sl = sl + (t + (e + aij*xl))
  end subroutine accumulate

  !> sum(x y) in double-double, rounded to double.
  pure function dot_dd(x, y) result(d)
    real(wp), intent(in) :: x(:), y(:)
    real(wp) :: d
    real(wp) :: sh, sl
    integer :: i
    sh = 0.0_wp
    sl = 0.0_wp
    do i = 1, size(x)
      call accumulate(sh, sl, x(i), y(i), 0.0_wp)
    end do
    d = sh + sl
  end function dot_dd
end module udmap_blade_dd
