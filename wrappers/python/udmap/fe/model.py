"""The finite element model every reader returns (PHYSICS.md 1.3)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..errors import InputError

#: Component names 1..6 (translations, then rotations).
COMPONENTS = ("UX", "UY", "UZ", "RX", "RY", "RZ")


@dataclass
class FEModel:
    """Sparse ``K``, ``M`` (full symmetric storage, SI units), the map from every row to
    ``(dof_node[i], dof_comp[i])`` with components 1..6, and the node coordinates. Internal
    nodes that the FE code numbers itself (Abaqus numbers them negative) have no coordinates:
    their rows of ``node_xyz`` are NaN; they may carry DOFs anywhere except on the platform, at
    the excitation or in a gauge (:meth:`internal`)."""
    K: sp.csr_matrix
    M: sp.csr_matrix
    dof_node: np.ndarray   # int64 (n,)
    dof_comp: np.ndarray   # int64 (n,), 1..6
    node_ids: np.ndarray   # int64 (m,)
    node_xyz: np.ndarray   # float64 (m, 3)

    @property
    def n(self) -> int:
        return self.K.shape[0]

    def node_index(self) -> dict:
        """Node id -> row of ``node_ids`` / ``node_xyz``."""
        return {int(i): k for k, i in enumerate(self.node_ids)}

    def dof_index(self) -> dict:
        """(node id, component) -> 0-based matrix row."""
        return {(int(a), int(c)): k for k, (a, c) in enumerate(zip(self.dof_node, self.dof_comp))}

    def coords(self, node: int) -> np.ndarray:
        return self.node_xyz[self.node_index()[int(node)]]

    def internal(self) -> set:
        """Ids of the nodes without coordinates (internal nodes of the FE code)."""
        return set(self.node_ids[np.isnan(self.node_xyz).any(axis=1)].tolist())


def make_model(K, M, dof_node, dof_comp, node_ids, node_xyz, *, where: str) -> FEModel:
    """Builds an :class:`FEModel`, checking the sizes (``where`` names the files in errors)."""
    K, M = sp.csr_matrix(K, dtype=float), sp.csr_matrix(M, dtype=float)
    dof_node = np.asarray(dof_node, dtype=np.int64).ravel()
    dof_comp = np.asarray(dof_comp, dtype=np.int64).ravel()
    node_ids = np.asarray(node_ids, dtype=np.int64).ravel()
    node_xyz = np.asarray(node_xyz, dtype=float).reshape(-1, 3)
    if K.shape[0] != K.shape[1] or M.shape[0] != M.shape[1]:
        raise InputError(f"{where}: K {K.shape} and M {M.shape} must be square")
    if K.shape != M.shape:
        raise InputError(f"{where}: K is {K.shape[0]} x {K.shape[1]} but M is "
                         f"{M.shape[0]} x {M.shape[1]}")
    n = K.shape[0]
    if len(dof_node) != n or len(dof_comp) != n:
        raise InputError(f"{where}: the DOF map has {len(dof_node)} rows but the matrices are "
                         f"{n} x {n}")
    if len(node_ids) != len(node_xyz):
        raise InputError(f"{where}: {len(node_ids)} node ids but {len(node_xyz)} coordinates")
    uniq, counts = np.unique(node_ids, return_counts=True)
    if len(uniq) != len(node_ids):
        raise InputError(f"{where}: node {int(uniq[np.argmax(counts > 1)])} is given twice in "
                         "the node coordinates")
    if n and (dof_comp.min() < 1 or dof_comp.max() > 6):
        raise InputError(f"{where}: DOF components must be 1..6")
    pairs = dof_node * 8 + dof_comp
    uniq, counts = np.unique(pairs, return_counts=True)
    if len(uniq) != n:
        k = int(np.argmax(counts > 1))
        rows = np.flatnonzero(pairs == uniq[k])[:3] + 1
        raise InputError(f"{where}: the DOF map lists (node {int(uniq[k] // 8)}, component "
                         f"{int(uniq[k] % 8)}) twice (rows {', '.join(map(str, rows))})")
    if not np.all(np.isfinite(node_xyz)):
        raise InputError(f"{where}: non-finite node coordinates")
    missing = np.setdiff1d(dof_node, node_ids)
    if np.any(missing >= 0):
        raise InputError(f"{where}: the DOF map refers to node {int(missing[missing >= 0][0])}, "
                         "which has no coordinates")
    if len(missing):   # internal nodes numbered negative by the FE code (Abaqus): no coordinates
        node_ids = np.concatenate([node_ids, missing])
        node_xyz = np.vstack([node_xyz, np.full((len(missing), 3), np.nan)])
    if not (np.all(np.isfinite(K.data)) and np.all(np.isfinite(M.data))):
        raise InputError(f"{where}: non-finite values in the matrices")
    K.sort_indices()
    M.sort_indices()
    return FEModel(K, M, dof_node, dof_comp, node_ids, node_xyz)


def convert_units(fe: FEModel, units: str) -> FEModel:
    """Converts a model in ``units`` to SI. ``mm-t-s``: lengths mm, mass t, force N, so a
    translation scales by 1e-3 and a moment by 1e-3: ``A_SI[i, j] = A[i, j] c_i / s_j`` with
    ``c`` the force factor of row ``i`` and ``s`` the displacement factor of column ``j``."""
    if units == "SI":
        return fe
    if units != "mm-t-s":
        raise AssertionError(units)
    rot = fe.dof_comp > 3
    c = np.where(rot, 1e-3, 1.0)     # N -> N, N mm -> N m
    s = np.where(rot, 1.0, 1e-3)     # mm -> m, rad -> rad
    scale = sp.diags(c) @ fe.K @ sp.diags(1 / s)
    mscale = sp.diags(c) @ fe.M @ sp.diags(1 / s)
    return FEModel(sp.csr_matrix(scale), sp.csr_matrix(mscale), fe.dof_node, fe.dof_comp,
                   fe.node_ids, fe.node_xyz * 1e-3)
