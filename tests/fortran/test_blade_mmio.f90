!> Matrix Market reader and writer (udmap_blade_io_mmio) and the imported blade's file checks: exact
!> round trip of doubles, the formats and fields accepted, and a clear error (status 2, naming
!> the file and line) for each kind of malformed file.
module test_blade_mmio
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, UDMAP_EINPUT
  use udmap_blade_io_mmio, only: mtx_type, read_mtx, write_mtx, mtx_to_dense, mtx_bandwidth
  use udmap_blade_type, only: blade_type
  use udmap_blade_io_matrices, only: read_matrices_blade
  use fixtures, only: temp_dir
  use testing, only: test_suite, check_close, check_true, check_no_error, check_error, &
    & unittest_type, new_unittest
  implicit none
  private
  public :: collect_blade_mmio

contains

  !> Matrix Market: round trip, formats, malformed files, imported blade files.
  subroutine collect_blade_mmio(testsuite)
    type(unittest_type), allocatable, intent(out) :: testsuite(:)
    testsuite = [new_unittest("blade_mmio", run_blade_mmio)]
  end subroutine collect_blade_mmio

  !> Matrix Market files: exact round trip, accepted formats, one clear error per malformed file.
  subroutine run_blade_mmio(suite)
    type(test_suite), intent(inout) :: suite
    character(len=:), allocatable :: dir

    dir = temp_dir("mmio")
    call round_trip()
    call formats()
    call malformed()
    call blade_files()
    call execute_command_line("rm -rf "//dir)

  contains

    !> Doubles of every magnitude survive write and read bit for bit.
    subroutine round_trip()
      type(mtx_type) :: a, b
      type(error_type), allocatable :: error
      real(wp), parameter :: v(8) = [1.0_wp/3, -2.0_wp/7, 1.0e-300_wp, -1.7976931348623157e308_wp, &
        & 4.9406564584124654e-324_wp, 123456789.123456789_wp, -0.1_wp, nearest(1.0_wp, 1.0_wp)]
      integer :: k
      a%nrows = 5
      a%ncols = 4
      a%symmetric = .false.
      a%row = [1, 2, 3, 4, 5, 1, 2, 5]
      a%col = [1, 1, 2, 3, 4, 4, 3, 1]
      a%val = v
      call write_mtx(dir//"/general.mtx", a, error)
      call check_no_error(suite, "write general", error)
      call read_mtx(dir//"/general.mtx", b, error)
      call check_no_error(suite, "read general", error)
      if (allocated(error)) return
      call check_true(suite, "general: sizes", b%nrows == 5 .and. b%ncols == 4 .and. .not.b%symmetric)
      call check_true(suite, "general: indices", all(b%row == a%row) .and. all(b%col == a%col))
      call check_true(suite, "general: values bit for bit", all(b%val == a%val))
      a%nrows = 5
      a%ncols = 5
      a%symmetric = .true.
      a%row = [1, 2, 3, 4, 5, 4, 3, 5]
      a%col = [1, 1, 2, 3, 4, 4, 3, 1]
      call write_mtx(dir//"/symmetric.mtx", a, error, comment="a test")
      call read_mtx(dir//"/symmetric.mtx", b, error)
      call check_no_error(suite, "read symmetric", error)
      if (allocated(error)) return
      call check_true(suite, "symmetric: values bit for bit", b%symmetric .and. all(b%val == a%val))
      do k = 1, size(v)
        if (b%val(k) /= v(k)) call check_true(suite, "value differs", .false.)
      end do
      call check_true(suite, "bandwidth of the symmetric matrix", mtx_bandwidth(b) == 4)
    end subroutine round_trip

    subroutine formats()
      type(mtx_type) :: a
      type(error_type), allocatable :: error
      real(wp), allocatable :: d(:, :)
      ! Array, general, integer field, with comments, blank lines and an upper-case banner.
      call write_text("array.mtx", [character(len=60) :: "%%MatrixMarket MATRIX Array INTEGER General", &
        & "% comment", "", "2 3", "1", "-2", "3", "4", "  5  ", "6"])
      call read_mtx(dir//"/array.mtx", a, error)
      call check_no_error(suite, "array integer general", error)
      if (allocated(error)) return
      call mtx_to_dense(a, d)
      call check_true(suite, "array is column-major", d(1, 1) == 1 .and. d(2, 1) == -2 .and. &
        & d(1, 2) == 3 .and. d(2, 3) == 6)
      ! Array, symmetric: the lower triangle by columns.
      call write_text("arraysym.mtx", [character(len=60) :: "%%MatrixMarket matrix array real symmetric", &
        & "3 3", "1.5", "2e0", "3.0D0", "4", "5", "6"])
      call read_mtx(dir//"/arraysym.mtx", a, error)
      call check_no_error(suite, "array real symmetric", error)
      if (allocated(error)) return
      call mtx_to_dense(a, d)
      call check_true(suite, "array symmetric mirrored", d(1, 1) == 1.5_wp .and. d(2, 1) == 2 .and. &
        & d(1, 2) == 2 .and. d(3, 1) == 3 .and. d(2, 2) == 4 .and. d(3, 2) == 5 .and. d(2, 3) == 5 &
        & .and. d(3, 3) == 6)
      ! Coordinate symmetric, duplicates summed, last line without newline.
      call write_text("dup.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real symmetric", &
        & "2 2 3", "1 1 1.0", "2 1 0.5", "2 1 0.25"], newline=.false.)
      call read_mtx(dir//"/dup.mtx", a, error)
      call check_no_error(suite, "last line without newline", error)
      if (allocated(error)) return
      call mtx_to_dense(a, d)
      call check_close(suite, "duplicates summed", d(1, 2), 0.75_wp, 0.0_wp)
    end subroutine formats

    subroutine malformed()
      call expect("missing.mtx", [character(len=60) :: ""], "'"//dir//"/missing.mtx' not found", &
        & create=.false.)
      call expect("banner.mtx", [character(len=60) :: "%MatrixMarket matrix coordinate real general", &
        & "1 1 1", "1 1 1"], "line 1: bad banner")
      call expect("banner2.mtx", [character(len=60) :: "1 1 1", "1 1 1"], "line 1: bad banner")
      call expect("complex.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate complex general", &
        & "1 1 1", "1 1 1 0"], "unsupported field 'complex'")
      call expect("pattern.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate pattern general", &
        & "1 1 1", "1 1"], "unsupported field 'pattern'")
      call expect("herm.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real hermitian", &
        & "1 1 1", "1 1 1"], "unsupported symmetry 'hermitian'")
      call expect("empty.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real general"], &
        & "file ends before the size line")
      call expect_general("size.mtx", [character(len=12) :: "3 3", "1 1 1"], &
        & "line 2: bad size line '3 3'")
      call expect_general("size2.mtx", [character(len=12) :: "3 x 2", "1 1 1"], &
        & "sizes must be integers")
      call expect_general("short.mtx", [character(len=12) :: "3 3 5", "1 1 1", "2 2 1", "3 3 1"], &
        & "line 5: file ends after 3 of 5 entries")
      call expect_general("long.mtx", [character(len=12) :: "3 3 1", "1 1 1", "2 2 1"], &
        & "line 4: more entries than the 1 declared")
      call expect_general("range.mtx", [character(len=12) :: "3 3 2", "1 1 1", "4 1 2.5"], &
        & "line 4: index (4, 1) out of range for a 3 x 3 matrix")
      call expect_general("range0.mtx", [character(len=12) :: "3 3 1", "0 1 1"], &
        & "index (0, 1) out of range")
      call expect_general("number.mtx", [character(len=12) :: "3 3 1", "1 1 1.0x"], &
        & "line 3: unparsable or non-finite number '1.0x'")
      call expect_general("nan.mtx", [character(len=12) :: "3 3 1", "1 1 NaN"], &
        & "unparsable or non-finite number 'NaN'")
      call expect_general("overflow.mtx", [character(len=12) :: "3 3 1", "1 1 1e999"], &
        & "non-finite number '1e999'")
      call expect_general("index.mtx", [character(len=12) :: "3 3 1", "1.5 1 1"], &
        & "unparsable index")
      call expect_general("fields.mtx", [character(len=12) :: "3 3 1", "1 1"], &
        & "expected 'row column value'")
      call expect("upper.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real symmetric", &
        & "3 3 1", "1 2 1.0"], "entry (1, 2) above the diagonal")
      call expect("nonsquare.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real symmetric", &
        & "3 2 1", "1 1 1.0"], "a symmetric matrix must be square")
      call expect("arrayshort.mtx", [character(len=60) :: "%%MatrixMarket matrix array real general", &
        & "2 2", "1", "2", "3"], "file ends after 3 of 4 entries")
    end subroutine malformed

    !> The imported blade names the matrix and file when the data do not fit.
    subroutine blade_files()
      type(blade_type) :: b
      type(error_type), allocatable :: error
      character(len=64) :: line
      integer :: unit, i
      call write_text("M.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real symmetric", &
        & "2 2 2", "1 1 1.0", "2 2 1.0"])
      call write_text("K.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real general", &
        & "2 2 4", "1 1 2.0", "2 1 -1.0", "1 2 -1.5", "2 2 2.0"])
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/K.mtx", 1, 2, 0.01_wp, error)
      call check_error(suite, "non-symmetric K file", error, UDMAP_EINPUT, &
        & "K ('"//dir//"/K.mtx') is not symmetric: entry (2, 1) = -1.000000000 but (1, 2) = -1.500000000")
      call write_text("K.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real general", &
        & "2 2 4", "1 1 2.0", "2 1 -1.0", "1 2 -1.0", "2 2 2.0"])
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/K.mtx", 1, 2, 0.01_wp, error)
      call check_no_error(suite, "2-DOF chain from general files", error)
      if (.not.allocated(error)) then
        ! K = [2 -1; -1 2], M = I: omega^2 = 1 and 3.
        call check_close(suite, "2-DOF chain omega_1 = 1", b%omega(1), 1.0_wp, 1.0e-14_wp)
        call check_close(suite, "2-DOF chain omega_2 = sqrt(3)", b%omega(2), sqrt(3.0_wp), 1.0e-14_wp)
      end if
      call write_text("K3.mtx", [character(len=60) :: "%%MatrixMarket matrix coordinate real symmetric", &
        & "3 3 1", "1 1 2.0"])
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/K3.mtx", 1, 2, 0.01_wp, error)
      call check_error(suite, "K of another size", error, UDMAP_EINPUT, "K ('"//dir//"/K3.mtx') must be 2 x 2")
      call write_text("s.mtx", [character(len=60) :: "%%MatrixMarket matrix array real general", &
        & "2 2", "1", "2", "3", "4"])
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/K.mtx", 1, 2, 0.01_wp, error, sK_path=dir//"/s.mtx")
      call check_error(suite, "stress row of wrong shape", error, UDMAP_EINPUT, &
        & "stress_K ('"//dir//"/s.mtx') must be a 1 x 2 or 2 x 1 matrix, got 2 x 2")
      call write_text("s.mtx", [character(len=60) :: "%%MatrixMarket matrix array real general", &
        & "2 1", "1", "2"])
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/K.mtx", 1, 2, 0.01_wp, error, sM_path=dir//"/s.mtx")
      call check_no_error(suite, "stress row as a column", error)
      call check_true(suite, "stress row read", b%has_stress)
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/K.mtx", 3, 2, 0.01_wp, error)
      call check_error(suite, "gamma_dof out of range", error, UDMAP_EINPUT, "gamma_dof must be a DOF number from 1 to 2")
      call read_matrices_blade(b, dir//"/M.mtx", dir//"/range.mtx", 1, 2, 0.01_wp, error)
      call check_error(suite, "malformed K file", error, UDMAP_EINPUT, "range.mtx', line 4")
      ! Above the dense limit the symmetry check runs on band storage: a 2001 x 2001 diagonal
      ! with one unmatched off-diagonal entry.
      open(newunit=unit, file=dir//"/big.mtx", status="replace", action="write")
      write(unit, '(a)') "%%MatrixMarket matrix coordinate real general"
      write(unit, '(a)') "2001 2001 2002"
      do i = 1, 2001
        write(line, '(i0, 1x, i0, a)') i, i, " 1.0"
        write(unit, '(a)') trim(line)
      end do
      write(unit, '(a)') "7 5 0.5"
      close(unit)
      call read_matrices_blade(b, dir//"/big.mtx", dir//"/big.mtx", 1, 2, 0.01_wp, error)
      call check_error(suite, "large non-symmetric M (band check)", error, UDMAP_EINPUT, &
        & "big.mtx') is not symmetric: entry (5, 7) = 0.000000000 but (7, 5) = 0.5000000000")
    end subroutine blade_files

    ! ------------------------------------------------------------------ helpers

    subroutine expect(name, lines, needle, create)
      character(len=*), intent(in) :: name, lines(:), needle
      logical, intent(in), optional :: create
      type(mtx_type) :: a
      type(error_type), allocatable :: error
      logical :: make
      make = .true.
      if (present(create)) make = create
      if (make) call write_text(name, lines)
      call read_mtx(dir//"/"//name, a, error)
      call check_error(suite, "malformed "//name, error, UDMAP_EINPUT, needle)
      if (allocated(error)) then
        call check_true(suite, name//": message names the file", index(error%message, dir//"/"//name) > 0)
      end if
    end subroutine expect

    !> expect() of a coordinate real general file: its banner, then lines.
    subroutine expect_general(name, lines, needle)
      character(len=*), intent(in) :: name, lines(:), needle
      call expect(name, [character(len=60) :: "%%MatrixMarket matrix coordinate real general", &
        & lines], needle)
    end subroutine expect_general

    subroutine write_text(name, lines, newline)
      character(len=*), intent(in) :: name, lines(:)
      logical, intent(in), optional :: newline
      integer :: unit, i
      logical :: nl
      nl = .true.
      if (present(newline)) nl = newline
      open(newunit=unit, file=dir//"/"//name, status="replace", action="write", access="stream", &
        & form="unformatted")
      do i = 1, size(lines)
        if (i < size(lines) .or. nl) then
          write(unit) trim(lines(i))//achar(10)
        else
          write(unit) trim(lines(i))
        end if
      end do
      close(unit)
    end subroutine write_text

  end subroutine run_blade_mmio
end module test_blade_mmio
