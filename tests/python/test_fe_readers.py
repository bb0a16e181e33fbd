"""Every FE reader gives the same model as the plain Matrix Market form of the same blade:
the real Abaqus and ANSYS exports in tests/data/fe (EXUDYN test data, LICENSE-EXUDYN.txt) and
fresh CalculiX exports made here by running ccx."""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse as sp
from scipy.spatial import cKDTree

from udmap._lib import InputError
from udmap.fe import matrix_market, nastran, read_fe

from fe_deck import assemble, make_deck, write_inp

DATA = Path(__file__).resolve().parents[1] / "data" / "fe"
ROTOR_ABAQUS = {"format": "abaqus", "files": {"stiffness": "abaqus/rotorDiscTestSTIF1.mtx",
                                              "mass": "abaqus/rotorDiscTestMASS1.mtx",
                                              "inp": "abaqus/rotorDiscTest.inp"}}
BLOCK_ABAQUS = {"format": "abaqus", "files": {"stiffness": "abaqus/blockC3D8_STIF1.mtx",
                                              "mass": "abaqus/blockC3D8_MASS1.mtx",
                                              "inp": "abaqus/blockC3D8.inp"}}
ROTOR_ANSYS = {"format": "ansys", "files": {
    "stiffness": "ansys/rotorAnsysStiffnessMatrixSparse.txt",
    "mass": "ansys/rotorAnsysMassMatrixSparse.txt",
    "dof_map": "ansys/rotorAnsysMatrixDofMappingVector.txt",
    "nodes": "ansys/rotorAnsysNodalCoordinates.txt"}}


def rel(A, B):
    return abs(sp.csr_matrix(A) - sp.csr_matrix(B)).max() / abs(sp.csr_matrix(B)).max()


def same_model(a, b, tol=0.0):
    assert a.n == b.n
    assert np.array_equal(a.dof_node, b.dof_node) and np.array_equal(a.dof_comp, b.dof_comp)
    assert np.array_equal(a.node_ids, b.node_ids)
    assert np.allclose(a.node_xyz, b.node_xyz, rtol=0, atol=tol * abs(b.node_xyz).max())
    assert rel(a.K, b.K) <= tol and rel(a.M, b.M) <= tol


def via_matrix_market(fe, tmp_path):
    files = matrix_market.write(fe, tmp_path, "mm")
    return read_fe({"format": "matrix_market", "files": files}, tmp_path)


def seventh_frequency(fe):
    w = la.eigh(fe.K.toarray(), fe.M.toarray(), eigvals_only=True)
    return np.sqrt(w[6]) / (2 * np.pi)


@pytest.mark.parametrize("section", [ROTOR_ABAQUS, BLOCK_ABAQUS, ROTOR_ANSYS])
def test_fixture_equals_its_matrix_market_form(section, tmp_path):
    fe = read_fe(section, DATA)
    assert fe.K.dtype == np.float64 and fe.dof_node.dtype == np.int64
    assert abs(fe.K - fe.K.T).max() == 0 and abs(fe.M - fe.M.T).max() == 0
    assert fe.n == 3 * len(fe.node_ids)
    same_model(via_matrix_market(fe, tmp_path), fe)


def test_ansys_rotor_known_frequency():
    # The ANSYS German export (tabs, decimal commas): first elastic mode 104.637010551 Hz.
    fe = read_fe(ROTOR_ANSYS, DATA)
    assert fe.n == 345 and len(fe.node_ids) == 115
    assert fe.node_xyz[list(fe.node_ids).index(2), 2] == pytest.approx(0.1, abs=1e-15)
    assert seventh_frequency(fe) == pytest.approx(104.637010551, rel=1e-9)


def test_abaqus_rotor_is_the_ansys_rotor():
    # Abaqus' rotor carries E = 2.1e11 in its deck where the ANSYS export's stiffness is 100
    # times smaller (EXUDYN scales the Abaqus matrix by 1e-2 for the common 104.637 Hz), so its
    # first elastic mode is 10 x 104.637013261 Hz; mapped node by node through the coordinates
    # its matrices equal the ANSYS ones to the single precision of Abaqus' coordinates.
    ab, an = read_fe(ROTOR_ABAQUS, DATA), read_fe(ROTOR_ANSYS, DATA)
    assert seventh_frequency(ab) == pytest.approx(1046.37013261, rel=1e-9)
    dist, near = cKDTree(an.node_xyz).query(ab.node_xyz)
    assert dist.max() < 1e-7 and len(set(near)) == len(near)
    node_map = dict(zip(ab.node_ids.tolist(), an.node_ids[near].tolist()))
    index = an.dof_index()
    perm = [index[(node_map[int(a)], int(c))] for a, c in zip(ab.dof_node, ab.dof_comp)]
    P = sp.csr_matrix((np.ones(ab.n), (np.arange(ab.n), perm)), shape=(ab.n, ab.n))
    assert rel(ab.K * 1e-2, P @ an.K @ P.T) < 1e-6
    assert rel(ab.M, P @ an.M @ P.T) < 1e-6


