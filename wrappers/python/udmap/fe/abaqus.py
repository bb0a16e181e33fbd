"""Abaqus: ``*MATRIX GENERATE`` / ``*MATRIX OUTPUT`` files and the ``.inp`` nodes.

Two layouts are read (told apart by the number of values per line):
- labelled (``FORMAT=MATRIX INPUT``): ``row node, row dof, column node, column dof, value``;
  the DOF map is every (node, dof) that occurs, sorted by node and dof;
- coordinate (``FORMAT=COORDINATE``): ``row column value`` over Abaqus' global DOF numbering,
  which for a single part is the nodes in their ``*Node`` order with the same number of DOFs
  (3 for solids, 6 with rotations) at each node.
One triangle or both may be given (Abaqus writes both for the coordinate format). Internal nodes
that Abaqus adds itself (Lagrange multipliers, the extra nodes of some beams and connectors) are
numbered negative and have no coordinates: they may carry DOFs (labelled layout only) anywhere but
on the platform, at the excitation or in a gauge.
"""
from __future__ import annotations

import numpy as np

from ..errors import InputError
from ._deck import parse_deck_nodes
from ._text import symmetric_from_triplets, text_lines
from .model import FEModel, make_model


def _lines(path, field):
    out = []
    for lineno, line in text_lines(path, field):
        s = line.strip()
        if not s or s.startswith("*") or s.startswith("%") or s.startswith("#"):
            continue
        out.append((lineno, [p for p in s.replace(",", " ").split()]))
    if not out:
        raise InputError(f"{field}: {path}: no matrix entries")
    return out


def _parse(path, field):
    lines = _lines(path, field)
    width = len(lines[0][1])
    if width not in (3, 5):
        raise InputError(f"{field}: {path}:{lines[0][0]}: expected 'row col value' or "
                         "'node, dof, node, dof, value'")
    cols = [[] for _ in range(width)]
    for lineno, parts in lines:
        try:
            if len(parts) != width:
                raise ValueError
            for k in range(width - 1):
                cols[k].append(int(parts[k]))
            cols[-1].append(float(parts[-1].replace("D", "E").replace("d", "e")))
        except ValueError:
            raise InputError(f"{field}: {path}:{lineno}: expected {width} numbers, got "
                             f"{' '.join(parts)!r}") from None
    return width, [np.array(c) for c in cols]


def read(files: dict) -> FEModel:
    node_ids, xyz = parse_deck_nodes(files["inp"], "blade.files.inp")
    parsed = {key: _parse(files[key], f"blade.files.{key}") for key in ("stiffness", "mass")}
    widths = {w for w, _ in parsed.values()}
    if len(widths) != 1:
        raise InputError(f"blade.files: {files['stiffness']} and {files['mass']} are not in the "
                         "same format (labelled and coordinate)")
    where = f"blade.files ({files['stiffness']}, {files['inp']})"
    if widths == {5}:
        pairs = np.concatenate([np.column_stack([c[0], c[1]]) for _, c in parsed.values()] +
                               [np.column_stack([c[2], c[3]]) for _, c in parsed.values()])
        pairs = np.unique(pairs, axis=0)   # sorted by node, then dof
        if pairs[:, 1].min() < 1 or pairs[:, 1].max() > 6:
            raise InputError(f"{where}: DOF numbers must be 1..6 (only displacement and "
                             "rotation DOFs are supported)")
        key = {(int(a), int(b)): k + 1 for k, (a, b) in enumerate(pairs)}
        mats = []
        for name, (_, c) in parsed.items():
            r = np.array([key[(int(a), int(b))] for a, b in zip(c[0], c[1])])
            q = np.array([key[(int(a), int(b))] for a, b in zip(c[2], c[3])])
            mats.append(symmetric_from_triplets(r, q, c[4], len(pairs), f"blade.files.{name}"))
        return make_model(mats[0], mats[1], pairs[:, 0], pairs[:, 1], node_ids, xyz,
                          where=where)
    n = max(int(max(c[0].max(), c[1].max())) for _, c in parsed.values())
    per, rem = divmod(n, len(node_ids))
    if rem or per not in (3, 6):
        raise InputError(f"{where}: the coordinate format has {n} DOFs for {len(node_ids)} "
                         "nodes: not 3 or 6 per node (use the labelled format, "
                         "*MATRIX OUTPUT, FORMAT=MATRIX INPUT)")
    mats = [symmetric_from_triplets(c[0], c[1], c[2], n, f"blade.files.{name}")
            for name, (_, c) in parsed.items()]
    return make_model(mats[0], mats[1], np.repeat(node_ids, per),
                      np.tile(np.arange(1, per + 1), len(node_ids)), node_ids, xyz, where=where)
