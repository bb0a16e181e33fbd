"""Acceptance of the Platform Centred Reduction (issue 12) against the independent reference:
on a generated hex8 blade of about 10^4 DOFs, the reduced model's eigenfrequencies in
[0, 3 f_max] equal those of the full model with the same rigid platform to 1e-6, and H_gg, H_gE
and the gauge stress in the band equal a direct sparse solve of the full model to 1e-6.

"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse.linalg as sla

import fe_reference as ref
from udmap.reduction import platform_centred_reduction
from fe_deck import assemble, make_deck
from udmap.fe import FEModel
from udmap.case.fe import gauge_row

ZETA = 0.002
AXIS, DIRECTION = [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]


@pytest.fixture(scope="module")
def blade():
    deck = make_deck(h=0.002)                     # 7173 free DOFs, 663 platform nodes
    K, M = assemble(deck)
    fe = FEModel(K, M, np.repeat(deck.node_ids, 3), np.tile([1, 2, 3], len(deck.node_ids)),
                 deck.node_ids, deck.xyz)
    rig = ref.rigid_platform(fe, deck.platform, deck.ref_point, AXIS, deck.exc_node, DIRECTION,
                             deck.clamp)
    f1 = np.sqrt(sla.eigsh(rig.K.tocsc(), k=1, M=rig.M.tocsc(), sigma=0,
                           return_eigenvectors=False)[0]) / (2 * np.pi)
    f_min, f_max = 0.9 * f1, 1.05 * f1
    s = gauge_row(fe, *deck.gauge, 2.0e11)
    red = platform_centred_reduction(
        fe, platform_nodes=deck.platform, ref_point=deck.ref_point, axis=AXIS,
        exc_node=deck.exc_node, exc_direction=DIRECTION, clamp_nodes=deck.clamp,
        stress_rows=[s], f_max=f_max)
    return {"fe": fe, "rig": rig, "red": red, "s": s, "band": (f_min, f_max)}


def test_eigenfrequencies_up_to_three_f_max(blade):
    rig, red = blade["rig"], blade["red"]
    f_top = 3 * blade["band"][1]
    full = ref.frequencies(rig.K, rig.M, f_top)
    w = la.eigh(np.asarray(red.K), np.asarray(red.M), eigvals_only=True)
    reduced = np.sqrt(np.clip(w, 0, None)) / (2 * np.pi)
    reduced = reduced[reduced <= f_top * (1 + 1e-6)]
    assert len(full) >= 2 and len(reduced) == len(full)
    np.testing.assert_allclose(reduced, full, rtol=1e-6)
    np.testing.assert_allclose(red.freqs_full, full, rtol=1e-9)


def test_receptances_and_gauge_stress_in_the_band(blade):
    rig, red = blade["rig"], blade["red"]
    Kr, Mr = np.asarray(red.K), np.asarray(red.M)
    beta = 2 * ZETA / np.sqrt(la.eigh(Kr, Mr, eigvals_only=True)[0])
    s_full = rig.T.T @ blade["s"].toarray().ravel()
    s_red = np.asarray(red.stress_K).ravel()
    g, e = red.gamma_dof - 1, red.exc_dof - 1
    sources = ((e, rig.exc), (g, rig.gamma))
    loads = np.zeros((rig.K.shape[0], len(sources)))
    for j, (_, src_full) in enumerate(sources):
        loads[src_full, j] = 1.0
    for f in np.linspace(*blade["band"], 5):
        w = 2 * np.pi * f
        Zr = Kr * (1 + 1j * w * beta) - w * w * Mr
        u_all = ref.solve(rig.K, rig.M, beta, f, loads)  # one factorisation, both loads
        for j, (src_red, _) in enumerate(sources):
            q = la.solve(Zr, np.eye(len(Kr))[src_red])
            u = u_all[:, j]
            assert q[g] == pytest.approx(u[rig.gamma], rel=1e-6)     # H_gE, H_gg
            assert s_red @ q == pytest.approx(s_full @ u, rel=1e-6)  # gauge stress
