!> The rigid platform of the Platform Centred Reduction (PHYSICS.md 1.3, paper section 2.1), by
!> transformation u = T q (RBE2-like, not by penalty). The platform nodes follow one rigid
!> body, u_i = u_R + theta x (x_i - x_R), theta = gamma a + theta_b b + theta_c c with (a, b, c)
!> a right-handed orthonormal basis from the unit axis a, so gamma_P = theta . a is one DOF;
!> the clamp nodes are fixed; the excitation node's translations are written in a local
!> orthonormal basis (d, e2, e3) so that u_E = u . d is one DOF. The transformed DOFs q are
!> numbered interior first (every other DOF in the original order, then the excitation node's
!> e2, e3), then the seven boundary DOFs of the Craig-Bampton reduction:
!> gamma, theta_b, theta_c, u_Rx, u_Ry, u_Rz, u_E.
module udmap_blade_reduce_rigid_platform
  use udmap_core_kinds, only: wp
  use udmap_core_sorting, only: bisect
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_EPHYSICS
  use udmap_core_strings, only: itoa
  use udmap_blade_reduce_sparse_coo, only: coo_type
  implicit none
  private
  public :: platform_map_type, new_platform_map, transform_matrix, transform_vector
  public :: n_boundary, b_gamma, b_exc

  !> Boundary DOFs, and the places of gamma and u_E among them.
  integer, parameter :: n_boundary = 7, b_gamma = 1, b_exc = 7

  !> T by rows: full DOF j is sum_k coef(k) q(idx(k)), k = ptr(j), ..., ptr(j+1) - 1.
  type :: platform_map_type
    integer :: n_full = 0, n_t = 0, n_i = 0
    integer, allocatable :: ptr(:), idx(:)
    real(wp), allocatable :: coef(:)
  end type platform_map_type

