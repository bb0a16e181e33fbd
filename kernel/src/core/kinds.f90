!> Real kind used throughout the kernel.
module udmap_core_kinds
  implicit none
  private
  public :: wp, pi

  !> Working precision: IEEE double.
  integer, parameter :: wp = selected_real_kind(15)
  !> The circle constant.
  real(wp), parameter :: pi = 3.141592653589793238462643383279502884_wp
end module udmap_core_kinds
