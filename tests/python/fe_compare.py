"""Comparisons of FE models shared by the reader tests."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from udmap.fe import matrix_market, read_fe


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


def ccx_section(job):
    """The blade section of a CalculiX export ``job.sti/.mas/.dof/.inp``."""
    return {"format": "calculix", "files": {k: f"{job}.{k}" for k in ("sti", "mas", "dof", "inp")}}
