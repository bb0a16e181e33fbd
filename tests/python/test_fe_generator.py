"""The generated 3D solid blade (udmap.fe.generator): its files read back to the same model, and
CalculiX (ccx) on its deck gives the same stiffness and mass (.sti, .mas of the deck's
*FREQUENCY, SOLVER=MATRIXSTORAGE step, in the order of its .dof) and the same
eigenfrequencies, so the bricks are CalculiX's C3D8."""
import json
import re
import subprocess
from shutil import which as shutil_which

import numpy as np
import pytest
import scipy.io as sio
import scipy.sparse as sp
import scipy.sparse.linalg as sla

from udmap.fe.generator import generate_blade, write_blade


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    d = tmp_path_factory.mktemp("blade")
    b = generate_blade(3000)
    case = write_blade(b, d)
    return b, case, d


def test_size_and_sets(written):
    b, case, d = written
    n = b.fe.K.shape[0]
    assert 2500 < n < 3500
    assert np.all(b.fe.dof_comp >= 1) and np.all(b.fe.dof_comp <= 3)
    assert not np.isin(b.fe.dof_node, b.root_nodes).any()          # root face clamped
    assert b.exc_node not in set(b.platform_nodes.tolist())
    y = b.fe.node_xyz[np.isin(b.fe.node_ids, b.platform_nodes), 1]
    assert y.min() >= 0.020 - 1e-12 and y.max() <= 0.024 + 1e-12


def test_files_read_back(written):
    b, case, d = written
    K = sio.mmread(d / "K.mtx").tocsr()
    M = sio.mmread(d / "M.mtx").tocsr()
    assert abs(K - b.fe.K).max() <= 1e-15 * abs(b.fe.K).max()
    assert abs(M - b.fe.M).max() <= 1e-15 * abs(b.fe.M).max()
    dm = np.loadtxt(d / "dof_map.csv", delimiter=",", skiprows=1, dtype=np.int64)
    np.testing.assert_array_equal(dm[:, 0], np.arange(1, K.shape[0] + 1))
    np.testing.assert_array_equal(dm[:, 1], b.fe.dof_node)
    np.testing.assert_array_equal(dm[:, 2], b.fe.dof_comp)
    nodes = np.loadtxt(d / "nodes.csv", delimiter=",", skiprows=1)
    np.testing.assert_array_equal(nodes[:, 0], b.fe.node_ids)
    np.testing.assert_array_equal(nodes[:, 1:], b.fe.node_xyz)
    c = json.loads((d / "case.json").read_text())
    assert c == json.loads(json.dumps(case))
    blade = c["blade"]
    assert blade["kind"] == "fe" and blade["format"] == "matrix_market"
    assert blade["files"] == {"K": "K.mtx", "M": "M.mtx", "dof_map": "dof_map.csv",
                              "nodes": "nodes.csv"}
    assert blade["platform"]["nodes"] == b.platform_nodes.tolist()
    assert blade["excitation"]["node"] == b.exc_node
    assert blade["stress"]["gauge"] == list(b.gauge)


def _ccx(d, job):
    assert shutil_which("ccx"), "ccx not found: make deps installs calculix-ccx"
    r = subprocess.run(["ccx", job], cwd=d, capture_output=True, text=True, timeout=100)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]


def test_calculix_matrices_and_frequencies(written):
    b, case, d = written
    n = b.fe.K.shape[0]
    _ccx(d, "blade")
    dof = np.loadtxt(d / "blade.dof")
    node = np.floor(dof + 1e-9).astype(np.int64)
    comp = np.round((dof - node) * 10).astype(np.int64)
    np.testing.assert_array_equal(node, b.fe.dof_node)
    np.testing.assert_array_equal(comp, b.fe.dof_comp)
    for ext, A in (("sti", b.fe.K), ("mas", b.fe.M)):
        a = np.loadtxt(d / f"blade.{ext}")
        S = sp.coo_matrix((a[:, 2], (a[:, 0].astype(int) - 1, a[:, 1].astype(int) - 1)),
                          shape=(n, n)).tocsr()
        S = S + S.T - sp.diags(S.diagonal())
        # ccx prints 14 significant digits; its own integration agrees to about 1e-10
        assert abs(S - A).max() <= 1e-9 * abs(A).max(), ext
    deck = (d / "blade.inp").read_text()
    (d / "eig.inp").write_text(deck.replace("*FREQUENCY, SOLVER=MATRIXSTORAGE", "*FREQUENCY\n5"))
    _ccx(d, "eig")
    text = (d / "eig.dat").read_text()
    block = text[text.index("E I G E N V A L U E   O U T P U T"):]
    rows = re.findall(r"^\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$", block, re.M)[:5]
    f_ccx = np.array([float(r[3]) for r in rows])
    w, _ = sla.eigsh(b.fe.K, k=5, M=b.fe.M, sigma=0)
    f = np.sort(np.sqrt(w)) / (2 * np.pi)
    # ccx prints 7 significant digits
    np.testing.assert_allclose(f_ccx, f, rtol=1e-6)
