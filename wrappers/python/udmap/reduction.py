"""Platform Centred Reduction of a sparse FE blade (PHYSICS.md 1.3, paper section 2.1) over the
kernel's C API (udmap_reduce): rigid platform by transformation, optional clamp, Craig-Bampton
onto the platform's six rigid DOFs (gamma_P first) and the excitation DOF u_E, with static
constraint modes, fixed-interface modes (ARPACK shift-invert on a MUMPS factorisation) and
residual vectors; stress rows reduced as s_r = V^T T^T s.
"""
from __future__ import annotations

import ctypes
import time
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from . import _capi
from ._capi import ErrorHandle
from .errors import InputError

__all__ = ["Reduced", "platform_centred_reduction", "DEFAULT_RESIDUAL_BLOCKS",
           "TRANSLATION_DOFS", "platform_frame", "platform_rows", "in_platform_frame"]

#: Blocks of residual (Krylov) vectors added to the fixed-interface modes by default: they
#: carry the inertia of the modes left out, which brings the band to 1e-6 and below.
DEFAULT_RESIDUAL_BLOCKS = 3

_vp = ctypes.c_void_p
_ci = ctypes.c_int

#: The reduced DOFs (1-based) of the platform's rigid translation at the reference point,
#: u_Rx, u_Ry, u_Rz in the model's axes (the boundary DOFs are gamma_P, theta_b, theta_c, u_R,
#: u_E, in this order, kernel/src/blade/reduce/rigid_platform.f90).
TRANSLATION_DOFS = (4, 5, 6)

_INFO_KEYS = ("f_cut", "f_check", "cut_count", "cut_found", "full_count", "full_found", "n_t",
              "n_i", "factor_entries", "n_residual")
_TIME_KEYS = ("transform", "factor_static", "modes", "projection", "full_check")


@dataclass
class Reduced:
    """The reduced model: dense M, K (r x r), gamma_dof, exc_dof (1-based), the first reduced
    stress row stress_K (or None) and all of them in ``stress`` (n_stress x r), eigenfrequencies
    [Hz] of the full model with the rigid platform in [0, 3 f_max] and of the reduced model in
    the same band (all r in info["freqs_reduced_all"]), and ``info``."""

    M: np.ndarray
    K: np.ndarray
    gamma_dof: int
    exc_dof: int
    stress_K: "np.ndarray | None"
    freqs_full: np.ndarray
    freqs_reduced: np.ndarray
    info: dict = field(default_factory=dict)
    stress: "np.ndarray | None" = None
    #: DOFs (1-based) of the platform's circumferential and radial translations, when the
    #: model is in the platform's frame (:func:`in_platform_frame`).
    u_dof: "int | None" = None
    v_dof: "int | None" = None


def _ints(a, name):
    a = np.asarray(a)
    if a.size and (not np.issubdtype(a.dtype, np.integer)):
        if not np.all(np.isfinite(a)) or np.any(a != np.round(a)):
            raise InputError(f"{name}: node ids must be integers")
    a = a.astype(np.int64).ravel()
    if a.size and (a.min() < -2**31 or a.max() > 2**31 - 1):
        raise InputError(f"{name}: node ids must fit in 32 bits")
    return np.ascontiguousarray(a, dtype=np.int32)


def _vec3(v, name):
    try:
        a = np.asarray(v, dtype=np.float64).ravel()
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be three numbers") from None
    if a.size != 3 or not np.all(np.isfinite(a)):
        raise InputError(f"{name}: must be three finite numbers")
    return np.ascontiguousarray(a)


def _lower(A, name, n):
    if not sp.issparse(A):
        raise InputError(f"{name}: must be a scipy.sparse matrix")
    if A.shape != (n, n):
        raise InputError(f"{name}: shape {A.shape} does not match the {n} rows of the DOF map")
    A = sp.csr_matrix(A, dtype=np.float64)
    scale = abs(A).max() if A.nnz else 0.0
    if not np.all(np.isfinite(A.data)):
        raise InputError(f"{name}: a value is not finite")
    if scale == 0:
        raise InputError(f"{name}: the matrix is zero")
    asym = abs(A - A.T).max()
    if asym > 1e-10 * scale:
        raise InputError(f"{name}: the matrix is not symmetric (max |A - A^T| = {asym:.3g}, "
                         f"max |A| = {scale:.3g})")
    L = sp.tril(A, format="coo")
    return (np.ascontiguousarray(L.row + 1, dtype=np.int32),
            np.ascontiguousarray(L.col + 1, dtype=np.int32),
            np.ascontiguousarray(L.data, dtype=np.float64))


def _ptr(a):
    return a.ctypes.data_as(_vp) if a is not None and a.size else None


