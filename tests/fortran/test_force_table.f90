!> The force table (kernel/src/mapping/harmonic/force_table.f90) on known functions of
!> u = ln F_E, driven as udmap_mapping_harmonic_mapping drives it: a smooth function is
!> interpolated to the tolerance wherever a panel was verified, the first force of a level-0
!> panel is not tabulated, a jump is confined to exact leaves of the deepest level, and points
!> of another structure or another H are never mixed into a panel.
module test_force_table
  use, intrinsic :: iso_fortran_env, only: int64
  use testing, only: test_suite, check_true, unittest_type, new_unittest
  use udmap_core_kinds, only: wp
  use udmap_mapping_harmonic_types, only: force_table_type, SIGNATURE_SIZE
  use udmap_mapping_harmonic_force_table, only: table_reset, table_lookup, table_first_visit, &
    & table_panel, table_has_node, table_add_node, table_judge, node_force, TABLE_MISSING, &
    & TABLE_VERIFIED, TABLE_EXACT, TABLE_SPLIT, LEVEL_MAX
  implicit none
  private
  public :: collect_force_table

contains

  !> The force table of the multi-harmonic mapping on known functions.
  subroutine collect_force_table(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("force_table", run_force_table)]
  end subroutine collect_force_table

  !> The force table interpolates smooth outputs, confines jumps and never mixes keys.
  subroutine run_force_table(suite)
    type(test_suite), intent(inout) :: suite
    real(wp), parameter :: tol = 1.0e-8_wp
    integer, parameter :: SMOOTH = 1, JUMP = 2, STRUCTURE = 3

    call smooth_function()
    call jump_function()
    call structure_change()
    call reset_on_new_key()

  contains

    !> The outputs at u: two smooth functions, and for JUMP a step of 1e-3 at u = 1 in the first
    !> (a lift-off jump); STRUCTURE changes the signature (e.g. the number of roots) at u = 1.
    subroutine outputs(kind, u, y, sig)
      integer, intent(in) :: kind
      real(wp), intent(in) :: u
      real(wp), intent(out) :: y(2)
      integer, intent(out) :: sig(SIGNATURE_SIZE)
      y = [2 + sin(3*u), exp(0.7_wp*u)]
      sig = [3, 1, 0, 4, 0]
      if (kind == JUMP .and. u >= 1) y(1) = y(1) + 1.0e-3_wp
      if (kind == STRUCTURE .and. u >= 1) sig(2) = 2
    end subroutine outputs

    !> Asks the table at u as the mapping does; status: how it answered, y the answer.
    subroutine ask(t, kind, u, status, y)
      type(force_table_type), intent(inout) :: t
      integer, intent(in) :: kind
      real(wp), intent(in) :: u
      integer, intent(out) :: status
      real(wp), allocatable, intent(inout) :: y(:)
      integer(int64) :: idx(9)
      integer :: sig(SIGNATURE_SIZE), L, j
      real(wp) :: yn(2)
      call table_lookup(t, u, status, y, sig)
      if (status /= TABLE_MISSING) return
      if (table_first_visit(t, u)) return
      do L = 0, LEVEL_MAX
        idx = table_panel(u, L)
        do j = 1, 9
          if (table_has_node(t, idx(j), 3)) cycle
          call outputs(kind, log(node_force(idx(j))), yn, sig)
          call table_add_node(t, idx(j), 3, .true., sig, yn, [1.0_wp, 1.0_wp])
        end do
        if (table_judge(t, idx, 3, tol, L == LEVEL_MAX) /= TABLE_SPLIT) exit
      end do
      call table_lookup(t, u, status, y, sig)
    end subroutine ask

    subroutine smooth_function()
      type(force_table_type) :: t
      real(wp), allocatable :: y(:)
      real(wp) :: u, exact(2), worst
      integer :: i, status, sig(SIGNATURE_SIZE), n_first, n_verified
      call table_reset(t, [1.0_wp])
      worst = 0
      n_first = 0
      n_verified = 0
      do i = 1, 400
        u = log(1 + 9*modulo(0.6180339887498949_wp*i, 1.0_wp))
        call ask(t, SMOOTH, u, status, y)
        if (status == TABLE_MISSING) n_first = n_first + 1
        if (status == TABLE_VERIFIED) then
          n_verified = n_verified + 1
          call outputs(SMOOTH, u, exact, sig)
          worst = max(worst, maxval(abs(y - exact)))
        end if
      end do
      ! ln 10 spans eight level-0 panels (nine with the one holding ln 10)
      call check_true(suite, "smooth: only the first force of each level-0 panel is not "// &
        & "tabulated", n_first >= 8 .and. n_first <= 9)
      call check_true(suite, "smooth: every other force interpolated", n_verified == 400 - n_first)
      call check_true(suite, "smooth: interpolated within the tolerance", worst <= tol)
      call check_true(suite, "smooth: and not exactly (the interpolation is used)", worst > 0)
    end subroutine smooth_function

    subroutine jump_function()
      type(force_table_type) :: t
      real(wp), allocatable :: y(:)
      real(wp) :: u, exact(2), worst, width
      integer :: i, status, sig(SIGNATURE_SIZE), n_exact
      call table_reset(t, [1.0_wp])
      worst = 0
      n_exact = 0
      do i = 1, 2000
        u = 0.5_wp + modulo(0.6180339887498949_wp*i, 1.0_wp)
        call ask(t, JUMP, u, status, y)
        if (status == TABLE_EXACT) then
          n_exact = n_exact + 1
          width = log(10.0_wp)/8/2**LEVEL_MAX
          call check_true(suite, "jump: exact leaves only within the deepest panel of the jump", &
            & abs(u - 1) <= width)
        else if (status == TABLE_VERIFIED) then
          call outputs(JUMP, u, exact, sig)
          worst = max(worst, maxval(abs(y - exact)))
        end if
      end do
      call check_true(suite, "jump: interpolated within the tolerance on both sides", worst <= tol)
      ! a force right at the jump answers exactly
      call ask(t, JUMP, 1.0_wp, status, y)
      call ask(t, JUMP, 1.0_wp + 1.0e-6_wp, status, y)
      call check_true(suite, "jump: a force at the jump is solved exactly", status == TABLE_EXACT)
    end subroutine jump_function

    subroutine structure_change()
      type(force_table_type) :: t
      real(wp), allocatable :: y(:)
      integer :: status, i
      integer(int64) :: idx(9)
      real(wp) :: u
      logical :: mixed
      call table_reset(t, [1.0_wp])
      mixed = .false.
      do i = 1, 1000
        u = 0.5_wp + modulo(0.6180339887498949_wp*i, 1.0_wp)
        call ask(t, STRUCTURE, u, status, y)
        if (status == TABLE_VERIFIED .and. abs(u - 1) < log(10.0_wp)/8/2**LEVEL_MAX) mixed = .true.
      end do
      call check_true(suite, "structure: no panel mixes two structures", .not.mixed)
      ! points of another H at the same positions are other nodes
      idx = table_panel(0.7_wp, 0)
      call check_true(suite, "structure: nodes are keyed by H", &
        & table_has_node(t, idx(1), 3) .and. .not.table_has_node(t, idx(1), 5))
    end subroutine structure_change

    subroutine reset_on_new_key()
      type(force_table_type) :: t
      real(wp), allocatable :: y(:)
      integer :: status
      call table_reset(t, [1.0_wp])
      call ask(t, SMOOTH, 0.3_wp, status, y)
      call ask(t, SMOOTH, 0.31_wp, status, y)
      call check_true(suite, "reset: built", status == TABLE_VERIFIED)
      call table_reset(t, [1.0_wp])
      call ask(t, SMOOTH, 0.31_wp, status, y)
      call check_true(suite, "reset: same key keeps the table", status == TABLE_VERIFIED)
      call table_reset(t, [2.0_wp])
      call ask(t, SMOOTH, 0.31_wp, status, y)
      call check_true(suite, "reset: a new key empties it (first visit again)", &
        & status == TABLE_MISSING)
    end subroutine reset_on_new_key
  end subroutine run_force_table
end module test_force_table
