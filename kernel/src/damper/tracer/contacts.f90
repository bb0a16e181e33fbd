!> The damper's contacts (PHYSICS.md 2.1): their states and the geometry, the forces of a
!> state, and the equilibrium of the damper for a set of contact states (the rates of its DOFs,
!> forces and sliders per unit travel), what the tracer (udmap_damper_tracer_core) and its
!> derivatives (udmap_damper_tracer_tangent) share.
module udmap_damper_tracer_contacts
  use udmap_core_kinds, only: wp
  implicit none
  private
  public :: contact_forces, contact_force, compute_rates, mode_stiffness, solve3, cofactors3, &
    & mode_code, code_modes

  !> Contact states.
  integer, parameter, public :: CONTACT_OPEN = 0, CONTACT_STICK = 1, CONTACT_SLIP_POS = 2, &
    & CONTACT_SLIP_NEG = 3

  !> Contact kinematics in generalised form. For contact i with point r, normal n (into the
  !> damper), tangent t = (-n_y, n_x) and platform centre P: the normal approach is
  !> g = -bn.q + gamma cn and the tangential relative displacement s = bt.q - gamma ct, with
  !> bn = (n_x, n_y, r x n), bt = (t_x, t_y, r x t), cn = n.a, ct = t.a, a = (-(r_y - P_y), r_x - P_x).
  !> Contacts 1, 2 are the flat points, 3 the curved point.
  type, public :: damper_geometry_type
    !> bn(:,i), bt(:,i): generalised directions of the normal and tangent of contact i.
    real(wp) :: bn(3,3) = 0, bt(3,3) = 0
    !> Lever arms of the platform rotation along the normal and the tangent [m].
    real(wp) :: cn(3) = 0, ct(3) = 0
    !> Normal and tangential stiffnesses [N/m] and the friction coefficient.
    real(wp) :: kn(3) = 0, kt(3) = 0, mu = 0
    !> Face inclinations [deg] (for messages).
    real(wp) :: beta_deg(2) = 0
    !> Force rate per unit gamma (max of kn |cn|, kt |ct|), a scale for tolerances [N/rad].
    real(wp) :: rate_scale = 0
    !> Moment rate per unit gamma (rate_scale times the largest lever arm) [N m/rad].
    real(wp) :: moment_scale = 0
    !> Rigid platform kinematics (PHYSICS.md 2.6): contact i touches platform side(i) (1: the
    !> flat side, blade j; 2: the curved side, blade j + 1) with centre P; a platform motion
    !> (u_P, v_P, gamma_P) moves the contact point by n.(...) = pn(:,i).(u_P, v_P, gamma_P)
    !> along the normal and pt(:,i).(...) along the tangent (pn = (n_x, n_y, cn),
    !> pt = (t_x, t_y, ct)). These are also the generalised directions of the contact force
    !> on the platform's coordinates.
    real(wp) :: pn(3,3) = 0, pt(3,3) = 0
    integer :: side(3) = 0
  end type damper_geometry_type

  !> State of the damper on its loading path: DOFs, sliders, contact states, loads.
  type, public :: damper_state_type
    !> Damper DOFs (x [m], y [m], theta [rad]).
    real(wp) :: q(3) = 0
    !> Slider positions of the Jenkins elements [m].
    real(wp) :: w(3) = 0
    !> Platform rotation [rad] and centrifugal load [N].
    real(wp) :: gamma = 0, CF = 0
    !> Contact states (CONTACT_*).
    integer :: mode(3) = CONTACT_OPEN
    !> Last direction of motion in gamma (+1, -1; 0 before any).
    integer :: direction = 0
    !> Derivatives of q, w, gamma with respect to the path parameter p (loop amplitude);
    !> zero unless the targets depend on p.
    real(wp) :: q_p(3) = 0, w_p(3) = 0, gamma_p = 0
    !> Platform displacement at each contact beyond gamma (cn, ct): off(1,i) along the
    !> normal, off(2,i) along the tangent [m]; zero on in-phase paths (PHYSICS.md 2.6).
    real(wp) :: off(2,3) = 0
    !> Both platforms' coordinates (u_P, v_P, gamma_P of side 1, then of side 2) on a
    !> traveling-wave path (trace_path).
    real(wp) :: X(6) = 0
  end type damper_state_type

  !> Range [lo, hi] of the parameter p around p0 in which the traced event sequence holds.
  type, public :: validity_type
    real(wp) :: p0 = 0, lo = -huge(1.0_wp), hi = huge(1.0_wp)
  end type validity_type

  !> Vertices (gamma, M_r) of a traced path, with their p-derivatives; slope(j) is dM_r/dgamma
  !> on the segment that ends at vertex j (j >= 2). States are kept on request.
  type, public :: branch_record_type
    integer :: n = 0
    real(wp), allocatable :: gamma(:), gamma_p(:), M(:), M_p(:), slope(:)
    logical :: keep_states = .false.
    type(damper_state_type), allocatable :: states(:)
    !> Some contact slipped / was open along a segment of positive length.
    logical :: slipped = .false., opened = .false.
  end type branch_record_type

  !> The contact states of each step of a trace (mode_code) and the value of gamma where the
  !> step ended (trace_path's events; cheaper than a branch record with states).
  type, public :: mode_log_type
    integer :: n = 0
    real(wp), allocatable :: s(:)
    integer, allocatable :: code(:)
    !> The event that ended each step: 4 contact + its new state, or 0 (the target); the
    !> rate at which that contact's boundary came nearer (what the derivatives of the step
    !> need: udmap_damper_tracer_tangent).
    integer, allocatable :: event(:)
    real(wp), allocatable :: rate(:)
  end type mode_log_type

  !> Rates per unit travel of a set of contact states.
  type, public :: rates_type
    real(wp) :: dq(3) = 0, dg(3) = 0, ds(3) = 0, dN(3) = 0, dT(3) = 0, dw(3) = 0, dM = 0
  end type rates_type

  !> The cofactors and determinants of the equilibrium matrices (mode_stiffness) of the
  !> contact states met so far (mode_code 0..63), for one damper: they depend on its
  !> stiffnesses and directions, not on the lever arms, so a trace's segments share them.
  type, public :: equilibrium_cache_type
    logical :: known(0:63) = .false., regular(0:63) = .false.
    real(wp) :: C(3, 3, 0:63) = 0, det(0:63) = 0
  end type equilibrium_cache_type

  !> The rates (compute_rates) of the contact states met so far in gamma (dgam = -1, +1; dcf =
  !> 0), for one damper geometry (they depend on the lever arms too): the loops of one table.
  type, public :: rates_cache_type
    logical :: known(0:63, 2) = .false.
    logical :: ok(0:63, 2)
    type(rates_type) :: rt(0:63, 2)
  end type rates_cache_type