contains

  !> Builds T from the DOF map (node id, component 1-6 of each row), the nodes and the
  !> platform, clamp and excitation definitions. Errors name the argument at fault.
  subroutine new_platform_map(map, dof_node, dof_comp, node_ids, node_xyz, platform_nodes, &
      & ref_point, axis, exc_node, exc_direction, clamp_nodes, error)
    type(platform_map_type), intent(out) :: map
    integer, intent(in) :: dof_node(:), dof_comp(:), node_ids(:), platform_nodes(:)
    integer, intent(in) :: exc_node, clamp_nodes(:)
    real(wp), intent(in) :: node_xyz(:, :), ref_point(3), axis(3), exc_direction(3)
    type(error_type), allocatable, intent(out) :: error
    integer, parameter :: free = 0, on_platform = 1, clamped = 2, excited = 3
    integer, allocatable :: order(:), sorted_ids(:), role(:), node_of_dof(:)
    integer :: n, m, j, i, c, k, e_node, seen_exc(3), next
    real(wp) :: a(3), b(3), cc(3), d(3), e2(3), e3(3), r(3), g(6, 6), w(6), t(6)
    character(len=32) :: buf
    n = size(dof_node)
    m = size(node_ids)
    if (size(dof_comp) /= n) then
      call fatal_error(error, "dof_comp: has "//itoa(size(dof_comp))//" entries, the matrices "// &
        & itoa(n)//" rows")
      return
    end if
    if (n < 1) then
      call fatal_error(error, "n: the model has no DOF")
      return
    end if
    if (size(node_xyz, 1) /= 3 .or. size(node_xyz, 2) /= m) then
      call fatal_error(error, "node_xyz: must be 3 x n_nodes")
      return
    end if
    if (any(dof_comp < 1) .or. any(dof_comp > 6)) then
      call fatal_error(error, "dof_comp: components must be 1 to 6")
      return
    end if
    if (size(platform_nodes) == 0) then
      call fatal_error(error, "platform_nodes: the platform set is empty")
      return
    end if
    a = unit(axis)
    if (norm2(axis) == 0 .or. any(a /= a)) then
      call fatal_error(error, "axis: the axis of gamma_P has zero length")
      return
    end if
    d = unit(exc_direction)
    if (norm2(exc_direction) == 0 .or. any(d /= d)) then
      call fatal_error(error, "exc_direction: the excitation direction has zero length")
      return
    end if
    if (any(ref_point /= ref_point) .or. any(node_xyz /= node_xyz)) then
      call fatal_error(error, "ref_point/node_xyz: not finite")
      return
    end if
    ! Node ids sorted once, looked up by bisection.
    order = sorted_order(node_ids)
    sorted_ids = node_ids(order)
    do k = 2, m
      if (node_ids(order(k)) == node_ids(order(k-1))) then
        call fatal_error(error, "node_ids: node "//itoa(node_ids(order(k)))//" is listed twice")
        return
      end if
    end do
    allocate(role(m), source=free)
    do k = 1, size(platform_nodes)
      call find_listed(platform_nodes(k), "platform_nodes", i)
      if (allocated(error)) return
      role(i) = on_platform
    end do
    do k = 1, size(clamp_nodes)
      call find_listed(clamp_nodes(k), "clamp_nodes", i)
      if (allocated(error)) return
      if (role(i) == on_platform) then
        call fatal_error(error, "clamp_nodes: node "//itoa(clamp_nodes(k))// &
          & " is also a platform node")
        return
      end if
      role(i) = clamped
    end do
    call find_listed(exc_node, "exc_node", e_node)
    if (allocated(error)) return
    if (role(e_node) /= free) then
      call fatal_error(error, "exc_node: node "//itoa(exc_node)//" is on the platform or clamped")
      return
    end if
    role(e_node) = excited
    allocate(node_of_dof(n))
    seen_exc = 0
    do j = 1, n
      i = find(dof_node(j))
      if (i == 0) then
        call fatal_error(error, "dof_node: node "//itoa(dof_node(j))//" of row "//itoa(j)// &
          & " is not in node_ids")
        return
      end if
      node_of_dof(j) = i
      if (i == e_node .and. dof_comp(j) <= 3) seen_exc(dof_comp(j)) = seen_exc(dof_comp(j)) + 1
    end do
    if (any(seen_exc /= 1)) then
      call fatal_error(error, "exc_node: node "//itoa(exc_node)// &
        & " must have its three translations as DOFs, once each")
      return
    end if
    call basis(a, b, cc)
    call basis(d, e2, e3)
    ! Numbering: interior DOFs first, then the boundary.
    map%n_full = n
    map%n_i = count(role(node_of_dof) == free) + count(role(node_of_dof) == excited .and. &
      & dof_comp > 3) + 2
    map%n_t = map%n_i + n_boundary
    allocate(map%ptr(n+1), map%idx(4*n), map%coef(4*n))
    next = 0
    map%ptr(1) = 1
    k = 0
    g = 0
    do j = 1, n
      i = node_of_dof(j)
      c = dof_comp(j)
      select case (role(i))
      case (free)
        next = next + 1
        call put(next, 1.0_wp)
      case (excited)
        if (c > 3) then
          next = next + 1
          call put(next, 1.0_wp)
        else
          call put(map%n_t, d(c))
          call put(map%n_i - 1, e2(c))
          call put(map%n_i, e3(c))
        end if
      case (on_platform)
        t = 0
        if (c <= 3) then
          r = node_xyz(:, i) - ref_point
          t(1) = cross_c(a, r, c)
          t(2) = cross_c(b, r, c)
          t(3) = cross_c(cc, r, c)
          t(3+c) = 1
        else
          t(1:3) = [a(c-3), b(c-3), cc(c-3)]
        end if
        do i = 1, 6
          if (t(i) /= 0) call put(map%n_i + i, t(i))
        end do
        ! Gram matrix of the platform's rigid-body DOFs (scaled below): a singular one means
        ! the platform nodes do not fix all six (e.g. collinear nodes without rotations)
        g = g + spread(t, 2, 6)*spread(t, 1, 6)
      case default
        ! clamped: no entry
      end select
      map%ptr(j+1) = k + 1
    end do
    if (next /= map%n_i - 2) then
      call fatal_error(error, "platform map: internal numbering mismatch")
      return
    end if
    map%idx = map%idx(1:k)
    map%coef = map%coef(1:k)
    ! Scaled to a unit diagonal (rotations and translations have different units).
    w = sqrt(max([(g(i, i), i = 1, 6)], tiny(1.0_wp)))
    do i = 1, 6
      g(:, i) = g(:, i)/(w*w(i))
    end do
    if (min_eigenvalue(g) < 1e-10_wp) then
      write(buf, '(es10.3)') min_eigenvalue(g)
      call fatal_error(error, "platform_nodes: the platform nodes do not fix a rigid body "// &
        & "(collinear nodes without rotations, or no DOF left; Gram eigenvalue "// &
        & trim(adjustl(buf))//")", UDMAP_EINPUT)
      return
    end if
  contains
    subroutine put(col, value)
      integer, intent(in) :: col
      real(wp), intent(in) :: value
      k = k + 1
      map%idx(k) = col
      map%coef(k) = value
    end subroutine put

    !> The index of node id, an error naming the input `name` when the model has no such node.
    subroutine find_listed(id, name, i)
      integer, intent(in) :: id
      character(len=*), intent(in) :: name
      integer, intent(out) :: i
      i = find(id)
      if (i == 0) call fatal_error(error, name//": node "//itoa(id)//" is not in the model")
    end subroutine find_listed

    integer function find(id)
      integer, intent(in) :: id
      integer :: i
      find = 0
      i = bisect(sorted_ids, id) + 1
      if (i <= m) then
        if (sorted_ids(i) == id) find = order(i)
      end if
    end function find
  end subroutine new_platform_map

  !> A_t = T^T A T for the symmetric A given by its lower-triangle entries (row >= col,
  !> checked by the caller), returned by its lower-triangle entries on the transformed DOFs.
  subroutine transform_matrix(map, row, col, val, at)
    type(platform_map_type), intent(in) :: map
    integer, intent(in) :: row(:), col(:)
    real(wp), intent(in) :: val(:)
    type(coo_type), intent(out) :: at
    integer(8) :: e, cnt
    integer :: i, j, k, l, p, q, lmin
    real(wp) :: w
    cnt = 0
    do e = 1, size(row, kind=8)
      i = row(e)
      j = col(e)
      if (i == j) then
        k = map%ptr(i+1) - map%ptr(i)
        cnt = cnt + (k*(k + 1))/2
      else
        cnt = cnt + (map%ptr(i+1) - map%ptr(i))*(map%ptr(j+1) - map%ptr(j))
      end if
    end do
    at%n = map%n_t
    allocate(at%row(cnt), at%col(cnt), at%val(cnt))
    cnt = 0
    do e = 1, size(row, kind=8)
      i = row(e)
      j = col(e)
      do k = map%ptr(i), map%ptr(i+1) - 1
        lmin = map%ptr(j)
        ! a diagonal entry: each unordered pair of T's entries once
        if (i == j) lmin = k
        do l = lmin, map%ptr(j+1) - 1
          p = map%idx(k)
          q = map%idx(l)
          w = map%coef(k)*map%coef(l)*val(e)
          ! an off-diagonal entry stands for (i, j) and (j, i): both land on (p, p)
          if (i /= j .and. p == q) w = 2*w
          cnt = cnt + 1
          at%row(cnt) = max(p, q)
          at%col(cnt) = min(p, q)
          at%val(cnt) = w
        end do
      end do
    end do
    at%nnz = cnt
  end subroutine transform_matrix

  !> s_t = T^T s (a row over the full DOFs to one over the transformed DOFs).
  pure function transform_vector(map, s) result(st)
    type(platform_map_type), intent(in) :: map
    real(wp), intent(in) :: s(:)
    real(wp) :: st(map%n_t)
    integer :: j, k
    st = 0
    do j = 1, map%n_full
      do k = map%ptr(j), map%ptr(j+1) - 1
        st(map%idx(k)) = st(map%idx(k)) + map%coef(k)*s(j)
      end do
    end do
  end function transform_vector

  !> Completes the unit vector a to a right-handed orthonormal basis (a, b, c).
  pure subroutine basis(a, b, c)
    real(wp), intent(in) :: a(3)
    real(wp), intent(out) :: b(3), c(3)
    real(wp) :: e(3)
    e = 0
    e(minloc(abs(a), 1)) = 1
    b = unit(cross(a, e))
    c = cross(a, b)
  end subroutine basis

  pure function unit(v) result(u)
    real(wp), intent(in) :: v(3)
    real(wp) :: u(3)
    u = v/norm2(v)
  end function unit

  pure function cross(a, b) result(c)
    real(wp), intent(in) :: a(3), b(3)
    real(wp) :: c(3)
    c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
  end function cross

  !> Component c of a x r.
  pure real(wp) function cross_c(a, r, c)
    real(wp), intent(in) :: a(3), r(3)
    integer, intent(in) :: c
    real(wp) :: v(3)
    v = cross(a, r)
    cross_c = v(c)
  end function cross_c

  !> Smallest eigenvalue of a symmetric 6 x 6 matrix (cyclic Jacobi: no LAPACK workspace).
  pure real(wp) function min_eigenvalue(g0)
    real(wp), intent(in) :: g0(6, 6)
    real(wp) :: g(6, 6), th, t, c, s, gpp, gqq, gpq, row_p(6), row_q(6)
    integer :: sweep, p, q
    g = g0
    do sweep = 1, 30
      do p = 1, 5
        do q = p + 1, 6
          if (abs(g(p, q)) < 1e-300_wp) cycle
          th = (g(q, q) - g(p, p))/(2*g(p, q))
          t = sign(1.0_wp, th)/(abs(th) + sqrt(th*th + 1))
          c = 1/sqrt(t*t + 1)
          s = t*c
          gpp = g(p, p)
          gqq = g(q, q)
          gpq = g(p, q)
          row_p = c*g(p, :) - s*g(q, :)
          row_q = s*g(p, :) + c*g(q, :)
          g(p, :) = row_p
          g(q, :) = row_q
          g(:, p) = row_p
          g(:, q) = row_q
          g(p, p) = gpp - t*gpq
          g(q, q) = gqq + t*gpq
          g(p, q) = 0
          g(q, p) = 0
        end do
      end do
    end do
    min_eigenvalue = minval([(g(p, p), p = 1, 6)])
  end function min_eigenvalue

  !> Order that sorts the ids ascending (heap sort of an index).
  pure function sorted_order(ids) result(order)
    integer, intent(in) :: ids(:)
    integer :: order(size(ids))
    integer :: n, i, last, t
    n = size(ids)
    order = [(i, i = 1, n)]
    do i = n/2, 1, -1
      call sift(i, n)
    end do
    do last = n, 2, -1
      t = order(1)
      order(1) = order(last)
      order(last) = t
      call sift(1, last - 1)
    end do
  contains
    pure subroutine sift(start, end)
      integer, intent(in) :: start, end
      integer :: root, child, tt
      root = start
      do while (2*root <= end)
        child = 2*root
        if (child < end) then
          if (ids(order(child)) < ids(order(child+1))) child = child + 1
        end if
        if (ids(order(root)) >= ids(order(child))) return
        tt = order(root)
        order(root) = order(child)
        order(child) = tt
        root = child
      end do
    end subroutine sift
  end function sorted_order
end module udmap_blade_reduce_rigid_platform