def platform_centred_reduction(fe, *, platform_nodes, ref_point, axis, exc_node, exc_direction,
                               clamp_nodes=None, stress_rows=None, n_modes=None, f_max=None,
                               n_residual=DEFAULT_RESIDUAL_BLOCKS, check_full=True) -> Reduced:
    """Reduces ``fe`` (a udmap.fe.FEModel) with a rigid platform (its node ids, the reference
    point and the unit axis of gamma_P = theta . a, right-hand sense) and the excitation at
    node ``exc_node`` along ``exc_direction``. Fixed-interface modes: ``n_modes``, or all below
    3 ``f_max``. ``stress_rows``: rows over the full DOFs (sigma = s^T u). ``check_full`` (default)
    adds the checks that cost a sparse factorisation each: M positive semi-definite (massless
    DOFs are fine; no eigenvalue below -1e-12 max|M|), and the full
    model (with the rigid platform) solved in [0, 3 f_max] with its inertia count. Bad input
    raises InputError naming the argument; nothing is returned half-made."""
    t_start = time.perf_counter()
    dof_node = np.asarray(fe.dof_node).ravel()
    dof_comp = np.asarray(fe.dof_comp).ravel()
    n = fe.K.shape[0] if sp.issparse(fe.K) else -1
    if n < 1:
        raise InputError("K: must be a non-empty scipy.sparse matrix")
    if dof_node.size != n:
        raise InputError(f"dof_node: {dof_node.size} entries for the {n} rows of K")
    if dof_comp.size != n:
        raise InputError(f"dof_comp: {dof_comp.size} entries for the {n} rows of K")
    node_ids = _ints(fe.node_ids, "node_ids")
    node_xyz = np.ascontiguousarray(np.asarray(fe.node_xyz, dtype=np.float64))
    if node_xyz.shape != (node_ids.size, 3):
        raise InputError(f"node_xyz: shape {node_xyz.shape}, expected ({node_ids.size}, 3)")
    internal = np.isnan(node_xyz).any(axis=1)   # internal nodes of the FE code: no coordinates
    if internal.any():
        on = np.isin(node_ids[internal], np.asarray(platform_nodes if platform_nodes is not None
                                                    else [], dtype=np.int64))
        if on.any():
            raise InputError(f"platform_nodes: node {int(node_ids[internal][on][0])} has no "
                             "coordinates (an internal node of the FE code)")
        node_xyz = np.where(internal[:, None], 0.0, node_xyz)   # only platform nodes' are used
    kr, kc, kv = _lower(fe.K, "K", n)
    mr, mc, mv = _lower(fe.M, "M", n)
    if np.any(mv[mr == mc] < 0):
        raise InputError("M: a diagonal entry is negative (the mass matrix is not positive "
                         "definite, nor semi-definite)")
    platform = _ints(platform_nodes if platform_nodes is not None else [], "platform_nodes")
    if platform.size == 0:
        raise InputError("platform_nodes: the platform set is empty")
    clamp = _ints(clamp_nodes if clamp_nodes is not None else [], "clamp_nodes")
    ref = _vec3(ref_point, "ref_point")
    ax = _vec3(axis, "axis")
    if np.linalg.norm(ax) == 0:
        raise InputError("axis: the axis of gamma_P has zero length")
    d = _vec3(exc_direction, "exc_direction")
    if np.linalg.norm(d) == 0:
        raise InputError("exc_direction: the excitation direction has zero length")
    if stress_rows is None:
        S = np.zeros((0, n))
    else:
        rows = [np.asarray(s.toarray() if sp.issparse(s) else s, dtype=np.float64).ravel()
                for s in stress_rows]
        for k, s in enumerate(rows):
            if s.size != n:
                raise InputError(f"stress_rows: row {k} has {s.size} entries for {n} DOFs")
        S = np.array(rows, dtype=np.float64).reshape(len(rows), n)
    S = np.ascontiguousarray(S)
    nm = -1 if n_modes is None else int(n_modes)
    if n_modes is not None and nm < 0:
        raise InputError("n_modes: must be >= 0")
    fm = 0.0 if f_max is None else float(f_max)
    if f_max is not None and not (np.isfinite(fm) and fm > 0):
        raise InputError("f_max: must be a positive number")
    if n_modes is None and f_max is None:
        raise InputError("n_modes/f_max: give the number of modes or f_max")
    dn = np.ascontiguousarray(_ints(dof_node, "dof_node"))
    dc = np.ascontiguousarray(dof_comp.astype(np.int32))
    t_prep = time.perf_counter() - t_start

    error = ErrorHandle()
    handle = _vp()
    t0 = time.perf_counter()
    error.check(_capi.reduce(error.ptr, n, kv.size, _ptr(kr), _ptr(kc), _ptr(kv), mv.size,
                             _ptr(mr),
                             _ptr(mc), _ptr(mv), _ptr(dn), _ptr(dc), node_ids.size, _ptr(node_ids),
                             _ptr(node_xyz), platform.size, _ptr(platform), _ptr(ref), _ptr(ax),
                             int(exc_node), _ptr(d), clamp.size, _ptr(clamp), S.shape[0], _ptr(S),
                        nm, fm, int(n_residual), 1 if check_full else 0, ctypes.byref(handle)))
    t_kernel = time.perf_counter() - t0
    try:
        r, nmod, ns, nf, g, e = (_ci() for _ in range(6))
        error.check(_capi.reduction_sizes(error.ptr, handle, ctypes.byref(r), ctypes.byref(nmod),
                           ctypes.byref(ns), ctypes.byref(nf), ctypes.byref(g), ctypes.byref(e)))
        r = r.value
        Mr = np.zeros((r, r))
        Kr = np.zeros((r, r))
        Sr = np.zeros((ns.value, r))
        fr = np.zeros(r)
        ff = np.zeros(nf.value)
        error.check(_capi.reduction_get(error.ptr, handle, _ptr(Mr), _ptr(Kr), _ptr(Sr), _ptr(fr),
                                        _ptr(ff)))
        raw = np.zeros(15)
        error.check(_capi.reduction_info(error.ptr, handle, _ptr(raw)))
    finally:
        _capi.delete_reduction(ctypes.byref(handle))
    info = {k: float(v) for k, v in zip(_INFO_KEYS, raw[:10])}
    for k in ("cut_count", "cut_found", "full_count", "full_found", "n_t", "n_i",
              "factor_entries", "n_residual"):
        info[k] = int(info[k])
    info["timings"] = {k: float(v) for k, v in zip(_TIME_KEYS, raw[10:])}
    info["timings"]["kernel"] = t_kernel
    info["timings"]["python_prep"] = t_prep
    info["n_modes"] = nmod.value
    info["r"] = r
    info["inertia_ok"] = (info["cut_count"] == info["cut_found"]
                          and info["full_count"] == info["full_found"])
    info["freqs_reduced_all"] = fr.copy()
    top = info["f_check"]
    in_band = fr[fr <= top * (1 + 1e-9)] if top > 0 else fr
    return Reduced(M=Mr, K=Kr, gamma_dof=g.value, exc_dof=e.value,
                   stress_K=Sr[0].copy() if Sr.shape[0] else None, freqs_full=ff,
                   freqs_reduced=in_band, info=info, stress=Sr if Sr.shape[0] else None)


