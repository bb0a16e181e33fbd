"""An independent reference for the Platform Centred Reduction tests (plain scipy.sparse).

Rigid platform by transformation (u_i = u_R + theta x (x_i - x_R), rotations equal theta),
gamma_P = theta . a, clamp by deleting DOFs, the excitation node's translations turned so that
one DOF is the displacement along d; full-model eigenfrequencies by eigsh in shift-invert mode and
receptances by a direct sparse solve.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla


def _basis(v):
    """Orthonormal (v, p, q), right-handed, v unit."""
    v = np.asarray(v, float) / np.linalg.norm(v)
    t = np.eye(3)[np.argmin(abs(v))]
    p = np.cross(v, t)
    p /= np.linalg.norm(p)
    return np.column_stack([v, p, np.cross(v, p)])


@dataclass
class Rigid:
    T: sp.csr_matrix          # full DOFs (n) x kept coordinates
    gamma: int                # 0-based coordinate of gamma_P
    rigid: np.ndarray         # the six rigid coordinates (u_R, gamma, two other rotations)
    exc: int                  # coordinate of u_E (displacement of the node along d)
    K: sp.csr_matrix = field(default=None)
    M: sp.csr_matrix = field(default=None)


def rigid_platform(fe, platform_nodes, ref_point, axis, exc_node, exc_direction,
                   clamp_nodes=()) -> Rigid:
    n = fe.n
    xyz = dict(zip(fe.node_ids.tolist(), fe.node_xyz))
    plat, clamp = set(int(i) for i in platform_nodes), set(int(i) for i in (clamp_nodes or ()))
    B = _basis(axis)
    D = _basis(exc_direction)
    rows, cols, vals = [], [], []
    ncoord = 0
    free_of = {}
    exc_cols = None
    for k, (node, comp) in enumerate(zip(fe.dof_node.tolist(), fe.dof_comp.tolist())):
        if node in clamp or node in plat:
            continue
        if node == exc_node and comp <= 3:
            if exc_cols is None:
                exc_cols = [ncoord, ncoord + 1, ncoord + 2]
                ncoord += 3
            for m in range(3):
                rows.append(k), cols.append(exc_cols[m]), vals.append(D[comp - 1, m])
            continue
        free_of[k] = ncoord
        rows.append(k), cols.append(ncoord), vals.append(1.0)
        ncoord += 1
    r0 = ncoord
    xr = np.asarray(ref_point, float)
    for k, (node, comp) in enumerate(zip(fe.dof_node.tolist(), fe.dof_comp.tolist())):
        if node not in plat:
            continue
        if comp <= 3:
            rows.append(k), cols.append(r0 + comp - 1), vals.append(1.0)
            r = xyz[node] - xr
            for m in range(3):
                rows.append(k), cols.append(r0 + 3 + m), vals.append(np.cross(B[:, m], r)[comp - 1])
        else:
            for m in range(3):
                rows.append(k), cols.append(r0 + 3 + m), vals.append(B[comp - 4, m])
    T = sp.csr_matrix((vals, (rows, cols)), shape=(n, r0 + 6))
    T.eliminate_zeros()
    rig = Rigid(T, r0 + 3, np.arange(r0, r0 + 6), exc_cols[0])
    rig.K = sp.csr_matrix(T.T @ fe.K @ T)
    rig.M = sp.csr_matrix(T.T @ fe.M @ T)
    return rig


def frequencies(K, M, f_top, k=None):
    """Eigenfrequencies [Hz] of the sparse pencil up to f_top (shift-invert about a small
    negative shift, so free rigid-body modes are fine), ascending."""
    n = K.shape[0]
    sigma = -1e-3 * (2 * np.pi * f_top) ** 2 * 1e-4
    k = k or 12
    while True:
        k = min(k, n - 2)
        w = sla.eigsh(K.tocsc(), k=k, M=M.tocsc(), sigma=sigma, which="LM",
                      return_eigenvectors=False, tol=1e-13)
        f = np.sqrt(np.clip(np.sort(w), 0, None)) / (2 * np.pi)
        if f[-1] > f_top or k >= n - 2:
            return f[f <= f_top]
        k *= 2


def solve(K, M, beta, freq, rhs):
    """Direct sparse solve of (K (1 + i omega beta) - omega^2 M) u = rhs."""
    w = 2 * np.pi * freq
    Z = (K * (1 + 1j * w * beta) - w * w * M).tocsc()
    return sla.spsolve(Z, np.asarray(rhs, dtype=complex))
