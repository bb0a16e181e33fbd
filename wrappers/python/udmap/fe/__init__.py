"""Finite element blades (PHYSICS.md 1.3): the model a reader gives, ``FEModel``.

``K``, ``M``: scipy.sparse.csr_matrix, full symmetric storage, SI units; ``dof_node``,
``dof_comp`` (1..6): the node and component of every row; ``node_ids``, ``node_xyz``: the nodes.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

__all__ = ["FEModel"]


@dataclass
class FEModel:
    """A sparse FE model: K, M (n x n, csr, full symmetric), the row map and the nodes."""

    K: sp.csr_matrix
    M: sp.csr_matrix
    dof_node: np.ndarray  # int64 (n,)
    dof_comp: np.ndarray  # int64 (n,), 1..6
    node_ids: np.ndarray  # int64 (m,)
    node_xyz: np.ndarray  # float64 (m, 3)