def test_abaqus_labelled_format_equals_coordinate_format(tmp_path):
    # The labelled layout of *MATRIX INPUT ("row node, dof, column node, dof, value", one
    # triangle allowed) written from the real coordinate export of the block.
    fe = read_fe(BLOCK_ABAQUS, DATA)
    for name, A in (("K.mtx", fe.K), ("M.mtx", fe.M)):
        L = sp.tril(A).tocoo()
        with open(tmp_path / name, "w") as f:
            for i, j, v in zip(L.row, L.col, L.data):
                f.write(f"{fe.dof_node[i]},{fe.dof_comp[i]}, {fe.dof_node[j]},{fe.dof_comp[j]}, "
                        f"{v:.16e}\n")
    shutil.copy(DATA / "abaqus" / "blockC3D8.inp", tmp_path)
    lab = read_fe({"format": "abaqus", "files": {"stiffness": "K.mtx", "mass": "M.mtx",
                                                "inp": "blockC3D8.inp"}}, tmp_path)
    same_model(lab, fe, tol=1e-15)


@pytest.fixture(scope="module")
def ccx_exports(tmp_path_factory):
    """Fresh CalculiX exports of the test blade: free, clamped, and free in mm-t-s units."""
    d = tmp_path_factory.mktemp("ccx")
    deck = make_deck()
    step = "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP"
    write_inp(deck, d / "free.inp", step, clamp=False)
    write_inp(deck, d / "clamp.inp", step, clamp=True)
    mm = make_deck()
    mm.xyz = mm.xyz * 1e3
    mm.h = mm.h * 1e3
    write_inp(mm, d / "mm.inp", step, clamp=False, E=2.0e5, rho=7.8e-9)   # MPa, t/mm^3
    for job in ("free", "clamp", "mm"):
        subprocess.run(["ccx", "-i", job], cwd=d, check=True, capture_output=True, timeout=100)
    return d, deck


def _ccx(job):
    return {"format": "calculix", "files": {k: f"{job}.{k}" for k in ("sti", "mas", "dof", "inp")}}


