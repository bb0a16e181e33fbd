!> The linear blade as the standard method and the time integration see it: mass, stiffness
!> and damping matrices (dense, or symmetric band storage when the bandwidth is small), the
!> damper DOF gamma, the excitation DOF E and the stress functional
!> sigma = (s_K - omega^2 s_M)^T q (PHYSICS.md 1).
module udmap_baseline_linear_structure
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT, UDMAP_ENUMERIC
  use udmap_core_strings, only: itoa
  use udmap_core_lapack, only: zgbtrf, zgbtrs, zgetrf, zgetrs
  use udmap_blade_type, only: blade_type, receptances_type
  implicit none
  private
  public :: structure_type, structure_receptances_type, new_structure, structure_receptances
  public :: structure_from_blade

  !> Matrices of the linear blade. kd >= 0: M, K, C in LAPACK symmetric band storage 'U'
  !> (kd+1, ndof), A(i,j) = X(kd+1+i-j, j) for max(1,j-kd) <= i <= j; kd < 0: dense (ndof, ndof).
  type :: structure_type
    integer :: ndof = 0        !< number of DOFs
    integer :: gamma_dof = 0   !< DOF of the platform rotation gamma_P (1-based)
    integer :: exc_dof = 0     !< DOF of the excitation point E (1-based)
    integer :: kd = -1         !< band half-width (>= 0) or -1 for dense storage
    logical :: has_stress = .false.   !< whether s_K, s_M are given
    real(wp), allocatable :: M(:,:), K(:,:), C(:,:)
    real(wp), allocatable :: s_K(:), s_M(:)
    !> The blade it was built from, if any: its (modal, exact) receptances are used.
    type(blade_type), allocatable :: blade
  contains
    !> Entry (i, j) of 'M', 'K' or 'C'.
    procedure :: entry => structure_entry
  end type structure_type

  !> Receptances H_ab(omega) = e_a^T D(omega)^-1 e_b, D = K - omega^2 M + i omega C, and the
  !> omega-derivatives of those on gamma and E.
  type :: structure_receptances_type
    complex(wp) :: gg = 0, gE = 0, EE = 0, sE = 0, sg = 0
    complex(wp) :: dgg = 0, dgE = 0, dEE = 0
  end type structure_receptances_type

