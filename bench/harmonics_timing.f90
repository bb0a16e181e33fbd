!> Multi-harmonic layers (PHYSICS.md 4.1) on gg10 (blade A, F_E = 1..10 N): the cold time of
!> the layered backbone (new model and the ten peaks) at H = 1, 3, 5, 9, 17 and auto, the
!> standard method (condensed, harmonics 0..H, warm-started from peak to peak) with the same
!> harmonics timed in the same run, and the errors of both against the standard method at
!> H = 33. Argument: 0 blade A's asymmetric damper, 1 a Jenkins damper (its stuck stiffness and
!> half its moment range). One JSON object per line on stdout (bench/bench_harmonics.py).
program harmonics_timing
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_blade_beam, only: beam_params_type
  use udmap_blade_type, only: blade_type, new_beam_blade
  use udmap_damper_type, only: damper_type, new_asymmetric_damper, new_jenkins_damper
  use udmap_damper_params, only: blade_a_damper_params
  use udmap_mapping_model, only: model_type, analysis_type, point_type, new_model, backbone
  use udmap_baseline_linear_structure, only: structure_type, structure_from_blade
  use udmap_contact_element_asymmetric, only: contact_element_type, new_contact_element
  use udmap_contact_element_jenkins, only: jenkins_element_type, new_jenkins_element
  use udmap_baseline_hbm, only: hbm_settings_type, hbm_point_type, hbm_peaks
  implicit none
  type(beam_params_type) :: bp
  type(blade_type), target :: blade
  type(damper_type), target :: damper
  type(model_type) :: model
  type(analysis_type) :: an
  type(point_type), allocatable :: pa(:)
  type(error_type), allocatable :: error
  type(structure_type) :: st
  type(contact_element_type) :: el
  type(jenkins_element_type) :: jen
  type(hbm_settings_type) :: set
  type(hbm_point_type), allocatable :: hp(:), ref(:)
  real(wp) :: FE(10), e_map(3), e_hbm(3), kt, ms, t_ref
  real(wp), allocatable :: t(:), ts(:)
  integer, parameter :: Hs(6) = [1, 3, 5, 9, 17, 0]
  integer :: i, k, r, nrep, nstd, kind
  integer(int64) :: c0, c1, cr
  character(len=16) :: arg

  call get_command_argument(1, arg)
  read(arg, *) kind
  FE = [(real(i, wp), i = 1, 10)]
  bp = beam_params_type(E=170e9_wp, rho=8200.0_wp, zeta=0.002_wp, neck_L=0.020_wp, &
    & neck_h=0.008_wp, neck_b=0.020_wp, platform_L=0.010_wp, platform_m=0.021_wp, &
    & platform_J=1.4e-6_wp, airfoil_L=0.120_wp, airfoil_h=0.004_wp, airfoil_b=0.030_wp, &
    & neck_elements=8, airfoil_elements=24)
  call new_beam_blade(blade, bp, error)
  call structure_from_blade(st, blade, error)
  call new_asymmetric_damper(damper, blade_a_damper_params(), error)
  call new_contact_element(el, blade_a_damper_params(), error)
  if (kind == 1) then
    kt = damper%k_stuck
    ms = 0.5_wp*(damper%M_max - damper%M_min)
    call new_jenkins_element(jen, kt, ms, error)
    call new_jenkins_damper(damper, kt, ms, error)
  end if
  an%f_min = 150
  an%f_max = 230
  set%variant = 0
  set%harmonic0 = .true.
  set%warm_start = 2
  set%full_band = .false.
  set%harmonics = 33
  call system_clock(c0, cr)
  call run_hbm(ref)
  call system_clock(c1)
  t_ref = real(c1 - c0, wp)/cr
  if (allocated(error)) then
    write(*, '(a)') '{"error": "reference: '//error%message//'"}'
    stop 1
  end if
  ! per H, the repeats of the layered backbone and of the standard method alternate, so that a
  ! change of the machine's load affects both alike (2 shared cores)
  do k = 1, size(Hs)
    an%harmonics = Hs(k)
    nrep = 50
    if (Hs(k) /= 1) nrep = merge(7, 15, Hs(k) == 0)
    nstd = 0
    if (Hs(k) > 0) nstd = merge(7, 3, Hs(k) <= 5)
    allocate(t(nrep), ts(max(nstd, 1)))
    set%harmonics = max(Hs(k), 1)
    do r = 1, max(nrep, nstd)
      if (r <= nrep) then
        call system_clock(c0)
        call new_model(model, blade, damper, an, error)
        call backbone(model, FE, pa, error)
        call system_clock(c1)
        t(r) = real(c1 - c0, wp)/cr
        if (allocated(error)) then
          write(*, '(a)') '{"error": "'//error%message//'"}'
          stop 1
        end if
      end if
      if (r <= nstd) then
        call system_clock(c0)
        call run_hbm(hp)
        call system_clock(c1)
        ts(r) = real(c1 - c0, wp)/cr
        if (allocated(error)) then
          write(*, '(a)') '{"error": "standard method: '//error%message//'"}'
          stop 1
        end if
      end if
    end do
    e_map = 0
    do i = 1, 10
      e_map = max(e_map, abs([pa(i)%gamma_P/ref(i)%gamma_P, pa(i)%sigma_a/ref(i)%sigma_a, &
        & pa(i)%f_res/ref(i)%f_res] - 1))
    end do
    call emit("backbone", Hs(k), t, e_map, maxval(pa(:)%harmonics))
    if (nstd > 0) then
      e_hbm = 0
      do i = 1, 10
        e_hbm = max(e_hbm, abs([hp(i)%gamma_P/ref(i)%gamma_P, hp(i)%sigma_a/ref(i)%sigma_a, &
          & hp(i)%f_res/ref(i)%f_res] - 1))
      end do
      call emit("standard_condensed", Hs(k), ts, e_hbm, Hs(k))
    end if
    deallocate(t, ts)
  end do
  allocate(t(1))
  t = t_ref
  call emit("standard_condensed", 33, t, [0.0_wp, 0.0_wp, 0.0_wp], 33)