def platform_frame(axis, tangent) -> np.ndarray:
    """The platform's frame (PHYSICS.md 2.6) as the columns of an orthogonal 3 x 3 matrix:
    the circumferential direction ``t`` (``tangent`` without its component along the axis,
    normalised), the radial ``a x t`` and the axis ``a``."""
    a = _vec3(axis, "axis")
    t = _vec3(tangent, "tangent")
    if np.linalg.norm(a) == 0 or np.linalg.norm(t) == 0:
        raise InputError("axis, tangent: must not be zero")
    a = a / np.linalg.norm(a)
    t = t - (t @ a) * a
    if not np.linalg.norm(t) > 0.5 * np.linalg.norm(_vec3(tangent, "tangent")):
        raise InputError("tangent: must be orthogonal to the axis")
    t = t / np.linalg.norm(t)
    return np.column_stack([t, np.cross(a, t), a])


def platform_rows(r: int, axis, tangent) -> "tuple[np.ndarray, np.ndarray]":
    """The rows (u_row, v_row) of a reduced model of ``r`` DOFs that give the platform's
    circumferential and radial translations, u_P = t . u_R and v_P = (a x t) . u_R."""
    Q = platform_frame(axis, tangent)
    u, v = np.zeros(r), np.zeros(r)
    k = TRANSLATION_DOFS[0] - 1
    u[k:k + 3], v[k:k + 3] = Q[:, 0], Q[:, 1]
    return u, v


def in_platform_frame(red: Reduced, axis, tangent) -> Reduced:
    """The reduced model with its platform translation DOFs turned into the platform's frame
    (:func:`platform_frame`): q = T q', T the identity but for Q on TRANSLATION_DOFS, an exact
    orthogonal change of coordinates (M' = T^T M T, K' = T^T K T, stress rows s' = T^T s). DOF
    4 is then u_P, DOF 5 v_P (u_dof, v_dof), DOF 6 the axial translation."""
    Q = platform_frame(axis, tangent)
    k = slice(TRANSLATION_DOFS[0] - 1, TRANSLATION_DOFS[-1])

    def turned(A):
        A = np.array(A, dtype=np.float64)
        A[:, k] = A[:, k] @ Q
        A[k, :] = Q.T @ A[k, :]
        return (A + A.T) / 2
    stress = None
    if red.stress is not None:
        stress = np.array(red.stress, dtype=np.float64)
        stress[:, k] = stress[:, k] @ Q
    return Reduced(M=turned(red.M), K=turned(red.K), gamma_dof=red.gamma_dof,
                   exc_dof=red.exc_dof,
                   stress_K=stress[0].copy() if stress is not None else None,
                   freqs_full=red.freqs_full, freqs_reduced=red.freqs_reduced,
                   info=dict(red.info), stress=stress, u_dof=TRANSLATION_DOFS[0],
                   v_dof=TRANSLATION_DOFS[1])