contains

  !> Builds the structure from dense symmetric M, K, C (C explicit: beta K or imported), the
  !> 1-based DOFs of gamma and E and optional stress rows. Band storage is chosen when the
  !> bandwidth is small compared with the size.
  subroutine new_structure(st, M, K, C, gamma_dof, exc_dof, error, s_K, s_M)
    type(structure_type), intent(out) :: st
    real(wp), intent(in) :: M(:,:), K(:,:), C(:,:)
    integer, intent(in) :: gamma_dof, exc_dof
    type(error_type), allocatable, intent(out) :: error
    real(wp), intent(in), optional :: s_K(:), s_M(:)
    integer :: n, i, j, kd
    n = size(K, 1)
    if (n < 1 .or. any([size(K,2), size(M,1), size(M,2), size(C,1), size(C,2)] /= n)) then
      call fatal_error(error, "structure: M, K and C must be square and of equal size", UDMAP_EINPUT)
      return
    end if
    if (.not.all(abs(M) <= huge(1.0_wp)) .or. .not.all(abs(K) <= huge(1.0_wp)) &
        & .or. .not.all(abs(C) <= huge(1.0_wp))) then
      call fatal_error(error, "structure: M, K or C has non-finite entries", UDMAP_EINPUT)
      return
    end if
    if (gamma_dof < 1 .or. gamma_dof > n) then
      call fatal_error(error, "structure: gamma_dof out of range", UDMAP_EINPUT)
      return
    end if
    if (exc_dof < 1 .or. exc_dof > n) then
      call fatal_error(error, "structure: exc_dof out of range", UDMAP_EINPUT)
      return
    end if
    kd = 0
    do j = 1, n
      do i = 1, j - 1
        if (K(i,j) /= 0.0_wp .or. M(i,j) /= 0.0_wp .or. C(i,j) /= 0.0_wp .or. &
            & K(j,i) /= 0.0_wp .or. M(j,i) /= 0.0_wp .or. C(j,i) /= 0.0_wp) kd = max(kd, j - i)
      end do
    end do
    st%ndof = n
    st%gamma_dof = gamma_dof
    st%exc_dof = exc_dof
    if (n > 4 .and. 3*(kd + 1) <= n) then
      st%kd = kd
      allocate(st%M(kd+1, n), st%K(kd+1, n), st%C(kd+1, n))
      st%M = 0.0_wp; st%K = 0.0_wp; st%C = 0.0_wp
      do j = 1, n
        do i = max(1, j - kd), j
          st%M(kd+1+i-j, j) = M(i,j)
          st%K(kd+1+i-j, j) = K(i,j)
          st%C(kd+1+i-j, j) = C(i,j)
        end do
      end do
    else
      st%kd = -1
      st%M = M
      st%K = K
      st%C = C
    end if
    if (present(s_K) .and. present(s_M)) then
      if (size(s_K) /= n .or. size(s_M) /= n) then
        call fatal_error(error, "structure: stress rows must have ndof entries", UDMAP_EINPUT)
        return
      end if
      st%has_stress = .true.
      st%s_K = s_K
      st%s_M = s_M
    end if
  end subroutine new_structure

  !> The structure of a kernel blade (PHYSICS.md 1): its band (or dense) matrices, with
  !> C = beta K unless the blade has an explicit C; the receptances come from the blade.
  subroutine structure_from_blade(st, blade, error)
    type(structure_type), intent(out) :: st
    type(blade_type), intent(in) :: blade
    type(error_type), allocatable, intent(out) :: error
    if (blade%ndof < 1) then
      call fatal_error(error, "structure: the blade has not been built", UDMAP_EINPUT)
      return
    end if
    st%ndof = blade%ndof
    st%gamma_dof = blade%gamma_dof
    st%exc_dof = blade%exc_dof
    if (blade%kd >= 0 .and. allocated(blade%Kb) .and. allocated(blade%Mb)) then
      st%kd = blade%kd
      st%M = blade%Mb
      st%K = blade%Kb
      if (blade%explicit_C) then
        if (.not.allocated(blade%Cb)) then
          call fatal_error(error, "structure: explicit C of the blade is not in band storage", &
            & UDMAP_EINPUT)
          return
        end if
        st%C = blade%Cb
      else
        st%C = blade%beta*blade%Kb
      end if
    else if (allocated(blade%K) .and. allocated(blade%M)) then
      st%kd = -1
      st%M = blade%M
      st%K = blade%K
      if (blade%explicit_C) then
        st%C = blade%C
      else
        st%C = blade%beta*blade%K
      end if
    else
      call fatal_error(error, "structure: the blade keeps neither band nor dense matrices", &
        & UDMAP_EINPUT)
      return
    end if
    st%has_stress = blade%has_stress
    if (blade%has_stress) then
      st%s_K = blade%s_K
      st%s_M = blade%s_M
    end if
    allocate(st%blade, source=blade)
  end subroutine structure_from_blade

  !> Entry (i, j) of the matrix named by `which` ('M', 'K' or 'C').
  pure real(wp) function structure_entry(self, which, i, j) result(a)
    class(structure_type), intent(in) :: self
    character(len=1), intent(in) :: which
    integer, intent(in) :: i, j
    integer :: r, c
    if (self%kd < 0) then
      r = i; c = j
    else
      r = min(i, j); c = max(i, j)
      if (c - r > self%kd) then
        a = 0.0_wp
        return
      end if
      r = self%kd + 1 + r - c
    end if
    select case (which)
    case ('M')
      a = self%M(r, c)
    case ('K')
      a = self%K(r, c)
    case default
      a = self%C(r, c)
    end select
  end function structure_entry

  !> Receptances at omega [rad/s]: the blade's when the structure has one, else by a direct
  !> (banded or dense) complex LU solve.
  subroutine structure_receptances(st, omega, r, error)
    type(structure_type), intent(in) :: st
    real(wp), intent(in) :: omega
    type(structure_receptances_type), intent(out) :: r
    type(error_type), allocatable, intent(out) :: error
    type(receptances_type) :: rb
    complex(wp), allocatable :: A(:,:), X(:,:), DX(:,:)
    integer, allocatable :: ipiv(:)
    integer :: n, kd, i, j, info, nrhs, ldab
    complex(wp) :: dp
    integer :: lo, hi
    real(wp), allocatable :: s(:)
    if (allocated(st%blade)) then
      call st%blade%receptances(omega, rb, error, derivatives=.true.)
      if (allocated(error)) return
      r%gg = rb%gg; r%gE = rb%gE; r%EE = rb%EE; r%sE = rb%sE; r%sg = rb%sg
      r%dgg = rb%dgg; r%dgE = rb%dgE; r%dEE = rb%dEE
      return
    end if
    n = st%ndof
    kd = st%kd
    nrhs = 2
    if (st%has_stress) nrhs = 3
    allocate(X(n, nrhs), ipiv(n))
    X = (0.0_wp, 0.0_wp)
    X(st%gamma_dof, 1) = (1.0_wp, 0.0_wp)
    X(st%exc_dof, 2) = (1.0_wp, 0.0_wp)
    if (st%has_stress) then
      s = st%s_K - omega**2*st%s_M
      X(:, 3) = s
    end if
    if (kd >= 0) then
      ldab = 3*kd + 1
      allocate(A(ldab, n))
      A = (0.0_wp, 0.0_wp)
      do j = 1, n
        do i = max(1, j - kd), min(n, j + kd)
          A(2*kd+1+i-j, j) = dyn(i, j)
        end do
      end do
      call zgbtrf(n, n, kd, kd, A, ldab, ipiv, info)
      if (info == 0) call zgbtrs('N', n, kd, kd, nrhs, A, ldab, ipiv, X, n, info)
    else
      allocate(A(n, n))
      do j = 1, n
        do i = 1, n
          A(i, j) = dyn(i, j)
        end do
      end do
      call zgetrf(n, n, A, n, ipiv, info)
      if (info == 0) call zgetrs('N', n, nrhs, A, n, ipiv, X, n, info)
    end if
    if (info /= 0) then
      call fatal_error(error, "receptances: zgbtrf/zgetrf failed (info = "//itoa(info)// &
        & "): the dynamic stiffness is singular at this frequency", UDMAP_ENUMERIC)
      return
    end if
    r%gg = X(st%gamma_dof, 1)
    r%gE = X(st%gamma_dof, 2)
    r%EE = X(st%exc_dof, 2)
    if (st%has_stress) then
      r%sg = X(st%gamma_dof, 3)
      r%sE = X(st%exc_dof, 3)
    end if
    ! dH_ab/domega = -x_a^T D'(omega) x_b with D' = -2 omega M + i C (D symmetric)
    allocate(DX(n, 2))
    DX = (0.0_wp, 0.0_wp)
    do j = 1, n
      lo = 1; hi = n
      if (kd >= 0) then
        lo = max(1, j - kd); hi = min(n, j + kd)
      end if
      do i = lo, hi
        dp = cmplx(-2.0_wp*omega*st%entry('M', i, j), st%entry('C', i, j), wp)
        if (dp == (0.0_wp, 0.0_wp)) cycle
        DX(i, 1) = DX(i, 1) + dp*X(j, 1)
        DX(i, 2) = DX(i, 2) + dp*X(j, 2)
      end do
    end do
    r%dgg = -sum(X(:, 1)*DX(:, 1))
    r%dgE = -sum(X(:, 1)*DX(:, 2))
    r%dEE = -sum(X(:, 2)*DX(:, 2))
  contains
    pure complex(wp) function dyn(i, j)
      integer, intent(in) :: i, j
      dyn = cmplx(st%entry('K', i, j) - omega**2*st%entry('M', i, j), omega*st%entry('C', i, j), wp)
    end function dyn
  end subroutine structure_receptances
end module udmap_baseline_linear_structure
