"""CalculiX: ``.sti``, ``.mas`` (``row col value``, upper triangle, rows of the free DOFs),
``.dof`` (one ``node.component`` per row) from ``*FREQUENCY, SOLVER=MATRIXSTORAGE``, and the
deck (``.inp``) for the node coordinates. Constrained DOFs are already removed by CalculiX."""
from __future__ import annotations

import numpy as np

from ..errors import InputError
from ._text import parse_deck_nodes, read_text, read_triplets, symmetric_from_triplets
from .model import FEModel, make_model


def read_dof(path, field: str):
    nodes, comps = [], []
    for lineno, line in enumerate(read_text(path, field).splitlines(), 1):
        s = line.strip()
        if not s:
            continue
        try:
            a, b = s.split(".")
            nodes.append(int(a))
            comps.append(int(b))
        except ValueError:
            raise InputError(f"{field}: {path}:{lineno}: expected 'node.component', got "
                             f"{s!r}") from None
    return np.array(nodes, dtype=np.int64), np.array(comps, dtype=np.int64)


def read(files: dict) -> FEModel:
    dof_node, dof_comp = read_dof(files["dof"], "blade.files.dof")
    n = len(dof_node)
    mats = []
    for key in ("sti", "mas"):
        r, c, v = read_triplets(files[key], f"blade.files.{key}")
        if len(r) and max(r.max(), c.max()) > n:
            raise InputError(f"blade.files.{key}: {files[key]} refers to row "
                             f"{int(max(r.max(), c.max()))} but the DOF map "
                             f"{files['dof']} has {n} rows")
        mats.append(symmetric_from_triplets(r, c, v, n, f"blade.files.{key}"))
    node_ids, xyz = parse_deck_nodes(files["inp"], "blade.files.inp")
    return make_model(mats[0], mats[1], dof_node, dof_comp, node_ids, xyz,
                      where=f"blade.files ({files['sti']}, {files['dof']})")
