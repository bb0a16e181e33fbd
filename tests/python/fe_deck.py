"""A small hex8 blade for the tests: CalculiX deck and an independent numpy assembly.

The blade stands along z and bends in x: a neck column, a platform slab and an airfoil plate,
all axis-aligned boxes of one structured grid of spacing ``h``. The root face z = 0 is the clamp.
The numpy assembly (trilinear C3D8, 2x2x2 Gauss points, consistent mass) is the textbook element
that CalculiX's C3D8 is, so the matrices CalculiX exports must equal it to rounding.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import scipy.sparse as sp

E, NU, RHO = 2.0e11, 0.3, 7800.0


@dataclass
class Deck:
    node_ids: np.ndarray      # (m,)
    xyz: np.ndarray           # (m, 3)
    elements: np.ndarray      # (e, 8) node ids, CalculiX order
    h: float
    clamp: list               # node ids on z = 0
    platform: list            # node ids of the platform slab
    platform_z: tuple         # (z0, z1) of the slab
    ref_point: list           # platform centre
    exc_node: int             # airfoil node at mid-height, on the x+ face
    gauge: tuple              # two nodes on the airfoil's x+ face above the platform


def make_deck(h=0.004, neck=(0.016, 0.016, 0.016), slab=(0.032, 0.024, 0.004),
              airfoil=(0.008, 0.016, 0.048)) -> Deck:
    """Neck (bx, by, L), platform slab (bx, by, t) and airfoil plate (bx, by, L), centred on z."""
    def n(v):
        k = round(v / h)
        assert abs(k * h - v) < 1e-12, "dimensions must be multiples of h"
        return k
    zn, zs, za = n(neck[2]), n(slab[2]), n(airfoil[2])
    for b in (*neck[:2], *slab[:2], *airfoil[:2]):
        assert n(b) % 2 == 0, "widths must be even multiples of h (centred sections)"
    cells = []
    for k in range(zn + zs + za):
        bx, by = (neck if k < zn else slab if k < zn + zs else airfoil)[:2]
        ix, iy = n(bx) // 2, n(by) // 2
        for i in range(-ix, ix):
            for j in range(-iy, iy):
                cells.append((i, j, k))
    ids = {}

    def node(i, j, k):
        key = (i, j, k)
        if key not in ids:
            ids[key] = len(ids) + 1
        return ids[key]
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    elements = np.array([[node(i + a, j + b, k + c) for a, b, c in corners] for i, j, k in cells])
    keys = sorted(ids, key=ids.get)
    xyz = np.array(keys, dtype=float) * h
    node_ids = np.arange(1, len(keys) + 1)
    z0, z1 = zn * h, (zn + zs) * h
    clamp = [int(i) for i, p in zip(node_ids, xyz) if abs(p[2]) < 1e-12]
    platform = [int(i) for i, p in zip(node_ids, xyz) if z0 - 1e-12 <= p[2] <= z1 + 1e-12]
    zm = z1 + round(za / 2) * h
    xa = airfoil[0] / 2
    exc = ids[(round(xa / h), 0, round(zm / h))]
    g = (ids[(round(xa / h), 0, zn + zs + 1)], ids[(round(xa / h), 0, zn + zs + 3)])
    return Deck(node_ids, xyz, elements, h, clamp, platform, (z0, z1),
                [0.0, 0.0, (z0 + z1) / 2], exc, g)


def _hex8_matrices(a, b, c, E=E, nu=NU, rho=RHO):
    """Stiffness and consistent mass (24 x 24, DOFs node-major) of an a x b x c brick."""
    nat = np.array([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                    (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)], dtype=float)
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    D = np.zeros((6, 6))
    D[:3, :3] = lam
    D[np.arange(3), np.arange(3)] += 2 * mu
    D[3:, 3:] = np.eye(3) * mu
    jac = np.array([a / 2, b / 2, c / 2])
    detj = np.prod(jac)
    g = 1 / np.sqrt(3)
    K = np.zeros((24, 24))
    Mn = np.zeros((8, 8))
    for xi, eta, zeta in itertools.product((-g, g), repeat=3):
        p = np.array([xi, eta, zeta])
        N = np.prod(1 + nat * p, axis=1) / 8
        dN = np.empty((8, 3))
        for d in range(3):
            q = (1 + nat * p)
            q[:, d] = nat[:, d]
            dN[:, d] = np.prod(q, axis=1) / 8 / jac[d]
        B = np.zeros((6, 24))
        for i in range(8):
            B[0, 3 * i], B[1, 3 * i + 1], B[2, 3 * i + 2] = dN[i]
            B[3, 3 * i], B[3, 3 * i + 1] = dN[i, 1], dN[i, 0]
            B[4, 3 * i + 1], B[4, 3 * i + 2] = dN[i, 2], dN[i, 1]
            B[5, 3 * i], B[5, 3 * i + 2] = dN[i, 2], dN[i, 0]
        K += B.T @ D @ B * detj
        Mn += rho * np.outer(N, N) * detj
    M = np.kron(Mn, np.eye(3))
    return K, M


def assemble(deck: Deck, E=E, nu=NU, rho=RHO):
    """Free (unclamped) sparse K, M of the deck; DOF 3 (i - 1) + c is node i, component c."""
    Ke, Me = _hex8_matrices(deck.h, deck.h, deck.h, E, nu, rho)
    dofs = (3 * (deck.elements[:, :, None] - 1) + np.arange(3)).reshape(len(deck.elements), 24)
    rows = np.repeat(dofs, 24, axis=1).ravel()
    cols = np.tile(dofs, (1, 24)).ravel()
    n = 3 * len(deck.node_ids)
    K = sp.coo_matrix((np.tile(Ke.ravel(), len(dofs)), (rows, cols)), shape=(n, n)).tocsr()
    M = sp.coo_matrix((np.tile(Me.ravel(), len(dofs)), (rows, cols)), shape=(n, n)).tocsr()
    return K, M


def write_inp(deck: Deck, path: Path, step: str, extra_nodes=(), extra: str = "",
              clamp=True, E=E, rho=RHO) -> None:
    """A CalculiX deck: mesh, material, the clamp and then ``extra`` and the ``step`` text."""
    lines = ["*HEADING", "udmap test blade", "*NODE, NSET=NALL"]
    lines += [f"{i}, {x:.17g}, {y:.17g}, {z:.17g}" for i, (x, y, z) in zip(deck.node_ids, deck.xyz)]
    lines += [f"{i}, {x:.17g}, {y:.17g}, {z:.17g}" for i, (x, y, z) in extra_nodes]
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=EALL")
    lines += [", ".join(str(v) for v in [k + 1, *e]) for k, e in enumerate(deck.elements)]
    lines += ["*NSET, NSET=PLAT"] + [str(i) for i in deck.platform]
    lines += ["*NSET, NSET=ROOT"] + [str(i) for i in deck.clamp]
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E!r}, {NU}", "*DENSITY", f"{rho!r}",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL"]
    if clamp:
        lines += ["*BOUNDARY", "ROOT, 1, 3"]
    lines.append(extra.strip())
    lines.append(step.strip())
    Path(path).write_text("\n".join(x for x in lines if x) + "\n")
