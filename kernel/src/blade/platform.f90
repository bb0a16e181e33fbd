!> The blade seen from its rigid platform (PHYSICS.md 2.6). Its translations: the rows of q that
!> give the circumferential u_P = u_row . q and the radial v_P = v_row . q translation of the
!> platform centre P, which a traveling wave (interblade phase phi /= 0) needs besides gamma_P
!> (the beam builder sets them itself, u_P = -w_P, v_P held; imported blades get them here: a
!> matrices blade's u_dof, v_dof, or an FE blade's rigid platform translations along
!> platform.tangent). Receptances between the platform's
!> coordinates p = (u_P, v_P, gamma_P), the excitation E and the root stress s,
!>   H_ab(omega) = b_a^T D(omega)^-1 b_b,  D = K - omega^2 M + i omega C,
!> with b_u, b_v the blade's platform_uv rows and b_g the unit row of gamma_dof. One dense
!> complex solve per frequency for the four right-hand sides; the traveling-wave layers call
!> it a few times per layer (the in-phase hot path keeps the modal sums of udmap_blade_type).
module udmap_blade_platform
  use udmap_core_kinds, only: wp
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_core_strings, only: itoa
  use udmap_core_lapack, only: zgetrf, zgetrs
  use udmap_blade_type, only: blade_type
  use udmap_blade_band, only: band_to_dense
  use udmap_blade_dd, only: dot_dd
  implicit none
  private
  public :: set_platform_translations, platform_translations_known
  public :: platform_receptances_type, platform_receptances, platform_rows
  public :: platform_modal_type, platform_modal
  public :: platform_unknowns_type, platform_active, platform_count, platform_scales, &
    & platform_pack, platform_unpack, platform_balance

  !> Receptances at one frequency: pp(a,b) between platform coordinates (u, v, gamma), pE(a)
  !> between coordinate a and E, sp(b) and sE from a unit force to the stress, EE at E.
  type :: platform_receptances_type
    complex(wp) :: pp(3,3) = 0, pE(3) = 0, sp(3) = 0, sE = 0, EE = 0
    !> d/domega of pp and pE (on request): -Z_a^T D'(omega) Z_b, D' = -2 omega M + i C.
    complex(wp) :: dpp(3,3) = 0, dpE(3) = 0
  end type platform_receptances_type

  !> The platform receptances as modal sums, for the inner loops of the traveling waves:
  !> with C = beta K and every mode computed, D(omega)^-1 = sum_r phi_r phi_r^T/(w_r^2 f -
  !> omega^2), f = 1 + i omega beta, exactly; an evaluation then costs O(ndof) instead of a
  !> dense complex factorisation. Products per mode r, b(:, r): the rows u_P, v_P, gamma_P, the
  !> excitation DOF, s_K and s_M with phi_r.
  type :: platform_modal_type
    logical :: active = .false.
    real(wp) :: beta = 0
    real(wp), allocatable :: w2(:), b(:, :)
  end type platform_modal_type

  !> The unknowns of the platform's harmonic balance (PHYSICS.md 2.6): harmonics 1 (H = 1) or
  !> 0..H, coordinates c = 1 (u_P), 2 (v_P, when the blade has it), 3 (gamma_P); at h = 0 only
  !> Gamma_0 (the static translations are shared by the two platforms of a damper and drop out);
  !> Gamma_1 is left out when it is held fixed (the amplitude layers). Each complex harmonic is
  !> two real unknowns (real part, imaginary part), in the order h, c.
  type :: platform_unknowns_type
    integer :: H = 1
    logical :: v_free = .false., gamma1_fixed = .true.
    !> Length that scales translations to rotations [m].
    real(wp) :: lever = 1
  end type platform_unknowns_type

