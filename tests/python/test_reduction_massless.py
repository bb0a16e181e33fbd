"""A reduced model whose own mass matrix is singular: the hex8 test blade with the excitation
at a massless node held by springs to one platform node only, so the static mode of u_E moves
no mass (V^T M V has a zero eigenvalue). The reduction still holds: the reduced eigenfrequencies
(from the inverted pencil, the massless direction at infinity) equal the full model's with the
rigid platform to 1e-6, and H_gE, H_EE equal a direct sparse solve to 1e-6; through the case,
reduce, the platform check, the matrices blade and backbone all take it."""
from __future__ import annotations

import json

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as sla

import fe_reference as ref
from fe_deck import assemble, make_deck
from udmap.fe import FEModel
from udmap.reduction import platform_centred_reduction

K_LINK = 1.0e8      # N/m, each translation of the massless node to its platform node
ZETA = 0.002


@pytest.fixture(scope="module")
def model():
    deck = make_deck()
    K, M = assemble(deck)
    n0 = K.shape[0]
    x = int(deck.node_ids.max()) + 1                 # the massless node, beside platform node p
    p = deck.platform[0]
    link = sp.lil_matrix((n0 + 3, n0 + 3))
    for c in range(3):
        i, j = 3 * (p - 1) + c, n0 + c
        link[i, i] += K_LINK
        link[j, j] += K_LINK
        link[i, j] -= K_LINK
        link[j, i] -= K_LINK
    K = sp.block_diag([K, sp.csr_matrix((3, 3))]).tocsr() + link.tocsr()
    M = sp.block_diag([M, sp.csr_matrix((3, 3))]).tocsr()
    keep = np.ones(n0 + 3, bool)
    for node in deck.clamp:
        keep[3 * (node - 1):3 * node] = False
    idx = np.nonzero(keep)[0]
    node_ids = np.r_[deck.node_ids, x]
    xyz = np.vstack([deck.xyz, deck.xyz[p - 1] + [deck.h, 0, 0]])
    fe = FEModel(K=sp.csr_matrix(K[idx][:, idx]), M=sp.csr_matrix(M[idx][:, idx]),
                 dof_node=idx // 3 + 1, dof_comp=idx % 3 + 1, node_ids=node_ids,
                 node_xyz=xyz)
    args = dict(platform_nodes=deck.platform, ref_point=deck.ref_point, axis=[0, 1, 0],
                exc_node=x, exc_direction=[1, 0, 0])
    return fe, args


def test_singular_reduced_mass(model):
    fe, args = model
    red = platform_centred_reduction(fe, f_max=3000.0, **args)
    Mr = np.asarray(red.M)
    ev = np.linalg.eigvalsh(Mr)
    assert ev[0] < 1e-12 * ev[-1]                    # the reduced M is singular
    allf = red.info["freqs_reduced_all"]
    assert np.isinf(allf[-1]) and np.all(np.isfinite(allf[:-1]))
    rig = ref.rigid_platform(fe, args["platform_nodes"], args["ref_point"], args["axis"],
                             args["exc_node"], args["exc_direction"])
    full = ref.frequencies(rig.K, rig.M, 9000.0)
    assert len(full) >= 2 and red.info["inertia_ok"]
    np.testing.assert_allclose(red.freqs_full, full, rtol=1e-8)
    np.testing.assert_allclose(red.freqs_reduced, full, rtol=1e-6)
    # receptances of a unit force at the massless node (D = K (1 + i w beta) - w^2 M)
    beta = 2 * ZETA / (2 * np.pi * full[0])
    Kr, g, e = np.asarray(red.K), red.gamma_dof - 1, red.exc_dof - 1
    QE = np.zeros(rig.K.shape[0])
    QE[rig.exc] = 1.0
    for f in (0.5 * full[0], full[0], 0.5 * (full[0] + full[1])):
        w = 2 * np.pi * f
        x = sla.spsolve((rig.K * (1 + 1j * w * beta) - w * w * rig.M).tocsc(),
                        QE.astype(complex))
        y = np.linalg.solve(Kr * (1 + 1j * w * beta) - w * w * Mr,
                            np.eye(len(Kr))[:, e].astype(complex))
        for want, got in ((x[rig.gamma], y[g]), (x[rig.exc], y[e])):
            assert abs(got - want) <= 1e-6 * abs(want), (f, want, got)


def test_singular_reduced_mass_through_the_case(model, tmp_path, monkeypatch, capsys):
    # reduce (cached), the platform check and the matrices blade all take the singular
    # reduced M; backbone runs on it
    from udmap.cli import main
    from udmap.fe.generator import _write_mtx
    fe, args = model
    monkeypatch.setenv("UDMAP_CACHE_DIR", str(tmp_path / "cache"))
    _write_mtx(tmp_path / "K.mtx", fe.K)
    _write_mtx(tmp_path / "M.mtx", fe.M)
    np.savetxt(tmp_path / "dof_map.csv", np.column_stack([np.arange(1, fe.n + 1), fe.dof_node,
                                                          fe.dof_comp]),
               fmt="%d", delimiter=",", header="row,node,component", comments="")
    np.savetxt(tmp_path / "nodes.csv", np.column_stack([fe.node_ids, fe.node_xyz]),
               fmt=["%d", "%.17g", "%.17g", "%.17g"], delimiter=",", header="node,x,y,z",
               comments="")
    case = {"blade": {"kind": "fe", "format": "matrix_market",
                      "files": {"K": "K.mtx", "M": "M.mtx", "dof_map": "dof_map.csv",
                                "nodes": "nodes.csv"},
                      "platform": {"nodes": [int(v) for v in args["platform_nodes"]],
                                   "ref_point": list(args["ref_point"]), "axis": args["axis"]},
                      "excitation": {"node": int(args["exc_node"]),
                                     "direction": args["exc_direction"]},
                      "zeta": ZETA},
            "damper": {"kind": "jenkins", "kt": 1.0e5, "M_slip": 0.05},
            "analysis": {"f_min": 2400, "f_max": 3000}}
    (tmp_path / "case.json").write_text(json.dumps(case))
    status = main(["backbone", str(tmp_path / "case.json"), "--forces", "0.5,3", "--json"])
    out, err = capsys.readouterr()
    assert status == 0, err
    bb = json.loads(out)
    rig = ref.rigid_platform(fe, args["platform_nodes"], args["ref_point"], args["axis"],
                             args["exc_node"], args["exc_direction"])
    f1 = ref.frequencies(rig.K, rig.M, 3000.0)[0]
    assert bb["f1_bare"] == pytest.approx(f1, rel=1e-6)
    f_res = [p["f_res"] for p in bb["points"]]
    assert f1 < f_res[1] < f_res[0] < 3000
