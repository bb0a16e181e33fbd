!> Benchmark of the blade's hot path: time per call of blade%receptances (and of the layer
!> response) over the band of blade A's first mode, for each evaluation path, plus the setup
!> times (process CPU time, so that other load on the machine does not count): median, min and
!> max of `repeats` samples. Prints a table and, with the argument --json, one JSON object per
!> line (read by bench/bench_blade.py). Takes some ten seconds.
program blade_receptances
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, receptances_type, new_beam_blade, new_matrices_blade, &
    & layer_response
  implicit none
  type(beam_params_type) :: a
  type(blade_type) :: b, base
  type(error_type), allocatable :: error
  logical :: json
  character(len=16) :: arg
  real(wp), allocatable :: c(:, :)
  !> Samples per measurement.
  integer, parameter :: repeats = 5

  json = .false.
  if (command_argument_count() > 0) then
    call get_command_argument(1, arg)
    json = arg == "--json"
  end if
  a = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, &
    & neck_L=0.020_wp, neck_h=0.008_wp, neck_b=0.020_wp, &
    & platform_L=0.010_wp, platform_m=0.021_wp, platform_J=1.4e-6_wp, &
    & airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
    & neck_elements=8, airfoil_elements=24)

  call setup_time("blade A (64 DOFs): build", a, 0, 10)
  call new_beam_blade(b, a, error)
  call per_call("blade A, default (8 modes + series)", b, .false., 500000)
  call per_call("blade A, default, with derivatives", b, .true., 200000)
  call per_call_layer("blade A, layer response (receptances + Sherman-Morrison)", b, 500000)
  call new_beam_blade(b, a, error, kept_modes=64)
  call per_call("blade A, every mode summed (64)", b, .false., 200000)
  call new_beam_blade(b, a, error, kept_modes=20)
  call per_call("blade A, large-model path (20 modes + series)", b, .false., 200000)
  call new_beam_blade(base, a, error)
  allocate(c, source=base%beta*base%K)
  call new_matrices_blade(b, base%M, base%K, base%gamma_dof, base%exc_dof, 0.0_wp, error, C=c, &
    & s_K=base%s_K, s_M=base%s_M)
  call per_call("blade A, explicit C (direct refined solve)", b, .false., 500)
  a%airfoil_elements = 2048
  call setup_time("2048-element beam (4112 DOFs): build", a, 0, 1)
  call new_beam_blade(b, a, error)
  call per_call("2048-element beam, in band (20 modes + series)", b, .false., 200000)

contains

  subroutine per_call(label, bl, deriv, n)
    character(len=*), intent(in) :: label
    type(blade_type), intent(in) :: bl
    logical, intent(in) :: deriv
    integer, intent(in) :: n
    type(receptances_type) :: r
    real(wp) :: acc, om, t0, t1, samples(repeats)
    integer :: i, k
    acc = 0
    do k = 1, repeats
      call cpu_time(t0)
      do i = 1, n
        ! Sweep 150..230 Hz, as the mapping does.
        om = 2*pi*(150.0_wp + 80.0_wp*real(i, wp)/n)
        call bl%receptances(om, r, error, derivatives=deriv)
        acc = acc + r%gE%re
      end do
      call cpu_time(t1)
      samples(k) = (t1 - t0)/n
    end do
    if (allocated(error)) then
      write(*, '(a)') label//": "//error%message
      return
    end if
    call report(label, samples, "per call", acc)
  end subroutine per_call

  subroutine per_call_layer(label, bl, n)
    character(len=*), intent(in) :: label
    type(blade_type), intent(in) :: bl
    integer, intent(in) :: n
    type(receptances_type) :: r
    complex(wp) :: g, s, u
    real(wp) :: acc, om, t0, t1, samples(repeats)
    integer :: i, k
    acc = 0
    do k = 1, repeats
      call cpu_time(t0)
      do i = 1, n
        om = 2*pi*(150.0_wp + 80.0_wp*real(i, wp)/n)
        call bl%receptances(om, r, error)
        call layer_response(r, (1.3e4_wp, 2.0e3_wp), g, s, u)
        acc = acc + g%re
      end do
      call cpu_time(t1)
      samples(k) = (t1 - t0)/n
    end do
    call report(label, samples, "per call", acc)
  end subroutine per_call_layer

  subroutine setup_time(label, p, kept, n)
    character(len=*), intent(in) :: label
    type(beam_params_type), intent(in) :: p
    integer, intent(in) :: kept, n
    type(blade_type) :: bl
    real(wp) :: t0, t1, samples(repeats)
    integer :: i, k
    do k = 1, repeats
      call cpu_time(t0)
      do i = 1, n
        if (kept > 0) then
          call new_beam_blade(bl, p, error, kept_modes=kept)
        else
          call new_beam_blade(bl, p, error)
        end if
      end do
      call cpu_time(t1)
      samples(k) = (t1 - t0)/n
    end do
    call report(label, samples, "per build", bl%omega1)
  end subroutine setup_time

  !> Median, min and max of the samples, as a table row or a JSON line.
  subroutine report(label, samples, unit, checksum)
    character(len=*), intent(in) :: label, unit
    real(wp), intent(in) :: samples(:), checksum
    real(wp) :: s(size(samples)), med, t
    integer :: i, j
    s = samples
    do i = 2, size(s)
      t = s(i)
      j = i - 1
      do while (j >= 1)
        if (s(j) <= t) exit
        s(j+1) = s(j)
        j = j - 1
      end do
      s(j+1) = t
    end do
    med = s((size(s) + 1)/2)
    if (json) then
      write(*, '(a, 3(es12.5, a), i0, a)') '{"setting": "'//label//'", "seconds_median": ', med, &
        & ', "seconds_min": ', s(1), ', "seconds_max": ', s(size(s)), ', "repeats": ', size(s), &
        & ', "unit": "'//unit//'"}'
    else if (med < 1.0e-3_wp) then
      write(*, '(a60, f12.1, a, es10.2)') label, med*1.0e9_wp, " ns "//unit//"  (checksum", checksum
    else
      write(*, '(a60, f12.3, a, es10.2)') label, med, " s  "//unit//"  (checksum", checksum
    end if
  end subroutine report
end program blade_receptances
