"""Platform Centred Reduction (PHYSICS.md 1.3) of a generated 3D solid blade of about 10^4
DOFs: H_gg, H_gE and the gauge stress H_sE in the band equal a direct sparse solve (scipy splu)
of the full model with the same rigid platform, built independently in test_reduction.py, to
1e-6, with C = beta K, beta = 2 zeta / omega_1 (PHYSICS.md 1.3)."""
import numpy as np
import pytest
import scipy.sparse.linalg as sla

from test_reduction import BAND, ZETA, _args, full_model
from udmap.fe.generator import generate_blade
from udmap.reduction import platform_centred_reduction


@pytest.fixture(scope="module")
def blade():
    return generate_blade(10_000)


@pytest.fixture(scope="module")
def reduced(blade):
    return platform_centred_reduction(blade.fe, **_args(blade, check_full=False))


def test_receptances_and_gauge_equal_direct_solve(blade, reduced):
    T, Kt, Mt, nf = full_model(blade)
    fe = blade.fe
    a = blade.axis / np.linalg.norm(blade.axis)
    d = blade.exc_direction / np.linalg.norm(blade.exc_direction)
    Qg = np.zeros(Kt.shape[0])
    Qg[nf + 3:nf + 6] = a                       # unit moment about a on the platform
    fE = np.zeros(fe.K.shape[0])
    for c in range(3):
        fE[(fe.dof_node == blade.exc_node) & (fe.dof_comp == c + 1)] = d[c]
    QE = T.T @ fE                               # unit force at E along d
    s = T.T @ blade.gauge_row()
    # C = beta K with beta = 2 zeta / omega_1 of the reduced bare blade (PHYSICS.md 1.3)
    Kr, Mr, g, e = reduced.K, reduced.M, reduced.gamma_dof - 1, reduced.exc_dof - 1
    w1 = 2 * np.pi * reduced.info["freqs_reduced_all"][0]
    beta = 2 * ZETA / w1
    f1, f2 = reduced.info["freqs_reduced_all"][:2]
    worst = 0.0
    for f in (BAND[0], f1, f2, BAND[1]):
        w = 2 * np.pi * f
        A = (Kt * (1 + 1j * w * beta) - w * w * Mt).tocsc()
        x = sla.splu(A).solve(np.column_stack([Qg, QE]).astype(complex))
        xg, xE = x[:, 0], x[:, 1]
        H_gg, H_gE, S_E = a @ xg[nf + 3:nf + 6], a @ xE[nf + 3:nf + 6], s @ xE
        Ar = Kr * (1 + 1j * w * beta) - w * w * Mr
        yg = np.linalg.solve(Ar, np.eye(Kr.shape[0])[:, g])
        yE = np.linalg.solve(Ar, np.eye(Kr.shape[0])[:, e])
        for ref, got in ((H_gg, yg[g]), (H_gE, yE[g]), (S_E, reduced.stress_K @ yE)):
            assert abs(got - ref) <= 1e-6 * abs(ref), (f, ref, got)
            worst = max(worst, abs(got - ref) / abs(ref))
        # u_E of the moment equals gamma of the force (reciprocity of the reduced model)
        assert abs(yg[e] - yE[g]) <= 1e-9 * abs(yE[g])
    print(f"largest relative error of H_gg, H_gE, sigma_E in the band: {worst:.2e}")