contains

  pure logical function platform_active(u, h, c)
    type(platform_unknowns_type), intent(in) :: u
    integer, intent(in) :: h, c
    if (h == 0) then
      platform_active = c == 3
    else if (c == 2) then
      platform_active = u%v_free
    else
      platform_active = .not. (h == 1 .and. c == 3 .and. u%gamma1_fixed)
    end if
  end function platform_active

  !> Number of real unknowns.
  pure integer function platform_count(u)
    type(platform_unknowns_type), intent(in) :: u
    integer :: h, c
    platform_count = 0
    do h = merge(1, 0, u%H == 1), u%H
      do c = 1, 3
        if (platform_active(u, h, c)) platform_count = platform_count + merge(1, 2, h == 0)
      end do
    end do
  end function platform_count

  !> Scales of the unknowns: rotations by gscale [rad], translations by gscale times the lever.
  pure subroutine platform_scales(u, gscale, sc)
    type(platform_unknowns_type), intent(in) :: u
    real(wp), intent(in) :: gscale
    real(wp), intent(out) :: sc(:)
    integer :: i, h, c
    i = 0
    do h = merge(1, 0, u%H == 1), u%H
      do c = 1, 3
        if (.not. platform_active(u, h, c)) cycle
        i = i + 1
        sc(i) = gscale*merge(u%lever, 1.0_wp, c < 3)
        if (h > 0) then
          i = i + 1
          sc(i) = sc(i-1)
        end if
      end do
    end do
  end subroutine platform_scales

  !> The unknowns x of the static Gamma_0 (P0g) and the harmonics P(3, H).
  pure subroutine platform_pack(u, P0g, P, x)
    type(platform_unknowns_type), intent(in) :: u
    real(wp), intent(in) :: P0g
    complex(wp), intent(in) :: P(:, :)
    real(wp), intent(out) :: x(:)
    integer :: i, h, c
    i = 0
    do h = merge(1, 0, u%H == 1), u%H
      do c = 1, 3
        if (.not. platform_active(u, h, c)) cycle
        i = i + 1
        if (h == 0) then
          x(i) = P0g
        else
          x(i) = real(P(c, h), wp)
          i = i + 1
          x(i) = aimag(P(c, h))
        end if
      end do
    end do
  end subroutine platform_pack

  !> Gamma_0 and the harmonics from x; the inactive ones are 0, except a fixed Gamma_1.
  pure subroutine platform_unpack(u, x, P0g, P)
    type(platform_unknowns_type), intent(in) :: u
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: P0g
    complex(wp), intent(inout) :: P(:, :)
    integer :: i, h, c
    i = 0
    P0g = 0
    do h = merge(1, 0, u%H == 1), u%H
      do c = 1, 3
        if (.not. platform_active(u, h, c)) then
          if (h > 0 .and. .not. (h == 1 .and. c == 3)) P(c, h) = 0
          cycle
        end if
        i = i + 1
        if (h == 0) then
          P0g = x(i)
        else
          P(c, h) = cmplx(x(i), x(i+1), wp)
          i = i + 1
        end if
      end do
    end do
  end subroutine platform_unpack

  !> The condensed balance of the active rows, blade 0 with the damper's restoring action
  !> (A0, A(3, H)) and the force F [N] at E:
  !>   R_h = p_h + H_pp(h omega) A_h - delta_h1 H_pE(omega) F   (h >= 1),
  !>   R_0 = Gamma_0 + [H_pp(0) (A_0 - A_ref)]_gamma,
  !> rh(h) the receptances at h omega, r0 the static ones, A_ref the loaded damper at rest.
  pure subroutine platform_balance(u, rh, r0, P0g, P, A0, A, A_ref, F, res)
    type(platform_unknowns_type), intent(in) :: u
    type(platform_receptances_type), intent(in) :: rh(:), r0
    real(wp), intent(in) :: P0g, A0(3), A_ref(3)
    complex(wp), intent(in) :: P(:, :), A(:, :), F
    real(wp), intent(out) :: res(:)
    complex(wp) :: z, HA(3)
    real(wp) :: HA0(3)
    integer :: i, h, c
    i = 0
    do h = merge(1, 0, u%H == 1), u%H
      if (h > 0) then
        HA = matmul(rh(h)%pp, A(:, h))
      else
        HA0 = real(matmul(r0%pp, cmplx(A0 - A_ref, 0.0_wp, wp)), wp)
      end if
      do c = 1, 3
        if (.not. platform_active(u, h, c)) cycle
        i = i + 1
        if (h == 0) then
          res(i) = P0g + HA0(3)
        else
          z = P(c, h) + HA(c)
          if (h == 1) z = z - rh(1)%pE(c)*F
          res(i) = real(z, wp)
          i = i + 1
          res(i) = aimag(z)
        end if
      end do
    end do
  end subroutine platform_balance

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

  !> The rows b_u, b_v, b_g as the columns of B (ndof, 3).
  pure subroutine platform_rows(blade, B)
    type(blade_type), intent(in) :: blade
    real(wp), intent(out) :: B(:, :)
    B = 0
    if (allocated(blade%platform_uv)) B(:, 1:2) = blade%platform_uv
    B(blade%gamma_dof, 3) = 1
  end subroutine platform_rows

  !> The modal form of the blade's platform receptances (inactive, and the dense solve kept,
  !> with an explicit C or when not every mode is computed).
  subroutine platform_modal(blade, pm)
    type(blade_type), intent(in) :: blade
    type(platform_modal_type), intent(out) :: pm
    real(wp), allocatable :: B(:, :)
    real(wp) :: pg, pe
    integer :: m
    pm%active = platform_translations_known(blade) .and. .not. blade%explicit_C .and. &
      & blade%nmodes == blade%ndof .and. allocated(blade%phi) .and. allocated(blade%w2)
    if (.not. pm%active) return
    allocate(B(blade%ndof, 6), source=0.0_wp)
    call platform_rows(blade, B(:, 1:3))
    B(blade%exc_dof, 4) = 1
    pm%b = transpose(matmul(transpose(blade%phi), B))
    if (blade%has_stress) then
      ! s_K.phi_r as the blade took it, without the cancellation of the element stiffnesses
      ! (blade%coef: (s_K.phi) phi_E, (s_K.phi) phi_g; s_M.phi in double-double)
      do m = 1, blade%nmodes
        pg = blade%phi(blade%gamma_dof, m)
        pe = blade%phi(blade%exc_dof, m)
        if (abs(pg) >= abs(pe) .and. pg /= 0) then
          pm%b(5, m) = blade%coef(6, m)/pg
        else if (pe /= 0) then
          pm%b(5, m) = blade%coef(4, m)/pe
        else
          pm%b(5, m) = dot_dd(blade%s_K, blade%phi(:, m))
        end if
        pm%b(6, m) = dot_dd(blade%s_M, blade%phi(:, m))
      end do
    end if
    pm%w2 = blade%w2(1:blade%nmodes)
    pm%beta = blade%beta
  end subroutine platform_modal

  !> Platform receptances at omega [rad/s] (omega = 0: static); from the modal sums where
  !> `modal` is given and active, else by a dense solve.
  subroutine platform_receptances(blade, omega, r, error, derivatives, modal)
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: omega
    type(platform_receptances_type), intent(out) :: r
    type(error_type), allocatable, intent(out) :: error
    logical, intent(in), optional :: derivatives
    type(platform_modal_type), intent(in), optional :: modal
    complex(wp), allocatable :: D(:, :), Z(:, :), dD(:, :), Y(:, :)
    real(wp), allocatable :: B(:, :), K(:, :), M(:, :), s(:), Cd(:, :)
    integer, allocatable :: ipiv(:)
    integer :: n, info, a, c
    n = blade%ndof
    if (.not. platform_translations_known(blade)) then
      call fatal_error(error, "blade: the platform translations are unknown (traveling "// &
        & "waves need u_P: blade.u_dof on a matrices blade, platform.tangent on an fe blade)", &
        & UDMAP_EINPUT)
      return
    end if
    if (present(modal)) then
      if (modal%active) then
        call modal_sums(modal)
        return
      end if
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

  contains

    !> The receptances as sums over every mode (the same equations as the dense solve).
    subroutine modal_sums(pm)
      type(platform_modal_type), intent(in) :: pm
      complex(wp) :: g(size(pm%w2)), dg(size(pm%w2)), gs(size(pm%w2))
      integer :: ic
      g = 1/(pm%w2*cmplx(1.0_wp, omega*pm%beta, wp) - omega**2)
      if (.not. all(g == g .and. abs(g) <= huge(1.0_wp))) then
        call fatal_error(error, "blade: the dynamic stiffness is singular at this frequency "// &
          & "(an undamped natural frequency)", UDMAP_ENUMERIC)
        return
      end if
      call weighted(pm, g, r%pp, r%pE)
      r%EE = sum(pm%b(4, :)**2*g)
      if (present(derivatives)) then
        if (derivatives) then
          dg = -cmplx(-2*omega, pm%beta*pm%w2, wp)*g*g
          call weighted(pm, dg, r%dpp, r%dpE)
        end if
      end if
      if (blade%has_stress) then
        gs = (pm%b(5, :) - omega**2*pm%b(6, :))*g
        do ic = 1, 3
          r%sp(ic) = sum(pm%b(ic, :)*gs)
        end do
        r%sE = sum(pm%b(4, :)*gs)
      end if
    end subroutine modal_sums

    !> The platform rows' and the excitation's products with the modes, summed with the modal
    !> weights wt (the receptances, or their derivatives).
    pure subroutine weighted(pm, wt, pp, pE)
      type(platform_modal_type), intent(in) :: pm
      complex(wp), intent(in) :: wt(:)
      complex(wp), intent(out) :: pp(3, 3), pE(3)
      integer :: ja, jc
      do jc = 1, 3
        do ja = 1, 3
          pp(ja, jc) = sum(pm%b(ja, :)*pm%b(jc, :)*wt)
        end do
        pE(jc) = sum(pm%b(jc, :)*pm%b(4, :)*wt)
      end do
    end subroutine weighted
  end subroutine platform_receptances
end module udmap_blade_platform
