!> Sparse symmetric LDL^T factorisation of A = K - sigma M with sequential MUMPS (SYM=2),
!> for the shift-invert eigen-solves and static modes of the Platform Centred Reduction.
!> The MUMPS instance lives in a sparse_factor_type that the caller owns (no module state):
!> the pattern is analysed once and new values (another shift) refactored on it. The inertia
!> (number of negative pivots, INFOG(12)) counts the eigenvalues of (K, M) below sigma
!> (Sylvester's law), which checks that a shift-invert solve missed no mode.
!> Without MUMPS (the FMU's object set) every routine returns an error.
module udmap_blade_reduce_sparse_factor
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_ENUMERIC, UDMAP_EPHYSICS
  implicit none
  private
  public :: sparse_factor_type, factor_analyse, factor_numeric, factor_solve, factor_free

#ifdef UDMAP_WITH_MUMPS
  include 'dmumps_struc.h'

  interface
    !> The MUMPS driver (double precision).
    subroutine dmumps(id)
      import :: dmumps_struc
      type(dmumps_struc), intent(inout) :: id
    end subroutine dmumps
  end interface
#endif

  !> MUMPS's value for the communicator of the sequential library (any value works).
  integer, parameter :: comm_world = -987654

  !> A factorisation owned by the caller; free it with factor_free.
  type :: sparse_factor_type
#ifdef UDMAP_WITH_MUMPS
    type(dmumps_struc), allocatable :: id
#endif
    !> Order of the matrix.
    integer :: n = 0
    !> Negative pivots of the last factorisation (inertia), -1 before one.
    integer :: negative_pivots = -1
    !> Entries of the factors (INFOG(29)) of the last factorisation.
    integer(8) :: factor_entries = 0
    !> True after a successful numeric factorisation.
    logical :: factored = .false.
  end type sparse_factor_type

contains

  !> Analyses (orders) the pattern of the lower-triangle entries (row(k) >= col(k)).
  subroutine factor_analyse(f, n, row, col, error)
    type(sparse_factor_type), intent(inout) :: f
    integer, intent(in) :: n
    integer, intent(in) :: row(:), col(:)
    type(error_type), allocatable, intent(out) :: error
#ifdef UDMAP_WITH_MUMPS
    call factor_free(f)
    allocate(f%id)
    f%n = n
    f%id%comm = comm_world
    f%id%sym = 2
    f%id%par = 1
    f%id%job = -1
    call dmumps(f%id)
    if (f%id%infog(1) < 0) then
      call mumps_error(f, "initialisation", error)
      return
    end if
    call quiet(f)
    f%id%n = n
    f%id%nnz = size(row, kind=8)
    allocate(f%id%irn(size(row)), f%id%jcn(size(col)), f%id%a(size(row)))
    f%id%irn = row
    f%id%jcn = col
    f%id%a = 0
    f%id%job = 1
    call dmumps(f%id)
    if (f%id%infog(1) < 0) call mumps_error(f, "analysis", error)
#else
    f%n = n
    if (size(row) /= size(col)) continue
    call fatal_error(error, "the FE reduction is not in this build of udmap (built without MUMPS, "// &
      & "as the Windows library is): reduce the blade with a Linux build and use its matrices", &
      & UDMAP_ENUMERIC)
#endif
  end subroutine factor_analyse

  !> Factorises the analysed pattern with values `a` (one per entry, duplicates add up).
  !> `what` names the matrix in messages. A numerically singular matrix is a physics error.
  subroutine factor_numeric(f, a, what, error)
    type(sparse_factor_type), intent(inout) :: f
    real(wp), intent(in) :: a(:)
    character(len=*), intent(in) :: what
    type(error_type), allocatable, intent(out) :: error
#ifdef UDMAP_WITH_MUMPS
    integer :: attempt
    f%factored = .false.
    if (.not.allocated(f%id)) then
      call fatal_error(error, "sparse factorisation: not analysed", UDMAP_ENUMERIC)
      return
    end if
    f%id%a = a
    do attempt = 1, 4
      f%id%job = 2
      call dmumps(f%id)
      ! -8, -9: workspace estimate too small (delayed pivots); relax it and retry
      if (f%id%infog(1) /= -8 .and. f%id%infog(1) /= -9) exit
      f%id%icntl(14) = 2*f%id%icntl(14)
    end do
    if (f%id%infog(1) == -10) then
      call fatal_error(error, what//" is singular (MUMPS found a zero pivot)", UDMAP_EPHYSICS)
      return
    else if (f%id%infog(1) < 0) then
      call mumps_error(f, "factorisation of "//what, error)
      return
    end if
    f%negative_pivots = f%id%infog(12)
    f%factor_entries = int(f%id%infog(29), 8)
    if (f%factor_entries < 0) f%factor_entries = -1000000_8*f%factor_entries
    f%factored = .true.
#else
    f%factored = .false.
    if (size(a) < 0) continue
    call fatal_error(error, "sparse factorisation of "//what//": udmap was built without MUMPS", &
      & UDMAP_ENUMERIC)
#endif
  end subroutine factor_numeric

  !> Solves A X = B in place for the columns of b(n, nrhs).
  subroutine factor_solve(f, b, error)
    type(sparse_factor_type), intent(inout) :: f
    real(wp), intent(inout) :: b(:, :)
    type(error_type), allocatable, intent(out) :: error
#ifdef UDMAP_WITH_MUMPS
    integer :: nrhs, j
    if (.not.f%factored) then
      call fatal_error(error, "sparse solve: not factorised", UDMAP_ENUMERIC)
      return
    end if
    nrhs = size(b, 2)
    if (nrhs == 0) return
    allocate(f%id%rhs(f%n*nrhs))
    do j = 1, nrhs
      f%id%rhs((j-1)*f%n+1:j*f%n) = b(:, j)
    end do
    f%id%nrhs = nrhs
    f%id%lrhs = f%n
    f%id%job = 3
    call dmumps(f%id)
    if (f%id%infog(1) < 0) then
      call mumps_error(f, "solve", error)
    else
      do j = 1, nrhs
        b(:, j) = f%id%rhs((j-1)*f%n+1:j*f%n)
      end do
    end if
    deallocate(f%id%rhs)
    nullify(f%id%rhs)
#else
    if (size(b) < 0 .or. f%n < 0) continue
    call fatal_error(error, "sparse solve: udmap was built without MUMPS", UDMAP_ENUMERIC)
#endif
  end subroutine factor_solve

  !> Releases the MUMPS instance and the arrays it pointed to.
  subroutine factor_free(f)
    type(sparse_factor_type), intent(inout) :: f
#ifdef UDMAP_WITH_MUMPS
    if (allocated(f%id)) then
      f%id%job = -2
      call dmumps(f%id)
      if (associated(f%id%irn)) deallocate(f%id%irn)
      if (associated(f%id%jcn)) deallocate(f%id%jcn)
      if (associated(f%id%a)) deallocate(f%id%a)
      deallocate(f%id)
    end if
#endif
    f%factored = .false.
    f%negative_pivots = -1
  end subroutine factor_free

#ifdef UDMAP_WITH_MUMPS
  !> No printing (errors travel as values); PORD ordering of the plain graph; more pivoting
  !> workspace. On the generated hexahedral blades (10^4 and 10^5 DOFs) PORD on the plain
  !> graph (ICNTL(12) = 1) needs 2.4 to 3.6 times fewer flops than MUMPS's automatic choice
  !> (AMF on the compressed graph of its 2x2-pivot ordering): 2.6e10 against 9.4e10 at 10^5
  !> DOFs, with 37 instead of 70 million factor entries. The factorised matrices (K - sigma M
  !> near the bottom of the spectrum) have few negative pivots, so the compressed ordering's
  !> 2x2 pivots buy nothing.
  subroutine quiet(f)
    type(sparse_factor_type), intent(inout) :: f
    f%id%icntl(1) = -1
    f%id%icntl(2) = -1
    f%id%icntl(3) = -1
    f%id%icntl(4) = 0
    f%id%icntl(7) = 4
    f%id%icntl(12) = 1
    f%id%icntl(14) = 40
  end subroutine quiet

  !> An error with MUMPS's INFOG(1), INFOG(2).
  subroutine mumps_error(f, stage, error)
    type(sparse_factor_type), intent(in) :: f
    character(len=*), intent(in) :: stage
    type(error_type), allocatable, intent(out) :: error
    character(len=64) :: buf
    write(buf, '(a,i0,a,i0,a)') " (INFOG(1) = ", f%id%infog(1), ", INFOG(2) = ", &
      & f%id%infog(2), ")"
    call fatal_error(error, "MUMPS "//stage//" failed"//trim(buf), UDMAP_ENUMERIC)
  end subroutine mumps_error
#endif
end module udmap_blade_reduce_sparse_factor
