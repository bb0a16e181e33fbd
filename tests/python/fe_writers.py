"""Writers of FE export files for the reader tests: NASTRAN punch and bulk data (free field),
Abaqus labelled matrices, and a model with an internal node (Abaqus numbering)."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp


def card(fields):
    """A free-field card (8 data fields a line, continuation lines start with +)."""
    data = fields[1:]
    return [",".join([fields[0] if k == 0 else "+"] + data[k:k + 8])
            for k in range(0, max(len(data), 1), 8)]


def write_nastran(pch, bdf, K, M, dof_node, dof_comp, node_ids, xyz, cp=None, cd=None,
                  cords=(), names=("KAAX", "MAAX"), extra=()):
    """Punch (DMIG, IFO 6, upper triangle) and bulk data (CORD cards, GRIDs with ``cp``,
    ``cd`` and coordinates ``xyz`` as given, i.e. already in CP), free field, 17 digits."""
    out = []
    for name, A in zip(names, (K, M)):
        out += card(["DMIG", name, "0", "6", "2", "", "", "", ""])
        U = sp.triu(A).tocsc()
        for j in range(A.shape[0]):
            lo, hi = U.indptr[j], U.indptr[j + 1]
            if lo == hi:
                continue
            f = ["DMIG", name, str(dof_node[j]), str(dof_comp[j]), ""]
            for i, v in zip(U.indices[lo:hi], U.data[lo:hi]):
                f += [str(dof_node[i]), str(dof_comp[i]), f"{v:.17e}", ""]
            out += card(f)
    for text in extra:
        out += text
    pch.write_text("$ DMIG punch\n" + "\n".join(out) + "\n")
    lines = ["SOL 103", "CEND", "  TITLE = local systems", "BEGIN BULK"]
    for c in cords:
        lines += card(c)
    for k, (i, p) in enumerate(zip(node_ids, xyz)):
        lines += card(["GRID", str(i), str(cp[k]) if cp is not None else "",
                        *(f"{v:.17e}" for v in p), str(cd[k]) if cd is not None else ""])
    bdf.write_text("\n".join(lines + ["ENDDATA"]) + "\n")


def write_labelled(path, A, dof_node, dof_comp):
    """Abaqus ``*MATRIX OUTPUT, FORMAT=MATRIX INPUT``: ``node, dof, node, dof, value``."""
    L = sp.tril(A).tocoo()
    with open(path, "w") as f:
        for i, j, v in zip(L.row, L.col, L.data):
            f.write(f"{dof_node[i]},{dof_comp[i]}, {dof_node[j]},{dof_comp[j]}, {v:.16e}\n")


def with_internal_node(fe, anchor, k=1e8, m=0.05):
    """``fe`` plus an internal node -1 (3 DOFs, mass ``m``) tied to ``anchor`` by springs."""
    n = fe.n
    idx = fe.dof_index()
    K = sp.lil_matrix(sp.block_diag([fe.K, sp.csr_matrix((3, 3))]))
    M = sp.lil_matrix(sp.block_diag([fe.M, m * sp.identity(3)]))
    for c in range(3):
        a, b = idx[(anchor, c + 1)], n + c
        K[a, a] += k
        K[b, b] += k
        K[a, b] -= k
        K[b, a] -= k
    return (sp.csr_matrix(K), sp.csr_matrix(M), np.append(fe.dof_node, [-1, -1, -1]),
            np.append(fe.dof_comp, [1, 2, 3]))
