!> Matrix Market files (https://math.nist.gov/MatrixMarket/formats.html): reader for
!> `matrix coordinate|array real|integer general|symmetric` and writer for coordinate
!> real general/symmetric with 17 significant digits (exact round trip of doubles).
!> Entries are held as coordinate triplets; symmetric files list the lower triangle only.
module udmap_blade_io_mmio
  use udmap_core_kinds, only: wp
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_core_strings, only: itoa
  implicit none
  private
  public :: mtx_type, read_mtx, write_mtx, mtx_to_dense, mtx_bandwidth

  !> A sparse matrix as read from or written to a Matrix Market file (1-based triplets).
  !> With `symmetric`, only entries with row >= col are stored and the matrix is their
  !> symmetric extension.
  type :: mtx_type
    integer :: nrows = 0, ncols = 0
    logical :: symmetric = .false.
    integer, allocatable :: row(:), col(:)
    real(wp), allocatable :: val(:)
  end type mtx_type

contains

  !> Reads `path` into `a`. Errors (status 2) name the file and line: missing file, bad banner,
  !> unsupported field or symmetry, bad size line, unparsable or non-finite numbers, an index
  !> out of range, an entry above the diagonal of a symmetric file, too few or too many entries.
  subroutine read_mtx(path, a, error)
    character(len=*), intent(in) :: path
    type(mtx_type), intent(out) :: a
    type(error_type), allocatable, intent(out) :: error
    character(len=:), allocatable :: line
    character(len=64) :: banner(6)
    integer :: unit, ios, lineno, nnz, k, i, j, ntok, nb
    logical :: coordinate, exists, ok1, ok2
    real(wp) :: v
    character(len=64) :: tok(5)

    inquire(file=path, exist=exists)
    if (.not.exists) then
      call fatal_error(error, "Matrix Market file '"//path//"' not found", UDMAP_EINPUT)
      return
    end if
    open(newunit=unit, file=path, status='old', action='read', form='formatted', iostat=ios)
    if (ios /= 0) then
      call fatal_error(error, "cannot open Matrix Market file '"//path//"'", UDMAP_EINPUT)
      return
    end if
    lineno = 1
    call read_line(unit, line, ios)
    if (ios /= 0) then
      call fail("empty file, expected the banner '%%MatrixMarket matrix ...'")
      return
    end if
    call tokens(lower(line), banner, nb)
    if (nb /= 5) then
      call fail("bad banner '"//trim(line)//"', expected '%%MatrixMarket matrix "// &
        & "coordinate|array real|integer general|symmetric'")
      return
    end if
    if (banner(1) /= "%%matrixmarket" .or. banner(2) /= "matrix") then
      call fail("bad banner '"//trim(line)//"', expected '%%MatrixMarket matrix ...'")
      return
    end if
    select case (banner(3))
    case ("coordinate")
      coordinate = .true.
    case ("array")
      coordinate = .false.
    case default
      call fail("unsupported format '"//trim(banner(3))//"' (coordinate or array)")
      return
    end select
    if (banner(4) /= "real" .and. banner(4) /= "integer" .and. banner(4) /= "double") then
      call fail("unsupported field '"//trim(banner(4))//"' (real or integer)")
      return
    end if
    select case (banner(5))
    case ("general")
      a%symmetric = .false.
    case ("symmetric")
      a%symmetric = .true.
    case default
      call fail("unsupported symmetry '"//trim(banner(5))//"' (general or symmetric)")
      return
    end select

    ! Size line after comments and blank lines.
    if (coordinate) then
      call next_tokens(0, 3, "bad size line '", "', expected 'rows columns entries'", ok1)
    else
      call next_tokens(0, 2, "bad size line '", "', expected 'rows columns'", ok1)
    end if
    if (.not.ok1) return
    call parse_int(tok(1), a%nrows, ok1)
    call parse_int(tok(2), a%ncols, ok2)
    if (.not.(ok1 .and. ok2)) then
      call fail("bad size line '"//trim(line)//"': sizes must be integers")
      return
    end if
    if (a%nrows < 1 .or. a%ncols < 1) then
      call fail("bad size line '"//trim(line)//"': sizes must be positive")
      return
    end if
    if (a%symmetric .and. a%nrows /= a%ncols) then
      call fail("a symmetric matrix must be square")
      return
    end if
    if (coordinate) then
      call parse_int(tok(3), nnz, ok1)
      if (.not.ok1) then
        call fail("bad size line '"//trim(line)//"': the entry count must be an integer")
        return
      end if
      if (nnz < 0) then
        call fail("bad size line '"//trim(line)//"': negative entry count")
        return
      end if
    else if (a%symmetric) then
      nnz = a%nrows*(a%nrows + 1)/2
    else
      nnz = a%nrows*a%ncols
    end if
    allocate(a%row(nnz), a%col(nnz), a%val(nnz), stat=ios)
    if (ios /= 0) then
      call fail("not enough memory for the declared number of entries")
      return
    end if

    i = 1
    j = 1
    do k = 1, nnz
      if (coordinate) then
        call next_tokens(k, 3, "expected 'row column value', got '", "'", ok1)
      else
        call next_tokens(k, 1, "expected one value per line, got '", "'", ok1)
      end if
      if (.not.ok1) return
      if (coordinate) then
        call parse_int(tok(1), i, ok1)
        call parse_int(tok(2), j, ok2)
        if (.not.(ok1 .and. ok2)) then
          call fail("unparsable index in '"//trim(line)//"'")
          return
        end if
        if (i < 1 .or. i > a%nrows .or. j < 1 .or. j > a%ncols) then
          call fail("index ("//itoa(i)//", "//itoa(j)//") out of range for a "// &
            & itoa(a%nrows)//" x "//itoa(a%ncols)//" matrix")
          return
        end if
        if (a%symmetric .and. i < j) then
          call fail("entry ("//itoa(i)//", "//itoa(j)//") above the diagonal in a symmetric "// &
            & "file (only the lower triangle may be listed)")
          return
        end if
      end if
      call parse_real(tok(ntok), v, ok1)
      if (.not.ok1) then
        call fail("unparsable or non-finite number '"//trim(tok(ntok))//"'")
        return
      end if
      a%row(k) = i
      a%col(k) = j
      a%val(k) = v
      if (.not.coordinate) then
        ! Column-major order; symmetric arrays list the lower triangle of each column.
        i = i + 1
        if (i > a%nrows) then
          j = j + 1
          i = 1
          if (a%symmetric) i = j
        end if
      end if
    end do
    call next_data_line(ios)
    if (ios == 0) then
      call fail("more entries than the "//itoa(nnz)//" declared")
      return
    end if
    close(unit)

  contains

    subroutine fail(message)
      character(len=*), intent(in) :: message
      call fatal_error(error, "Matrix Market file '"//path//"', line "//itoa(lineno)//": "// &
        & message, UDMAP_EINPUT)
      close(unit)
    end subroutine fail

    !> The size line (entry = 0) or the line of entry `entry`, split into tok(1:ntok);
    !> ok = .false. after a failure: the file ends or the line has not `count` tokens
    !> (message head, the line, tail).
    subroutine next_tokens(entry, count, head, tail, ok)
      integer, intent(in) :: entry, count
      character(len=*), intent(in) :: head, tail
      logical, intent(out) :: ok
      integer :: ios
      ok = .false.
      call next_data_line(ios)
      if (ios /= 0) then
        if (entry == 0) then
          call fail("file ends before the size line")
        else
          call fail("file ends after "//itoa(entry-1)//" of "//itoa(nnz)//" entries")
        end if
        return
      end if
      call tokens(line, tok, ntok)
      ok = ntok == count
      if (.not.ok) call fail(head//trim(line)//tail)
    end subroutine next_tokens

    !> Next line that is neither a comment nor blank; ios /= 0 at the end of the file.
    subroutine next_data_line(ios)
      integer, intent(out) :: ios
      do
        call read_line(unit, line, ios)
        if (ios /= 0) return
        lineno = lineno + 1
        if (len_trim(line) == 0) cycle
        if (line(first_char(line):first_char(line)) == '%') cycle
        return
      end do
    end subroutine next_data_line
  end subroutine read_mtx

  !> Writes `a` as `%%MatrixMarket matrix coordinate real general|symmetric` with 17
  !> significant digits (es24.16e3), which reads back exactly. Symmetric matrices must hold
  !> their lower triangle (row >= col) only.
  subroutine write_mtx(path, a, error, comment)
    character(len=*), intent(in) :: path
    type(mtx_type), intent(in) :: a
    type(error_type), allocatable, intent(out) :: error
    character(len=*), intent(in), optional :: comment
    integer :: unit, ios, k
    open(newunit=unit, file=path, status='replace', action='write', form='formatted', iostat=ios)
    if (ios /= 0) then
      call fatal_error(error, "cannot write Matrix Market file '"//path//"'", UDMAP_EINPUT)
      return
    end if
    if (a%symmetric) then
      write(unit, '(a)', iostat=ios) "%%MatrixMarket matrix coordinate real symmetric"
    else
      write(unit, '(a)', iostat=ios) "%%MatrixMarket matrix coordinate real general"
    end if
    if (present(comment)) write(unit, '(a)', iostat=ios) "% "//comment
    write(unit, '(i0, 1x, i0, 1x, i0)', iostat=ios) a%nrows, a%ncols, size(a%val)
    do k = 1, size(a%val)
      if (ios /= 0) exit
      write(unit, '(i0, 1x, i0, 1x, es24.16e3)', iostat=ios) a%row(k), a%col(k), a%val(k)
    end do
    if (ios /= 0) then
      call fatal_error(error, "error while writing Matrix Market file '"//path//"'", UDMAP_EINPUT)
    end if
    close(unit)
  end subroutine write_mtx

  !> Dense (nrows, ncols) copy; symmetric storage is mirrored, duplicate entries are summed.
  pure subroutine mtx_to_dense(a, d)
    type(mtx_type), intent(in) :: a
    real(wp), allocatable, intent(out) :: d(:, :)
    integer :: k
    allocate(d(a%nrows, a%ncols), source=0.0_wp)
    do k = 1, size(a%val)
      d(a%row(k), a%col(k)) = d(a%row(k), a%col(k)) + a%val(k)
      if (a%symmetric .and. a%row(k) /= a%col(k)) &
        & d(a%col(k), a%row(k)) = d(a%col(k), a%row(k)) + a%val(k)
    end do
  end subroutine mtx_to_dense

  !> Largest |row - col| over the nonzero entries.
  pure function mtx_bandwidth(a) result(kd)
    type(mtx_type), intent(in) :: a
    integer :: kd
    integer :: k
    kd = 0
    do k = 1, size(a%val)
      if (a%val(k) /= 0.0_wp) kd = max(kd, abs(a%row(k) - a%col(k)))
    end do
  end function mtx_bandwidth

  !> Reads one line of any length.
  subroutine read_line(unit, line, ios)
    integer, intent(in) :: unit
    character(len=:), allocatable, intent(out) :: line
    integer, intent(out) :: ios
    character(len=256) :: chunk
    integer :: n
    line = ""
    do
      read(unit, '(a)', advance='no', iostat=ios, size=n) chunk
      line = line//chunk(1:n)
      if (is_iostat_eor(ios)) then
        ios = 0
        exit
      end if
      if (ios /= 0) exit
    end do
    ! A last line without a newline ends with end-of-file after some characters.
    if (is_iostat_end(ios) .and. len(line) > 0) ios = 0
  end subroutine read_line

  pure integer function first_char(s)
    character(len=*), intent(in) :: s
    first_char = verify(s, ' '//achar(9))
  end function first_char

  !> Whitespace-separated tokens (at most size(tok); ntok counts all of them).
  pure subroutine tokens(s, tok, ntok)
    character(len=*), intent(in) :: s
    character(len=*), intent(out) :: tok(:)
    integer, intent(out) :: ntok
    integer :: i, start
    logical :: in_token
    ntok = 0
    tok = ""
    in_token = .false.
    start = 1
    do i = 1, len(s) + 1
      if (i <= len(s)) then
        if (s(i:i) /= ' ' .and. s(i:i) /= achar(9) .and. s(i:i) /= achar(13)) then
          if (.not.in_token) start = i
          in_token = .true.
          cycle
        end if
      end if
      if (in_token) then
        ntok = ntok + 1
        if (ntok <= size(tok)) tok(ntok) = s(start:i-1)
        in_token = .false.
      end if
    end do
  end subroutine tokens

  pure function lower(s) result(t)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: t
    integer :: i
    t = s
    do i = 1, len(s)
      if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
    end do
  end function lower

  !> An integer token: optional sign and digits only.
  pure subroutine parse_int(tok, v, ok)
    character(len=*), intent(in) :: tok
    integer, intent(out) :: v
    logical, intent(out) :: ok
    integer :: ios, k
    k = len_trim(tok)
    ok = .false.
    v = 0
    if (k == 0 .or. k > 10) return
    if (verify(tok(1:k), '+-0123456789') /= 0) return
    if (scan(tok(2:k), '+-') /= 0) return
    read(tok(1:k), *, iostat=ios) v
    ok = ios == 0
  end subroutine parse_int

  !> A finite real token (Fortran/C number syntax; no separators, no inf or nan).
  pure subroutine parse_real(tok, v, ok)
    character(len=*), intent(in) :: tok
    real(wp), intent(out) :: v
    logical, intent(out) :: ok
    integer :: ios, k
    k = len_trim(tok)
    ok = .false.
    v = 0
    if (k == 0) return
    if (verify(tok(1:k), '+-0123456789.eEdD') /= 0) return
    if (scan(tok(1:k), '0123456789') == 0) return
    read(tok(1:k), *, iostat=ios) v
    ok = ios == 0
    if (ok) ok = ieee_is_finite(v)
  end subroutine parse_real
end module udmap_blade_io_mmio
