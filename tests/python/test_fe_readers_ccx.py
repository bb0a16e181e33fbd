"""The CalculiX reader on fresh exports made here by running ccx (free, clamped, mm-t-s units)
against an independent numpy hex8 assembly, and the NASTRAN DMIG/GRID reader on the same model
written in the three bulk data field formats."""
from __future__ import annotations

import subprocess

import numpy as np
import pytest
import scipy.sparse as sp

from udmap.fe import read_fe

from fe_deck import assemble, make_deck, write_inp
from fe_compare import ccx_section as _ccx, rel, same_model, via_matrix_market


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
        # fixed fields: small 8 fields of 8 a line (continuation +), large "*" 4 of 16
        name, per_line, width, cont = ((fields[0], 8, 8, "+") if field == "small" else
                                       (fields[0] + "*", 4, 16, "*"))
        out, line = [], name.ljust(8)
        for k, v in enumerate(fields[1:]):
            if k and k % per_line == 0:
                out.append(line)
                line = cont.ljust(8)
            line += v.rjust(width)
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
