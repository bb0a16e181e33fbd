!> The Fortran test driver (dftd4's test/unit/main.f90): `udmap-tester [suite ...]` runs the
!> named suites, or all of them without an argument. Exits non-zero when a unit test fails or
!> a suite name is unknown. ctest runs one suite per entry (tests/CMakeLists.txt).
program tester
  use testing, only: testsuite_type, new_testsuite, run_testsuite
  use test_admissible, only: collect_admissible
  use test_api_legacy, only: collect_api_legacy
  use test_blade_beam, only: collect_blade_beam
  use test_blade_large, only: collect_blade_large
  use test_blade_mmio, only: collect_blade_mmio
  use test_blade_receptances, only: collect_blade_receptances
  use test_damper_blade_a, only: collect_damper_blade_a
  use test_damper_bruteforce, only: collect_damper_bruteforce
  use test_damper_geometries, only: collect_damper_geometries
  use test_damper_kinds, only: collect_damper_kinds
  use test_damper_liftoff, only: collect_damper_liftoff
  use test_damper_tracer, only: collect_damper_tracer
  use test_damper_wedge, only: collect_damper_wedge
  use test_force_table, only: collect_force_table
  use test_dense_lu, only: collect_dense_lu
  use test_hbm_aft, only: collect_hbm_aft
  use test_hbm_blade_a, only: collect_hbm_blade_a
  use test_hbm_chain, only: collect_hbm_chain
  use test_hbm_dti, only: collect_hbm_dti
  use test_hbm_wheel, only: collect_hbm_wheel
  use test_hbm_oscillator, only: collect_hbm_oscillator
  use test_hbm_stress, only: collect_hbm_stress
  use test_hbm_stress_contact, only: collect_hbm_stress_contact
  use test_mapping_backbone, only: collect_mapping_backbone
  use test_mapping_blade_a, only: collect_mapping_blade_a
  use test_mapping_curves, only: collect_mapping_curves
  use test_mapping_harmonics, only: collect_mapping_harmonics
  use test_mapping_harmonics_dti, only: collect_mapping_harmonics_dti
  use test_mapping_isola, only: collect_mapping_isola
  use test_mapping_oscillator, only: collect_mapping_oscillator
  use test_plausibility, only: collect_plausibility
  use test_traveling, only: collect_traveling
  use test_umbrella, only: collect_umbrella
  implicit none
  type(testsuite_type), allocatable :: testsuites(:)
  character(len=:), allocatable :: name
  integer :: i, j, k, n, nfailed

  allocate(testsuites, source=[ &
    & new_testsuite("admissible", collect_admissible), &
    & new_testsuite("api_legacy", collect_api_legacy), &
    & new_testsuite("blade_beam", collect_blade_beam), &
    & new_testsuite("blade_large", collect_blade_large), &
    & new_testsuite("blade_mmio", collect_blade_mmio), &
    & new_testsuite("blade_receptances", collect_blade_receptances), &
    & new_testsuite("damper_blade_a", collect_damper_blade_a), &
    & new_testsuite("damper_bruteforce", collect_damper_bruteforce), &
    & new_testsuite("damper_geometries", collect_damper_geometries), &
    & new_testsuite("damper_kinds", collect_damper_kinds), &
    & new_testsuite("damper_liftoff", collect_damper_liftoff), &
    & new_testsuite("damper_tracer", collect_damper_tracer), &
    & new_testsuite("damper_wedge", collect_damper_wedge), &
    & new_testsuite("force_table", collect_force_table), &
    & new_testsuite("dense_lu", collect_dense_lu), &
    & new_testsuite("hbm_aft", collect_hbm_aft), &
    & new_testsuite("hbm_blade_a", collect_hbm_blade_a), &
    & new_testsuite("hbm_chain", collect_hbm_chain), &
    & new_testsuite("hbm_dti", collect_hbm_dti), &
    & new_testsuite("hbm_oscillator", collect_hbm_oscillator), &
    & new_testsuite("hbm_stress", collect_hbm_stress), &
    & new_testsuite("hbm_stress_contact", collect_hbm_stress_contact), &
    & new_testsuite("hbm_wheel", collect_hbm_wheel), &
    & new_testsuite("mapping_backbone", collect_mapping_backbone), &
    & new_testsuite("mapping_blade_a", collect_mapping_blade_a), &
    & new_testsuite("mapping_curves", collect_mapping_curves), &
    & new_testsuite("mapping_harmonics", collect_mapping_harmonics), &
    & new_testsuite("mapping_harmonics_dti", collect_mapping_harmonics_dti), &
    & new_testsuite("mapping_isola", collect_mapping_isola), &
    & new_testsuite("mapping_oscillator", collect_mapping_oscillator), &
    & new_testsuite("plausibility", collect_plausibility), &
    & new_testsuite("traveling", collect_traveling), &
    & new_testsuite("umbrella", collect_umbrella)])

  nfailed = 0
  if (command_argument_count() == 0) then
    do j = 1, size(testsuites)
      write(*, '(a)') "# suite "//testsuites(j)%name
      call run_testsuite(testsuites(j), nfailed)
    end do
  end if
  do i = 1, command_argument_count()
    call get_command_argument(i, length=n)
    allocate(character(len=n) :: name)
    call get_command_argument(i, name)
    j = findloc([(testsuites(k)%name == name, k = 1, size(testsuites))], .true., 1)
    if (j == 0) then
      write(*, '(a)') "unknown test suite '"//name//"'; the suites are:"
      do j = 1, size(testsuites)
        write(*, '(2x, a)') testsuites(j)%name
      end do
      error stop 2
    end if
    call run_testsuite(testsuites(j), nfailed)
    deallocate(name)
  end do
  if (nfailed > 0) then
    write(*, '(i0, a)') nfailed, " unit test(s) failed"
    error stop 1
  end if
end program tester
