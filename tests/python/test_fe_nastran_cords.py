"""NASTRAN grids in local coordinate systems (CP and CD with CORD2R/2C/2S and CORD1R/1C/1S):
the same model written in the basic system and in local systems (positions in CP, matrices in
each grid's CD frame, transformed here) reads as the same model; tabs in GRID cards; the DMIG
names; and the errors, each naming the field, the file and the line."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse as sp

from udmap import InputError
from udmap.fe import FEModel, read_fe
from udmap.fe.nastran_coords import System, _from_points

from fe_compare import rel
from fe_writers import card, write_nastran
from fe_deck import assemble, make_deck


# Systems of the test: 1 rectangular (rotated, shifted), 2 cylindrical defined in 1,
# 3 spherical defined in 2, 4 rectangular by three grids (CORD1R) of the model.
CORDS = [["CORD2R", "1", "0", "0.01", "-0.02", "0.005", "0.31", "0.52", "0.8", "0.9",
          "-0.2", "0.1"],
         ["CORD2C", "2", "1", "0.003", "0.001", "-0.01", "0.003", "0.001", "1.0", "1.0",
          "0.5", "0.0"],
         ["CORD2S", "3", "2", "0.02", "30.0", "0.0", "0.02", "30.0", "1.0", "1.0", "80.0",
          "0.0"]]


def _systems(fe):
    basic = System("R", np.zeros(3), np.eye(3))
    s1 = _from_points("R", *basic.to_basic(np.reshape([0.01, -0.02, 0.005, 0.31, 0.52, 0.8,
                                                       0.9, -0.2, 0.1], (3, 3))), "1")
    s2 = _from_points("C", *s1.to_basic(np.reshape([0.003, 0.001, -0.01, 0.003, 0.001, 1.0,
                                                    1.0, 0.5, 0.0], (3, 3))), "2")
    s3 = _from_points("S", *s2.to_basic(np.reshape([0.02, 30.0, 0.0, 0.02, 30.0, 1.0, 1.0,
                                                    80.0, 0.0], (3, 3))), "3")
    g = [int(fe.node_ids[k]) for k in (0, 5, 40)]
    s4 = _from_points("R", *fe.node_xyz[[0, 5, 40]], "4")
    return {0: basic, 1: s1, 2: s2, 3: s3, 4: s4}, g


def _in_system(S, x):
    """Coordinates of basic points x in system S (inverse of S.to_basic)."""
    v = (x - S.origin) @ S.R
    if S.kind == "R":
        return v
    if S.kind == "C":
        return np.column_stack([np.hypot(v[:, 0], v[:, 1]),
                                np.degrees(np.arctan2(v[:, 1], v[:, 0])), v[:, 2]])
    r = np.linalg.norm(v, axis=1)
    return np.column_stack([r, np.degrees(np.arccos(v[:, 2] / r)),
                            np.degrees(np.arctan2(v[:, 1], v[:, 0]))])


@pytest.fixture(scope="module")
def model():
    """A small clamped hex8 blade (numpy assembly of the test deck) with rotations added: a
    6-DOF model (rotation springs and masses on every node, coupled) so both frame blocks are
    exercised."""
    deck = make_deck(neck=(0.008, 0.008, 0.008), slab=(0.016, 0.008, 0.004),
                     airfoil=(0.008, 0.008, 0.016))
    K, M = assemble(deck)
    dn0, dc0 = np.repeat(deck.node_ids, 3), np.tile([1, 2, 3], len(deck.node_ids))
    free = ~np.isin(dn0, deck.clamp)
    nodes = deck.node_ids[~np.isin(deck.node_ids, deck.clamp)]
    rot_node, rot_comp = np.repeat(nodes, 3), np.tile([4, 5, 6], len(nodes))
    rng = np.random.default_rng(7)
    R = sp.random(len(rot_node), len(rot_node), density=0.01, random_state=3)
    kr = sp.diags(rng.uniform(1e3, 2e3, len(rot_node))) + 10 * (R @ R.T)
    mr = sp.diags(rng.uniform(1e-9, 2e-9, len(rot_node)))
    K = sp.csr_matrix(sp.block_diag([K[free][:, free], kr]))
    M = sp.csr_matrix(sp.block_diag([M[free][:, free], mr]))
    dn = np.concatenate([dn0[free], rot_node])
    dc = np.concatenate([dc0[free], rot_comp])
    order = np.lexsort((dc, dn))            # the reader's order: by grid, then component
    fe = FEModel(None, None, None, None, deck.node_ids, deck.xyz)
    return None, fe, K[order][:, order], M[order][:, order], dn[order], dc[order]


def _freqs(K, M, k=12):
    w = la.eigh(K.toarray(), M.toarray(), eigvals_only=True, subset_by_index=[0, k - 1])
    return np.sqrt(w) / (2 * np.pi)


def test_local_systems_give_the_same_model(model, tmp_path):
    d, fe, K, M, dn, dc = model
    ids, xyz = fe.node_ids, fe.node_xyz
    write_nastran(tmp_path / "basic.pch", tmp_path / "basic.bdf", K, M, dn, dc, ids, xyz)
    basic = read_fe({"format": "nastran", "files": {"pch": "basic.pch", "bdf": "basic.bdf"}},
                    tmp_path)
    systems, g4 = _systems(fe)
    rng = np.random.default_rng(11)
    cp = rng.integers(0, 5, len(ids))
    cd = rng.integers(0, 5, len(ids))
    cp[[0, 5, 40]] = [1, 2, 3]                  # the CORD1R grids themselves in local systems
    local_xyz = np.empty_like(xyz)
    T = np.zeros((len(ids), 3, 3))
    for s, S in systems.items():
        local_xyz[cp == s] = _in_system(S, xyz[cp == s])
        if (cd == s).any():
            T[cd == s] = S.frames(xyz[cd == s])
    row = {int(i): k for k, i in enumerate(ids)}
    # B maps basic components to each grid's CD frame: q_local = B q_basic, K_local = B K B^T.
    B = sp.lil_matrix(K.shape)
    index = {(int(a), int(c)): k for k, (a, c) in enumerate(zip(dn, dc))}
    for (a, c), k in index.items():
        blk = (c - 1) // 3
        for c2 in range(3):
            B[k, index[(a, 3 * blk + c2 + 1)]] = T[row[a]][c2, (c - 1) % 3]
    B = sp.csr_matrix(B)
    cords = CORDS + [["CORD1R", "4", *map(str, g4)]]
    write_nastran(tmp_path / "local.pch", tmp_path / "local.bdf", B @ K @ B.T, B @ M @ B.T,
                  dn, dc, ids, local_xyz, cp, cd, cords)
    local = read_fe({"format": "nastran", "files": {"pch": "local.pch", "bdf": "local.bdf"}},
                    tmp_path)
    assert (cd != 0).sum() > 0.7 * len(ids) and (cp != 0).sum() > 0.7 * len(ids)
    assert np.allclose(local.node_xyz, basic.node_xyz, rtol=0, atol=1e-14)
    assert rel(local.K, basic.K) < 1e-13 and rel(local.M, basic.M) < 1e-13
    f0, f1 = _freqs(basic.K, basic.M), _freqs(local.K, local.M)
    assert f0[0] > 100 and np.max(np.abs(f1 / f0 - 1)) < 1e-10


def test_tabs_lowercase_and_dmig_names(model, tmp_path):
    d, fe, K, M, dn, dc = model
    extra = [card(["DMIG", "MUG1T", "0", "6", "2", "", "", "", ""]),
             card(["DMIG", "MUG1T", str(dn[0]), str(dc[0]), "", str(dn[0]), str(dc[0]),
                    "1.0", ""])]
    write_nastran(tmp_path / "m.pch", tmp_path / "m.bdf", K, M, dn, dc, fe.node_ids,
                  fe.node_xyz, extra=extra)
    # GRID cards with tabs (each tab to the next 8-column field) and in lower case.
    bdf = tmp_path / "m.bdf"
    text = bdf.read_text().splitlines()
    tabbed = []
    for line in text:
        if line.startswith("GRID"):
            f = line.split(",")
            tabbed.append("grid\t" + "\t".join([f[1], "", *(f"{float(v):.5f}" for v in f[3:6])]))
        else:
            tabbed.append(line)
    bdf.write_text("\r\n".join(tabbed) + "\r\n")
    sec = {"format": "nastran", "files": {"pch": "m.pch", "bdf": "m.bdf"}}
    with pytest.raises(InputError, match=r"blade\.files\.pch: .*m\.pch needs exactly one DMIG "
                                         r"whose name starts with M \(found: KAAX, MAAX, MUG1T\); "
                                         r"name it in blade\.dmig\.M"):
        read_fe(sec, tmp_path)
    got = read_fe({**sec, "dmig": {"K": "kaax", "M": "MAAX"}}, tmp_path)
    assert np.allclose(got.node_xyz, fe.node_xyz, rtol=0, atol=5e-6)
    assert rel(got.K, K) < 1e-15 and np.array_equal(got.dof_node, dn)


BAD = {
    "undefined CP": (lambda b: b.replace("GRID,1,,", "GRID,1,9,"),
                     r"blade\.files\.bdf: .*m\.bdf:\d+: GRID 1 has CP 9, a coordinate system "
                     r"that is not defined"),
    "undefined CD": (lambda b: b.replace("GRID,1,,", "GRID,1,,").replace(
        ",\nGRID,2,", ",99\nGRID,2,", 1),
        r"blade\.files\.bdf: .*m\.bdf:\d+: GRID 1 has CD 99, a coordinate system that is not "
        r"defined"),
    "system defined twice": (lambda b: b.replace("BEGIN BULK", "BEGIN BULK\n" + "\n".join(
        card(CORDS[0]) * 2)), r"blade\.files\.bdf: .*m\.bdf:\d+: coordinate system 1 is "
                               r"defined again \(first at .*m\.bdf:\d+\)"),
    "degenerate system": (lambda b: b.replace("BEGIN BULK", "BEGIN BULK\n" + "\n".join(card(
        ["CORD2R", "5", "0", "0", "0", "0", "0", "0", "1", "0", "0", "2"]))),
        r"blade\.files\.bdf: .*m\.bdf:\d+: the points A, B, C do not define a system"),
    "bad GRID": (lambda b: b.replace("GRID,1,,", "GRID,1,,x", 1),
                 r"blade\.files\.bdf: .*m\.bdf:\d+: bad GRID card"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_bulk_data_names_field_file_and_line(model, tmp_path, name):
    d, fe, K, M, dn, dc = model
    write_nastran(tmp_path / "m.pch", tmp_path / "m.bdf", K, M, dn, dc, fe.node_ids,
                  fe.node_xyz)
    edit, pattern = BAD[name]
    text = (tmp_path / "m.bdf").read_text()
    (tmp_path / "m.bdf").write_text(edit(text))
    assert edit(text) != text
    with pytest.raises(InputError, match=pattern):
        read_fe({"format": "nastran", "files": {"pch": "m.pch", "bdf": "m.bdf"}}, tmp_path)


def test_partial_frame_block_is_refused(model, tmp_path):
    d, fe, K, M, dn, dc = model
    g = int(dn[-1])
    keep = ~((dn == g) & (dc == 2))                    # grid g loses its component 2
    cd = np.where(fe.node_ids == g, 1, 0)
    write_nastran(tmp_path / "m.pch", tmp_path / "m.bdf", K[keep][:, keep], M[keep][:, keep],
                  dn[keep], dc[keep], fe.node_ids, fe.node_xyz, cd=cd, cords=CORDS[:1])
    with pytest.raises(InputError, match=rf"blade\.files\.bdf: .*m\.bdf:\d+: GRID {g} has a "
                                         r"local CD frame but the "
                                         r"matrices hold only components 1, 3 of its "
                                         r"translations"):
        read_fe({"format": "nastran", "files": {"pch": "m.pch", "bdf": "m.bdf"}}, tmp_path)
