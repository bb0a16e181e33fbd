"""Plain Matrix Market with CSV maps: ``K``, ``M`` (Matrix Market, symmetric or general),
``dof_map`` (CSV ``row,node,component``, rows 1-based) and ``nodes`` (CSV ``node,x,y,z``)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import scipy.sparse as sp

from ..errors import InputError
from ._text import read_mm, text_lines
from .model import FEModel, make_model


def _csv(path: Path, field: str, ncol: int, kinds):
    rows = []
    for lineno, line in text_lines(path, field):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        parts = [p.strip() for p in s.split(",")]
        try:
            if len(parts) != ncol:
                raise ValueError
            rows.append([k(p) for k, p in zip(kinds, parts)])
        except ValueError:
            if not rows and lineno == 1:
                continue  # header
            raise InputError(f"{field}: {path}:{lineno}: expected {ncol} comma-separated "
                             f"values, got {s!r}") from None
    return rows


def read_dof_map(path: Path, n: int, field: str):
    rows = _csv(path, field, 3, (int, int, int))
    if len(rows) != n:
        raise InputError(f"{field}: {path} has {len(rows)} rows but the matrices are {n} x {n}")
    a = np.array(rows, dtype=np.int64).reshape(-1, 3)
    order = np.argsort(a[:, 0])
    if not np.array_equal(a[order, 0], np.arange(1, n + 1)):
        raise InputError(f"{field}: {path}: the rows must be 1..{n}, each once")
    return a[order, 1], a[order, 2]


def read_nodes_csv(path: Path, field: str):
    rows = _csv(path, field, 4, (int, float, float, float))
    if not rows:
        raise InputError(f"{field}: {path}: no nodes")
    return (np.array([r[0] for r in rows], dtype=np.int64),
            np.array([r[1:] for r in rows], dtype=float))


def read(files: dict) -> FEModel:
    K = read_mm(files["K"], "blade.files.K")
    M = read_mm(files["M"], "blade.files.M")
    dof_node, dof_comp = read_dof_map(files["dof_map"], K.shape[0], "blade.files.dof_map")
    node_ids, xyz = read_nodes_csv(files["nodes"], "blade.files.nodes")
    return make_model(K, M, dof_node, dof_comp, node_ids, xyz,
                      where=f"blade.files ({files['K']}, {files['M']})")


def write(fe: FEModel, directory, stem: str = "blade") -> dict:
    """Writes ``fe`` in this format (lower triangle, 17 digits); returns the ``files`` section."""
    d = Path(directory)
    names = {"K": f"{stem}_K.mtx", "M": f"{stem}_M.mtx", "dof_map": f"{stem}_dofs.csv",
             "nodes": f"{stem}_nodes.csv"}
    for key in ("K", "M"):
        A = sp.tril(getattr(fe, key)).tocoo()
        with open(d / names[key], "w") as f:
            f.write("%%MatrixMarket matrix coordinate real symmetric\n")
            f.write(f"{fe.n} {fe.n} {A.nnz}\n")
            np.savetxt(f, np.column_stack([A.row + 1, A.col + 1, A.data]),
                       fmt=["%d", "%d", "%.17g"])
    np.savetxt(d / names["dof_map"], np.column_stack([np.arange(1, fe.n + 1), fe.dof_node,
                                                      fe.dof_comp]),
               fmt="%d", delimiter=",", header="row,node,component", comments="")
    with open(d / names["nodes"], "w") as f:
        f.write("node,x,y,z\n")
        for i, (x, y, z) in zip(fe.node_ids, fe.node_xyz):
            f.write(f"{i},{x:.17g},{y:.17g},{z:.17g}\n")
    return names