contains

  !> Normal approach g, tangential displacement s and forces N, T of the three contacts for
  !> the states `mode` at (q, gamma, w). Linear and homogeneous in (q, gamma, w), so it also
  !> maps p-derivatives to p-derivatives.
  pure subroutine contact_forces(geo, mode, q, gamma, w, g, s, N, T, off)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: q(3), gamma, w(3)
    real(wp), intent(out) :: g(3), s(3), N(3), T(3)
    !> The state's platform offsets (damper_state_type%off); absent: none.
    real(wp), intent(in), optional :: off(2,3)
    integer :: i
    do i = 1, 3
      g(i) = -(geo%bn(1,i)*q(1) + geo%bn(2,i)*q(2) + geo%bn(3,i)*q(3)) + gamma*geo%cn(i)
      s(i) = geo%bt(1,i)*q(1) + geo%bt(2,i)*q(2) + geo%bt(3,i)*q(3) - gamma*geo%ct(i)
      if (present(off)) then
        g(i) = g(i) + off(1,i)
        s(i) = s(i) - off(2,i)
      end if
      ! contact_force's cases, written out: a call per contact here (not inlined) cost 11 %
      ! more instructions on a lift-off design
      select case (mode(i))
      case (CONTACT_STICK)
        N(i) = geo%kn(i)*g(i)
        T(i) = -geo%kt(i)*(s(i) - w(i))
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        N(i) = geo%kn(i)*g(i)
        T(i) = merge(geo%mu, -geo%mu, mode(i) == CONTACT_SLIP_POS)*N(i)
      case default
        N(i) = 0
        T(i) = 0
      end select
    end do
  end subroutine contact_forces

  !> The forces N, T of contact i in the state mode_i from its gap g, travel s and slider w
  !> (contact_forces holds the same cases inline).
  pure subroutine contact_force(geo, i, mode_i, g, s, w, N, T)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: i, mode_i
    real(wp), intent(in) :: g, s, w
    real(wp), intent(out) :: N, T
    select case (mode_i)
    case (CONTACT_STICK)
      N = geo%kn(i)*g
      T = -geo%kt(i)*(s - w)
    case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
      N = geo%kn(i)*g
      T = merge(geo%mu, -geo%mu, mode_i == CONTACT_SLIP_POS)*N
    case default
      N = 0
      T = 0
    end select
  end subroutine contact_force

  !> Rates of q, gaps, forces, sliders and moment per unit travel for the contact states
  !> `mode` under load rates (dgam, dcf); ok is false for a singular equilibrium.
  pure subroutine compute_rates(geo, mode, dgam, dcf, rt, ok, cache)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(in) :: dgam, dcf
    type(rates_type), intent(out) :: rt
    logical, intent(out) :: ok
    !> The equilibrium matrices' cofactors of geo's damper met so far (the same arithmetic).
    type(equilibrium_cache_type), intent(inout), optional :: cache
    real(wp) :: K(3,3), h(3), v(3)
    integer :: i, sg, code

    h = 0
    do i = 1, 3
      select case (mode(i))
      case (CONTACT_STICK)
        h = h + geo%kn(i)*geo%cn(i)*geo%bn(:,i) + geo%kt(i)*geo%ct(i)*geo%bt(:,i)
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        sg = merge(1, -1, mode(i) == CONTACT_SLIP_POS)
        v = geo%bn(:,i) + sg*geo%mu*geo%bt(:,i)
        h = h + geo%kn(i)*geo%cn(i)*v
      end select
    end do
    if (present(cache)) then
      code = mode_code(mode)
      if (.not. cache%known(code)) then
        call mode_stiffness(geo, mode, K)
        call cofactors3(K, cache%C(:, :, code), cache%det(code), cache%regular(code))
        cache%known(code) = .true.
      end if
      ok = cache%regular(code)
      rt%dq = 0
      if (ok) rt%dq = adjugate_solve(cache%C(:, :, code), cache%det(code), &
        & dgam*h + [0.0_wp, dcf, 0.0_wp])
    else
      call mode_stiffness(geo, mode, K)
      call solve3(K, dgam*h + [0.0_wp, dcf, 0.0_wp], rt%dq, ok)
    end if
    if (.not. ok) return
    do i = 1, 3
      rt%dg(i) = -dot_product(geo%bn(:,i), rt%dq) + dgam*geo%cn(i)
      rt%ds(i) = dot_product(geo%bt(:,i), rt%dq) - dgam*geo%ct(i)
      select case (mode(i))
      case (CONTACT_STICK)
        rt%dN(i) = geo%kn(i)*rt%dg(i)
        rt%dT(i) = -geo%kt(i)*rt%ds(i)
        rt%dw(i) = 0
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        sg = merge(1, -1, mode(i) == CONTACT_SLIP_POS)
        rt%dN(i) = geo%kn(i)*rt%dg(i)
        rt%dT(i) = sg*geo%mu*rt%dN(i)
        rt%dw(i) = rt%ds(i) + rt%dT(i)/geo%kt(i)
      case default
        rt%dN(i) = 0
        rt%dT(i) = 0
        rt%dw(i) = rt%ds(i)
      end select
    end do
    rt%dM = sum(geo%cn*rt%dN + geo%ct*rt%dT)
  end subroutine compute_rates

  !> The damper's equilibrium matrix K in the contact states `mode` (K dq = h, compute_rates):
  !> kn bn bn^T + kt bt bt^T a contact that sticks, kn v bn^T one that slips (v = bn +- mu bt),
  !> element by element (the tracer's most frequent work, without whole-array temporaries).
  pure subroutine mode_stiffness(geo, mode, K)
    type(damper_geometry_type), intent(in) :: geo
    integer, intent(in) :: mode(3)
    real(wp), intent(out) :: K(3,3)
    real(wp) :: v(3)
    integer :: i, r, c
    K = 0
    do i = 1, 3
      select case (mode(i))
      case (CONTACT_STICK)
        do c = 1, 3
          do r = 1, 3
            K(r,c) = K(r,c) + geo%kn(i)*(geo%bn(r,i)*geo%bn(c,i)) + &
              & geo%kt(i)*(geo%bt(r,i)*geo%bt(c,i))
          end do
        end do
      case (CONTACT_SLIP_POS, CONTACT_SLIP_NEG)
        v = geo%bn(:,i) + merge(1, -1, mode(i) == CONTACT_SLIP_POS)*geo%mu*geo%bt(:,i)
        do c = 1, 3
          do r = 1, 3
            K(r,c) = K(r,c) + geo%kn(i)*(v(r)*geo%bn(c,i))
          end do
        end do
      end select
    end do
  end subroutine mode_stiffness

  !> Solves the 3x3 system A x = b by cofactors; ok is false if A is numerically singular.
  pure subroutine solve3(A, b, x, ok)
    real(wp), intent(in) :: A(3,3), b(3)
    real(wp), intent(out) :: x(3)
    logical, intent(out) :: ok
    real(wp) :: C(3,3), det
    call cofactors3(A, C, det, ok)
    x = 0
    if (ok) x = adjugate_solve(C, det, b)
  end subroutine solve3

  !> The cofactors C and the determinant of A; ok is false if A is numerically singular.
  pure subroutine cofactors3(A, C, det, ok)
    real(wp), intent(in) :: A(3,3)
    real(wp), intent(out) :: C(3,3), det
    logical, intent(out) :: ok
    real(wp) :: scale
    C(1,1) = A(2,2)*A(3,3) - A(2,3)*A(3,2)
    C(1,2) = A(2,3)*A(3,1) - A(2,1)*A(3,3)
    C(1,3) = A(2,1)*A(3,2) - A(2,2)*A(3,1)
    C(2,1) = A(1,3)*A(3,2) - A(1,2)*A(3,3)
    C(2,2) = A(1,1)*A(3,3) - A(1,3)*A(3,1)
    C(2,3) = A(1,2)*A(3,1) - A(1,1)*A(3,2)
    C(3,1) = A(1,2)*A(2,3) - A(1,3)*A(2,2)
    C(3,2) = A(1,3)*A(2,1) - A(1,1)*A(2,3)
    C(3,3) = A(1,1)*A(2,2) - A(1,2)*A(2,1)
    det = A(1,1)*C(1,1) + A(1,2)*C(1,2) + A(1,3)*C(1,3)
    scale = norm2(A(:,1))*norm2(A(:,2))*norm2(A(:,3))
    ok = abs(det) > 1e-12_wp*scale
  end subroutine cofactors3

  !> x = adj(A) b / det, adj(A) = transpose(C), C the cofactors of A.
  pure function adjugate_solve(C, det, b) result(x)
    real(wp), intent(in) :: C(3,3), det, b(3)
    real(wp) :: x(3)
    x(1) = (C(1,1)*b(1) + C(2,1)*b(2) + C(3,1)*b(3))/det
    x(2) = (C(1,2)*b(1) + C(2,2)*b(2) + C(3,2)*b(3))/det
    x(3) = (C(1,3)*b(1) + C(2,3)*b(2) + C(3,3)*b(3))/det
  end function adjugate_solve

  !> The three contacts' states as one integer (base 4), and back.
  pure integer function mode_code(mode)
    integer, intent(in) :: mode(3)
    mode_code = mode(1) + 4*mode(2) + 16*mode(3)
  end function mode_code

  pure function code_modes(code) result(mode)
    integer, intent(in) :: code
    integer :: mode(3)
    mode = [modulo(code, 4), modulo(code/4, 4), code/16]
  end function code_modes
end module udmap_damper_tracer_contacts
