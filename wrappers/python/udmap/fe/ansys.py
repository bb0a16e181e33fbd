"""ANSYS Mechanical APDL: stiffness and mass as Matrix Market from APDL Math ``*EXPORT``, the DOF
map and the nodal coordinates.

- DOF map: either the DOF mapping vector (Matrix Market array of node numbers: with
  ``k = n / len`` DOFs per node, matrix rows ``k (j - 1) + 1 .. k j`` are components 1..k of the
  j-th entry) or the ``.mapping`` file that ``HBMAT, ..., Mapping=YES`` writes beside the matrix
  (a header line, then ``equation node label`` per matrix row, labels ``UX UY UZ ROTX ROTY
  ROTZ``).
- Nodes: a table ``node x y z`` (tab, semicolon, comma or blank separated, header lines in any
  language, decimal commas as written by a German ANSYS), also the ``NWRITE`` node file (fixed
  columns that may touch, trailing zero coordinates left out) and ``NLIST`` listings (page
  headers, rotation angles after the coordinates)."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..errors import InputError
from ._text import number, read_mm, text_lines
from .model import FEModel, make_model

#: DOF labels of the HBMAT mapping file -> component.
LABELS = {"UX": 1, "UY": 2, "UZ": 3, "ROTX": 4, "ROTY": 5, "ROTZ": 6}
_WORD = re.compile(r"[^\W\d_]{2,}")        # two letters: a word, never part of a number
_REAL = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?")


def _fields(s: str):
    if ";" in s:
        return [p for p in s.split(";") if p.strip()]
    if "," in s and "." in s:
        return [p for p in s.split(",") if p.strip()]
    if "," in s:                      # decimal commas, blank (or tab) separated
        return s.split()
    tokens = s.split()
    if all(_REAL.fullmatch(t) for t in tokens):
        return tokens
    touching = _REAL.findall(s)       # NWRITE's fixed columns: "1-0.25E-01-0.5" has no blanks
    return touching if "".join(touching) == "".join(tokens) else tokens


def read_nodes_table(path: Path, field: str):
    ids, xyz = [], []
    for lineno, line in text_lines(path, field):
        s = line.strip()
        if not s or not (s[0].isdigit() or s[0] in "+-") or _WORD.search(s):
            continue                  # header lines in any language, NLIST page headers
        parts = _fields(s)
        try:
            node = int(parts[0])
            c = [number(p) for p in parts[1:]]
            if len(c) > 6:
                raise ValueError
        except (ValueError, IndexError):
            raise InputError(f"{field}: {path}:{lineno}: expected 'node x y z' (trailing zero "
                             f"coordinates may be left out), got {s!r}") from None
        ids.append(node)
        xyz.append((c + [0.0, 0.0, 0.0])[:3])
    if not ids:
        raise InputError(f"{field}: {path}: no node lines")
    return np.array(ids, dtype=np.int64), np.array(xyz, dtype=float)


def read_mapping(path: Path, n: int, field: str):
    """The HBMAT ``.mapping`` file: ``(dof_node, dof_comp)`` of matrix rows 1..n."""
    rows = {}
    for lineno, line in text_lines(path, field):
        parts = line.split()
        if not parts or not parts[0].lstrip("+-").isdigit():
            continue                  # the header "Matrix Eqn  Node  DOF"
        try:
            eq, node, label = int(parts[0]), int(parts[1]), parts[2].upper()
            if len(parts) != 3:
                raise ValueError
        except (ValueError, IndexError):
            raise InputError(f"{field}: {path}:{lineno}: expected 'equation node DOF', got "
                             f"{line.strip()!r}") from None
        if label not in LABELS:
            raise InputError(f"{field}: {path}:{lineno}: DOF {label}: only {', '.join(LABELS)} "
                             "are supported")
        if not 1 <= eq <= n or eq in rows:
            raise InputError(f"{field}: {path}:{lineno}: equation {eq} is "
                             f"{'given twice' if eq in rows else 'outside'} the {n} rows of "
                             "the matrices")
        rows[eq] = (node, LABELS[label])
    if len(rows) != n:
        raise InputError(f"{field}: {path} maps {len(rows)} equations but the matrices are "
                         f"{n} x {n}")
    a = np.array([rows[k] for k in range(1, n + 1)], dtype=np.int64).reshape(-1, 2)
    return a[:, 0], a[:, 1]


def _is_matrix_market(path: Path, field: str) -> bool:
    for _, line in text_lines(path, field):
        if line.strip():
            return line.lstrip().lower().startswith("%%matrixmarket")
    return False


def read(files: dict) -> FEModel:
    K = read_mm(files["stiffness"], "blade.files.stiffness")
    M = read_mm(files["mass"], "blade.files.mass")
    n = K.shape[0]
    if not _is_matrix_market(files["dof_map"], "blade.files.dof_map"):
        dof_node, dof_comp = read_mapping(files["dof_map"], n, "blade.files.dof_map")
    else:
        nodes = read_mm(files["dof_map"], "blade.files.dof_map", vector=True)
        if not np.all(nodes == np.round(nodes)) or len(nodes) == 0:
            raise InputError(f"blade.files.dof_map: {files['dof_map']}: node numbers must be "
                             "integers")
        per, rem = divmod(n, len(nodes))
        if rem or not 1 <= per <= 6:
            raise InputError(f"blade.files.dof_map: {files['dof_map']} has {len(nodes)} "
                             f"entries, which does not match the {n} x {n} matrices (1 to 6 "
                             "DOFs per entry)")
        dof_node = np.repeat(nodes.astype(np.int64), per)
        dof_comp = np.tile(np.arange(1, per + 1), len(nodes))
    node_ids, xyz = read_nodes_table(files["nodes"], "blade.files.nodes")
    return make_model(K, M, dof_node, dof_comp, node_ids, xyz,
                      where=f"blade.files ({files['stiffness']}, {files['dof_map']})")
