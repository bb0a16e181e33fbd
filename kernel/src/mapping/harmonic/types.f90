!> The data of the multi-harmonic mapping (PHYSICS.md 4.1; data only, the algorithms sit above):
!> a solved layer, the workspace of the layer solves with the contact element and the AFT scratch,
!> the backbone roots kept as warm starts, a layer's outputs (udmap_mapping_harmonic_layer), and
!> the adaptive force table (udmap_mapping_harmonic_force_table).
module udmap_mapping_harmonic_types
  use, intrinsic :: iso_fortran_env, only: int64
  use udmap_core_kinds, only: wp
  use udmap_blade_type, only: receptances_type
  use udmap_contact_element, only: hysteretic_element_type
  use udmap_contact_aft_moment, only: aft_workspace_type
  implicit none
  private
  public :: HARMONICS_MAX, harmonic_state_type, harmonic_workspace_type, &
    & harmonic_root_memory_type, harmonic_outputs_type, table_node_type, force_table_type, &
    & SIGNATURE_SIZE

  !> Largest number of harmonics of a layer.
  integer, parameter :: HARMONICS_MAX = 64

  !> A solved layer (gamma, omega) with harmonics 0..H; also the warm start of the next solve.
  type :: harmonic_state_type
    integer :: H = 0
    real(wp) :: gamma = 0, omega = 0
    !> Gamma_0 and Gamma_h (h = 1..H, Gamma_1 = gamma) [rad]; M_0 and M_h [N m].
    real(wp) :: G0 = 0, M0 = 0
    complex(wp), allocatable :: G(:), M(:)
    !> Damper Jacobian d(M_0, Re M_1, Im M_1, ..)/d(Gamma_0, Re Gamma_2, Im Gamma_2, ..) and the
    !> unknowns it was taken at.
    real(wp), allocatable :: JM(:,:), x_jm(:)
    !> dM/dGamma_1 (the same rows, Gamma_1 real) with JM.
    real(wp), allocatable :: JM1(:)
    !> d(Gamma_0, Re Gamma_2, Im Gamma_2, ..)/dgamma and /domega at the solution (implicit
    !> function theorem): the predictor of a neighbouring layer's solve.
    real(wp), allocatable :: dx_dg(:), dx_dw(:)
    logical :: dx_valid = .false.
    logical :: jm_valid = .false.
    !> Bare receptances at h omega, h = 1..H (with d/domega).
    type(receptances_type), allocatable :: r(:)
    !> Force on the layer [N] (complex, phase of Gamma_1 = 0) and psi = d|P|^2/domega.
    complex(wp) :: P = 0
    real(wp) :: psi = 0
    !> d(ln|P|, d ln|P|/d ln omega)/d(ln gamma, ln omega): the Jacobian of the backbone root
    !> search, from the implicit function theorem (the harmonics' second-order dependence on
    !> omega neglected: a Newton matrix, not a result).
    real(wp) :: Jroot(2, 2) = 0
    !> A contact opened during the cycle.
    logical :: lift_off = .false.
  end type harmonic_state_type

  !> The contact element the layers are traced through, and the scratch of the solves (one per
  !> model; nothing shared).
  type :: harmonic_workspace_type
    class(hysteretic_element_type), allocatable :: element
    type(aft_workspace_type) :: aft
    !> Static moment of the loaded damper [N m].
    real(wp) :: M_ref = 0
    !> Static receptances H_gg(0), H_sg(0).
    complex(wp) :: gg0 = 0, sg0 = 0
    !> Damper revision and summary numbers the element was built for.
    integer :: revision = -huge(1)
    real(wp) :: fingerprint(5) = 0
    !> Traces and layer solves done (statistics).
    integer :: traces = 0, solves = 0
    !> The last backbone root found with h harmonics (rung(h)): the warm start of the next
    !> root with as many harmonics (after a change of F_E alone, the next force of a list, the
    !> same rung of the automatic H).
    type(harmonic_root_memory_type), allocatable :: rung(:)
  end type harmonic_workspace_type

  !> A backbone root kept to start the next one: its layer and the single-harmonic root it
  !> started from (gamma1 [rad], omega1 [rad/s]; 0: none).
  type :: harmonic_root_memory_type
    type(harmonic_state_type) :: root
    real(wp) :: gamma1 = 0, omega1 = 0
  end type harmonic_root_memory_type

  !> Outputs of a solved layer at force |P|.
  type :: harmonic_outputs_type
    !> First harmonics: stress [Pa] and displacement at E [m] (complex).
    complex(wp) :: S1 = 0, U1 = 0
    !> Largest excursions of gamma(t), sigma(t) from their means.
    real(wp) :: gamma_max = 0, sigma_max = 0
    !> |Gamma_h|, |sigma_h|, h = 0..H.
    real(wp), allocatable :: gamma_h(:), sigma_h(:)
  end type harmonic_outputs_type

  !> Entries of a table point's signature (H, roots, jump, harmonic content, regime + 1 or 0).
  integer, parameter :: SIGNATURE_SIZE = 5

  !> An exact point: its structure (H, roots, jump, sizes, regime), packed outputs y and check
  !> scales s.
  type :: table_node_type
    integer(int64) :: idx = 0
    integer :: h = 0
    logical :: ok = .false.
    integer :: signature(SIGNATURE_SIZE) = 0
    real(wp), allocatable :: y(:), s(:)
  end type table_node_type

  type :: force_table_type
    !> What the table was built for (damper revision and summary numbers, harmonics,
    !> harmonic_tol, interblade phase); a change of any empties it.
    real(wp), allocatable :: key(:)
    !> The limit force the table's points were classified with [N] (negative: not yet known).
    real(wp) :: F_lim = -1
    integer :: n_node = 0, n_leaf = 0, n_visit = 0
    !> Exact points, sorted by idx.
    type(table_node_type), allocatable :: node(:)
    !> Leaves [lo, hi) (node positions), their status (TABLE_VERIFIED or TABLE_EXACT) and the
    !> harmonics of their points.
    integer(int64), allocatable :: leaf_lo(:), leaf_hi(:)
    integer, allocatable :: leaf_status(:), leaf_h(:)
    !> Level-0 panels visited (their position) and the harmonics of their points (0: not set).
    integer(int64), allocatable :: visited(:)
    integer, allocatable :: visited_h(:)
  end type force_table_type
end module udmap_mapping_harmonic_types
