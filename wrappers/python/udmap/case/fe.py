"""The ``fe`` blade of a case: validation, the stress witness and the excitation from the case,
the Platform Centred Reduction cached by the content of its inputs, and the reduced ``matrices``
blade every command then uses (PHYSICS.md 1.3, INTERFACES.md "Finite element blade").

The cache lives in ``$UDMAP_CACHE_DIR`` (default ``$XDG_CACHE_HOME/udmap`` or ``~/.cache/udmap``),
one directory per key: the SHA-256 of the blade section (without ``zeta``, which the reduction
does not use), ``analysis.f_max`` and the bytes of every input file. Directories are written
under a temporary name and renamed, so a cache entry is complete or absent.
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np
import scipy.sparse as sp

from ..errors import InputError, UdmapError
from ..fe import FORMAT_FILES, UNITS, read_fe, read_mm, resolve_files
from ..progress import Progress
from .schema import Field, check_field
from .traveling import check_tangent
from .. import reduction

CACHE_VERSION = "fe-reduction-1"
_NODE_FILE = {"calculix": "inp", "abaqus": "inp", "ansys": "nodes", "nastran": "bdf",
              "matrix_market": "nodes"}
_MASS_FILE = {"calculix": "mas", "abaqus": "mass", "ansys": "mass", "nastran": "pch",
              "matrix_market": "M"}
_FIELDS = ("kind", "format", "files", "units", "platform", "clamp", "excitation", "stress",
           "zeta", "modes", "dmig")


#: The number fields of an ``fe`` blade as rows of the case schema (the coordinates and units
#: come from the FE model: only finiteness, signs and directions are checked here).
FE_FIELDS = {
    "platform.ref_point": Field("vec3", doc="reference point of the platform rotation"),
    "platform.axis": Field("vec3", nonzero=True, doc="axis of gamma_P"),
    "platform.tangent": Field("vec3", nonzero=True,
                              doc="circumferential direction (traveling waves)"),
    "excitation.node": Field("node", doc="node of the excitation"),
    "excitation.direction": Field("vec3", nonzero=True, doc="direction of the excitation"),
    "stress.gauge": Field("node", doc="gauge nodes [a, b]"),
    "stress.E": Field("finite", lo=0.0, open=True, unit="Pa", doc="Young's modulus of the gauge"),
    "zeta": Field("finite", lo=0.0, default=0.0, doc="damping ratio of the first mode"),
    "box": Field("vec3", doc="a corner of a node box"),
    "node": Field("node", doc="a node id of a node set"),
}


def _node_set(path, sec, allow_extra=()):
    if not isinstance(sec, dict):
        raise InputError(f"{path} must be an object with 'nodes' or 'box'")
    for key in sec:
        if key not in ("nodes", "box", *allow_extra):
            raise InputError(f"{path}.{key}: unknown field")
    if ("nodes" in sec) == ("box" in sec):
        raise InputError(f"{path}: give exactly one of 'nodes' (ids) or 'box'")
    if "nodes" in sec:
        nodes = sec["nodes"]
        if not isinstance(nodes, list):
            raise InputError(f"{path}.nodes must be a list of node ids")
        if not nodes:
            raise InputError(f"{path}.nodes is empty: the set needs at least one node")
        return {"nodes": [check_field(f"{path}.nodes[{i}]", v, FE_FIELDS["node"])
                          for i, v in enumerate(nodes)]}
    box = sec["box"]
    if not (isinstance(box, list) and len(box) == 2):
        raise InputError(f"{path}.box must be two corners [[x0, y0, z0], [x1, y1, z1]]")
    b = [check_field(f"{path}.box[{i}]", c, FE_FIELDS["box"]) for i, c in enumerate(box)]
    if any(lo > hi for lo, hi in zip(*b)):
        raise InputError(f"{path}.box: the first corner must be the lower one in x, y and z")
    return {"box": b}


def validate_fe(blade_in: dict, base_dir: Path) -> dict:
    """Checks an ``fe`` blade section without reading the model; returns it normalised (files
    as absolute paths, defaults filled in)."""
    for key in blade_in:
        if key not in _FIELDS:
            raise InputError(f"blade.{key}: unknown field (allowed: {', '.join(_FIELDS)})")
    for key in ("format", "files", "platform", "excitation"):
        if key not in blade_in:
            raise InputError(f"blade.{key}: missing field")
    out = {"kind": "fe", "format": blade_in["format"]}
    out["files"] = {k: str(p) for k, p in resolve_files(blade_in, base_dir).items()}
    out["units"] = blade_in.get("units", "SI")
    if out["units"] not in UNITS:
        raise InputError(f"blade.units must be one of {', '.join(UNITS)}, got "
                         f"{json.dumps(out['units'])}")
    plat = blade_in["platform"]
    if not isinstance(plat, dict):
        raise InputError("blade.platform must be an object")
    for key in ("ref_point", "axis"):
        if key not in plat:
            raise InputError(f"blade.platform.{key}: missing field")
    out["platform"] = _node_set("blade.platform", {k: v for k, v in plat.items()
                                                   if k not in ("ref_point", "axis", "tangent")})
    for key in ("ref_point", "axis"):
        out["platform"][key] = check_field(f"blade.platform.{key}", plat[key],
                                           FE_FIELDS[f"platform.{key}"])
    if plat.get("tangent") is not None:
        t = check_field("blade.platform.tangent", plat["tangent"], FE_FIELDS["platform.tangent"])
        check_tangent(out["platform"]["axis"], t)
        out["platform"]["tangent"] = t
    if "clamp" in blade_in and blade_in["clamp"] is not None:
        out["clamp"] = _node_set("blade.clamp", blade_in["clamp"])
    exc = blade_in["excitation"]
    if not isinstance(exc, dict) or set(exc) != {"node", "direction"}:
        raise InputError("blade.excitation must be {\"node\": id, \"direction\": [x, y, z]}")
    out["excitation"] = {key: check_field(f"blade.excitation.{key}", exc[key],
                                          FE_FIELDS[f"excitation.{key}"])
                         for key in ("node", "direction")}
    if "stress" in blade_in and blade_in["stress"] is not None:
        st = blade_in["stress"]
        if isinstance(st, dict) and set(st) == {"gauge", "E"}:
            g = st["gauge"]
            if not (isinstance(g, list) and len(g) == 2):
                raise InputError("blade.stress.gauge must be two node ids [a, b]")
            g = [check_field(f"blade.stress.gauge[{i}]", v, FE_FIELDS["stress.gauge"])
                 for i, v in enumerate(g)]
            if g[0] == g[1]:
                raise InputError("blade.stress.gauge: the two nodes must differ")
            out["stress"] = {"gauge": g, "E": check_field("blade.stress.E", st["E"],
                                                          FE_FIELDS["stress.E"])}
        elif isinstance(st, dict) and set(st) == {"row"}:
            if not isinstance(st["row"], str) or not st["row"]:
                raise InputError("blade.stress.row must be a file path (string)")
            p = Path(st["row"])
            p = p if p.is_absolute() else base_dir / p
            if not p.is_file():
                raise InputError(f"blade.stress.row: file not found: {p}")
            out["stress"] = {"row": str(p)}
        else:
            raise InputError("blade.stress must be {\"gauge\": [a, b], \"E\": ...} or "
                             "{\"row\": \"file.mtx\"}")
    out["zeta"] = check_field("blade.zeta", blade_in.get("zeta", FE_FIELDS["zeta"].default),
                              FE_FIELDS["zeta"])
    if blade_in.get("modes") is not None:
        m = blade_in["modes"]
        if isinstance(m, bool) or not isinstance(m, int) or m < 1:
            raise InputError(f"blade.modes must be an integer >= 1, got {json.dumps(m)}")
        out["modes"] = m
    if blade_in.get("dmig") is not None:
        if out["format"] != "nastran":
            raise InputError("blade.dmig: only for format nastran")
        dm = blade_in["dmig"]
        if not (isinstance(dm, dict) and set(dm) <= {"K", "M"} and
                all(isinstance(v, str) and v for v in dm.values())):
            raise InputError("blade.dmig must be {\"K\": name, \"M\": name} (DMIG names)")
        out["dmig"] = dict(dm)
    return out


# ---------------------------------------------------------------------------------------------
# Inputs of the reduction, checked against the model

def _select(fe, sec, path, where):
    """Node ids of a set (ids or box), each checked to be in the model."""
    known = set(fe.node_ids.tolist())
    if "nodes" in sec:
        for i, node in enumerate(sec["nodes"]):
            if node not in known:
                raise InputError(f"{path}.nodes[{i}]: node {node} is not in the model ({where})")
        return sorted(set(sec["nodes"]))
    (x0, y0, z0), (x1, y1, z1) = sec["box"]
    lo, hi = np.array([x0, y0, z0]), np.array([x1, y1, z1])
    tol = 1e-9 * max(1.0, float(np.nanmax(np.abs(fe.node_xyz))))   # internal nodes: NaN
    inside = np.all((fe.node_xyz >= lo - tol) & (fe.node_xyz <= hi + tol), axis=1)
    nodes = fe.node_ids[inside].tolist()
    # Only nodes that carry DOFs count (unused coordinates of the deck do not).
    nodes = sorted(set(nodes) & set(fe.dof_node.tolist()))
    if not nodes:
        raise InputError(f"{path}.box selects no node of the model ({where})")
    return nodes


def gauge_row(fe, a: int, b: int, E: float) -> sp.csr_matrix:
    """The virtual strain gauge sigma = E ((u_b - u_a) . e) / |x_b - x_a| as a row over the DOFs
    (PHYSICS.md 1.3), e the unit vector from a to b."""
    xa, xb = fe.coords(a), fe.coords(b)
    L = float(np.linalg.norm(xb - xa))
    e = (xb - xa) / L
    idx = fe.dof_index()
    cols, vals = [], []
    for node, sign in ((a, -1.0), (b, 1.0)):
        for c in range(3):
            if e[c] != 0.0 and (node, c + 1) in idx:
                cols.append(idx[(node, c + 1)])
                vals.append(sign * E * e[c] / L)
    return sp.csr_matrix((vals, (np.zeros(len(cols), dtype=int), cols)), shape=(1, fe.n))


def _si(blade: dict) -> dict:
    """The case's lengths (ref_point, boxes) and gauge E in SI (the model is converted on
    reading)."""
    if blade["units"] == "SI":
        return blade
    b = json.loads(json.dumps(blade))
    b["platform"]["ref_point"] = [x * 1e-3 for x in b["platform"]["ref_point"]]
    for key in ("platform", "clamp"):
        if key in b and "box" in b[key]:
            b[key]["box"] = [[x * 1e-3 for x in c] for c in b[key]["box"]]
    if "stress" in b and "E" in b["stress"]:
        b["stress"]["E"] *= 1e6
    return b


def _no_internal(nodes, internal, path, sec, where):
    """Internal nodes of the FE code (no coordinates) cannot be on the platform (its rigid
    motion needs their positions), at the excitation or in a gauge."""
    for node in nodes:
        if node in internal:
            at = path
            if sec is not None and "nodes" in sec and node in sec["nodes"]:
                at = f"{path}[{sec['nodes'].index(node)}]"
            raise InputError(f"{at}: node {node} is an internal node of the FE code, without "
                             f"coordinates ({where}): choose nodes of the mesh")


def reduction_inputs(fe, blade: dict) -> dict:
    """The keyword arguments of ``platform_centred_reduction`` from the case, each checked
    against the model (node ids present, sets not empty, DOFs where they are needed)."""
    fmt, files = blade["format"], blade["files"]
    where = f"nodes of {files[_NODE_FILE[fmt]]}"
    blade = _si(blade)
    has_dof = set(fe.dof_node.tolist())
    plat = _select(fe, blade["platform"], "blade.platform", where)
    internal = fe.internal()
    _no_internal(plat, internal, "blade.platform.nodes", blade["platform"], where)
    for node in plat:
        if node not in has_dof:
            raise InputError(f"blade.platform: node {node} has no DOF in the matrices "
                             f"({files[_MASS_FILE[fmt]]}): constrained platform nodes cannot "
                             "move rigidly")
    clamp = _select(fe, blade["clamp"], "blade.clamp", where) if "clamp" in blade else None
    if clamp and set(clamp) & set(plat):
        raise InputError(f"blade.clamp: node {sorted(set(clamp) & set(plat))[0]} is also a "
                         "platform node")
    exc = blade["excitation"]["node"]
    if exc not in set(fe.node_ids.tolist()):
        raise InputError(f"blade.excitation.node: node {exc} is not in the model ({where})")
    _no_internal([exc], internal, "blade.excitation.node", None, where)
    idx = fe.dof_index()
    if exc in plat or (clamp and exc in clamp) or not all((exc, c) in idx for c in (1, 2, 3)):
        raise InputError(f"blade.excitation.node: node {exc} must be a free node off the "
                         "platform with its three displacements in the matrices")
    d = np.asarray(blade["excitation"]["direction"], float)
    axis = np.asarray(blade["platform"]["axis"], float)
    kw = {"platform_nodes": plat, "ref_point": list(blade["platform"]["ref_point"]),
          "axis": (axis / np.linalg.norm(axis)).tolist(), "exc_node": exc,
          "exc_direction": (d / np.linalg.norm(d)).tolist(), "clamp_nodes": clamp,
          "stress_rows": None}
    st = blade.get("stress")
    if st and "gauge" in st:
        a, b = st["gauge"]
        for i, node in enumerate((a, b)):
            if node not in set(fe.node_ids.tolist()):
                raise InputError(f"blade.stress.gauge[{i}]: node {node} is not in the model "
                                 f"({where})")
            _no_internal([node], internal, f"blade.stress.gauge[{i}]", None, where)
        if not np.linalg.norm(fe.coords(b) - fe.coords(a)) > 0:
            raise InputError("blade.stress.gauge: the two nodes are at the same place")
        kw["stress_rows"] = [gauge_row(fe, a, b, st["E"])]
    elif st and "row" in st:
        row = read_mm(st["row"], "blade.stress.row", vector=True)
        if len(row) != fe.n:
            raise InputError(f"blade.stress.row: {st['row']} has {len(row)} entries but the "
                             f"matrices are {fe.n} x {fe.n}")
        if blade["units"] == "mm-t-s":   # MPa per mm (or per rad) -> Pa per m (or per rad)
            row = row * 1e6 / np.where(fe.dof_comp > 3, 1.0, 1e-3)
        kw["stress_rows"] = [sp.csr_matrix(row.reshape(1, -1))]
    return kw


def check_matrices(fe, blade: dict) -> None:
    """K and M symmetric, M positive semi-definite: no eigenvalue below -MASS_TOL max|M|
    (massless DOFs are valid input, PHYSICS.md 1.3)."""
    files = blade["files"]
    fmt = blade["format"]
    for name, A, fkey in (("stiffness", fe.K, _FILES_K[fmt]), ("mass", fe.M, _MASS_FILE[fmt])):
        big = abs(A).max()
        if not big > 0:
            raise InputError(f"blade.files.{fkey}: the {name} matrix is zero ({files[fkey]})")
        if abs(A - A.T).max() > 1e-10 * big:
            raise InputError(f"blade.files.{fkey}: the {name} matrix is not symmetric "
                             f"({files[fkey]})")
    fkey = _MASS_FILE[fmt]
    d = fe.M.diagonal()
    bad = not np.all(d >= 0)
    if not bad and fe.n <= INERTIA_MAX:
        bad = not semi_definite(fe.M)
    if bad:
        raise InputError(f"blade.files.{fkey}: the mass matrix is not positive definite "
                         f"(nor semi-definite: an eigenvalue below -{MASS_TOL:g} max|M|; "
                         f"{files[fkey]})")


#: Largest model whose mass matrix gets the exact inertia test (a sparse factorisation as costly
#: as the reduction's own); above it, a non-negative diagonal, the kernel's inertia test of
#: M + tau I and a positive semi-definite reduced mass.
INERTIA_MAX = 200_000
#: M may have eigenvalues down to -MASS_TOL max|M| (rounding of a semi-definite M).
MASS_TOL = 1e-12


def semi_definite(M) -> bool:
    """No eigenvalue of M below -MASS_TOL max|M|: Sylvester's inertia of M + tau I,
    tau = MASS_TOL max|M|, from a symmetric-mode sparse LU (pivots on the diagonal, the same
    permutation of rows and columns, so U's diagonal is D of P A P^T = L D L^T)."""
    import scipy.sparse.linalg as sla
    tau = MASS_TOL * abs(M).max()
    A = sp.csc_matrix(M + tau * sp.identity(M.shape[0], format="csc"))
    try:
        lu = sla.splu(A, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                      options={"SymmetricMode": True})
    except RuntimeError:        # exactly singular: an eigenvalue at -tau
        return False
    piv = lu.U.diagonal()
    if not np.array_equal(lu.perm_r, lu.perm_c):
        # SuperLU left the diagonal: fall back to Lanczos on the unit-diagonal scaling.
        Dm = sp.diags(1 / np.sqrt(A.diagonal()))
        try:
            lo = sla.eigsh(sp.csr_matrix(Dm @ A @ Dm), k=1, which="SA", tol=1e-3, ncv=40,
                           maxiter=5000, return_eigenvectors=False)[0]
        except sla.ArpackNoConvergence as exc:
            lo = min(exc.eigenvalues) if len(exc.eigenvalues) else 1.0
        return bool(lo > 0)
    return bool(np.all(piv > 0))


_FILES_K = {"calculix": "sti", "abaqus": "stiffness", "ansys": "stiffness", "nastran": "pch",
            "matrix_market": "K"}


# ---------------------------------------------------------------------------------------------
# Cache

def cache_root() -> Path:
    env = os.environ.get("UDMAP_CACHE_DIR")
    if env:
        return Path(env)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "udmap"


def cache_key(blade: dict, f_max: float) -> str:
    h = hashlib.sha256()
    section = {k: v for k, v in blade.items() if k not in ("zeta",)}
    files = dict(section.pop("files"))
    if "stress" in section and "row" in section["stress"]:
        files["stress.row"] = section["stress"]["row"]
        section["stress"] = {"row": True}
    h.update(json.dumps([CACHE_VERSION, section, float(f_max)], sort_keys=True).encode())
    for key in sorted(files):
        h.update(key.encode())
        with open(files[key], "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                h.update(hashlib.sha256(chunk).digest())
    return h.hexdigest()


def _write_mtx_dense(path: Path, A: np.ndarray) -> None:
    n = A.shape[0]
    jj, ii = np.triu_indices(n)        # column-major lower triangle
    order = np.lexsort((ii, jj))
    with open(path, "w") as f:
        f.write("%%MatrixMarket matrix array real symmetric\n")
        f.write(f"{n} {n}\n")
        np.savetxt(f, A[ii[order], jj[order]], fmt="%.17g")


def _write_mtx_vector(path: Path, v: np.ndarray) -> None:
    with open(path, "w") as f:
        f.write("%%MatrixMarket matrix array real general\n")
        f.write(f"{len(v)} 1\n")
        np.savetxt(f, v, fmt="%.17g")


def write_reduced(directory: Path, red, prefix: str = "") -> dict:
    """Writes the reduced matrices (and stress row) as Matrix Market; returns the file names."""
    names = {"M": f"{prefix}M.mtx", "K": f"{prefix}K.mtx"}
    _write_mtx_dense(directory / names["M"], np.asarray(red.M))
    _write_mtx_dense(directory / names["K"], np.asarray(red.K))
    if red.stress_K is not None:
        names["stress_K"] = f"{prefix}stress_K.mtx"
        _write_mtx_vector(directory / names["stress_K"], np.asarray(red.stress_K).ravel())
    return names


def reduce_fe(blade: dict, f_max: float, *, use_cache: bool = True):
    """Reads and reduces an ``fe`` blade (or takes it from the cache). Returns
    ``(directory, meta)``: the directory holds M.mtx, K.mtx (stress_K.mtx) and ``meta`` has
    ``gamma_dof``, ``exc_dof``, ``freqs_full``, ``freqs_reduced``, ``info``, ``cached``; with
    ``platform.tangent`` also ``u_dof``, ``v_dof`` (see :func:`_in_platform_frame`)."""
    if blade["platform"].get("tangent") is not None:
        return _in_platform_frame(blade, f_max, use_cache)
    key = cache_key(blade, f_max)
    root = cache_root() / "fe"
    final = root / key
    meta_path = final / "reduced.json"
    if use_cache and meta_path.is_file():
        meta = json.loads(meta_path.read_text())
        meta["cached"] = True
        return final, meta
    # Stages of a reduction that can take minutes: read, check, reduce (bar on a terminal).
    with Progress(3, "fe reduction") as bar:
        fe = read_fe(blade, "/")
        bar.update()
        check_matrices(fe, blade)
        kw = reduction_inputs(fe, blade)
        bar.update()
        red = reduction.platform_centred_reduction(fe, n_modes=blade.get("modes"), f_max=f_max,
                                                   **kw)
        bar.update()
    Mr = np.asarray(red.M)
    if not (np.all(np.isfinite(Mr)) and np.all(np.isfinite(np.asarray(red.K)))):
        raise UdmapError("the reduced matrices are not finite")
    # V^T M V is positive semi-definite when M is: checked at any size
    if np.linalg.eigvalsh((Mr + Mr.T) / 2)[0] < -MASS_TOL * abs(Mr).max():
        fkey = _MASS_FILE[blade["format"]]
        raise InputError(f"blade.files.{fkey}: the mass matrix is not positive definite "
                         f"(nor semi-definite: its reduction is not; {blade['files'][fkey]})")
    meta = {"gamma_dof": int(red.gamma_dof), "exc_dof": int(red.exc_dof),
            "freqs_full": [float(x) for x in red.freqs_full],
            "freqs_reduced": [float(x) for x in red.freqs_reduced],
            "n_full": int(fe.n), "n_reduced": int(Mr.shape[0]),
            "info": {k: v for k, v in (red.info or {}).items()
                     if isinstance(v, (int, float, str, bool))}}
    return _store(root, final, red, meta)


def _store(root: Path, final: Path, red, meta: dict):
    """Writes a cache entry (matrices and ``reduced.json``) under a temporary name and renames
    it; returns ``(directory, meta)``."""
    root.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=".tmp-", dir=root))
    try:
        meta["files"] = write_reduced(tmp, red)
        (tmp / "reduced.json").write_text(json.dumps(meta, indent=1))
        try:
            os.replace(tmp, final) if not final.exists() else None
        except OSError:
            pass            # another process wrote the same entry first
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
    if not (final / "reduced.json").is_file():
        raise UdmapError(f"could not write the reduction cache in {root}")
    meta["cached"] = False
    return final, meta


