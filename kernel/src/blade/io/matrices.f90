!> The blade to and from Matrix Market files: an imported blade (real symmetric M, K and optional
!> C; stress rows as 1 x n or n x 1 matrices) and the export of a blade with the case-file
!> blade section that reads it back.
module udmap_blade_io_matrices
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type, fatal_error, UDMAP_EINPUT
  use udmap_core_strings, only: itoa, ftoa
  use udmap_blade_io_mmio, only: mtx_type, read_mtx, write_mtx, mtx_to_dense, mtx_bandwidth
  use udmap_blade_band, only: sym_entry
  use udmap_blade_type, only: blade_type, common_checks, check_symmetric, store_dense, &
    & finish_import, blade_dense_limit, symmetry_rtol
  implicit none
  private
  public :: read_matrices_blade, export_blade

contains

  !> An imported blade from Matrix Market files (real symmetric M, K and optional C; stress rows
  !> as 1 x n or n x 1 matrices). Paths are used as given.
  subroutine read_matrices_blade(blade, M_path, K_path, gamma_dof, exc_dof, zeta, error, &
      & C_path, sK_path, sM_path, kept_modes)
    type(blade_type), intent(out) :: blade
    character(len=*), intent(in) :: M_path, K_path
    integer, intent(in) :: gamma_dof, exc_dof
    real(wp), intent(in) :: zeta
    type(error_type), allocatable, intent(out) :: error
    character(len=*), intent(in), optional :: C_path, sK_path, sM_path
    !> As for new_beam_blade.
    integer, intent(in), optional :: kept_modes
    type(mtx_type) :: am, ak, ac
    real(wp), allocatable :: sk(:), sm(:), mm(:, :), kk(:, :), cc(:, :)
    integer :: n, kd
    logical :: with_c

    call read_mtx(M_path, am, error)
    if (allocated(error)) return
    n = am%nrows
    if (am%ncols /= n) then
      call fatal_error(error, "M ('"//M_path//"') must be square, got "//itoa(am%nrows)//" x "// &
        & itoa(am%ncols), UDMAP_EINPUT)
      return
    end if
    call read_like_M("K", K_path, ak)
    if (allocated(error)) return
    with_c = .false.
    if (present(C_path)) then
      with_c = .true.
      call read_like_M("C", C_path, ac)
      if (allocated(error)) return
    end if
    if (present(sK_path)) then
      call read_row(sK_path, "stress_K", sk)
      if (allocated(error)) return
    end if
    if (present(sM_path)) then
      call read_row(sM_path, "stress_M", sm)
      if (allocated(error)) return
    end if
    call common_checks(n, gamma_dof, exc_dof, zeta, error, sk, sm)
    if (allocated(error)) return

    if (n <= blade_dense_limit) then
      call mtx_to_dense(am, mm)
      call check_symmetric(mm, "M ('"//M_path//"')", error)
      if (allocated(error)) return
      call mtx_to_dense(ak, kk)
      call check_symmetric(kk, "K ('"//K_path//"')", error)
      if (allocated(error)) return
      if (with_c) then
        call mtx_to_dense(ac, cc)
        call check_symmetric(cc, "C ('"//C_path//"')", error)
        if (allocated(error)) return
      end if
      call store_dense(blade, mm, kk, cc)
    else
      kd = max(mtx_bandwidth(am), mtx_bandwidth(ak))
      if (with_c) kd = max(kd, mtx_bandwidth(ac))
      blade%ndof = n
      blade%kd = kd
      call mtx_to_sym_band(am, kd, "M ('"//M_path//"')", blade%Mb, error)
      if (allocated(error)) return
      call mtx_to_sym_band(ak, kd, "K ('"//K_path//"')", blade%Kb, error)
      if (allocated(error)) return
      if (with_c) then
        call mtx_to_sym_band(ac, kd, "C ('"//C_path//"')", blade%Cb, error)
        if (allocated(error)) return
      end if
    end if
    call finish_import(blade, gamma_dof, exc_dof, zeta, error, sk, sm, kept_modes)

  contains

    !> The matrix `name` from `path`, n x n like M.
    subroutine read_like_M(name, path, a)
      character(len=*), intent(in) :: name, path
      type(mtx_type), intent(out) :: a
      call read_mtx(path, a, error)
      if (allocated(error)) return
      if (a%nrows /= n .or. a%ncols /= n) then
        call fatal_error(error, name//" ('"//path//"') must be "//itoa(n)//" x "//itoa(n)// &
          & " like M, got "//itoa(a%nrows)//" x "//itoa(a%ncols), UDMAP_EINPUT)
      end if
    end subroutine read_like_M

    subroutine read_row(path, name, s)
      character(len=*), intent(in) :: path, name
      real(wp), allocatable, intent(out) :: s(:)
      type(mtx_type) :: a
      real(wp), allocatable :: d(:, :)
      call read_mtx(path, a, error)
      if (allocated(error)) return
      if (min(a%nrows, a%ncols) /= 1 .or. max(a%nrows, a%ncols) /= n) then
        call fatal_error(error, name//" ('"//path//"') must be a 1 x "//itoa(n)//" or "// &
          & itoa(n)//" x 1 matrix, got "//itoa(a%nrows)//" x "//itoa(a%ncols), UDMAP_EINPUT)
        return
      end if
      call mtx_to_dense(a, d)
      s = reshape(d, [n])
    end subroutine read_row
  end subroutine read_matrices_blade

  !> Writes M.mtx, K.mtx (symmetric coordinate), C.mtx with explicit damping, stress_K.mtx and
  !> stress_M.mtx (1 x ndof) with stress rows, and blade.json (the case-file blade section that
  !> reads them back) into the existing directory `dir`.
  subroutine export_blade(blade, dir, error)
    type(blade_type), intent(in) :: blade
    character(len=*), intent(in) :: dir
    type(error_type), allocatable, intent(out) :: error
    character(len=:), allocatable :: base
    type(mtx_type) :: a
    integer :: unit, ios
    character(len=32) :: zbuf
    logical :: exists
    if (blade%ndof < 1) then
      call fatal_error(error, "export of an empty blade", UDMAP_EINPUT)
      return
    end if
    base = trim(dir)
    do while (len(base) > 1 .and. base(len(base):len(base)) == '/')
      base = base(1:len(base)-1)
    end do
    inquire(file=base//"/.", exist=exists)
    if (.not.exists) then
      call fatal_error(error, "export directory '"//dir//"' does not exist", UDMAP_EINPUT)
      return
    end if
    call sym_to_mtx(blade%M, blade%Mb, blade%kd, blade%ndof, a)
    call write_mtx(base//"/M.mtx", a, error, "udmap blade mass matrix")
    if (allocated(error)) return
    call sym_to_mtx(blade%K, blade%Kb, blade%kd, blade%ndof, a)
    call write_mtx(base//"/K.mtx", a, error, "udmap blade stiffness matrix")
    if (allocated(error)) return
    if (blade%explicit_C) then
      call sym_to_mtx(blade%C, blade%Cb, blade%kd, blade%ndof, a)
      call write_mtx(base//"/C.mtx", a, error, "udmap blade damping matrix")
      if (allocated(error)) return
    end if
    if (blade%has_stress) then
      call row_to_mtx(blade%s_K, a)
      call write_mtx(base//"/stress_K.mtx", a, error, "udmap root stress row, stiffness part")
      if (allocated(error)) return
      call row_to_mtx(blade%s_M, a)
      call write_mtx(base//"/stress_M.mtx", a, error, "udmap root stress row, mass part")
      if (allocated(error)) return
    end if
    open(newunit=unit, file=base//"/blade.json", status='replace', action='write', iostat=ios)
    if (ios /= 0) then
      call fatal_error(error, "cannot write '"//base//"/blade.json'", UDMAP_EINPUT)
      return
    end if
    write(zbuf, '(es24.16e3)') blade%zeta
    write(unit, '(a)') '{"kind": "matrices", "M": "M.mtx", "K": "K.mtx",'
    if (blade%explicit_C) write(unit, '(a)') ' "C": "C.mtx",'
    if (blade%has_stress) write(unit, '(a)') ' "stress_K": "stress_K.mtx", "stress_M": "stress_M.mtx",'
    write(unit, '(a)') ' "gamma_dof": '//itoa(blade%gamma_dof)//', "exc_dof": '// &
      & itoa(blade%exc_dof)//', "zeta": '//trim(adjustl(zbuf))//'}'
    close(unit)

  contains

    !> Lower triangle (nonzeros, column by column) of a symmetric matrix.
    subroutine sym_to_mtx(d, b, kd, n, a)
      real(wp), allocatable, intent(in) :: d(:, :), b(:, :)
      integer, intent(in) :: kd, n
      type(mtx_type), intent(out) :: a
      integer :: i, j, cnt, pass, hi
      real(wp) :: v
      a%nrows = n
      a%ncols = n
      a%symmetric = .true.
      do pass = 1, 2
        cnt = 0
        do j = 1, n
          hi = n
          if (allocated(b)) hi = min(n, j + kd)
          do i = j, hi
            v = sym_entry(d, b, kd, i, j)
            if (v == 0.0_wp) cycle
            cnt = cnt + 1
            if (pass == 2) then
              a%row(cnt) = i
              a%col(cnt) = j
              a%val(cnt) = v
            end if
          end do
        end do
        if (pass == 1) allocate(a%row(cnt), a%col(cnt), a%val(cnt))
      end do
    end subroutine sym_to_mtx

    subroutine row_to_mtx(s, a)
      real(wp), intent(in) :: s(:)
      type(mtx_type), intent(out) :: a
      integer :: j, k
      a%nrows = 1
      a%ncols = size(s)
      a%symmetric = .false.
      allocate(a%row(count(s /= 0.0_wp)), a%col(count(s /= 0.0_wp)), a%val(count(s /= 0.0_wp)))
      k = 0
      do j = 1, size(s)
        if (s(j) /= 0.0_wp) then
          k = k + 1
          a%row(k) = 1
          a%col(k) = j
          a%val(k) = s(j)
        end if
      end do
    end subroutine row_to_mtx
  end subroutine export_blade

  !> Symmetric band storage (kd+1, n) of a Matrix Market matrix, with the symmetry check.
  subroutine mtx_to_sym_band(a, kd, name, ab, error)
    type(mtx_type), intent(in) :: a
    integer, intent(in) :: kd
    character(len=*), intent(in) :: name
    real(wp), allocatable, intent(out) :: ab(:, :)
    type(error_type), allocatable, intent(out) :: error
    real(wp), allocatable :: full(:, :)
    real(wp) :: amax, up, lo
    integer :: n, k, i, j
    n = a%nrows
    ! General band (2 kd + 1, n): full(kd+1+i-j, j) = a(i, j).
    allocate(full(2*kd+1, n), source=0.0_wp)
    do k = 1, size(a%val)
      i = a%row(k)
      j = a%col(k)
      if (a%val(k) == 0.0_wp) cycle
      full(kd+1+i-j, j) = full(kd+1+i-j, j) + a%val(k)
      if (a%symmetric .and. i /= j) full(kd+1+j-i, i) = full(kd+1+j-i, i) + a%val(k)
    end do
    amax = maxval(abs(full))
    allocate(ab(kd+1, n))
    do j = 1, n
      do i = max(1, j-kd), j
        up = full(kd+1+i-j, j)
        lo = full(kd+1+j-i, i)
        if (abs(up - lo) > symmetry_rtol*max(abs(up), abs(lo)) + 1.0e-14_wp*amax) then
          call fatal_error(error, name//" is not symmetric: entry ("//itoa(i)//", "//itoa(j)// &
            & ") = "//ftoa(up)//" but ("//itoa(j)//", "//itoa(i)//") = "//ftoa(lo), UDMAP_EINPUT)
          return
        end if
        ab(kd+1+i-j, j) = 0.5_wp*(up + lo)
      end do
    end do
  end subroutine mtx_to_sym_band
end module udmap_blade_io_matrices