contains
  subroutine run_hbm(points)
    type(hbm_point_type), allocatable, intent(out) :: points(:)
    if (kind == 1) then
      call hbm_peaks(st, jen, an%f_min, an%f_max, FE, set, points, error)
    else
      call hbm_peaks(st, el, an%f_min, an%f_max, FE, set, points, error)
    end if
  end subroutine run_hbm

  subroutine emit(method, H, times, err, H_used)
    character(len=*), intent(in) :: method
    integer, intent(in) :: H, H_used
    real(wp), intent(in) :: times(:), err(3)
    character(len=16) :: label
    if (H == 0) then
      label = "auto"
    else
      write(label, '(a, i0)') "H", H
    end if
    write(*, '(a, a, a, a, a, 3(es23.16, a), i0, a, 3(es23.16, a), i0, a)') &
      & '{"method": "', method, '", "setting": "gg10_', trim(label), '", "times": [', &
      & minval(times), ', ', median(times), ', ', maxval(times), '], "repeats": ', &
      & size(times), ', "errors": [', err(1), ', ', err(2), ', ', err(3), &
      & '], "harmonics": ', H_used, '}'
    flush(6)
  end subroutine emit

  real(wp) function median(x)
    real(wp), intent(in) :: x(:)
    real(wp) :: y(size(x)), tmp
    integer :: i, j
    y = x
    do i = 2, size(y)
      tmp = y(i)
      j = i - 1
      do while (j >= 1)
        if (y(j) <= tmp) exit
        y(j+1) = y(j)
        j = j - 1
      end do
      y(j+1) = tmp
    end do
    median = y((size(y) + 1)/2)
  end function median
end program harmonics_timing
