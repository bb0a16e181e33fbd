!> The public Fortran interface of udmap in one module: `use udmap` gives the version, the
!> error type and status codes, and (as the kernel grows) the blade, damper and model types
!> with their procedures. Users need nothing else; the udmap_* modules behind it may change.
module udmap
  use udmap_kinds, only: wp
  use udmap_error, only: error_type, UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC
  use udmap_version_info, only: udmap_version_string, udmap_version_major, &
    & udmap_version_minor, udmap_version_patch
  implicit none
  private

  public :: udmap_version, udmap_version_major, udmap_version_minor, udmap_version_patch
  public :: wp, error_type, UDMAP_OK, UDMAP_EINPUT, UDMAP_EPHYSICS, UDMAP_ENUMERIC

contains

  !> The library version as "major.minor.patch" (the version of the linked library, which
  !> may differ from the .mod files a program was compiled against if it was swapped later).
  pure function udmap_version() result(version)
    character(len=:), allocatable :: version
    version = udmap_version_string
  end function udmap_version
end module udmap
