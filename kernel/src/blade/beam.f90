!> The built-in beam blade (PHYSICS.md 1.1): a 2D Euler-Bernoulli beam of cubic Hermite
!> elements (w, theta per node, consistent mass) with a clamped neck, a rigid platform with
!> master point P (w_P, gamma_P) and the airfoil.
!>
!> DOFs are numbered along the beam so that K and M are banded with half-bandwidth 3:
!> neck nodes 1..n_neck-1 (w, theta), then the platform (w_P, gamma_P), then airfoil nodes
!> 1..n_airfoil (w, theta). The neck top node and the airfoil root node are rigidly linked
!> to P and eliminated by transformation:
!> neck top w = w_P - (L_p/2) gamma_P, airfoil root w = w_P + (L_p/2) gamma_P, theta = gamma_P.
!> Hence ndof = 2 (neck.elements + airfoil.elements), gamma_dof = 2 neck.elements and
!> exc_dof = 2 neck.elements + airfoil.elements - 1 (w of the mid-length airfoil node).
module udmap_blade_beam
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: beam_params_type, check_beam_params, assemble_beam, beam_kd, beam_max_elements

  !> Half-bandwidth of the assembled matrices.
  integer, parameter :: beam_kd = 3
  !> Largest accepted element count of the neck and of the airfoil.
  integer, parameter :: beam_max_elements = 1000000

  !> Parameters of the beam blade (SI units), named as in the case file.
  type :: beam_params_type
    real(wp) :: E = 0, rho = 0, zeta = 0
    real(wp) :: neck_L = 0, neck_h = 0, neck_b = 0
    real(wp) :: platform_L = 0, platform_m = 0, platform_J = 0
    real(wp) :: airfoil_L = 0, airfoil_h = 0, airfoil_b = 0
    integer :: neck_elements = 0, airfoil_elements = 0
  end type beam_params_type

  character(len=*), parameter :: fmt_i = '(i0)'

