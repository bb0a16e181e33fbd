!> Benchmark of the damper stiffness table for blade_a (one core): the full table from
!> scratch, the issue's reference workload (base cycle plus 40 direct loops below gamma_b),
!> and the cost of one k(gamma) evaluation. Prints a JSON array of records on stdout.
program bench_table
  use, intrinsic :: iso_fortran_env, only: int64, output_unit
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_damper_type, only: damper_type, asymmetric_params_type, new_asymmetric_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_damper_tracer_core, only: damper_geometry_type
  use udmap_damper_tracer, only: new_damper_geometry
  use udmap_damper_loops, only: ramp_type, base_cycle_type, loop_type, loop_workspace_type, &
    & trace_ramp, trace_base_cycle, steady_loop, loop_stiffness
  implicit none
  integer, parameter :: REPEATS = 301
  type(damper_type) :: d
  type(error_type), allocatable :: error
  real(wp) :: t(REPEATS), gamma_b, sink
  integer :: r

  call new_asymmetric_damper(d, blade_a_damper_params(), error)
  if (allocated(error)) error stop "bench_table: blade_a damper failed"
  gamma_b = d%gamma_b
  sink = 0

  write(output_unit, '(a)') "["
  ! 1. The full table as udmap builds it.
  do r = 1, REPEATS
    t(r) = now()
    call new_asymmetric_damper(d, blade_a_damper_params(), error)
    t(r) = now() - t(r)
  end do
  call emit("full_table", t, 1, d%table%n_int, ",")
  ! 2. Base cycle plus 40 loops below gamma_b, each with its own history.
  do r = 1, REPEATS
    t(r) = now()
    call base_plus_40()
    t(r) = now() - t(r)
  end do
  call emit("base_cycle_plus_40_loops", t, 1, 40, ",")
  ! 3. One k(gamma) evaluation, in each regime (1e5 calls per sample).
  call eval_time(0.5_wp*d%gamma_s, "eval_stuck", ",")
  call eval_time(0.5_wp*(d%gamma_s + gamma_b), "eval_partial_slip", ",")
  call eval_time(3*gamma_b, "eval_above_gamma_b", "")
  write(output_unit, '(a)') "]"
  if (sink == 12345) write(output_unit, *) sink

contains

  real(wp) function now()
    integer(int64) :: c, rate
    call system_clock(c, rate)
    now = real(c, wp)/real(rate, wp)
  end function now

  subroutine base_plus_40()
    type(asymmetric_params_type) :: params
    type(damper_geometry_type) :: geo
    type(ramp_type) :: ramp
    type(base_cycle_type) :: base
    type(loop_type) :: lp
    type(loop_workspace_type) :: work
    type(error_type), allocatable :: err
    complex(wp) :: k
    integer :: i
    params = blade_a_damper_params()
    call new_damper_geometry(geo, params, err)
    call trace_ramp(geo, params%CF, ramp, err)
    call trace_base_cycle(geo, ramp, base, err)
    do i = 1, 40
      call steady_loop(geo, ramp, base%gamma_b*10.0_wp**(-2*(40 - i)/39.0_wp), lp, work, err)
      call loop_stiffness(lp, lp%p0, k)
      sink = sink + real(k, wp)
    end do
    if (allocated(err)) error stop "bench_table: tracing failed"
  end subroutine base_plus_40

  subroutine eval_time(g0, name, sep)
    real(wp), intent(in) :: g0
    character(len=*), intent(in) :: name, sep
    integer, parameter :: n = 100000
    real(wp) :: te(31)
    integer :: i, j
    do j = 1, size(te)
      te(j) = now()
      do i = 1, n
        sink = sink + real(d%stiffness(g0*(1 + 1e-9_wp*i)), wp)
      end do
      te(j) = now() - te(j)
    end do
    call emit(name, te, n, 0, sep)
  end subroutine eval_time

  !> One record of INTERFACES.md "Benchmark output" (seconds per call of the setting).
  subroutine emit(setting, samples, inner, count, sep)
    character(len=*), intent(in) :: setting, sep
    real(wp), intent(in) :: samples(:)
    integer, intent(in) :: inner, count
    real(wp) :: s(size(samples))
    character(len=400) :: line
    s = sort(samples)/inner
    write(line, '(a, a, a, es12.5, a, es12.5, a, es12.5, a, i0, a, i0, a)') &
      & '{"case": "blade_a", "method": "table", "setting": "', setting, &
      & '", "seconds_median": ', s((size(s) + 1)/2), ', "seconds_min": ', s(1), &
      & ', "seconds_max": ', s(size(s)), ', "repeats": ', size(s), &
      & ', "error_gamma_P": null, "error_sigma_a": null, "error_f_res": null, "count": ', count, '}'
    write(output_unit, '(2a)') trim(line), sep
  end subroutine emit

  pure function sort(x) result(y)
    real(wp), intent(in) :: x(:)
    real(wp) :: y(size(x)), v
    integer :: i, j
    y = x
    do i = 2, size(y)
      v = y(i)
      j = i - 1
      do while (j >= 1)
        if (y(j) <= v) exit
        y(j+1) = y(j)
        j = j - 1
      end do
      y(j+1) = v
    end do
  end function sort
end program bench_table
