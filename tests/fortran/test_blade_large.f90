!> A large banded beam blade (blade A with 2048 airfoil elements, 4112 DOFs, band storage only):
!> the large-model path (lowest modes by subspace iteration, series of the dropped modes from
!> refined solves with K, direct banded solve beyond the series) against a direct banded complex
!> solve written here in quadruple precision (band Gaussian elimination with partial pivoting).
!> A double-precision solve would not do as reference: this stiffness has eps kappa ~ 1e-3 and a
!> plain double solve is off by ~0.7 % (that is why the kernel refines its solves).
module test_blade_large
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade, layer_response
  use fixtures, only: blade_a_beam_params, qp, receptances_from_solution
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_blade_large

contains

  !> A large banded beam blade through the large-model path.
  subroutine collect_blade_large(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("blade_large", run_blade_large)]
  end subroutine collect_blade_large

  !> The 4112-DOF banded blade: subspace modes and series against the small blade's values.
  subroutine run_blade_large(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: a
    type(blade_type) :: b
    type(error_type), allocatable :: error
    type(receptances_type) :: r, rr
    complex(wp) :: g, s, ue, gref, sref, uref
    real(wp) :: worst, e
    integer :: i
    !> The band of the first mode (150..230 Hz, resonance at 187.119054 Hz), the second and third
    !> resonances, up to the limit of the series (half the 21st natural frequency, 88.3 kHz) and
    !> beyond it (direct banded solve).
    real(wp), parameter :: f(15) = [150.0_wp, 170.0_wp, 185.0_wp, 187.0_wp, 187.119054_wp, &
      & 187.3_wp, 200.0_wp, 230.0_wp, 1079.37_wp, 2712.9_wp, 6000.0_wp, 15000.0_wp, 40000.0_wp, &
      & 85000.0_wp, 100000.0_wp]
    !> Near the resonance with a stuck-like damper.
    real(wp), parameter :: fl(2) = [190.0_wp, 197.6_wp]

    a = blade_a_beam_params()
    a%airfoil_elements = 2048
    call new_beam_blade(b, a, error)
    call check_no_error(suite, "2048-element blade builds", error)
    if (allocated(error)) return
    call check_true(suite, "band storage only", .not.allocated(b%K) .and. allocated(b%Kb) .and. b%kd == 3)
    call check_true(suite, "20 kept modes and the series", b%nmodes == 20 .and. b%nres > 0)
    write(*, '(a, f14.8, a, f12.3, a)') "f1 = ", b%omega1/(2*pi), " Hz; series valid up to ", &
      & b%omega_fast_max/(2*pi), " Hz"
    call check_close(suite, "f1 within 1e-7 of blade A's 24-element value", b%omega1/(2*pi), &
      & 187.119057676_wp, 1.0e-7_wp)

    worst = 0
    do i = 1, size(f)
      call b%receptances(2*pi*f(i), r, error)
      call check_no_error(suite, "receptances", error)
      rr = reference(2*pi*f(i), (0.0_wp, 0.0_wp))
      e = max(rel(r%gE, rr%gE), rel(r%gg, rr%gg), rel(r%EE, rr%EE), rel(r%sE, rr%sE), rel(r%sg, rr%sg))
      write(*, '(a, f10.3, a, es10.2)') "  f = ", f(i), " Hz: largest relative error ", e
      call check_close(suite, "large beam receptances vs quad banded solve (1e-9)", e, 0.0_wp, 0.0_wp, &
        & 1.0e-9_wp)
      worst = max(worst, e)
    end do
    write(*, '(a, es10.2)') "large beam: largest relative error vs quad banded solve ", worst

    ! Layer response with a stuck-like damper near the resonance with the damper.
    do i = 1, 2
      call b%receptances(2*pi*fl(i), r, error)
      call layer_response(r, (1.3e4_wp, 0.0_wp), g, s, ue)
      rr = reference(2*pi*fl(i), (1.3e4_wp, 0.0_wp))
      gref = rr%gE
      sref = rr%sE
      uref = rr%EE
      call check_close(suite, "large beam: Sherman-Morrison g~", abs(g - gref), 0.0_wp, 0.0_wp, &
        & 1.0e-9_wp*abs(gref))
      call check_close(suite, "large beam: Sherman-Morrison s~", abs(s - sref), 0.0_wp, 0.0_wp, &
        & 1.0e-9_wp*abs(sref))
      call check_close(suite, "large beam: Sherman-Morrison u~_E", abs(ue - uref), 0.0_wp, 0.0_wp, &
        & 1.0e-9_wp*abs(uref))
    end do

  contains

    real(wp) function rel(x, y)
      complex(wp), intent(in) :: x, y
      rel = abs(x - y)/abs(y)
    end function rel

    !> Quad banded solve of (D + k e_g e_g^T) q = [e_E, e_g]: gE = q_E(g), gg = q_g(g),
    !> EE = q_E(E), sE = s^T q_E, sg = s^T q_g (with k /= 0 these are g~, ., u~_E, s~, .).
    function reference(omega, k) result(res)
      real(wp), intent(in) :: omega
      complex(wp), intent(in) :: k
      type(receptances_type) :: res
      integer, parameter :: kl = 3, ku = 3, ld = 2*kl + ku + 1
      complex(qp), allocatable :: ab(:, :), x(:, :)
      complex(qp) :: t, tmp
      real(qp) :: om, kij, mij
      integer :: n, i, j, p, kk, last, jj
      n = b%ndof
      om = real(omega, qp)
      ! General band storage with room for fill-in: ab(kl+ku+1+i-j, j) = A(i, j).
      allocate(ab(ld, n), x(n, 2))
      ab = 0
      do j = 1, n
        do i = max(1, j-3), min(n, j+3)
          kij = real(b%Kb(4+min(i, j)-max(i, j), max(i, j)), qp)
          mij = real(b%Mb(4+min(i, j)-max(i, j), max(i, j)), qp)
          ab(kl+ku+1+i-j, j) = cmplx(kij - om**2*mij, om*real(b%beta, qp)*kij, qp)
        end do
      end do
      ab(kl+ku+1, b%gamma_dof) = ab(kl+ku+1, b%gamma_dof) + cmplx(k, kind=qp)
      x = 0
      x(b%exc_dof, 1) = 1
      x(b%gamma_dof, 2) = 1
      do j = 1, n
        last = min(n, j + kl)
        p = j - 1 + maxloc(abs(ab(kl+ku+1:kl+ku+1+last-j, j)), 1)
        if (p /= j) then
          do jj = j, min(n, j + kl + ku)
            tmp = ab(kl+ku+1+j-jj, jj)
            ab(kl+ku+1+j-jj, jj) = ab(kl+ku+1+p-jj, jj)
            ab(kl+ku+1+p-jj, jj) = tmp
          end do
          do kk = 1, 2
            tmp = x(j, kk)
            x(j, kk) = x(p, kk)
            x(p, kk) = tmp
          end do
        end if
        do i = j + 1, last
          t = ab(kl+ku+1+i-j, j)/ab(kl+ku+1, j)
          if (t == 0) cycle
          do jj = j + 1, min(n, j + kl + ku)
            ab(kl+ku+1+i-jj, jj) = ab(kl+ku+1+i-jj, jj) - t*ab(kl+ku+1+j-jj, jj)
          end do
          x(i, :) = x(i, :) - t*x(j, :)
        end do
      end do
      do j = n, 1, -1
        do kk = 1, 2
          t = x(j, kk)
          do jj = j + 1, min(n, j + kl + ku)
            t = t - ab(kl+ku+1+j-jj, jj)*x(jj, kk)
          end do
          x(j, kk) = t/ab(kl+ku+1, j)
        end do
      end do
      res = receptances_from_solution(b, omega, x)
    end function reference
  end subroutine run_blade_large
end module test_blade_large
