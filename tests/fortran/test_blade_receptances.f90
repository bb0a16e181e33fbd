!> Receptances of blade A (PHYSICS.md 1, 3) against an independent reference: a direct dense
!> complex solve of D(omega) q = e written here, in quadruple precision (Gaussian elimination
!> with partial pivoting), so that the reference is exact for the stored double-precision
!> matrices. (A double-precision solve is not: near resonance it is off by ~1e-9, see the
!> module documentation of udmap_blade_modes.) Covered: every evaluation path (series, all modes,
!> large-model path, explicit C), derivatives against central differences, the Sherman-Morrison
!> layer response against a direct solve with the damper stiffness, the Matrix Market round
!> trip and the input errors of imported matrices.
module test_blade_receptances
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade, new_matrices_blade, &
    & layer_response
  use udmap_blade_io_matrices, only: read_matrices_blade, export_blade
  use fixtures, only: blade_a_beam_params, ieee_nan, temp_dir, qp, receptances_from_solution
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_blade_receptances

contains

  !> Receptances of blade A against an independent reference.
  subroutine collect_blade_receptances(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("blade_receptances", run_blade_receptances)]
  end subroutine collect_blade_receptances

  !> Every receptance path against the quadruple-precision dense solve, and the import checks.
  subroutine run_blade_receptances(suite)
    type(test_suite), intent(inout) :: suite
    type(beam_params_type) :: a
    type(blade_type) :: b
    type(error_type), allocatable :: error
    !> Test frequencies [Hz]: the band of blade A's first mode (150..230 Hz) and beyond, through
    !> the second and third resonances, the limit of the series (13.8 kHz for the default
    !> evaluation: half the 9th natural frequency; 89.7 kHz for 20 kept modes) and past it.
    real(wp), parameter :: band(17) = [150.0_wp, 160.0_wp, 170.0_wp, 180.0_wp, 185.0_wp, &
      & 187.0_wp, 187.119057676_wp, 187.2_wp, 190.0_wp, 200.0_wp, 210.0_wp, 220.0_wp, 230.0_wp, &
      & 50.0_wp, 1079.375_wp, 2712.9_wp, 5000.0_wp]
    real(wp), parameter :: far(7) = [12000.0_wp, 13500.0_wp, 14200.0_wp, 20000.0_wp, 60000.0_wp, &
      & 89000.0_wp, 100000.0_wp]

    a = blade_a_beam_params()
    call new_beam_blade(b, a, error)
    call check_no_error(suite, "blade A builds", error)
    if (allocated(error)) return

    call evaluation_paths()
    call small_closed_forms()
    call explicit_damping()
    call derivatives()
    call sherman_morrison()
    call export_import()
    call bad_matrices()

  contains

    !> Every evaluation path against the quadruple-precision direct solve, 1e-10 relative.
    subroutine evaluation_paths()
      type(blade_type) :: all_modes, large
      real(wp) :: worst(3)
      call new_beam_blade(all_modes, a, error, kept_modes=64)
      call check_no_error(suite, "blade A with every mode summed", error)
      call new_beam_blade(large, a, error, kept_modes=20)
      call check_no_error(suite, "blade A on the large-model path (20 modes + series)", error)
      call check_true(suite, "default: 8 modes + series", b%nfast == 8 .and. b%nres > 0)
      call check_true(suite, "kept_modes = 64: every mode, no series", all_modes%nfast == 64 &
        & .and. all_modes%nres == 0)
      call check_true(suite, "kept_modes = 20: 20 modes + series", large%nmodes == 20 .and. &
        & large%nfast == 20 .and. large%nres > 0)
      call check_close(suite, "large path: same f1", large%omega1, b%omega1, 1.0e-13_wp)
      call check_close(suite, "large path: same f20", large%omega(20), all_modes%omega(20), 1.0e-12_wp)
      ! Every mode term by term: far above the first modes (100 kHz) the modal terms cancel
      ! (H_gE is then ~1e-11 relative); hence the default evaluation switches to the direct solve.
      worst = [compare(b, [band, far], 1.0e-10_wp, "default"), &
        & compare(all_modes, [band, far(1:6)], 1.0e-10_wp, "all modes"), &
        & compare(large, [band, far], 1.0e-10_wp, "large path")]
      write(*, '(a, 3es10.2)') "largest relative error vs quad direct solve (default, all modes, "// &
        & "large path): ", worst
    end subroutine evaluation_paths

    !> Closed forms: the one-DOF oscillator of PHYSICS.md 8 (m = 1, c = 0.01 given as C, k = 1),
    !> H = 1/(k - omega^2 m + i omega c), and a two-DOF chain with stiffness-proportional damping,
    !> K = [2 -1; -1 1], M = I: modes omega^2 = (3 -+ sqrt 5)/2, and H = (K - omega^2 M + i omega
    !> beta K)^-1 by Cramer's rule.
    subroutine small_closed_forms()
      type(blade_type) :: one, two
      type(receptances_type) :: r
      real(wp) :: om, beta
      complex(wp) :: d(2, 2), det
      integer :: i
      call new_matrices_blade(one, reshape([1.0_wp], [1, 1]), reshape([1.0_wp], [1, 1]), 1, 1, 0.0_wp, &
        & error, C=reshape([0.01_wp], [1, 1]))
      call check_no_error(suite, "one-DOF oscillator", error)
      if (allocated(error)) return
      call check_close(suite, "one-DOF: omega_1 = 1", one%omega1, 1.0_wp, 1.0e-15_wp)
      do i = 0, 4
        om = 0.9_wp + 0.05_wp*i
        call one%receptances(om, r, error, derivatives=.true.)
        call close_c("one-DOF: H", r%gE, 1.0_wp/cmplx(1.0_wp - om**2, 0.01_wp*om, wp), 1.0e-14_wp)
        call close_c("one-DOF: dH", r%dgE, -cmplx(-2*om, 0.01_wp, wp)/cmplx(1.0_wp - om**2, &
          & 0.01_wp*om, wp)**2, 1.0e-12_wp)
      end do
      call new_matrices_blade(two, reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2]), &
        & reshape([2.0_wp, -1.0_wp, -1.0_wp, 1.0_wp], [2, 2]), 2, 1, 0.01_wp, error)
      call check_no_error(suite, "two-DOF chain", error)
      if (allocated(error)) return
      call check_close(suite, "two-DOF: omega_1^2 = (3 - sqrt 5)/2", two%omega(1)**2, &
        & (3.0_wp - sqrt(5.0_wp))/2, 1.0e-14_wp)
      call check_close(suite, "two-DOF: omega_2^2 = (3 + sqrt 5)/2", two%omega(2)**2, &
        & (3.0_wp + sqrt(5.0_wp))/2, 1.0e-14_wp)
      beta = 2*0.01_wp/two%omega1
      do i = 0, 4
        om = two%omega1*(0.9_wp + 0.05_wp*i)
        d = cmplx(1.0_wp + 0*om, om*beta, wp)*reshape([(2.0_wp, 0.0_wp), (-1.0_wp, 0.0_wp), &
          & (-1.0_wp, 0.0_wp), (1.0_wp, 0.0_wp)], [2, 2]) - om**2*reshape([(1.0_wp, 0.0_wp), &
          & (0.0_wp, 0.0_wp), (0.0_wp, 0.0_wp), (1.0_wp, 0.0_wp)], [2, 2])
        det = d(1, 1)*d(2, 2) - d(1, 2)*d(2, 1)
        call two%receptances(om, r, error)
        ! g = DOF 2, E = DOF 1: H_gE = -d21/det, H_gg = d11/det, H_EE = d22/det.
        call close_c("two-DOF: H_gE", r%gE, -d(2, 1)/det, 1.0e-13_wp)
        call close_c("two-DOF: H_gg", r%gg, d(1, 1)/det, 1.0e-13_wp)
        call close_c("two-DOF: H_EE", r%EE, d(2, 2)/det, 1.0e-13_wp)
      end do
    end subroutine small_closed_forms

    !> Explicit C: C = beta K given as a matrix gives the modal result (direct complex solve);
    !> a general C (Rayleigh plus a dashpot on gamma_P) against the quad solve.
    subroutine explicit_damping()
      type(blade_type) :: c1, c2
      real(wp), allocatable :: c(:, :)
      real(wp) :: worst
      allocate(c, source=b%beta*b%K)
      call new_matrices_blade(c1, b%M, b%K, b%gamma_dof, b%exc_dof, 0.0_wp, error, C=c, &
        & s_K=b%s_K, s_M=b%s_M)
      call check_no_error(suite, "explicit C = beta K builds", error)
      if (allocated(error)) return
      call check_true(suite, "explicit C flagged", c1%explicit_C)
      worst = compare(c1, band(1:13), 1.0e-10_wp, "explicit C = beta K")
      c = 3.0_wp*b%M + 0.5_wp*b%beta*b%K
      c(b%gamma_dof, b%gamma_dof) = c(b%gamma_dof, b%gamma_dof) + 0.05_wp
      call new_matrices_blade(c2, b%M, b%K, b%gamma_dof, b%exc_dof, 0.0_wp, error, C=c, &
        & s_K=b%s_K, s_M=b%s_M)
      call check_no_error(suite, "general explicit C builds", error)
      if (allocated(error)) return
      worst = max(worst, compare(c2, band, 1.0e-10_wp, "general explicit C"))
      write(*, '(a, es10.2)') "explicit C: largest relative error ", worst
    end subroutine explicit_damping

    !> d/d omega against central differences (step 1e-6 omega), 1e-6 relative.
    subroutine derivatives()
      type(blade_type) :: large, cb
      real(wp), allocatable :: c(:, :)
      real(wp), parameter :: f(5) = [150.0_wp, 187.1_wp, 200.0_wp, 1000.0_wp, 20000.0_wp]
      call new_beam_blade(large, a, error, kept_modes=20)
      allocate(c, source=3.0_wp*b%M + 0.5_wp*b%beta*b%K)
      call new_matrices_blade(cb, b%M, b%K, b%gamma_dof, b%exc_dof, 0.0_wp, error, C=c, &
        & s_K=b%s_K, s_M=b%s_M)
      call fd_check(b, f, "default")
      call fd_check(large, f, "large path")
      call fd_check(cb, f, "explicit C")
    end subroutine derivatives

    !> Derivatives of `bl` at the frequencies f [Hz] against central differences.
    subroutine fd_check(bl, f, label)
      type(blade_type), intent(in) :: bl
      real(wp), intent(in) :: f(:)
      character(len=*), intent(in) :: label
      type(receptances_type) :: r, rp, rm
      real(wp) :: om, h
      integer :: i
      character(len=64) :: name
      do i = 1, size(f)
        om = 2*pi*f(i)
        h = 1.0e-6_wp*om
        call bl%receptances(om, r, error, derivatives=.true.)
        call bl%receptances(om + h, rp, error)
        call bl%receptances(om - h, rm, error)
        write(name, '(a, f9.1, a)') label//" at ", f(i), " Hz"
        call close_c(trim(name)//": dH_gE", r%dgE, (rp%gE - rm%gE)/(2*h), 1.0e-6_wp)
        call close_c(trim(name)//": dH_gg", r%dgg, (rp%gg - rm%gg)/(2*h), 1.0e-6_wp)
        call close_c(trim(name)//": dH_EE", r%dEE, (rp%EE - rm%EE)/(2*h), 1.0e-6_wp)
        call close_c(trim(name)//": dH_sE", r%dsE, (rp%sE - rm%sE)/(2*h), 1.0e-6_wp)
        call close_c(trim(name)//": dH_sg", r%dsg, (rp%sg - rm%sg)/(2*h), 1.0e-6_wp)
        ! Values are the same with and without derivatives.
        call bl%receptances(om, rp, error)
        call close_c(trim(name)//": H_gE with derivatives", r%gE, rp%gE, 1.0e-14_wp)
        call close_c(trim(name)//": H_sE with derivatives", r%sE, rp%sE, 1.0e-14_wp)
      end do
    end subroutine fd_check

    !> g~, s~, u~_E from the bare receptances equal a direct solve of (D + k e_g e_g^T) q = e_E,
    !> 1e-10 relative, for a stuck-like, a partial-slip-like and a large complex k, at and away
    !> from the bare resonance and at the resonance of the blade with the damper.
    subroutine sherman_morrison()
      complex(wp), parameter :: ks(3) = [(1.3e4_wp, 0.0_wp), (5.0e3_wp, 3.0e3_wp), (1.0e7_wp, 1.0e6_wp)]
      type(receptances_type) :: r
      complex(wp) :: g, s, ue, gref, sref, uref
      real(wp) :: f(6), fpk, best, worst
      integer :: i, j, n
      character(len=80) :: name
      worst = 0
      do i = 1, size(ks)
        ! Resonance of the blade with this damper: the peak of |g~| on a 0.01 Hz grid.
        best = 0
        fpk = 0
        do n = 0, 40000
          call b%receptances(2*pi*(150.0_wp + 0.01_wp*n), r, error)
          call layer_response(r, ks(i), g, s, ue)
          if (abs(g) > best) then
            best = abs(g)
            fpk = 150.0_wp + 0.01_wp*n
          end if
        end do
        write(*, '(a, 2es10.2, a, f10.3, a)') "k = ", ks(i), ": resonance with the damper at ", fpk, " Hz"
        f = [150.0_wp, 187.119057676_wp, fpk, fpk + 0.3_wp, 230.0_wp, 1000.0_wp]
        do j = 1, size(f)
          call b%receptances(2*pi*f(j), r, error)
          call layer_response(r, ks(i), g, s, ue)
          call reference(b, 2*pi*f(j), ks(i), gref, sref, uref)
          write(name, '(a, 2es9.1, a, f9.3, a)') "layer response k = ", ks(i), " at ", f(j), " Hz"
          call close_c(trim(name)//": g~", g, gref, 1.0e-10_wp)
          call close_c(trim(name)//": s~", s, sref, 1.0e-10_wp)
          call close_c(trim(name)//": u~_E", ue, uref, 1.0e-10_wp)
          worst = max(worst, abs(g - gref)/abs(gref), abs(s - sref)/abs(sref), abs(ue - uref)/abs(uref))
        end do
      end do
      write(*, '(a, es10.2)') "Sherman-Morrison vs direct solve: largest relative error ", worst
      ! k = 0 gives the bare receptances.
      call b%receptances(2*pi*200.0_wp, r, error)
      call layer_response(r, (0.0_wp, 0.0_wp), g, s, ue)
      call close_c("k = 0: g~ = H_gE", g, r%gE, 0.0_wp)
      call close_c("k = 0: u~_E = H_EE", ue, r%EE, 0.0_wp)
    end subroutine sherman_morrison

    !> Export to Matrix Market and import: the same receptances (stress included) to 1e-12.
    subroutine export_import()
      type(blade_type) :: c, large, cl
      character(len=:), allocatable :: dir
      type(receptances_type) :: r1, r2
      real(wp) :: worst
      integer :: i
      logical :: exists
      dir = temp_dir("blade_"//"export")
      call export_blade(b, dir, error)
      call check_no_error(suite, "export blade A", error)
      if (allocated(error)) return
      inquire(file=dir//"/blade.json", exist=exists)
      call check_true(suite, "export writes blade.json", exists)
      call read_matrices_blade(c, dir//"/M.mtx", dir//"/K.mtx", b%gamma_dof, b%exc_dof, b%zeta, error, &
        & sK_path=dir//"/stress_K.mtx", sM_path=dir//"/stress_M.mtx")
      call check_no_error(suite, "import blade A", error)
      if (allocated(error)) return
      call check_true(suite, "imported matrices are exact", all(c%K == b%K) .and. all(c%M == b%M) &
        & .and. all(c%s_K == b%s_K) .and. all(c%s_M == b%s_M))
      worst = 0
      do i = 1, size(band)
        call b%receptances(2*pi*band(i), r1, error)
        call c%receptances(2*pi*band(i), r2, error)
        worst = max(worst, rel(r1%gE, r2%gE), rel(r1%gg, r2%gg), rel(r1%EE, r2%EE), &
          & rel(r1%sE, r2%sE), rel(r1%sg, r2%sg))
      end do
      call check_close(suite, "export/import: same receptances to 1e-12", worst, 0.0_wp, 0.0_wp, 1.0e-12_wp)
      ! The same through the large-model path, and with explicit C.
      call new_beam_blade(large, a, error, kept_modes=20)
      call read_matrices_blade(cl, dir//"/M.mtx", dir//"/K.mtx", b%gamma_dof, b%exc_dof, b%zeta, error, &
        & sK_path=dir//"/stress_K.mtx", sM_path=dir//"/stress_M.mtx", kept_modes=20)
      call check_no_error(suite, "import on the large-model path", error)
      worst = 0
      do i = 1, size(band)
        call large%receptances(2*pi*band(i), r1, error)
        call cl%receptances(2*pi*band(i), r2, error)
        worst = max(worst, rel(r1%gE, r2%gE), rel(r1%sE, r2%sE), rel(r1%sg, r2%sg))
      end do
      call check_close(suite, "export/import, large path: same receptances to 1e-12", worst, 0.0_wp, &
        & 0.0_wp, 1.0e-12_wp)
      block
        type(blade_type) :: ce, ci
        real(wp), allocatable :: cm(:, :)
        allocate(cm, source=3.0_wp*b%M + 0.5_wp*b%beta*b%K)
        call new_matrices_blade(ce, b%M, b%K, b%gamma_dof, b%exc_dof, 0.0_wp, error, C=cm, s_K=b%s_K)
        call export_blade(ce, dir, error)
        call check_no_error(suite, "export with explicit C", error)
        inquire(file=dir//"/C.mtx", exist=exists)
        call check_true(suite, "C.mtx written", exists)
        call read_matrices_blade(ci, dir//"/M.mtx", dir//"/K.mtx", b%gamma_dof, b%exc_dof, 0.0_wp, &
          & error, C_path=dir//"/C.mtx", sK_path=dir//"/stress_K.mtx", sM_path=dir//"/stress_M.mtx")
        call check_no_error(suite, "import with explicit C", error)
        if (allocated(error)) return
        call ce%receptances(2*pi*187.0_wp, r1, error)
        call ci%receptances(2*pi*187.0_wp, r2, error)
        call check_close(suite, "explicit C round trip", max(rel(r1%gE, r2%gE), rel(r1%sE, r2%sE)), &
          & 0.0_wp, 0.0_wp, 1.0e-12_wp)
      end block
      call execute_command_line("rm -rf "//dir)
    end subroutine export_import

    subroutine bad_matrices()
      type(blade_type) :: c
      type(receptances_type) :: r
      real(wp), allocatable :: k(:, :), m(:, :)
      real(wp) :: nan
      nan = ieee_nan()
      call new_matrices_blade(c, b%M, b%K(1:63, 1:63), 16, 39, 0.002_wp, error)
      call check_error(suite, "K of another size", error, UDMAP_EINPUT, "K must be a square matrix")
      call new_matrices_blade(c, b%M(:, 1:63), b%K, 16, 39, 0.002_wp, error)
      call check_error(suite, "non-square M", error, UDMAP_EINPUT, "M must be a non-empty square")
      allocate(k, source=b%K)
      k(3, 7) = k(3, 7) + 1.0e3_wp
      call new_matrices_blade(c, b%M, k, 16, 39, 0.002_wp, error)
      call check_error(suite, "non-symmetric K", error, UDMAP_EINPUT, "K is not symmetric: entry (7, 3)")
      call new_matrices_blade(c, b%M, b%K, 0, 39, 0.002_wp, error)
      call check_error(suite, "gamma_dof 0", error, UDMAP_EINPUT, "gamma_dof must be a DOF number from 1 to 64")
      call new_matrices_blade(c, b%M, b%K, 65, 39, 0.002_wp, error)
      call check_error(suite, "gamma_dof 65", error, UDMAP_EINPUT, "gamma_dof")
      call new_matrices_blade(c, b%M, b%K, 16, -1, 0.002_wp, error)
      call check_error(suite, "exc_dof -1", error, UDMAP_EINPUT, "exc_dof")
      call new_matrices_blade(c, b%M, b%K, 16, 39, nan, error)
      call check_error(suite, "NaN zeta", error, UDMAP_EINPUT, "zeta must be a non-negative")
      call new_matrices_blade(c, b%M, b%K, 16, 39, 0.002_wp, error, s_K=b%s_K(1:60))
      call check_error(suite, "short stress row", error, UDMAP_EINPUT, "stress_K must have 64 entries")
      k = b%K
      k(5, 5) = nan
      call new_matrices_blade(c, b%M, k, 16, 39, 0.002_wp, error)
      call check_error(suite, "NaN in K", error, UDMAP_EINPUT, "K has a non-finite entry")
      allocate(m, source=b%M)
      m(20, 20) = -1.0_wp
      call new_matrices_blade(c, m, b%K, 16, 39, 0.002_wp, error)
      call check_error(suite, "indefinite M", error, UDMAP_EINPUT, "M is not positive definite")
      ! A free-free beam (clamp removed): K singular.
      k = 0
      k(1:2, 1:2) = reshape([1.0_wp, -1.0_wp, -1.0_wp, 1.0_wp], [2, 2])
      call new_matrices_blade(c, b%M(1:2, 1:2), k(1:2, 1:2), 1, 2, 0.0_wp, error)
      call check_error(suite, "singular K", error, UDMAP_EINPUT, "K is not positive definite")
      call new_matrices_blade(c, b%M, b%K, 16, 39, 0.002_wp, error, C=b%K(1:10, 1:10))
      call check_error(suite, "C of another size", error, UDMAP_EINPUT, "C must be a square matrix")
      call b%receptances(-1.0_wp, r, error)
      call check_error(suite, "negative frequency", error, UDMAP_EINPUT, "frequency must be a non-negative")
      call b%receptances(nan, r, error)
      call check_error(suite, "NaN frequency", error, UDMAP_EINPUT, "frequency")
      call read_matrices_blade(c, "no/such/M.mtx", "no/such/K.mtx", 16, 39, 0.002_wp, error)
      call check_error(suite, "missing Matrix Market file", error, UDMAP_EINPUT, "'no/such/M.mtx' not found")
    end subroutine bad_matrices

    ! ------------------------------------------------------------------ helpers

    !> Largest relative error of all five receptances of `bl` against the quad reference over
    !> the frequencies f [Hz], each checked to rtol. H_sg vanishes statically (a moment on the
    !> platform does not load the free airfoil), so it is not compared below 100 Hz.
    real(wp) function compare(bl, f, rtol, label) result(worst)
      type(blade_type), intent(in) :: bl
      real(wp), intent(in) :: f(:), rtol
      character(len=*), intent(in) :: label
      type(receptances_type) :: r, rr
      real(wp) :: e
      integer :: i
      character(len=80) :: name
      worst = 0
      do i = 1, size(f)
        call bl%receptances(2*pi*f(i), r, error)
        write(name, '(a, f10.3, a)') label//" at ", f(i), " Hz"
        call check_no_error(suite, trim(name), error)
        rr = reference_receptances(bl, 2*pi*f(i))
        e = max(rel(r%gE, rr%gE), rel(r%gg, rr%gg), rel(r%EE, rr%EE), rel(r%sE, rr%sE))
        if (f(i) >= 100.0_wp) e = max(e, rel(r%sg, rr%sg))
        call check_close(suite, trim(name)//": receptances", e, 0.0_wp, 0.0_wp, rtol)
        worst = max(worst, e)
      end do
    end function compare

    real(wp) function rel(x, y)
      complex(wp), intent(in) :: x, y
      rel = abs(x - y)/abs(y)
    end function rel

    subroutine close_c(name, x, y, rtol)
      character(len=*), intent(in) :: name
      complex(wp), intent(in) :: x, y
      real(wp), intent(in) :: rtol
      call check_close(suite, name, abs(x - y), 0.0_wp, 0.0_wp, rtol*abs(y))
    end subroutine close_c

    !> Bare receptances by the quad direct solve.
    function reference_receptances(bl, omega) result(r)
      type(blade_type), intent(in) :: bl
      real(wp), intent(in) :: omega
      type(receptances_type) :: r
      complex(qp), allocatable :: x(:, :)
      call quad_solve(bl, omega, (0.0_wp, 0.0_wp), x)
      r = receptances_from_solution(bl, omega, x)
    end function reference_receptances

    !> Layer response by the quad direct solve of (D + k e_g e_g^T) q = e_E.
    subroutine reference(bl, omega, k, g, s, ue)
      type(blade_type), intent(in) :: bl
      real(wp), intent(in) :: omega
      complex(wp), intent(in) :: k
      complex(wp), intent(out) :: g, s, ue
      complex(qp), allocatable :: x(:, :)
      call quad_solve(bl, omega, k, x)
      g = cmplx(x(bl%gamma_dof, 1), kind=wp)
      ue = cmplx(x(bl%exc_dof, 1), kind=wp)
      s = cmplx(sum((real(bl%s_K, qp) - real(omega, qp)**2*real(bl%s_M, qp))*x(:, 1)), kind=wp)
    end subroutine reference

    !> Solves (K - omega^2 M + i omega C + k e_g e_g^T) x = [e_E, e_g] in quadruple precision
    !> (C = beta K or the explicit C), Gaussian elimination with partial pivoting.
    subroutine quad_solve(bl, omega, k, x)
      type(blade_type), intent(in) :: bl
      real(wp), intent(in) :: omega
      complex(wp), intent(in) :: k
      complex(qp), allocatable, intent(out) :: x(:, :)
      complex(qp), allocatable :: d(:, :), row(:)
      complex(qp) :: t, xrow(2)
      real(qp) :: om
      integer :: n, i, j, p
      n = bl%ndof
      om = real(omega, qp)
      allocate(d(n, n), x(n, 2), row(n))
      if (bl%explicit_C) then
        d = cmplx(real(bl%K, qp) - om**2*real(bl%M, qp), om*real(bl%C, qp), qp)
      else
        d = cmplx(real(bl%K, qp) - om**2*real(bl%M, qp), om*real(bl%beta, qp)*real(bl%K, qp), qp)
      end if
      d(bl%gamma_dof, bl%gamma_dof) = d(bl%gamma_dof, bl%gamma_dof) + cmplx(k, kind=qp)
      x = 0
      x(bl%exc_dof, 1) = 1
      x(bl%gamma_dof, 2) = 1
      do j = 1, n
        p = j - 1 + maxloc(abs(d(j:n, j)), 1)
        if (p /= j) then
          row = d(j, :)
          d(j, :) = d(p, :)
          d(p, :) = row
          xrow = x(j, :)
          x(j, :) = x(p, :)
          x(p, :) = xrow
        end if
        do i = j + 1, n
          if (d(i, j) == 0) cycle
          t = d(i, j)/d(j, j)
          d(i, j+1:n) = d(i, j+1:n) - t*d(j, j+1:n)
          x(i, :) = x(i, :) - t*x(j, :)
        end do
      end do
      do j = n, 1, -1
        x(j, 1) = (x(j, 1) - sum(d(j, j+1:n)*x(j+1:n, 1)))/d(j, j)
        x(j, 2) = (x(j, 2) - sum(d(j, j+1:n)*x(j+1:n, 2)))/d(j, j)
      end do
    end subroutine quad_solve

  end subroutine run_blade_receptances
end module test_blade_receptances
