"""ANSYS Mechanical APDL: stiffness and mass as Matrix Market from APDL Math ``*EXPORT``, the DOF
mapping vector (Matrix Market array of node numbers: with ``k = n / len`` DOFs per node, matrix
rows ``k (j - 1) + 1 .. k j`` are components 1..k of the j-th entry) and the nodal coordinates
(a table ``node x y z``, tab, semicolon or space separated, with a header line in any language;
decimal commas as written by a German ANSYS are accepted)."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..errors import InputError
from ._text import number, read_mm, read_text
from .model import FEModel, make_model


def read_nodes_table(path: Path, field: str):
    ids, xyz = [], []
    for lineno, line in enumerate(read_text(path, field).splitlines(), 1):
        s = line.strip()
        if not s:
            continue
        if "\t" in s or ";" in s:
            parts = [p for p in re.split(r"[\t;]", s) if p.strip()]
        elif "." in s and "," in s:
            parts = [p for p in s.split(",") if p.strip()]
        else:
            parts = s.split()
        try:
            node = int(parts[0])
        except ValueError:
            if not ids:
                continue  # header lines
            raise InputError(f"{field}: {path}:{lineno}: expected 'node x y z', got {s!r}") from None
        try:
            c = [number(p) for p in parts[1:4]]
            if len(c) != 3:
                raise ValueError
        except ValueError:
            raise InputError(f"{field}: {path}:{lineno}: expected 'node x y z', got {s!r}") from None
        ids.append(node)
        xyz.append(c)
    if not ids:
        raise InputError(f"{field}: {path}: no node lines")
    return np.array(ids, dtype=np.int64), np.array(xyz, dtype=float)


def read(files: dict) -> FEModel:
    K = read_mm(files["stiffness"], "blade.files.stiffness")
    M = read_mm(files["mass"], "blade.files.mass")
    n = K.shape[0]
    nodes = read_mm(files["dof_map"], "blade.files.dof_map", vector=True)
    if not np.all(nodes == np.round(nodes)) or len(nodes) == 0:
        raise InputError(f"blade.files.dof_map: {files['dof_map']}: node numbers must be integers")
    per, rem = divmod(n, len(nodes))
    if rem or not 1 <= per <= 6:
        raise InputError(f"blade.files.dof_map: {files['dof_map']} has {len(nodes)} entries, "
                         f"which does not match the {n} x {n} matrices (1 to 6 DOFs per entry)")
    dof_node = np.repeat(nodes.astype(np.int64), per)
    dof_comp = np.tile(np.arange(1, per + 1), len(nodes))
    node_ids, xyz = read_nodes_table(files["nodes"], "blade.files.nodes")
    return make_model(K, M, dof_node, dof_comp, node_ids, xyz,
                      where=f"blade.files ({files['stiffness']}, {files['dof_map']})")