contains

  !> An error naming the first invalid field (case-file spelling, e.g. "blade.neck.L").
  pure subroutine check_beam_params(p, error)
    type(beam_params_type), intent(in) :: p
    type(error_type), allocatable, intent(out) :: error
    character(len=24) :: buf
    call positive(p%E, "blade.E", error); if (allocated(error)) return
    call positive(p%rho, "blade.rho", error); if (allocated(error)) return
    if (.not.ieee_is_finite(p%zeta)) then
      call fatal_error(error, "blade.zeta must be a non-negative finite number", UDMAP_EINPUT)
      return
    end if
    if (p%zeta < 0.0_wp) then
      call fatal_error(error, "blade.zeta must be a non-negative finite number", UDMAP_EINPUT)
      return
    end if
    call positive(p%neck_L, "blade.neck.L", error); if (allocated(error)) return
    call positive(p%neck_h, "blade.neck.h", error); if (allocated(error)) return
    call positive(p%neck_b, "blade.neck.b", error); if (allocated(error)) return
    call positive(p%platform_L, "blade.platform.L", error); if (allocated(error)) return
    call positive(p%platform_m, "blade.platform.m", error); if (allocated(error)) return
    call positive(p%platform_J, "blade.platform.J", error); if (allocated(error)) return
    call positive(p%airfoil_L, "blade.airfoil.L", error); if (allocated(error)) return
    call positive(p%airfoil_h, "blade.airfoil.h", error); if (allocated(error)) return
    call positive(p%airfoil_b, "blade.airfoil.b", error); if (allocated(error)) return
    write(buf, fmt_i) beam_max_elements
    if (p%neck_elements < 1 .or. p%neck_elements > beam_max_elements) then
      call fatal_error(error, "blade.neck.elements must be an integer from 1 to "//trim(buf), &
        & UDMAP_EINPUT)
    else if (p%airfoil_elements < 2 .or. p%airfoil_elements > beam_max_elements &
        & .or. modulo(p%airfoil_elements, 2) /= 0) then
      call fatal_error(error, "blade.airfoil.elements must be an even integer from 2 to "// &
        & trim(buf)//" (the excitation point is the mid-length node)", UDMAP_EINPUT)
    end if

  contains

    pure subroutine positive(x, name, error)
      real(wp), intent(in) :: x
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(inout) :: error
      ! ieee_is_finite first: comparing a NaN would raise the invalid flag.
      if (.not.ieee_is_finite(x)) then
        call fatal_error(error, name//" must be a positive finite number", UDMAP_EINPUT)
      else if (x <= 0.0_wp) then
        call fatal_error(error, name//" must be a positive finite number", UDMAP_EINPUT)
      end if
    end subroutine positive
  end subroutine check_beam_params

  !> Assembles K and M in symmetric band storage (beam_kd+1, ndof), uplo = 'U', and the
  !> root stress rows: sigma = (s_K - omega^2 s_M)^T q is the bending stress (h_a/2)/I_a times
  !> the moment entry of the first airfoil element's end forces (K_e - omega^2 M_e) u_e.
  pure subroutine assemble_beam(p, kb, mb, s_k, s_m, gamma_dof, exc_dof, error)
    type(beam_params_type), intent(in) :: p
    real(wp), allocatable, intent(out) :: kb(:, :), mb(:, :), s_k(:), s_m(:)
    integer, intent(out) :: gamma_dof, exc_dof
    type(error_type), allocatable, intent(out) :: error
    real(wp) :: ke(4, 4), me(4, 4), t(4, 4), i_a
    integer :: nn, na, n, e, g(4), stat
    call check_beam_params(p, error)
    if (allocated(error)) return
    nn = p%neck_elements
    na = p%airfoil_elements
    n = 2*(nn + na)
    gamma_dof = 2*nn
    exc_dof = 2*nn + na - 1
    allocate(kb(beam_kd+1, n), mb(beam_kd+1, n), s_k(n), s_m(n), stat=stat)
    if (stat /= 0) then
      call fatal_error(error, "not enough memory for the beam blade (blade.neck.elements and "// &
        & "blade.airfoil.elements too large)", UDMAP_EINPUT)
      return
    end if
    kb = 0.0_wp
    mb = 0.0_wp
    s_k = 0.0_wp
    s_m = 0.0_wp

    ! Neck: node 0 clamped, node nn is the neck top, rigidly linked to P.
    call element(p%E, p%rho, p%neck_b, p%neck_h, p%neck_L/nn, ke, me)
    do e = 0, nn - 1
      call element_map(e, 0, 0, nn, -0.5_wp*p%platform_L, g, t)
      call scatter(kb, ke, g, t)
      call scatter(mb, me, g, t)
    end do
    ! Platform: lumped mass and rotary inertia about P.
    mb(beam_kd+1, gamma_dof-1) = mb(beam_kd+1, gamma_dof-1) + p%platform_m
    mb(beam_kd+1, gamma_dof) = mb(beam_kd+1, gamma_dof) + p%platform_J
    ! Airfoil: node 0 is the root, rigidly linked to P.
    call element(p%E, p%rho, p%airfoil_b, p%airfoil_h, p%airfoil_L/na, ke, me)
    do e = 0, na - 1
      call element_map(e, gamma_dof, -1, 0, 0.5_wp*p%platform_L, g, t)
      call scatter(kb, ke, g, t)
      call scatter(mb, me, g, t)
      if (e == 0) then
        ! Moment entry (row 2) of the end-force vector, in terms of the element's global DOFs.
        i_a = p%airfoil_b*p%airfoil_h**3/12.0_wp
        call stress_row(s_k, ke, g, t, 0.5_wp*p%airfoil_h/i_a)
        call stress_row(s_m, me, g, t, 0.5_wp*p%airfoil_h/i_a)
      end if
    end do

  contains

    !> Global DOFs g (0: clamped) and transformation u_e = t q_g of element e of a segment:
    !> its node `clamped` clamped (-1: none), its node `linked` linked to P with lever c,
    !> node j otherwise free with the global DOFs offset + 2j - 1, offset + 2j.
    pure subroutine element_map(e, offset, clamped, linked, c, g, t)
      integer, intent(in) :: e, offset, clamped, linked
      real(wp), intent(in) :: c
      integer, intent(out) :: g(4)
      real(wp), intent(out) :: t(4, 4)
      integer :: k, node
      t = 0.0_wp
      do k = 0, 1
        node = e + k
        if (node == clamped) then
          g(2*k+1:2*k+2) = 0
        else if (node == linked) then
          call platform_link(k, c, g, t)
        else
          g(2*k+1:2*k+2) = [offset+2*node-1, offset+2*node]
          t(2*k+1, 2*k+1) = 1.0_wp
          t(2*k+2, 2*k+2) = 1.0_wp
        end if
      end do
    end subroutine element_map

    !> Node k of the element is linked to P: w = w_P + c gamma_P, theta = gamma_P.
    pure subroutine platform_link(k, c, g, t)
      integer, intent(in) :: k
      real(wp), intent(in) :: c
      integer, intent(inout) :: g(4)
      real(wp), intent(inout) :: t(4, 4)
      g(2*k+1:2*k+2) = [gamma_dof-1, gamma_dof]
      t(2*k+1, 2*k+1) = 1.0_wp
      t(2*k+1, 2*k+2) = c
      t(2*k+2, 2*k+2) = 1.0_wp
    end subroutine platform_link

    !> ab += t^T ae t on the global DOFs g (upper band).
    pure subroutine scatter(ab, ae, g, t)
      real(wp), intent(inout) :: ab(:, :)
      real(wp), intent(in) :: ae(4, 4), t(4, 4)
      integer, intent(in) :: g(4)
      real(wp) :: ag(4, 4)
      integer :: a, b
      ag = matmul(transpose(t), matmul(ae, t))
      do b = 1, 4
        do a = 1, 4
          if (g(a) == 0 .or. g(b) == 0) cycle
          if (g(a) <= g(b)) ab(beam_kd+1+g(a)-g(b), g(b)) = ab(beam_kd+1+g(a)-g(b), g(b)) + ag(a, b)
        end do
      end do
    end subroutine scatter

    pure subroutine stress_row(s, ae, g, t, scale)
      real(wp), intent(inout) :: s(:)
      real(wp), intent(in) :: ae(4, 4), t(4, 4), scale
      integer, intent(in) :: g(4)
      real(wp) :: row(4)
      integer :: b
      row = matmul(ae(2, :), t)
      do b = 1, 4
        if (g(b) /= 0) s(g(b)) = s(g(b)) + scale*row(b)
      end do
    end subroutine stress_row
  end subroutine assemble_beam

  !> Hermite element stiffness and consistent mass of a b x h section, length l.
  pure subroutine element(e, rho, b, h, l, ke, me)
    real(wp), intent(in) :: e, rho, b, h, l
    real(wp), intent(out) :: ke(4, 4), me(4, 4)
    real(wp) :: ei, ra
    ei = e*b*h**3/12.0_wp
    ra = rho*b*h*l/420.0_wp
    ke = ei/l**3*reshape([12.0_wp, 6*l, -12.0_wp, 6*l, &
      & 6*l, 4*l*l, -6*l, 2*l*l, &
      & -12.0_wp, -6*l, 12.0_wp, -6*l, &
      & 6*l, 2*l*l, -6*l, 4*l*l], [4, 4])
    me = ra*reshape([156.0_wp, 22*l, 54.0_wp, -13*l, &
      & 22*l, 4*l*l, 13*l, -3*l*l, &
      & 54.0_wp, 13*l, 156.0_wp, -22*l, &
      & -13*l, -3*l*l, -22*l, 4*l*l], [4, 4])
  end subroutine element
end module udmap_blade_beam