def test_calculix_export_equals_assembly(ccx_exports, tmp_path):
    d, deck = ccx_exports
    fe = read_fe(_ccx("free"), d)
    K, M = assemble(deck)
    n = K.shape[0]
    assert np.array_equal(fe.dof_node, np.repeat(deck.node_ids, 3))
    assert np.array_equal(fe.dof_comp, np.tile([1, 2, 3], n // 3))
    # The plain Matrix Market form of the same blade from the numpy assembly.
    from udmap.fe import FEModel
    plain = via_matrix_market(FEModel(K, M, fe.dof_node, fe.dof_comp, deck.node_ids, deck.xyz),
                              tmp_path)
    same_model(fe, plain, tol=1e-13)


def test_calculix_clamped_export_drops_the_root(ccx_exports):
    d, deck = ccx_exports
    free, clamped = read_fe(_ccx("free"), d), read_fe(_ccx("clamp"), d)
    keep = ~np.isin(free.dof_node, deck.clamp)
    assert np.array_equal(clamped.dof_node, free.dof_node[keep])
    assert np.array_equal(clamped.dof_comp, free.dof_comp[keep])
    assert rel(clamped.K, free.K[keep][:, keep]) < 1e-13
    assert rel(clamped.M, free.M[keep][:, keep]) < 1e-13


def test_units_mm_t_s(ccx_exports):
    d, _ = ccx_exports
    si = read_fe(_ccx("free"), d)
    mm = read_fe({**_ccx("mm"), "units": "mm-t-s"}, d)
    same_model(mm, si, tol=1e-12)


@pytest.mark.parametrize("field", ["small", "large", "free"])
def test_nastran_dmig_equals_matrix_market(ccx_exports, tmp_path, field):
    # No NASTRAN is available here: the punch and GRID cards are written after the Quick
    # Reference Guide (DMIG header NAME "0" IFO TIN, columns GJ CJ then Gi Ci Ai; IFO 6 with
    # each off-diagonal term once; small, large "*" and free field) from the CalculiX export.
    d, _ = ccx_exports
    fe = read_fe(_ccx("clamp"), d)
    pch, bdf = [], []

    def card(fields):
        if field == "free":     # 8 data fields a line, continuation lines start with +
            data = fields[1:]
            return [",".join([fields[0] if k == 0 else "+"] + data[k:k + 8])
                    for k in range(0, len(data), 8)]
        if field == "small":
            out, line = [], fields[0].ljust(8)
            for k, v in enumerate(fields[1:]):
                if k and k % 8 == 0:
                    out.append(line)
                    line = "+".ljust(8)
                line += v.rjust(8)
            return out + [line]
        out, line = [], (fields[0] + "*").ljust(8)
        for k, v in enumerate(fields[1:]):
            if k and k % 4 == 0:
                out.append(line)
                line = "*".ljust(8)
            line += v.rjust(16)
        return out + [line]

    def short(v):   # NASTRAN reals: as many digits as the field holds
        if field == "small":
            for digits in range(5, -1, -1):
                m, e = f"{v:.{digits}e}".split("e")
                s = f"{m}{int(e):+d}"      # the short form without E, e.g. 1.8803+8
                if len(s) <= 8:
                    return s
        return f"{v:.9e}".replace("e", "D") if field == "large" else f"{v:.15e}"

    for name, A in (("KAAX", fe.K), ("MAAX", fe.M)):
        pch += card(["DMIG", name, "0", "6", "2", "", "", "", ""])
        U = sp.triu(A).tocsc()
        for j in range(fe.n):
            lo, hi = U.indptr[j], U.indptr[j + 1]
            if lo == hi:
                continue
            f = ["DMIG", name, str(fe.dof_node[j]), str(fe.dof_comp[j]), ""]
            for i, v in zip(U.indices[lo:hi], U.data[lo:hi]):
                f += [str(fe.dof_node[i]), str(fe.dof_comp[i]), short(v), ""]
            pch += card(f)
    for i, (x, y, z) in zip(fe.node_ids, fe.node_xyz):
        bdf += card(["GRID", str(i), "", short(x) if field != "small" else f"{x:.5f}",
                     short(y) if field != "small" else f"{y:.5f}",
                     short(z) if field != "small" else f"{z:.5f}"])
    (tmp_path / "m.pch").write_text("$ DMIG punch\n" + "\n".join(pch) + "\n")
    (tmp_path / "m.bdf").write_text("\n".join(bdf) + "\n")
    nas = read_fe({"format": "nastran", "files": {"pch": "m.pch", "bdf": "m.bdf"}}, tmp_path)
    tol = {"small": 1e-3, "large": 1e-9, "free": 1e-14}[field]
    assert np.array_equal(nas.dof_node, fe.dof_node) and np.array_equal(nas.dof_comp, fe.dof_comp)
    assert np.array_equal(nas.node_ids, fe.node_ids)
    assert np.allclose(nas.node_xyz, fe.node_xyz, rtol=0, atol=1e-5)
    assert rel(nas.K, fe.K) <= tol and rel(nas.M, fe.M) <= tol


def test_nastran_short_reals():
    assert nastran.real("3.+5") == 3e5 and nastran.real("2.5+10") == 2.5e10
    assert nastran.real("-1.2-3") == -1.2e-3 and nastran.real("1.0D+00") == 1.0
    assert nastran.real(".5") == 0.5 and nastran.real("7.") == 7.0


def test_reader_errors_name_the_field_and_file(tmp_path):
    bad = tmp_path / "bad.mtx"
    shutil.copy(DATA / "ansys" / "rotorAnsysMassMatrixSparse.txt", bad)
    sec = {**ROTOR_ANSYS, "files": {**ROTOR_ANSYS["files"], "dof_map": str(bad)}}
    with pytest.raises(InputError, match=r"blade.files.dof_map: .*bad.mtx"):
        read_fe(sec, DATA)
    sec = {**ROTOR_ANSYS, "files": {**ROTOR_ANSYS["files"], "mass": "missing.txt"}}
    with pytest.raises(InputError, match=r"blade.files.mass: file not found"):
        read_fe(sec, DATA)
    # A DOF map that does not match the matrix size (CalculiX .dof one row short).
    d = tmp_path / "c"
    d.mkdir()
    for name in ("sti", "mas", "dof"):
        (d / f"b.{name}").write_text("1 1 1.0\n1 2 0.5\n2 2 1.0\n3 3 1.0\n" if name != "dof"
                                     else "1.1\n1.2\n")
    (d / "b.inp").write_text("*NODE\n1, 0, 0, 0\n")
    with pytest.raises(InputError, match=r"blade.files.sti: .*b.sti refers to row 3 but the "
                                         r"DOF map .*b.dof has 2 rows"):
        read_fe(_ccx("b"), d)
