"""A C3D20R blade (CalculiX's usual element for blades, whose consistent mass is only positive
semi-definite) of about 10^4 DOFs: the generated blade's mesh with 20-node bricks, K and M from
``ccx`` (*FREQUENCY, SOLVER=MATRIXSTORAGE). It reduces; the reduced model agrees with CalculiX's
own *RIGID BODY platform (bare, and with a rotational spring on gamma_P) to 1e-5 (CalculiX
prints 7 digits), with the full model to 1e-6, and its H_gg, H_gE with a direct sparse solve to
1e-6. A truly indefinite M (eigenvalues below -1e-12 max|M|) is refused, rounding is not."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as sla

import fe_reference as ref
from ccx_solids import K_SPRING, solid_blade
from udmap import InputError
from udmap.case.fe import semi_definite
from udmap.fe import FEModel
from udmap.reduction import platform_centred_reduction


@pytest.fixture(scope="module")
def blade(tmp_path_factory):
    return solid_blade(tmp_path_factory.mktemp("c3d20r"), 2500)


def _args(c, **kw):
    b = c["blade"]
    return dict(platform_nodes=c["mesh"].platform_nodes, ref_point=b.ref_point, axis=b.axis,
                exc_node=b.exc_node, exc_direction=b.exc_direction, **kw)


@pytest.fixture(scope="module")
def reduced(blade):
    return platform_centred_reduction(blade["fe"], **_args(blade, f_max=1.05 * blade["bare"][0]))


def test_reduced_model_equals_calculix_rigid_body(blade, reduced):
    K = np.array(reduced.K, dtype=float)
    g = reduced.gamma_dof - 1
    w = np.linalg.eigvals(np.linalg.solve(reduced.M, K)).real
    bare = np.sqrt(np.sort(w)[0]) / (2 * np.pi)
    K[g, g] += K_SPRING
    w = np.linalg.eigvals(np.linalg.solve(reduced.M, K)).real
    stuck = np.sqrt(np.sort(w)[0]) / (2 * np.pi)
    # the spring raises the first bending mode: the platform rocks in it
    assert blade["stuck"][0] > 1.05 * blade["bare"][0]
    assert bare == pytest.approx(blade["bare"][0], rel=1e-5)
    assert stuck == pytest.approx(blade["stuck"][0], rel=1e-5)
    # the full model with the rigid platform (inertia-counted) in [0, 3 f_max]
    assert reduced.info["inertia_ok"] and len(reduced.freqs_full) >= 1
    np.testing.assert_allclose(reduced.freqs_reduced, reduced.freqs_full, rtol=1e-6)
    print(f"C3D20R, {blade['fe'].n} DOFs: bare {bare:.7g} Hz (CalculiX {blade['bare'][0]}), "
          f"stuck {stuck:.7g} Hz (CalculiX {blade['stuck'][0]})")


def test_receptances_equal_direct_solve(blade, reduced):
    b, fe = blade["blade"], blade["fe"]
    rig = ref.rigid_platform(fe, blade["mesh"].platform_nodes, b.ref_point, b.axis, b.exc_node,
                             b.exc_direction)
    Qg = np.zeros(rig.K.shape[0])
    Qg[rig.gamma] = 1.0                         # unit moment on gamma_P
    QE = np.zeros(rig.K.shape[0])
    QE[rig.exc] = 1.0                           # unit force at E along d
    Kr, Mr, g, e = reduced.K, reduced.M, reduced.gamma_dof - 1, reduced.exc_dof - 1
    f1 = reduced.freqs_reduced[0]
    worst = 0.0
    for f in (0.95 * f1, 1.05 * f1):            # undamped, either side of the resonance
        w = 2 * np.pi * f
        x = sla.splu((rig.K - w * w * rig.M).tocsc()).solve(np.column_stack([Qg, QE]))
        y = np.linalg.solve(Kr - w * w * Mr, np.eye(Kr.shape[0])[:, [g, e]])
        for want, got in ((x[rig.gamma, 0], y[g, 0]), (x[rig.gamma, 1], y[g, 1])):
            assert abs(got - want) <= 1e-6 * abs(want), (f, want, got)
            worst = max(worst, abs(got - want) / abs(want))
    print(f"C3D20R: largest relative error of H_gg, H_gE in the band {worst:.2e}")


def test_receptances_up_to_three_f_max(blade, reduced):
    # The reduction keeps the modes up to 3 f_max: beyond the band, where `response --freq`
    # is answered, its H_gg and H_gE equal a direct sparse solve of the full model too.
    b, fe = blade["blade"], blade["fe"]
    rig = ref.rigid_platform(fe, blade["mesh"].platform_nodes, b.ref_point, b.axis, b.exc_node,
                             b.exc_direction)
    Q = np.zeros((rig.K.shape[0], 2))
    Q[rig.gamma, 0] = Q[rig.exc, 1] = 1.0
    Kr, Mr, g, e = reduced.K, reduced.M, reduced.gamma_dof - 1, reduced.exc_dof - 1
    f_max = reduced.info["f_cut"] / 3
    for f in (1.5 * f_max, 2.2 * f_max, 3.0 * f_max):
        w = 2 * np.pi * f
        x = sla.splu((rig.K - w * w * rig.M).tocsc()).solve(Q)
        y = np.linalg.solve(Kr - w * w * Mr, np.eye(Kr.shape[0])[:, [g, e]])
        np.testing.assert_allclose(y[g], x[rig.gamma], rtol=1e-6)


def test_semi_definite_mass_accepted_indefinite_refused(blade):
    fe = blade["fe"]
    assert 9000 <= fe.n <= 11000
    big = abs(fe.M).max()
    eye = sp.identity(fe.n, format="csr")
    # M is semi-definite (no eigenvalue below -1e-12 max|M|) and singular: M - 1e-9 max|M| I
    # has negative eigenvalues, so M has eigenvalues below 1e-9 max|M| (zero to rounding)
    assert semi_definite(fe.M)
    assert semi_definite(fe.M - 1e-14 * big * eye)
    shifted = FEModel(K=fe.K, M=fe.M - 1e-9 * big * eye, dof_node=fe.dof_node,
                      dof_comp=fe.dof_comp, node_ids=fe.node_ids, node_xyz=fe.node_xyz)
    assert not semi_definite(shifted.M)
    with pytest.raises(InputError, match=r"M: the mass matrix is not positive definite \(nor "
                                         r"semi-definite: \d+ eigenvalues of M_II below"):
        platform_centred_reduction(shifted, **_args(blade, n_modes=2))
