!> C API, section "damper" of wrappers/c/udmap.h: create a damper, read its base-cycle data,
!> evaluate k(gamma), dk/dgamma and the loop, change CF. Handles point to type(damper_type)
!> objects (module udmap_damper_type) allocated here.
module udmap_api_c_damper
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, c_loc, &
    & c_int, c_double
  use udmap_core_kinds, only: wp, pi
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input, take_handle
  ! udmap_asymmetric_params and its conversion, generated from kernel/parameters.toml
  use udmap_api_c_parameters, only: udmap_asymmetric_params, asymmetric_from_c
  use udmap_damper_type, only: damper_type, new_asymmetric_damper, &
    & new_jenkins_damper, new_table_damper, check_amplitudes
  implicit none
  private
  public :: udmap_asymmetric_params, udmap_damper_info, damper_from_handle, asymmetric_from_c

  !> udmap_damper_info.
  type, bind(C) :: udmap_damper_info
    real(c_double) :: gamma_b, gamma_s, M_max, M_min, k_stuck
    integer(c_int) :: lift_off
  end type udmap_damper_info

contains

  !> The damper behind a C handle (an input error naming `name` for NULL).
  subroutine damper_from_handle(handle, damper, name, error)
    type(c_ptr), intent(in) :: handle
    type(damper_type), pointer, intent(out) :: damper
    character(len=*), intent(in) :: name
    type(error_type), allocatable, intent(out) :: error
    damper => null()
    call check_handle(handle, name, error)
    if (.not. allocated(error)) call c_f_pointer(handle, damper)
  end subroutine damper_from_handle

  function udmap_new_damper_asymmetric(herr, params, hdamper) result(stat) &
      & bind(C, name="udmap_new_damper_asymmetric")
    type(c_ptr), value :: herr
    type(udmap_asymmetric_params), intent(in) :: params
    type(c_ptr), intent(out) :: hdamper
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    call start_new(herr, hdamper, d)
    call new_asymmetric_damper(d, asymmetric_from_c(params), error)
    stat = finish_new(herr, d, error, hdamper)
  end function udmap_new_damper_asymmetric

  function udmap_new_damper_jenkins(herr, kt, M_slip, hdamper) result(stat) &
      & bind(C, name="udmap_new_damper_jenkins")
    type(c_ptr), value :: herr
    real(c_double), value :: kt, M_slip
    type(c_ptr), intent(out) :: hdamper
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    call start_new(herr, hdamper, d)
    call new_jenkins_damper(d, real(kt, wp), real(M_slip, wp), error)
    stat = finish_new(herr, d, error, hdamper)
  end function udmap_new_damper_jenkins

  function udmap_new_damper_table(herr, n, gamma, k_re, k_im, has_delta_M, delta_M, hdamper) &
      & result(stat) bind(C, name="udmap_new_damper_table")
    type(c_ptr), value :: herr
    integer(c_int), value :: n, has_delta_M
    real(c_double), intent(in) :: gamma(*), k_re(*), k_im(*)
    real(c_double), value :: delta_M
    type(c_ptr), intent(out) :: hdamper
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    call start_new(herr, hdamper, d)
    call check_input(n >= 2, "udmap_new_damper_table: 'n' must be at least 2", error)
    if (.not.allocated(error)) then
      if (has_delta_M /= 0) then
        call new_table_damper(d, real(gamma(1:n), wp), real(k_re(1:n), wp), &
          & real(k_im(1:n), wp), error, real(delta_M, wp))
      else
        call new_table_damper(d, real(gamma(1:n), wp), real(k_re(1:n), wp), &
          & real(k_im(1:n), wp), error)
      end if
    end if
    stat = finish_new(herr, d, error, hdamper)
  end function udmap_new_damper_table

  subroutine udmap_delete_damper(hdamper) bind(C, name="udmap_delete_damper")
    type(c_ptr), intent(inout) :: hdamper
    type(damper_type), pointer :: d
    if (.not.c_associated(hdamper)) return
    call c_f_pointer(take_handle(hdamper), d)
    deallocate(d)
  end subroutine udmap_delete_damper

  function udmap_damper_get_info(herr, hdamper, info) result(stat) &
      & bind(C, name="udmap_damper_get_info")
    type(c_ptr), value :: herr, hdamper
    type(udmap_damper_info), intent(out) :: info
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    call clear_error(herr)
    info = udmap_damper_info(0, 0, 0, 0, 0, 0)
    call damper_from_handle(hdamper, d, "damper", error)
    if (.not. allocated(error)) then
      info%gamma_b = d%gamma_b
      info%gamma_s = d%gamma_s
      info%M_max = d%M_max
      info%M_min = d%M_min
      info%k_stuck = d%k_stuck
      info%lift_off = merge(1_c_int, 0_c_int, d%lift_off)
    end if
    stat = set_error(herr, error)
  end function udmap_damper_get_info

  function udmap_damper_stiffness(herr, hdamper, n, gamma, k_re, k_im) result(stat) &
      & bind(C, name="udmap_damper_stiffness")
    type(c_ptr), value :: herr, hdamper
    integer(c_int), value :: n
    real(c_double), intent(in) :: gamma(*)
    real(c_double), intent(out) :: k_re(*), k_im(*)
    integer(c_int) :: stat
    stat = evaluate_stiffness(herr, hdamper, n, gamma, k_re, k_im, derivative=.false.)
  end function udmap_damper_stiffness

  function udmap_damper_stiffness_derivative(herr, hdamper, n, gamma, dk_re, dk_im) result(stat) &
      & bind(C, name="udmap_damper_stiffness_derivative")
    type(c_ptr), value :: herr, hdamper
    integer(c_int), value :: n
    real(c_double), intent(in) :: gamma(*)
    real(c_double), intent(out) :: dk_re(*), dk_im(*)
    integer(c_int) :: stat
    stat = evaluate_stiffness(herr, hdamper, n, gamma, dk_re, dk_im, derivative=.true.)
  end function udmap_damper_stiffness_derivative

  !> k(gamma) or dk/dgamma for n checked amplitudes, as (re, im) arrays; the status.
  function evaluate_stiffness(herr, hdamper, n, gamma, out_re, out_im, derivative) result(stat)
    type(c_ptr), intent(in) :: herr, hdamper
    integer(c_int), intent(in) :: n
    real(c_double), intent(in) :: gamma(*)
    real(c_double), intent(out) :: out_re(*), out_im(*)
    logical, intent(in) :: derivative
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    complex(wp) :: k
    integer :: i
    call clear_error(herr)
    call damper_from_handle(hdamper, d, "damper", error)
    if (.not. allocated(error)) call check_c_amplitudes(d, n, gamma, error)
    if (.not. allocated(error)) then
      do i = 1, n
        if (derivative) then
          k = d%stiffness_derivative(real(gamma(i), wp))
        else
          k = d%stiffness(real(gamma(i), wp))
        end if
        out_re(i) = real(k, wp)
        out_im(i) = aimag(k)
      end do
    end if
    stat = set_error(herr, error)
  end function evaluate_stiffness

  function udmap_damper_loop(herr, hdamper, gamma_a, n, tau, M_r) result(stat) &
      & bind(C, name="udmap_damper_loop")
    type(c_ptr), value :: herr, hdamper
    real(c_double), value :: gamma_a
    integer(c_int), value :: n
    real(c_double), intent(out) :: tau(*), M_r(*)
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    real(wp), allocatable :: t(:), M(:)
    integer :: i
    call clear_error(herr)
    call damper_from_handle(hdamper, d, "damper", error)
    call check_input(n >= 1, "udmap_damper_loop: 'n' must be at least 1", error)
    if (.not. allocated(error)) then
      allocate(t(n), M(n))
      do i = 1, n
        t(i) = 2*pi*(i - 1)/n
      end do
      call d%loop(real(gamma_a, wp), t, M, error)
      if (.not. allocated(error)) then
        tau(1:n) = t
        M_r(1:n) = M
      end if
    end if
    stat = set_error(herr, error)
  end function udmap_damper_loop

  function udmap_damper_set_CF(herr, hdamper, CF) result(stat) bind(C, name="udmap_damper_set_CF")
    type(c_ptr), value :: herr, hdamper
    real(c_double), value :: CF
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    call clear_error(herr)
    call damper_from_handle(hdamper, d, "damper", error)
    if (.not. allocated(error)) call d%set_CF(real(CF, wp), error)
    stat = set_error(herr, error)
  end function udmap_damper_set_CF

  ! ------------------------------------------------------------------ internals

  !> n >= 0 and the amplitudes of the damper's check (udmap_damper_type's check_amplitudes).
  subroutine check_c_amplitudes(d, n, gamma, error)
    type(damper_type), intent(in) :: d
    integer(c_int), intent(in) :: n
    real(c_double), intent(in) :: gamma(*)
    type(error_type), allocatable, intent(out) :: error
    call check_input(n >= 0, "damper stiffness: 'n' must not be negative", error)
    if (.not. allocated(error)) call check_amplitudes(d, gamma(1:n), error)
  end subroutine check_c_amplitudes

  !> int udmap_damper_jump_count(error, damper, int *n): the number of jumps of k(gamma)
  !> (PHYSICS.md 2.5; 0 without lift-off).
  function udmap_damper_jump_count(herr, hdamper, n) result(stat) &
      & bind(C, name="udmap_damper_jump_count")
    type(c_ptr), value :: herr, hdamper
    integer(c_int), intent(out) :: n
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    call clear_error(herr)
    n = 0
    call damper_from_handle(hdamper, d, "damper", error)
    if (.not. allocated(error)) n = d%jump_count()
    stat = set_error(herr, error)
  end function udmap_damper_jump_count

  !> int udmap_damper_jump_get(error, damper, int i, double *gamma_c, double k_minus[2],
  !> double k_plus[2]): jump i (0-based, ascending gamma_c) at the current CF: its amplitude
  !> [rad] and the one-sided stiffnesses (re, im) [N m/rad] below and above it.
  function udmap_damper_jump_get(herr, hdamper, i, gamma_c, k_minus, k_plus) result(stat) &
      & bind(C, name="udmap_damper_jump_get")
    type(c_ptr), value :: herr, hdamper
    integer(c_int), value :: i
    real(c_double), intent(out) :: gamma_c, k_minus(2), k_plus(2)
    integer(c_int) :: stat
    type(damper_type), pointer :: d
    type(error_type), allocatable :: error
    real(wp) :: g
    complex(wp) :: km, kp
    call clear_error(herr)
    gamma_c = 0
    k_minus = 0
    k_plus = 0
    call damper_from_handle(hdamper, d, "damper", error)
    if (.not. allocated(error)) then
      if (i < 0 .or. i >= d%jump_count()) then
        call fatal_error(error, "udmap_damper_jump_get: 'i' must lie in [0, number of jumps)", &
          & UDMAP_EINPUT)
      else
        call d%jump(i + 1, g, km, kp)
        gamma_c = g
        k_minus = [real(km, wp), aimag(km)]
        k_plus = [real(kp, wp), aimag(kp)]
      end if
    end if
    stat = set_error(herr, error)
  end function udmap_damper_jump_get

  !> The start of a constructor: the error handle cleared, the output handle NULL and a new
  !> damper to build.
  subroutine start_new(herr, hdamper, d)
    type(c_ptr), intent(in) :: herr
    type(c_ptr), intent(out) :: hdamper
    type(damper_type), pointer, intent(out) :: d
    call clear_error(herr)
    hdamper = c_null_ptr
    allocate(d)
  end subroutine start_new

  !> The end of a constructor: hands the new damper to C, or frees it on error; the status.
  function finish_new(herr, d, error, hdamper) result(stat)
    type(c_ptr), intent(in) :: herr
    type(damper_type), pointer, intent(inout) :: d
    type(error_type), allocatable, intent(inout) :: error
    type(c_ptr), intent(inout) :: hdamper
    integer(c_int) :: stat
    if (allocated(error)) then
      deallocate(d)
      hdamper = c_null_ptr
    else
      hdamper = c_loc(d)
    end if
    stat = set_error(herr, error)
  end function finish_new
end module udmap_api_c_damper
