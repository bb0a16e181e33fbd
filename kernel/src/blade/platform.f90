!> The blade seen from its rigid platform (PHYSICS.md 2.6): receptances between the platform's
!> coordinates p = (u_P, v_P, gamma_P), the excitation E and the root stress s,
!>   H_ab(omega) = b_a^T D(omega)^-1 b_b,  D = K - omega^2 M + i omega C,
!> with b_u, b_v the blade's platform_uv rows and b_g the unit row of gamma_dof. One dense
!> complex solve per frequency for the four right-hand sides; the traveling-wave layers call
!> it a few times per layer (the in-phase hot path keeps the modal sums of udmap_blade_type).
module udmap_blade_platform
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_core_lapack, only: zgetrf, zgetrs
  use udmap_blade_type, only: blade_type
  use udmap_blade_band, only: band_to_dense
  implicit none
  private
  public :: platform_receptances_type, platform_receptances, platform_rows, has_platform

  !> Receptances at one frequency: pp(a,b) between platform coordinates (u, v, gamma), pE(a)
  !> between coordinate a and E, sp(b) and sE from a unit force to the stress, EE at E.
  type :: platform_receptances_type
    complex(wp) :: pp(3,3) = 0, pE(3) = 0, sp(3) = 0, sE = 0, EE = 0
    !> d/domega of pp and pE (on request): -Z_a^T D'(omega) Z_b, D' = -2 omega M + i C.
    complex(wp) :: dpp(3,3) = 0, dpE(3) = 0
  end type platform_receptances_type

contains

  !> True if the blade knows its platform translations (traveling waves need them).
  pure logical function has_platform(blade)
    type(blade_type), intent(in) :: blade
    has_platform = allocated(blade%platform_uv)
  end function has_platform

  !> The rows b_u, b_v, b_g as the columns of B (ndof, 3).
  pure subroutine platform_rows(blade, B)
    type(blade_type), intent(in) :: blade
    real(wp), intent(out) :: B(:, :)
    B = 0
    if (allocated(blade%platform_uv)) B(:, 1:2) = blade%platform_uv
    B(blade%gamma_dof, 3) = 1
  end subroutine platform_rows

  !> Platform receptances at omega [rad/s] (omega = 0: static).
  subroutine platform_receptances(blade, omega, r, error, derivatives)
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: omega
    type(platform_receptances_type), intent(out) :: r
    type(error_type), allocatable, intent(out) :: error
    logical, intent(in), optional :: derivatives
    complex(wp), allocatable :: D(:, :), Z(:, :), dD(:, :), Y(:, :)
    real(wp), allocatable :: B(:, :), K(:, :), M(:, :), s(:), Cd(:, :)
    integer, allocatable :: ipiv(:)
    integer :: n, info, a, c
    n = blade%ndof
    if (.not. has_platform(blade)) then
      call fatal_error(error, "blade: the platform translations are unknown (traveling "// &
        & "waves need u_P: blade.u_dof on a matrices blade, platform.tangent on an fe blade)", &
        & UDMAP_EINPUT)
      return
    end if
    if (allocated(blade%K)) then
      K = blade%K
      M = blade%M
    else
      call band_to_dense(blade%Kb, blade%kd, K)
      call band_to_dense(blade%Mb, blade%kd, M)
    end if
    if (blade%explicit_C) then
      if (allocated(blade%C)) then
        Cd = blade%C
      else
        call band_to_dense(blade%Cb, blade%kd, Cd)
      end if
    else
      Cd = blade%beta*K
    end if
    D = cmplx(K - omega**2*M, omega*Cd, wp)
    allocate(B(n, 3), Z(n, 4), ipiv(n))
    call platform_rows(blade, B)
    Z(:, 1:3) = B
    Z(:, 4) = 0
    Z(blade%exc_dof, 4) = 1
    call zgetrf(n, n, D, n, ipiv, info)
    if (info /= 0) then
      call fatal_error(error, "blade: the dynamic stiffness is singular at this frequency "// &
        & "(an undamped natural frequency)", UDMAP_ENUMERIC)
      return
    end if
    call zgetrs('N', n, 4, D, n, ipiv, Z, n, info)
    do c = 1, 3
      do a = 1, 3
        r%pp(a, c) = sum(B(:, a)*Z(:, c))
      end do
      r%pE(c) = sum(B(:, c)*Z(:, 4))
    end do
    r%EE = Z(blade%exc_dof, 4)
    if (present(derivatives)) then
      if (derivatives) then
        dD = cmplx(-2*omega*M, Cd, wp)
        Y = matmul(dD, Z)
        do c = 1, 3
          do a = 1, 3
            r%dpp(a, c) = -sum(Z(:, a)*Y(:, c))
          end do
          r%dpE(c) = -sum(Z(:, c)*Y(:, 4))
        end do
      end if
    end if
    if (blade%has_stress) then
      s = blade%s_K - omega**2*blade%s_M
      do c = 1, 3
        r%sp(c) = sum(s*Z(:, c))
      end do
      r%sE = sum(s*Z(:, 4))
    end if
  end subroutine platform_receptances
end module udmap_blade_platform
