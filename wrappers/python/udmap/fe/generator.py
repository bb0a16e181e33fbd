"""A 3D solid blade of chosen size for tests and benchmarks (issue 12, deliverable 6).

Root block, neck, platform slab and airfoil plate, meshed together on one tensor-product grid of
hexahedra (so the parts are conforming), C3D8-equivalent trilinear bricks with 2x2x2 Gauss
points and consistent mass, assembled vectorised (each distinct brick size is integrated once),
so that 10^6 DOFs take seconds. Axes as in PHYSICS.md 2.1: x circumferential, y radial, z axial;
gamma_P turns about z. Proportions follow blade A (cases/blade_a.json): neck 8 x 20 mm, 20 mm
long; platform 26 x 30 mm, 4 mm thick; airfoil 4 mm thick, 30 mm chord, 120 mm long; root
block 20 x 30 x 15 mm, clamped on its bottom face.

``generate_blade(n_dofs)`` gives a ``GeneratedBlade`` (the FEModel with the root face clamped,
i.e. its DOFs removed as CalculiX does, plus the platform, excitation and gauge nodes);
``write_blade(blade, directory)`` writes the CalculiX deck and the Matrix Market form with its
``fe`` case JSON (INTERFACES.md "Finite element blade", format matrix_market).
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import scipy.sparse as sp

from . import FEModel

__all__ = ["GeneratedBlade", "generate_blade", "write_blade", "brick_matrices", "QuadraticMesh",
           "quadratic_mesh", "write_solid_deck"]

MM = 1e-3
#: Part boxes [x0, x1], [y0, y1], [z0, z1] in mm.
PARTS = {
    "root": ((-10, 10), (-15, 0), (-15, 15)),
    "neck": ((-4, 4), (0, 20), (-10, 10)),
    "platform": ((-13, 13), (20, 24), (-15, 15)),
    "airfoil": ((-2, 2), (24, 144), (-15, 15)),
}


@dataclass
class GeneratedBlade:
    """The generated model and its sets (node ids)."""

    fe: FEModel
    platform_nodes: np.ndarray
    root_nodes: np.ndarray
    exc_node: int
    gauge: tuple
    ref_point: np.ndarray
    axis: np.ndarray
    exc_direction: np.ndarray
    E: float
    nu: float
    rho: float
    elements: np.ndarray = field(repr=False)  # (n_el, 8) node ids, C3D8 order
    all_xyz: np.ndarray = field(repr=False)   # (m, 3) every node, ids 1..m

    def gauge_row(self, fe: "FEModel | None" = None) -> np.ndarray:
        """The virtual strain gauge row s (sigma = s^T u, PHYSICS.md 1.3) over the DOFs of
        ``fe`` (default: the blade's own model; the quadratic mesh keeps the gauge's nodes)."""
        fe = self.fe if fe is None else fe
        a, b = self.gauge
        xa, xb = self.all_xyz[a - 1], self.all_xyz[b - 1]
        L = np.linalg.norm(xb - xa)
        e = (xb - xa) / L
        s = np.zeros(fe.K.shape[0])
        for node, sign in ((a, -1.0), (b, 1.0)):
            for c in range(3):
                rows = np.nonzero((fe.dof_node == node) & (fe.dof_comp == c + 1))[0]
                s[rows] += sign * self.E * e[c] / L
        return s


def brick_matrices(size, E, nu, rho):
    """Stiffness and consistent mass (24 x 24) of a rectangular trilinear brick of edge lengths
    size = (a, b, c), 2x2x2 Gauss points (C3D8), DOFs node-major (u1x, u1y, u1z, u2x, ...)."""
    a, b, c = size
    sgn = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    D = np.zeros((6, 6))
    D[:3, :3] = lam
    D[np.arange(3), np.arange(3)] += 2 * mu
    D[3:, 3:] = np.eye(3) * mu
    g = 1 / np.sqrt(3)
    jac = np.array([a / 2, b / 2, c / 2])
    detJ = np.prod(jac)
    Ke = np.zeros((24, 24))
    Me = np.zeros((24, 24))
    for p in sgn * g:
        N = np.prod(1 + sgn * p, axis=1) / 8
        dN = np.empty((8, 3))
        for k in range(3):
            others = [j for j in range(3) if j != k]
            dN[:, k] = sgn[:, k] * np.prod(1 + sgn[:, others] * p[others], axis=1) / 8 / jac[k]
        B = np.zeros((6, 24))
        B[0, 0::3] = dN[:, 0]
        B[1, 1::3] = dN[:, 1]
        B[2, 2::3] = dN[:, 2]
        B[3, 0::3] = dN[:, 1]
        B[3, 1::3] = dN[:, 0]
        B[4, 1::3] = dN[:, 2]
        B[4, 2::3] = dN[:, 1]
        B[5, 0::3] = dN[:, 2]
        B[5, 2::3] = dN[:, 0]
        Ke += B.T @ D @ B * detJ
        NN = np.kron(np.outer(N, N), np.eye(3))
        Me += rho * NN * detJ
    return 0.5 * (Ke + Ke.T), 0.5 * (Me + Me.T)


def _lines(breaks, h):
    """Grid coordinates [mm] through the breakpoints, cells of about h (at least 2 in the
    airfoil's and the platform's thickness)."""
    out = [breaks[0]]
    for x0, x1 in zip(breaks[:-1], breaks[1:]):
        n = max(1, int(round((x1 - x0) / h)))
        if (x0, x1) in ((-2, 2), (20, 24)):
            n = max(n, 2)
        out.extend(np.linspace(x0, x1, n + 1)[1:])
    return np.array(out, dtype=float)


def _grid(h):
    bx = sorted({v for p in PARTS.values() for v in p[0]})
    by = sorted({v for p in PARTS.values() for v in p[1]})
    bz = sorted({v for p in PARTS.values() for v in p[2]})
    gx, gy, gz = _lines(bx, h), _lines(by, h), _lines(bz, h)
    cx, cy, cz = (0.5 * (g[1:] + g[:-1]) for g in (gx, gy, gz))
    X, Y, Z = np.meshgrid(cx, cy, cz, indexing="ij")
    active = np.zeros(X.shape, dtype=bool)
    for (x0, x1), (y0, y1), (z0, z1) in PARTS.values():
        active |= (X > x0) & (X < x1) & (Y > y0) & (Y < y1) & (Z > z0) & (Z < z1)
    return gx, gy, gz, active


def _count_nodes(h):
    gx, gy, gz, active = _grid(h)
    used = np.zeros((gx.size, gy.size, gz.size), dtype=bool)
    i, j, k = np.nonzero(active)
    for di in (0, 1):
        for dj in (0, 1):
            for dk in (0, 1):
                used[i + di, j + dj, k + dk] = True
    return int(used.sum())


def _tree_sum(mats):
    """Sum of sparse matrices pairwise (each entry is copied O(log n) times, not O(n))."""
    while len(mats) > 1:
        mats = [mats[i] + mats[i + 1] if i + 1 < len(mats) else mats[i]
                for i in range(0, len(mats), 2)]
    return mats[0]


def generate_blade(n_dofs: int = 10_000, *, E: float = 170e9, nu: float = 0.3,
                   rho: float = 8200.0) -> GeneratedBlade:
    """A blade with about n_dofs DOFs (after the root clamp), SI units."""
    if n_dofs < 500:
        raise ValueError("n_dofs: at least 500")
    lo, hi = 0.05, 20.0  # element size [mm]: bisection on the node count (monotone in h)
    for _ in range(40):
        h = np.sqrt(lo * hi)
        if 3 * _count_nodes(h) > n_dofs:
            lo = h
        else:
            hi = h
    h = hi if abs(3 * _count_nodes(hi) - n_dofs) < abs(3 * _count_nodes(lo) - n_dofs) else lo
    gx, gy, gz, active = _grid(h)
    nx, ny, nz = gx.size, gy.size, gz.size
    i, j, k = np.nonzero(active)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
               (0, 1, 1)]
    gidx = np.stack([((i + a) * ny + (j + b)) * nz + (k + c) for a, b, c in corners], axis=1)
    used, inverse = np.unique(gidx, return_inverse=True)
    conn = inverse.reshape(gidx.shape)  # 0-based compact node indices
    m = used.size
    ui, rem = np.divmod(used, ny * nz)
    uj, uk = np.divmod(rem, nz)
    xyz = np.stack([gx[ui], gy[uj], gz[uk]], axis=1) * MM
    # Assembly, one integration per distinct brick size.
    sizes = np.stack([gx[i + 1] - gx[i], gy[j + 1] - gy[j], gz[k + 1] - gz[k]], axis=1)
    shapes, group = np.unique(np.round(sizes, 9), axis=0, return_inverse=True)
    group = group.ravel()
    ndof = 3 * m
    Ks, Ms = [], []
    loc = np.arange(3)
    for s, size in enumerate(shapes):
        Ke, Me = brick_matrices(size * MM, E, nu, rho)
        el = conn[group == s]
        for start in range(0, el.shape[0], 20000):
            e = el[start:start + 20000]
            dofs = (3 * e[:, :, None] + loc).reshape(e.shape[0], 24).astype(np.int32)
            rows = np.repeat(dofs, 24, axis=1).ravel()
            cols = np.tile(dofs, (1, 24)).ravel()
            Ks.append(sp.csr_matrix((np.tile(Ke.ravel(), e.shape[0]), (rows, cols)),
                                    shape=(ndof, ndof)))
            Ms.append(sp.csr_matrix((np.tile(Me.ravel(), e.shape[0]), (rows, cols)),
                                    shape=(ndof, ndof)))
    K, M = _tree_sum(Ks), _tree_sum(Ms)
    node_ids = np.arange(1, m + 1, dtype=np.int64)
    tol = 1e-9
    y = xyz[:, 1] / MM
    root = node_ids[np.abs(y - PARTS["root"][1][0]) < tol]
    keep = np.ones(ndof, dtype=bool)
    keep[(3 * (root - 1)[:, None] + loc).ravel()] = False
    free = np.nonzero(keep)[0]
    K = sp.csr_matrix(K[free][:, free])
    M = sp.csr_matrix(M[free][:, free])
    K = 0.5 * (K + K.T)
    M = 0.5 * (M + M.T)
    fe = FEModel(K=sp.csr_matrix(K), M=sp.csr_matrix(M), dof_node=free // 3 + 1,
                 dof_comp=free % 3 + 1, node_ids=node_ids, node_xyz=xyz)
    (px0, px1), (py0, py1), (pz0, pz1) = PARTS["platform"]
    p = xyz / MM
    on_platform = ((p[:, 0] >= px0 - tol) & (p[:, 0] <= px1 + tol) & (p[:, 1] >= py0 - tol)
                   & (p[:, 1] <= py1 + tol) & (p[:, 2] >= pz0 - tol) & (p[:, 2] <= pz1 + tol))

    def nearest(target_mm):
        return int(node_ids[np.argmin(np.linalg.norm(p - np.asarray(target_mm), axis=1))])

    # excitation near the tip on the airfoil's face; gauge along the span on that face
    exc = nearest((2.0, 130.0, 0.0))
    ga = nearest((2.0, 30.0, 0.0))
    gb = nearest((2.0, 40.0, 0.0))
    elements = conn + 1
    return GeneratedBlade(fe=fe, platform_nodes=node_ids[on_platform], root_nodes=root,
                          exc_node=exc, gauge=(ga, gb),
                          ref_point=np.array([0.0, 0.5 * (py0 + py1), 0.0]) * MM,
                          axis=np.array([0.0, 0.0, 1.0]), exc_direction=np.array([1.0, 0, 0]),
                          E=E, nu=nu, rho=rho, elements=elements, all_xyz=xyz)


def _write_mtx(path: Path, A) -> None:
    L = sp.tril(A, format="coo")
    with open(path, "w") as f:
        f.write("%%MatrixMarket matrix coordinate real symmetric\n")
        f.write(f"{A.shape[0]} {A.shape[1]} {L.nnz}\n")
        np.savetxt(f, np.column_stack([L.row + 1, L.col + 1, L.data]),
                   fmt=["%d", "%d", "%.17g"])


def _ccx_real(x) -> str:
    """``x`` in at most 20 characters, the width in which CalculiX reads a real (it cuts a
    longer field, and a cut exponent is an error): the shortest round-trip form, else fewer
    digits."""
    text = repr(float(x))
    digits = 16
    while len(text) > 20:
        text, digits = f"{float(x):.{digits}g}", digits - 1
    return text


def _node_lines(xyz) -> str:
    """*NODE data lines ``id, x, y, z`` for the nodes 1..len(xyz)."""
    return "".join(f"{k}, {_ccx_real(x)}, {_ccx_real(y)}, {_ccx_real(z)}\n"
                   for k, (x, y, z) in enumerate(np.asarray(xyz, dtype=float).tolist(), start=1))


def _idlines(ids, per_line=16):
    ids = list(map(int, ids))
    return "".join(", ".join(map(str, ids[i:i + per_line])) + ",\n"
                   for i in range(0, len(ids), per_line))


def write_blade(blade: GeneratedBlade, directory, *, name: str = "generated_blade",
                f_min: float = 150.0, f_max: float = 230.0, zeta: float = 0.002,
                modes: "int | None" = None) -> dict:
    """Writes blade.inp (CalculiX deck: *NODE, *ELEMENT TYPE=C3D8, *MATERIAL, *BOUNDARY clamp of
    the root face, node sets PLATFORM, EXC, GAUGE, ROOT, a *FREQUENCY step with
    SOLVER=MATRIXSTORAGE), K.mtx, M.mtx, dof_map.csv (row,node,component), nodes.csv
    (node,x,y,z) and case.json (an "fe" case, format matrix_market, with blade A's damper).
    Returns the case dict."""
    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    fe = blade.fe
    xyz = blade.all_xyz
    with open(d / "blade.inp", "w") as f:
        f.write("** udmap generated blade (root block, neck, platform, airfoil), SI units\n")
        f.write("*NODE, NSET=NALL\n")
        f.write(_node_lines(xyz))
        f.write("*ELEMENT, TYPE=C3D8, ELSET=EALL\n")
        np.savetxt(f, np.column_stack([np.arange(1, blade.elements.shape[0] + 1),
                                       blade.elements]), fmt="%d", delimiter=", ")
        f.write("*NSET, NSET=PLATFORM\n" + _idlines(blade.platform_nodes))
        f.write("*NSET, NSET=ROOT\n" + _idlines(blade.root_nodes))
        f.write(f"*NSET, NSET=EXC\n{blade.exc_node},\n")
        f.write(f"*NSET, NSET=GAUGE\n{blade.gauge[0]}, {blade.gauge[1]},\n")
        f.write("*MATERIAL, NAME=BLADE\n*ELASTIC\n"
                f"{blade.E:.17g}, {blade.nu:.17g}\n*DENSITY\n{blade.rho:.17g}\n")
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=BLADE\n")
        f.write("*BOUNDARY\nROOT, 1, 3\n")
        f.write("*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n")
    _write_mtx(d / "K.mtx", fe.K)
    _write_mtx(d / "M.mtx", fe.M)
    n = fe.K.shape[0]
    with open(d / "dof_map.csv", "w") as f:
        f.write("row,node,component\n")
        np.savetxt(f, np.column_stack([np.arange(1, n + 1), fe.dof_node, fe.dof_comp]),
                   fmt="%d", delimiter=",")
    with open(d / "nodes.csv", "w") as f:
        f.write("node,x,y,z\n")
        np.savetxt(f, np.column_stack([fe.node_ids, fe.node_xyz]),
                   fmt=["%d", "%.17g", "%.17g", "%.17g"], delimiter=",")
    blade_a = Path(__file__).resolve().parents[1] / "data" / "blade_a.json"
    damper = json.loads(blade_a.read_text())["damper"] if blade_a.is_file() else None
    case = {
        "name": name,
        "blade": {
            "kind": "fe", "format": "matrix_market",
            "files": {"K": "K.mtx", "M": "M.mtx", "dof_map": "dof_map.csv",
                      "nodes": "nodes.csv"},
            "units": "SI",
            "platform": {"nodes": [int(v) for v in blade.platform_nodes],
                         "ref_point": [float(v) for v in blade.ref_point],
                         "axis": [float(v) for v in blade.axis]},
            "excitation": {"node": int(blade.exc_node),
                           "direction": [float(v) for v in blade.exc_direction]},
            "stress": {"gauge": [int(blade.gauge[0]), int(blade.gauge[1])], "E": blade.E},
            "zeta": zeta,
        },
        "analysis": {"f_min": f_min, "f_max": f_max},
    }
    if modes is not None:
        case["blade"]["modes"] = int(modes)
    if damper is not None:
        case["damper"] = damper
    (d / "case.json").write_text(json.dumps(case, indent=1) + "\n")
    return case


#: The quadratic elements the generator writes: per CalculiX type, the corner count and the
#: corner pairs whose midpoints are the midside nodes, in CalculiX's node order.
QUADRATIC = {
    "C3D20": (8, ((0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
                  (0, 4), (1, 5), (2, 6), (3, 7))),
    "C3D10": (4, ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3))),
    "C3D15": (6, ((0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5))),
}
QUADRATIC["C3D20R"] = QUADRATIC["C3D20"]
#: Corners of a brick (C3D8 order) as lattice offsets.
_BRICK = ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1))
#: A brick as six tetrahedra around its diagonal from corner 0 to corner 6, one per order of
#: the axes (Kuhn's split: conforming on a grid where every brick is split alike); corners
#: ordered for a positive volume.
def _kuhn_tetrahedra() -> tuple:
    corner = {c: k for k, c in enumerate(_BRICK)}
    tets = []
    for order in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        path = [np.zeros(3, dtype=int)]
        for axis in order:                       # along the axes in this order to (1, 1, 1)
            path.append(path[-1] + np.eye(3, dtype=int)[axis])
        if np.linalg.det(np.array(path[1:]) - path[0]) < 0:
            path[1], path[2] = path[2], path[1]
        tets.append(tuple(corner[tuple(int(v) for v in q)] for q in path))
    return tuple(tets)


_KUHN = _kuhn_tetrahedra()
#: A brick as two wedges along z, split by its diagonal face 0-2-6-4 (triangles 0-1-2, 0-2-3
#: at the bottom, counterclockwise seen from the top).
_WEDGES = ((0, 1, 2, 4, 5, 6), (0, 2, 3, 4, 6, 7))


@dataclass
class QuadraticMesh:
    """The generated blade meshed with quadratic solids: bricks (C3D20 or C3D20R), tetrahedra
    (C3D10), or bricks with the airfoil in wedges (C3D15). The corner nodes keep their ids
    1..m (so the excitation and gauge nodes are the blade's), the midside nodes follow; the
    platform and root sets include their midside nodes."""

    xyz: np.ndarray            # (n, 3) every node, ids 1..n
    blocks: list               # [(CalculiX type, (n_el, nodes) node ids in its order)]
    platform_nodes: np.ndarray
    root_nodes: np.ndarray


def quadratic_mesh(blade: GeneratedBlade, shape: str = "brick") -> QuadraticMesh:
    """The blade's brick mesh with quadratic elements: ``shape`` "brick" (20-node bricks),
    "tetra" (each brick as six 10-node tetrahedra) or "mixed" (20-node bricks, the airfoil's
    bricks as two 15-node wedges each; the wedges meet the platform's bricks on whole faces).
    One midside node per distinct edge."""
    el = blade.elements - 1
    if shape == "brick":
        corners = [("C3D20", el)]
    elif shape == "tetra":
        corners = [("C3D10", np.vstack([el[:, list(t)] for t in _KUHN]))]
    elif shape == "mixed":
        y_mid = blade.all_xyz[el, 1].mean(axis=1) / MM
        foil = y_mid > PARTS["airfoil"][1][0]
        corners = [("C3D20", el[~foil]),
                   ("C3D15", np.vstack([el[foil][:, list(w)] for w in _WEDGES]))]
    else:
        raise ValueError("shape: brick, tetra or mixed")
    m = blade.all_xyz.shape[0]
    keys = [np.stack([np.sort(c[:, list(e)], axis=1) for e in QUADRATIC[t][1]], axis=1)
            for t, c in corners]
    flat = np.concatenate([(k[..., 0].astype(np.int64) * m + k[..., 1]).ravel() for k in keys])
    uniq, inverse = np.unique(flat, return_inverse=True)
    a, b = np.divmod(uniq, m)
    xyz = np.vstack([blade.all_xyz, 0.5 * (blade.all_xyz[a] + blade.all_xyz[b])])
    blocks, start = [], 0
    for (t, c), k in zip(corners, keys):
        mid = m + inverse[start:start + k.shape[0] * k.shape[1]].reshape(k.shape[:2])
        start += k.shape[0] * k.shape[1]
        blocks.append((t, np.hstack([c, mid]) + 1))
    ids = np.arange(1, xyz.shape[0] + 1)
    p = xyz / MM
    tol = 1e-9
    (px0, px1), (py0, py1), (pz0, pz1) = PARTS["platform"]
    on_platform = ((p[:, 0] >= px0 - tol) & (p[:, 0] <= px1 + tol) & (p[:, 1] >= py0 - tol)
                   & (p[:, 1] <= py1 + tol) & (p[:, 2] >= pz0 - tol) & (p[:, 2] <= pz1 + tol))
    root = np.abs(p[:, 1] - PARTS["root"][1][0]) < tol
    return QuadraticMesh(xyz=xyz, blocks=blocks, platform_nodes=ids[on_platform],
                         root_nodes=ids[root])


def write_solid_deck(blade: GeneratedBlade, mesh: QuadraticMesh, path, *,
                     brick: str = "C3D20R",
                     step: str = "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP",
                     extra_nodes=(), extra: str = "") -> None:
    """A CalculiX deck of the quadratic mesh: *NODE (plus ``extra_nodes``, (id, xyz) pairs), an
    *ELEMENT block per element type (the bricks as ``brick``, C3D20 or C3D20R), node sets
    PLATFORM and ROOT, the material, the root clamp, then ``extra`` and the ``step`` text."""
    if brick not in ("C3D20", "C3D20R"):
        raise ValueError("brick: C3D20 or C3D20R")
    types = [brick if t == "C3D20" else t for t, _ in mesh.blocks]
    with open(path, "w") as f:
        f.write(f"** udmap generated blade, {', '.join(types)}, SI units\n*NODE, NSET=NALL\n")
        f.write(_node_lines(mesh.xyz))
        for node, x in extra_nodes:
            f.write(f"{int(node)}, " + ", ".join(map(_ccx_real, x)) + "\n")
        k = 0
        for etype, (_, conn) in zip(types, mesh.blocks):
            f.write(f"*ELEMENT, TYPE={etype}, ELSET=EALL\n")
            for e in conn:     # at most 15 numbers a line: the rest on a continuation line
                k += 1
                nums = [str(k)] + [str(v) for v in e]
                f.write(", ".join(nums[:16]) + (",\n" + ", ".join(nums[16:]) if len(nums) > 16
                                                 else "") + "\n")
        f.write("*NSET, NSET=PLATFORM\n" + _idlines(mesh.platform_nodes))
        f.write("*NSET, NSET=ROOT\n" + _idlines(mesh.root_nodes))
        f.write("*MATERIAL, NAME=BLADE\n*ELASTIC\n"
                f"{blade.E:.17g}, {blade.nu:.17g}\n*DENSITY\n{blade.rho:.17g}\n")
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=BLADE\n*BOUNDARY\nROOT, 1, 3\n")
        if extra.strip():
            f.write(extra.strip() + "\n")
        f.write(step.strip() + "\n")