def _in_platform_frame(blade: dict, f_max: float, use_cache: bool):
    """The reduction of a blade with ``platform.tangent`` (PHYSICS.md 2.6): that of the same
    blade without it (cached under the same key), with the platform's translation DOFs turned
    into the frame (tangent, axis x tangent, axis) by an exact orthogonal change of coordinates
    (:func:`udmap.reduction.in_platform_frame`), so that u_P and v_P are DOFs 4 and 5
    (``u_dof``, ``v_dof``); cached under its own key."""
    final = cache_root() / "fe" / cache_key(blade, f_max)
    if use_cache and (final / "reduced.json").is_file():
        meta = json.loads((final / "reduced.json").read_text())
        meta["cached"] = True
        return final, meta
    base = json.loads(json.dumps(blade))
    del base["platform"]["tangent"]
    directory, base_meta = reduce_fe(base, f_max, use_cache=use_cache)
    files = base_meta["files"]
    stress = None
    if "stress_K" in files:
        stress = read_mm(directory / files["stress_K"], "reduced stress_K", vector=True)
        stress = np.asarray(stress, dtype=np.float64).reshape(1, -1)
    red = reduction.Reduced(
        M=read_mm(directory / files["M"], "reduced M").toarray(),
        K=read_mm(directory / files["K"], "reduced K").toarray(),
        gamma_dof=base_meta["gamma_dof"], exc_dof=base_meta["exc_dof"],
        stress_K=None if stress is None else stress[0], freqs_full=np.array([]),
        freqs_reduced=np.array([]), stress=stress)
    framed = reduction.in_platform_frame(red, blade["platform"]["axis"],
                                         blade["platform"]["tangent"])
    meta = {k: v for k, v in base_meta.items() if k not in ("files", "cached")}
    meta["u_dof"], meta["v_dof"] = framed.u_dof, framed.v_dof
    return _store(final.parent, final, framed, meta)


