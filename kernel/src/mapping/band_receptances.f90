!> Fast bare receptances inside the band, for the inner loops of the mapping.
!>
!> With C = beta K the receptances are modal sums, H_ab = sum_r c_ab,r/(w_r^2 f - omega^2),
!> f = 1 + i omega beta. Over the band only the modes near it vary quickly; the rest of the sum
!> (and the blade's residual of the modes it did not compute) is a smooth function of omega.
!> So the modes within one band width of the band are summed exactly and the smooth remainder
!> R(omega) = H(omega) - sum_near is interpolated by cubic Hermite polynomials between samples
!> of the blade's own receptances (values and derivatives). Errors: a pole at distance D from
!> the band contributes (h/D)^4/16 of its share with sample step h; the number of samples is
!> doubled (33 to 2049) until the interpolant matches the blade at every interval midpoint to
!> 1e-13 of each receptance's largest value in the band (1e-11 for the derivatives). An
!> evaluation then costs two or three dozen complex operations instead of the blade's modal
!> sum and series. With an explicit C matrix the modal form is not exact and this is off.
module udmap_mapping_band_receptances
  use udmap_core_kinds, only: wp
  use udmap_core_error, only: error_type
  use udmap_blade_type, only: blade_type, receptances_type
  use udmap_mapping_caches, only: band_receptances_type
  implicit none
  private
  public :: new_band_receptances, band_eval

  !> Samples tried first and at most.
  integer, parameter :: first_samples = 33, max_samples = 2049

contains

  !> Builds the interpolant over [omega_lo, omega_hi] [rad/s]; leaves it inactive (and no
  !> error) when the blade has an explicit C, when the check fails at max_samples, or when a
  !> blade evaluation fails.
  subroutine new_band_receptances(band, blade, omega_lo, omega_hi)
    type(band_receptances_type), intent(out) :: band
    type(blade_type), intent(in) :: blade
    real(wp), intent(in) :: omega_lo, omega_hi
    type(error_type), allocatable :: error
    type(receptances_type) :: r, ri
    real(wp) :: width, scale(5), dscale(5)
    complex(wp) :: v(5), dv(5), e(5), de(5)
    logical, allocatable :: near(:)
    integer :: n, i, nm
    band%active = .false.
    if (blade%explicit_C .or. .not.allocated(blade%omega) .or. .not.allocated(blade%phi)) return
    if (.not.(omega_hi > omega_lo .and. omega_lo > 0)) return
    nm = size(blade%omega)
    width = omega_hi - omega_lo
    near = blade%omega(1:nm) >= omega_lo - width .and. blade%omega(1:nm) <= omega_hi + width
    band%w2 = pack(blade%omega(1:nm)**2, near)
    band%pg = pack(blade%phi(blade%gamma_dof, 1:nm), near)
    band%pE = pack(blade%phi(blade%exc_dof, 1:nm), near)
    if (blade%has_stress) then
      band%psK = pack(matmul(blade%s_K, blade%phi(:, 1:nm)), near)
      band%psM = pack(matmul(blade%s_M, blade%phi(:, 1:nm)), near)
    else
      allocate(band%psK(size(band%w2)), band%psM(size(band%w2)), source=0.0_wp)
    end if
    band%beta = blade%beta
    band%omega_lo = omega_lo
    band%omega_hi = omega_hi
    n = first_samples
    do while (n <= max_samples)
      band%n = n
      band%h = width/(n - 1)
      if (allocated(band%rem)) deallocate(band%rem, band%drem)
      allocate(band%rem(5, n), band%drem(5, n))
      scale = 0
      dscale = 0
      do i = 1, n
        call blade%receptances(sample(i), r, error, derivatives=.true.)
        if (allocated(error)) return
        call set_receptances(r, v, dv)
        scale = max(scale, abs(v))
        dscale = max(dscale, abs(dv))
        call exact_modes(band, sample(i), e, de)
        band%rem(:, i) = v - e
        band%drem(:, i) = dv - de
      end do
      band%active = .true.
      do i = 1, n - 1
        call blade%receptances(sample(i) + 0.5_wp*band%h, r, error, derivatives=.true.)
        if (allocated(error)) then
          band%active = .false.
          return
        end if
        call set_receptances(r, v, dv)
        call band_eval(band, sample(i) + 0.5_wp*band%h, .true., ri)
        call set_receptances(ri, e, de)
        if (any(abs(e - v) > 1e-13_wp*scale) .or. any(abs(de - dv) > 1e-11_wp*dscale)) then
          band%active = .false.
          exit
        end if
      end do
      if (band%active) return
      n = 2*n - 1
    end do
  contains
    !> Sample j's frequency (the last one exactly omega_hi).
    pure real(wp) function sample(j)
      integer, intent(in) :: j
      sample = omega_lo + (j - 1)*band%h
      if (j == band%n) sample = omega_hi
    end function sample
  end subroutine new_band_receptances

  !> The five receptances and their derivatives as arrays.
  pure subroutine set_receptances(r, v, dv)
    type(receptances_type), intent(in) :: r
    complex(wp), intent(out) :: v(5), dv(5)
    v = [r%gE, r%gg, r%EE, r%sE, r%sg]
    dv = [r%dgE, r%dgg, r%dEE, r%dsE, r%dsg]
  end subroutine set_receptances

  !> The exactly summed modes' share of the five receptances and its d/d omega.
  pure subroutine exact_modes(band, omega, e, de)
    type(band_receptances_type), intent(in) :: band
    real(wp), intent(in) :: omega
    complex(wp), intent(out) :: e(5), de(5)
    complex(wp) :: t, dt, sr
    real(wp) :: dsr
    integer :: m
    e = 0
    de = 0
    do m = 1, size(band%w2)
      t = 1/cmplx(band%w2(m) - omega**2, omega*band%beta*band%w2(m), wp)
      dt = -cmplx(-2*omega, band%beta*band%w2(m), wp)*t*t
      sr = band%psK(m) - omega**2*band%psM(m)
      dsr = -2*omega*band%psM(m)
      e(1) = e(1) + band%pg(m)*band%pE(m)*t
      e(2) = e(2) + band%pg(m)**2*t
      e(3) = e(3) + band%pE(m)**2*t
      e(4) = e(4) + sr*band%pE(m)*t
      e(5) = e(5) + sr*band%pg(m)*t
      de(1) = de(1) + band%pg(m)*band%pE(m)*dt
      de(2) = de(2) + band%pg(m)**2*dt
      de(3) = de(3) + band%pE(m)**2*dt
      de(4) = de(4) + band%pE(m)*(dsr*t + sr*dt)
      de(5) = de(5) + band%pg(m)*(dsr*t + sr*dt)
    end do
  end subroutine exact_modes

  !> Receptances at omega inside the band (and d/d omega when derivatives): exact near
  !> modes plus the Hermite-interpolated remainder.
  pure subroutine band_eval(band, omega, derivatives, r)
    type(band_receptances_type), intent(in) :: band
    real(wp), intent(in) :: omega
    logical, intent(in) :: derivatives
    type(receptances_type), intent(out) :: r
    complex(wp) :: e(5), de(5)
    real(wp) :: t, h00, h10, h01, h11, d00, d10, d01, d11
    integer :: i
    i = min(max(int((omega - band%omega_lo)/band%h) + 1, 1), band%n - 1)
    t = (omega - (band%omega_lo + (i - 1)*band%h))/band%h
    h00 = (2*t - 3)*t*t + 1
    h10 = ((t - 2)*t + 1)*t*band%h
    h01 = (3 - 2*t)*t*t
    h11 = (t - 1)*t*t*band%h
    call exact_modes(band, omega, e, de)
    call store_receptances(hermite(e, h00, h10, h01, h11), r%gE, r%gg, r%EE, r%sE, r%sg)
    if (.not.derivatives) return
    d00 = 6*t*(t - 1)/band%h
    d10 = (3*t - 4)*t + 1
    d01 = -d00
    d11 = (3*t - 2)*t
    call store_receptances(hermite(de, d00, d10, d01, d11), r%dgE, r%dgg, r%dEE, r%dsE, r%dsg)
  contains
    !> The exact part x plus the remainder of panel i with the Hermite weights c00..c11.
    pure function hermite(x, c00, c10, c01, c11) result(v)
      complex(wp), intent(in) :: x(5)
      real(wp), intent(in) :: c00, c10, c01, c11
      complex(wp) :: v(5)
      v = x + c00*band%rem(:, i) + c10*band%drem(:, i) + c01*band%rem(:, i + 1) + &
        & c11*band%drem(:, i + 1)
    end function hermite
  end subroutine band_eval

  !> The five receptances in v (set_receptances' order: gE, gg, EE, sE, sg) into their fields.
  pure subroutine store_receptances(v, gE, gg, EE, sE, sg)
    complex(wp), intent(in) :: v(5)
    complex(wp), intent(out) :: gE, gg, EE, sE, sg
    gE = v(1)
    gg = v(2)
    EE = v(3)
    sE = v(4)
    sg = v(5)
  end subroutine store_receptances
end module udmap_mapping_band_receptances
