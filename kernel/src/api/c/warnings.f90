!> C API, plausibility warnings (wrappers/c/udmap.h, section "plausibility warnings"): the
!> checks of udmap_mapping_plausibility for a blade, damper and band, or for a model, as kinds
!> (UDMAP_WARNING_*) and texts in the caller's buffers.
module udmap_api_c_warnings
  use, intrinsic :: iso_c_binding, only: c_ptr, c_associated, c_f_pointer, c_int, c_double, &
    & c_char
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_api_c_support, only: set_error, clear_error, check_handle, check_input, put_out, &
    & copy_string
  use udmap_api_c_model, only: c_model_type, model_from_handle
  use udmap_blade_type, only: blade_type
  use udmap_damper_type, only: damper_type
  use udmap_mapping_plausibility, only: warning_type, plausibility_warnings, model_warnings
  implicit none
  private

contains

  !> int udmap_plausibility_warnings(error, blade, damper, f_min, f_max, nmax, len, kinds,
  !>   texts, n): the warnings of a blade, a damper (NULL: its check left out) and a band [Hz],
  !>   without the stuck peak.
  function udmap_plausibility_warnings(errh, bladeh, damperh, f_min, f_max, nmax, len, kinds, &
      & texts, n) result(stat) bind(C, name="udmap_plausibility_warnings")
    type(c_ptr), value :: errh, bladeh, damperh, kinds, texts, n
    real(c_double), value :: f_min, f_max
    integer(c_int), value :: nmax, len
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(blade_type), pointer :: blade
    type(damper_type), pointer :: damper
    type(warning_type), allocatable :: warnings(:)
    call clear_error(errh)
    call check_handle(bladeh, "blade", error)
    call check_buffers(nmax, len, kinds, texts, n, error)
    if (.not. allocated(error)) then
      call c_f_pointer(bladeh, blade)
      if (c_associated(damperh)) then
        call c_f_pointer(damperh, damper)
        call plausibility_warnings(blade, real(f_min, wp), real(f_max, wp), warnings, damper)
      else
        call plausibility_warnings(blade, real(f_min, wp), real(f_max, wp), warnings)
      end if
      call hand_out(warnings, nmax, len, kinds, texts, n)
    end if
    stat = set_error(errh, error)
  end function udmap_plausibility_warnings

  !> int udmap_model_warnings(error, model, nmax, len, kinds, texts, n): the warnings of the
  !>   model's blade, damper and band, with the stuck peak.
  function udmap_model_warnings(errh, modelh, nmax, len, kinds, texts, n) result(stat) &
      & bind(C, name="udmap_model_warnings")
    type(c_ptr), value :: errh, modelh, kinds, texts, n
    integer(c_int), value :: nmax, len
    integer(c_int) :: stat
    type(error_type), allocatable :: error
    type(c_model_type), pointer :: m
    type(warning_type), allocatable :: warnings(:)
    call model_from_handle(errh, modelh, m, error)
    call check_buffers(nmax, len, kinds, texts, n, error)
    if (.not. allocated(error)) then
      call model_warnings(m%model, warnings)
      call hand_out(warnings, nmax, len, kinds, texts, n)
    end if
    stat = set_error(errh, error)
  end function udmap_model_warnings

  !> The checks of the output arguments: n required; with nmax > 0, kinds and texts too and
  !> len >= 1.
  subroutine check_buffers(nmax, len, kinds, texts, n, error)
    integer(c_int), intent(in) :: nmax, len
    type(c_ptr), intent(in) :: kinds, texts, n
    type(error_type), allocatable, intent(inout) :: error
    call check_input(nmax >= 0, "nmax must not be negative", error)
    if (nmax > 0) then
      call check_input(len >= 1, "len must be at least 1", error)
      call check_handle(kinds, "kinds", error)
      call check_handle(texts, "texts", error)
    end if
    call check_handle(n, "n", error)
  end subroutine check_buffers

  !> *n, and the first nmax kinds and texts (text i at texts + i len, NUL-terminated, cut to
  !> len - 1 characters).
  subroutine hand_out(warnings, nmax, len, kinds, texts, n)
    type(warning_type), intent(in) :: warnings(:)
    integer(c_int), intent(in) :: nmax, len
    type(c_ptr), intent(in) :: kinds, texts, n
    integer(c_int), pointer :: k(:)
    character(kind=c_char), pointer :: t(:)
    integer :: i, m
    call put_out(n, size(warnings))
    m = min(size(warnings), int(nmax))
    if (m < 1) return
    call c_f_pointer(kinds, k, [m])
    call c_f_pointer(texts, t, [int(nmax)*int(len)])
    do i = 1, m
      k(i) = int(warnings(i)%kind, c_int)
      call copy_string(warnings(i)%text, t((i-1)*len+1:), len)
    end do
  end subroutine hand_out
end module udmap_api_c_warnings