#: Below this share of gamma_P's static flexibility the band's modes do not move the platform.
GAMMA_SHARE_MIN = 1e-8


def check_gamma_moves(directory: Path, meta: dict, f_min: float, f_max: float,
                      axis_file: str) -> None:
    """The platform must make gamma_P move in the band's modes (a rigid-body rotation about an
    axis that they do not excite would leave the damper without work). Judged on the mode
    shapes: the share of gamma_P's static flexibility (K^-1)_gg = sum_r phi_gr^2 / w_r^2 that
    the modes in [f_min, f_max] carry, each with the whole eigenspace of its eigenvalue (a
    repeated pair of a symmetric section, whichever basis of it the solver returns). The
    inverted pencil M z = mu K z (z^T K z = 1, mu = 1/w^2, phi_gr^2 / w_r^2 = z_gr^2) also
    takes a singular reduced M (massless directions: mu = 0)."""
    import scipy.linalg as la
    K = read_mm(directory / meta["files"]["K"], "reduced K").toarray()
    M = read_mm(directory / meta["files"]["M"], "reduced M").toarray()
    try:
        mu, Z = la.eigh(M, K)
    except la.LinAlgError:
        raise UdmapError("the reduced stiffness matrix is not positive definite") from None
    finite = mu > MASS_TOL * mu.max()
    f = np.full(len(mu), np.inf)
    f[finite] = 1 / (2 * np.pi * np.sqrt(mu[finite]))
    band = np.nonzero(finite & (f >= f_min) & (f <= f_max))[0]
    if not len(band):
        return
    space = np.zeros(len(mu), bool)
    for r in band:          # the eigenspace of each band eigenvalue (repeated ones to 1e-6)
        space |= finite & (abs(mu - mu[r]) <= 1e-6 * mu[r])
    z2 = Z[meta["gamma_dof"] - 1] ** 2
    share = float(z2[space].sum() / z2.sum())
    if not share >= GAMMA_SHARE_MIN:
        freqs = ", ".join(f"{x:.6g}" for x in np.sort(f[band]))
        raise InputError(f"blade.platform.axis: the platform rotation gamma_P about this axis "
                         f"does not move in the band's mode(s) at {freqs} Hz (their share of "
                         f"gamma_P's static flexibility is {share:.1e}, "
                         f"below {GAMMA_SHARE_MIN:g}): choose the platform and axis of the "
                         f"rocking that the damper resists ({axis_file})")


def resolve(blade: dict, analysis: dict) -> tuple[dict, dict]:
    """The ``matrices`` blade section of a validated ``fe`` section (reducing it once, cached),
    and a summary of the reduction."""
    directory, meta = reduce_fe(blade, analysis["f_max"])
    check_gamma_moves(directory, meta, analysis["f_min"], analysis["f_max"],
                      blade["files"][_NODE_FILE[blade["format"]]])
    out = {"kind": "matrices", "M": str(directory / meta["files"]["M"]),
           "K": str(directory / meta["files"]["K"]), "gamma_dof": meta["gamma_dof"],
           "exc_dof": meta["exc_dof"], "zeta": blade["zeta"]}
    if "u_dof" in meta:     # platform.tangent given: the frame of the platform
        out["u_dof"], out["v_dof"] = meta["u_dof"], meta["v_dof"]
    if "stress_K" in meta["files"]:
        out["stress_K"] = str(directory / meta["files"]["stress_K"])
    summary = dict(meta)
    summary["cache_dir"] = str(directory)
    summary["source"] = blade
    return out, summary
