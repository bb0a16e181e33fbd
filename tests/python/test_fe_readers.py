"""Every FE reader gives the same model as the plain Matrix Market form of the same blade:
the real Abaqus and ANSYS exports in tests/data/fe/real (EXUDYN test data, LICENSE-EXUDYN.txt) and
fresh CalculiX exports made here by running ccx."""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse as sp
from scipy.spatial import cKDTree

from udmap import InputError
from udmap.fe import nastran, read_fe

from fe_compare import ccx_section, rel, same_model, via_matrix_market


DATA = Path(__file__).resolve().parents[1] / "data" / "fe" / "real"
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
        read_fe(ccx_section("b"), d)
