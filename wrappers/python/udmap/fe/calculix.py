"""CalculiX: ``.sti``, ``.mas`` (``row col value``, upper triangle, rows of the free DOFs),
``.dof`` (one ``node.component`` per row) from ``*FREQUENCY, SOLVER=MATRIXSTORAGE``, and the
deck (``.inp``, with its ``*INCLUDE`` files) for the node coordinates. Constrained DOFs are
already removed by CalculiX.

Shell, beam and plane elements (``S*``, ``B3*``, ``CPS*``, ``CPE*``, ``CAX*``, ``M3D*``) are
expanded by CalculiX into 3D solids before it assembles: each node of such an element becomes
two or three nodes through the thickness (eight around a beam), and the ``.dof`` file gives the
original node's id for every one of them. Where the expanded nodes lie (offsets along the
normals CalculiX averages and corrects internally, knots where they differ) is not in the
export, so their rows cannot be mapped exactly: such a model is refused with the reason and
what to export instead (the blade meshed with solid elements)."""
from __future__ import annotations

import numpy as np

from ..errors import InputError
from ._deck import element_types, parse_deck_nodes
from ._text import read_triplets, symmetric_from_triplets, text_lines
from .model import FEModel, make_model

#: Element type prefixes CalculiX expands into 3D solids.
EXPANDED = ("S3", "S4", "S6", "S8", "B31", "B32", "CPS", "CPE", "CAX", "M3D")


def read_dof(path, field: str):
    nodes, comps = [], []
    for lineno, line in text_lines(path, field):
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


def _check_expanded(dof_node, dof_comp, files):
    """Refuses a .dof file that lists a (node, component) twice, naming the pair, its rows and,
    when the deck has elements CalculiX expands, why and what to export instead."""
    pairs = dof_node * 8 + dof_comp
    uniq, counts = np.unique(pairs, return_counts=True)
    if len(uniq) == len(pairs):
        return
    k = int(np.argmax(counts > 1))
    node, comp = int(uniq[k] // 8), int(uniq[k] % 8)
    rows = np.flatnonzero(pairs == uniq[k])[:3] + 1
    msg = (f"blade.files.dof: {files['dof']}:{rows[1]}: (node {node}, component {comp}) is "
           f"listed again (rows {', '.join(map(str, rows))})")
    types = element_types(files["inp"], "blade.files.inp")
    shells = sorted(t for t in types if t.startswith(EXPANDED))
    if shells:
        msg += (f": the deck {files['inp']} has {', '.join(shells)} elements, which CalculiX "
                "expands into 3D solids (two or three nodes through the thickness of a "
                "shell, eight around a beam) and exports under the original node's id; where "
                "the expanded nodes lie (along the normals CalculiX averages internally) is not "
                "in the export, so their rows cannot be mapped exactly. Mesh the blade with "
                "solid elements (C3D20R, C3D20, C3D10 or C3D8) and export it again")
    raise InputError(msg)


def read(files: dict) -> FEModel:
    dof_node, dof_comp = read_dof(files["dof"], "blade.files.dof")
    _check_expanded(dof_node, dof_comp, files)
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
