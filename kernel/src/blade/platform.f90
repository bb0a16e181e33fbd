!> The platform translations of a blade (PHYSICS.md 2.6): the rows of q that give the
!> circumferential u_P = u_row . q and the radial v_P = v_row . q translation of the platform
!> centre P, which a traveling wave (interblade phase phi /= 0) needs besides gamma_P. The beam
!> builder sets them itself (u_P = -w_P, v_P held); imported blades get them here (a matrices
!> blade's u_dof, v_dof, or an FE blade's rigid platform translations along platform.tangent).
module udmap_blade_platform
  use udmap_core_kinds, only: wp
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_core_strings, only: itoa
  use udmap_blade_type, only: blade_type
  implicit none
  private
  public :: set_platform_translations, platform_translations_known

contains

  !> Sets the rows of the platform translations: u_row (circumferential, required, not zero)
  !> and v_row (radial; absent: v_P held, a zero row), each of blade%ndof finite entries. On
  !> error the blade keeps the rows it had.
  subroutine set_platform_translations(blade, u_row, error, v_row)
    type(blade_type), intent(inout) :: blade
    real(wp), intent(in) :: u_row(:)
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: v_row(:)
    call check_row(u_row, "u_row")
    if (allocated(error)) return
    if (.not.any(u_row /= 0.0_wp)) then
      call fatal_error(error, "u_row is zero: the circumferential platform translation must "// &
        & "move with the blade's DOFs", UDMAP_EINPUT)
      return
    end if
    if (present(v_row)) then
      call check_row(v_row, "v_row")
      if (allocated(error)) return
    end if
    if (allocated(blade%platform_uv)) deallocate(blade%platform_uv)
    allocate(blade%platform_uv(blade%ndof, 2), source=0.0_wp)
    blade%platform_uv(:, 1) = u_row
    if (present(v_row)) blade%platform_uv(:, 2) = v_row

  contains

    subroutine check_row(row, name)
      real(wp), intent(in) :: row(:)
      character(len=*), intent(in) :: name
      if (size(row) /= blade%ndof) then
        call fatal_error(error, name//" must have "//itoa(blade%ndof)// &
          & " entries (one per DOF of the blade), got "//itoa(size(row)), UDMAP_EINPUT)
      else if (.not.all(ieee_is_finite(row))) then
        call fatal_error(error, name//" has a non-finite entry", UDMAP_EINPUT)
      end if
    end subroutine check_row
  end subroutine set_platform_translations

  !> Whether the blade knows its platform translations (traveling waves need them).
  pure logical function platform_translations_known(blade)
    type(blade_type), intent(in) :: blade
    platform_translations_known = allocated(blade%platform_uv)
  end function platform_translations_known
end module udmap_blade_platform
