!> Alternating frequency-time with the loading history: the exact event-driven AFT against the
!> closed-form Jenkins describing function (PHYSICS.md 2.4, values given to 6 digits), the sampled AFT converging to it as
!> 1/N^2, phase equivariance, multi-harmonic waveforms against a very fine sampled AFT, and the
!> closed-form Jacobian (aft_moment_jacobian) against finite differences of the moments; the
!> extrema of random waveforms.
module test_hbm_aft
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_contact_aft_moment, only: aft_workspace_type, aft_moment, aft_moment_jacobian
  use udmap_contact_aft_waveform, only: waveform_extrema, waveform_value, waveform_slope
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_damper_params, only: blade_a_damper_params
  use fixtures, only: uniform_sequence_type
  use testing, only: test_suite, check_close, check_true, check_no_error, unittest_type, &
    & new_unittest
  implicit none
  private
  public :: collect_hbm_aft

contains

  !> Alternating frequency-time with the loading history.
  subroutine collect_hbm_aft(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("hbm_aft", run_hbm_aft), &
      & new_unittest("waveform_extrema", run_extrema)]
  end subroutine collect_hbm_aft

  !> Exact and sampled AFT against the Jenkins describing function; the sampled error order.
  subroutine run_hbm_aft(suite)
    type(test_suite), intent(inout) :: suite
    type(jenkins_element_type) :: jen
    type(error_type), allocatable :: error
    type(aft_workspace_type) :: ws
    type(contact_element_type) :: el
    complex(wp) :: Gc(7)
    real(wp) :: amp_c
    real(wp), parameter :: amps_c(3) = [2.0e-6_wp, 8.0e-4_wp, 3.0e-3_wp]
    real(wp), parameter :: amp(3) = [1.6_wp, 2.0_wp, 5.0_wp]
    real(wp), parameter :: kre(3) = [1.947954_wp, 1.608998_wp, 0.504632_wp]
    real(wp), parameter :: kim(3) = [0.149208_wp, 0.477465_wp, 0.534761_wp]
    complex(wp) :: G1(1), M1(1), G3(5), M3(5), Mref(5), k
    real(wp) :: M0, gmax, err(2), b, kre_exact, kim_exact, a_s
    real(wp), allocatable :: tau(:)
    integer :: i, per, n, j
    character(len=8) :: tag

    ! kt = 2, slip limit 3 (PHYSICS.md 2.4 check values)
    call new_jenkins_element(jen, 2.0_wp, 3.0_wp, error)
    call check_no_error(suite, "jenkins", error)
    a_s = 1.5_wp
    do i = 1, 3
      write(tag, '(f4.1)') amp(i)
      ! any phase: k = M_1/Gamma_1 must not depend on it
      G1(1) = amp(i)*exp(cmplx(0.0_wp, 0.7_wp*i, wp))
      call aft_moment(jen, ws, 0.0_wp, G1, 0, 1, 8, 1.0e-12_wp, M0, M1, error, gmax, per)
      call check_no_error(suite, "aft a ="//tag, error)
      k = M1(1)/G1(1)
      call check_close(suite, "k_re a ="//tag, real(k, wp), kre(i), 0.0_wp, 6.0e-7_wp)
      call check_close(suite, "k_im a ="//tag, aimag(k), kim(i), 0.0_wp, 6.0e-7_wp)
      call check_close(suite, "gamma_max a ="//tag, gmax, amp(i), 1.0e-14_wp)
      call check_close(suite, "static moment a ="//tag, M0, 0.0_wp, 0.0_wp, 1.0e-13_wp)
      ! against the closed form to rounding
      b = acos(1.0_wp - 2.0_wp*a_s/amp(i))
      kre_exact = 2.0_wp/pi*(b - sin(2.0_wp*b)/2.0_wp)
      kim_exact = 4.0_wp*3.0_wp/(pi*amp(i))*(1.0_wp - a_s/amp(i))
      call check_close(suite, "k_re exact a ="//tag, real(k, wp), kre_exact, 1.0e-13_wp)
      call check_close(suite, "k_im exact a ="//tag, aimag(k), kim_exact, 1.0e-13_wp)
    end do
    ! stuck: k = kt exactly, no dissipation
    G1(1) = (1.0_wp, 0.5_wp)
    call aft_moment(jen, ws, 0.0_wp, G1, 0, 1, 8, 1.0e-12_wp, M0, M1, error)
    call check_close(suite, "stuck k_re", real(M1(1)/G1(1), wp), 2.0_wp, 1.0e-14_wp)
    call check_close(suite, "stuck k_im", aimag(M1(1)/G1(1)), 0.0_wp, 0.0_wp, 1.0e-14_wp)

    ! classical sampled AFT: error O(1/N^2) (ratio about 4 per doubling)
    G1(1) = (2.0_wp, 0.0_wp)
    do j = 1, 2
      n = 64*2**j
      call aft_moment(jen, ws, 0.0_wp, G1, n, 1, 8, 1.0e-12_wp, M0, M1, error)
      err(j) = abs(M1(1)/G1(1) - cmplx(1.608998_wp, 0.477465_wp, wp))
    end do
    call check_true(suite, "sampled AFT second order", err(1)/err(2) > 3.0_wp .and. &
      & err(1)/err(2) < 5.5_wp)
    call check_true(suite, "sampled AFT N = 256 error < 1e-3", err(1) < 1.0e-3_wp)

    ! multi-harmonic waveform with extra extrema (harmonics 1..5, static offset)
    G3 = [(1.8_wp, 0.3_wp), (0.25_wp, -0.1_wp), (0.5_wp, 0.4_wp), (0.0_wp, 0.2_wp), (-0.15_wp, 0.1_wp)]
    call waveform_extrema(G3, tau, n)
    call check_true(suite, "extrema alternate and cover a period", mod(n, 2) == 0 .and. n >= 4 &
      & .and. abs(tau(n+1) - tau(1) - 2.0_wp*pi) < 1.0e-12_wp)
    call check_true(suite, "first extremum is the global maximum", all([( &
      & waveform_value(0.0_wp, G3, tau(1)) >= waveform_value(0.0_wp, G3, 2.0_wp*pi*j/997.0_wp), &
      & j = 0, 996)]))
    call aft_moment(jen, ws, 0.3_wp, G3, 0, 1, 8, 1.0e-12_wp, M0, M3, error, gmax, per)
    call check_no_error(suite, "exact multi-harmonic", error)
    call aft_moment(jen, ws, 0.3_wp, G3, 200000, 1, 8, 1.0e-12_wp, M0, Mref, error)
    call check_no_error(suite, "sampled multi-harmonic", error)
    do j = 1, 5
      write(tag, '(i1)') j
      call check_close(suite, "multi-harmonic M_"//trim(tag), abs(M3(j) - Mref(j)), 0.0_wp, &
        & 0.0_wp, 1.0e-7_wp)
    end do

    ! closed-form Jacobian = central differences (M_r is piecewise linear: the differences are
    ! exact but for rounding while no event changes), moments = aft_moment's to the last bit
    call check_jacobian("jenkins, 5 harmonics", jen, 0.3_wp, G3, .true.)
    call new_contact_element(el, blade_a_damper_params(), error)
    call check_no_error(suite, "contact element", error)
    do j = 1, 3
      ! blade A's damper: stuck, gross slip, near lift-off, with harmonics 2..7
      amp_c = amps_c(j)
      Gc = amp_c*[(1.0_wp, 0.0_wp), (0.03_wp, -0.02_wp), (0.05_wp, 0.04_wp), (0.0_wp, 0.01_wp), &
        & (-0.02_wp, 0.01_wp), (0.01_wp, 0.005_wp), (0.004_wp, -0.003_wp)]
      write(tag, '(es8.1)') amp_c
      call check_jacobian("contact, gamma = "//tag, el, 0.05_wp*amp_c, Gc, j < 3)
    end do

  contains

    !> aft_moment_jacobian against central differences of aft_moment; must_ok: the closed form
    !> must apply (no event changes within the perturbations).
    subroutine check_jacobian(name, element, G0, G, must_ok)
      character(len=*), intent(in) :: name
      class(hysteretic_element_type), intent(inout) :: element
      real(wp), intent(in) :: G0
      complex(wp), intent(in) :: G(:)
      logical, intent(in) :: must_ok
      real(wp) :: JA(2*size(G)+1, 2*size(G)+1), JF(2*size(G)+1, 2*size(G)+1), MA0, Mp0, Mm0, d
      real(wp) :: vp(2*size(G)+1), vm(2*size(G)+1)
      complex(wp) :: MA(size(G)), Mb(size(G)), Mp(size(G)), Mm(size(G)), Gp(size(G)), Gm(size(G))
      real(wp) :: Mb0, scale, G0p, G0m
      integer :: c, H, k
      logical :: ok
      H = size(G)
      call aft_moment_jacobian(element, ws, G0, G, 1, 8, 1.0e-12_wp, MA0, MA, JA, ok, error)
      call check_no_error(suite, name//": jacobian", error)
      call aft_moment(element, ws, G0, G, 0, 1, 8, 1.0e-12_wp, Mb0, Mb, error)
      call check_true(suite, name//": same moments as aft_moment", MA0 == Mb0 .and. all(MA == Mb))
      if (must_ok) call check_true(suite, name//": closed form applies", ok)
      if (.not.ok) return
      d = 1.0e-6_wp*abs(G(1))
      do c = 1, 2*H + 1
        ! column c: G0 (c = 1), Re G_k (c = 2k), Im G_k (c = 2k + 1)
        Gp = G; Gm = G; G0p = G0; G0m = G0
        k = max(1, c/2)
        if (c == 1) then
          G0p = G0 + d; G0m = G0 - d
        else if (mod(c, 2) == 0) then
          Gp(k) = G(k) + d; Gm(k) = G(k) - d
        else
          Gp(k) = G(k) + cmplx(0.0_wp, d, wp); Gm(k) = G(k) - cmplx(0.0_wp, d, wp)
        end if
        call aft_moment(element, ws, G0p, Gp, 0, 1, 8, 1.0e-12_wp, Mp0, Mp, error)
        call aft_moment(element, ws, G0m, Gm, 0, 1, 8, 1.0e-12_wp, Mm0, Mm, error)
        vp = [Mp0, (real(Mp(k), wp), aimag(Mp(k)), k = 1, H)]
        vm = [Mm0, (real(Mm(k), wp), aimag(Mm(k)), k = 1, H)]
        JF(:, c) = (vp - vm)/(2*d)
      end do
      scale = maxval(abs(JF))
      call check_true(suite, name//": Jacobian = central differences", &
        & maxval(abs(JA - JF)) <= 1.0e-6_wp*scale)
    end subroutine check_jacobian
  end subroutine run_hbm_aft

  !> The extrema of 400 random waveforms (2 to 64 harmonics, amplitudes falling like 1/h^2 to
  !> 1/h^4 or e^{-h/3}, or only the first three; every seventh with a weak first harmonic): each
  !> a root of gamma', maxima and minima alternating, and gamma monotone between two of them on
  !> a grid 16 times finer than the search's, where a missed pair of extrema wider than a cell of
  !> the search's grid would show. (A
  !> continuous gamma's harmonics fall at least like 1/h^2; the Gibbs wiggles of a 1/h waveform,
  !> one with jumps, bring extrema closer than the search's grid resolves.)
  subroutine run_extrema(suite)
    type(test_suite), intent(inout) :: suite
    complex(wp), allocatable :: G(:)
    real(wp), allocatable :: tau(:)
    real(wp) :: amp, B1, B2, v0, v1, vp, v, tol, t, re, im
    integer :: trial, H, k, n, i, m, steps, total, not_root, not_alternating, not_monotone
    type(uniform_sequence_type) :: rng
    rng%state = 20261128_8
    total = 0
    not_root = 0
    not_alternating = 0
    not_monotone = 0
    do trial = 1, 400
      H = 2 + mod(37*trial, 63)
      allocate(G(H))
      do k = 1, H
        select case (mod(trial, 5))
        case (0)
          amp = 1.0_wp/k**3
        case (1)
          amp = 1.0_wp/k**2
        case (2)
          amp = 1.0_wp/k**4
        case (3)
          amp = merge(1.0_wp, 0.0_wp, k <= 3)
        case default
          amp = exp(-k/3.0_wp)
        end select
        re = rng%next()
        im = rng%next()
        G(k) = amp*cmplx(re - 0.5_wp, im - 0.5_wp, wp)
      end do
      if (mod(trial, 7) == 0) G(1) = 1.0e-3_wp*G(1)
      call waveform_extrema(G, tau, n)
      total = total + n
      B1 = sum([(k*abs(G(k)), k = 1, H)])
      B2 = sum([(real(k, wp)**2*abs(G(k)), k = 1, H)])
      ! a pair of extrema inside one cell of the search's grid (step 2 pi/max(64, 16 H)) is
      ! below its resolution: the bump it makes is at most B2 step^2/2
      tol = max(1.0e-12_wp*sum(abs(G)), 0.5_wp*B2*(2.0_wp*pi/max(64, 16*H))**2)
      do i = 1, n
        if (abs(waveform_slope(G, tau(i), 1)) > 1.0e-10_wp*H*B1) not_root = not_root + 1
        v0 = waveform_value(0.0_wp, G, tau(i))
        v1 = waveform_value(0.0_wp, G, tau(i+1))
        ! odd stretches fall from a maximum, even ones rise from a minimum
        if ((v1 < v0) .neqv. (mod(i, 2) == 1)) not_alternating = not_alternating + 1
        steps = ceiling((tau(i+1) - tau(i))/(2.0_wp*pi/(256*H)))
        vp = v0
        do m = 1, steps - 1
          t = tau(i) + (tau(i+1) - tau(i))*m/steps
          v = waveform_value(0.0_wp, G, t)
          if (merge(v > vp + tol, v < vp - tol, mod(i, 2) == 1)) then
            not_monotone = not_monotone + 1
            exit
          end if
          vp = v
        end do
      end do
      deallocate(G)
    end do
    call check_true(suite, "random waveforms: extrema found", total > 2*400)
    call check_true(suite, "random waveforms: each extremum a root of gamma'", not_root == 0)
    call check_true(suite, "random waveforms: maxima and minima alternate", &
      & not_alternating == 0)
    call check_true(suite, "random waveforms: monotone between extrema", not_monotone == 0)
  end subroutine run_extrema
end module test_hbm_aft
