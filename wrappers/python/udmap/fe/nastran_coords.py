"""NASTRAN coordinate systems (MSC/NX Quick Reference Guide): ``CORD2R/2C/2S`` (origin ``A``, a
point ``B`` on the z axis and a point ``C`` in the xz plane, given in the system ``RID``),
``CORD1R/1C/1S`` (the same three points as grids, up to two systems a card), rectangular,
cylindrical ``(R, theta, Z)`` and spherical ``(R, theta, phi)`` (angles in degrees). A grid's
``CP`` is the system its coordinates are given in; its ``CD`` the system of its displacement
components: at the grid's position, the axes of a rectangular system, ``(e_R, e_theta, e_Z)``
of a cylindrical and ``(e_R, e_theta, e_phi)`` of a spherical one."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError


@dataclass
class System:
    kind: str              # "R", "C" or "S"
    origin: np.ndarray     # (3,) in basic
    R: np.ndarray          # (3, 3): columns are the system's x, y, z axes in basic

    def to_basic(self, a: np.ndarray) -> np.ndarray:
        """Positions (n, 3) given in this system's coordinates -> basic."""
        a = np.atleast_2d(np.asarray(a, dtype=float))
        if self.kind == "C":
            t = np.radians(a[:, 1])
            loc = np.column_stack([a[:, 0] * np.cos(t), a[:, 0] * np.sin(t), a[:, 2]])
        elif self.kind == "S":
            t, p = np.radians(a[:, 1]), np.radians(a[:, 2])
            loc = a[:, :1] * np.column_stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p),
                                               np.cos(t)])
        else:
            loc = a
        return self.origin + loc @ self.R.T

    def frames(self, x: np.ndarray) -> np.ndarray:
        """(n, 3, 3): the displacement directions (columns, in basic) at basic positions x."""
        x = np.atleast_2d(x)
        if self.kind == "R":
            return np.broadcast_to(self.R, (len(x), 3, 3)).copy()
        v = (x - self.origin) @ self.R
        phi = np.arctan2(v[:, 1], v[:, 0])
        c, s, z, o = np.cos(phi), np.sin(phi), np.zeros(len(x)), np.ones(len(x))
        if self.kind == "C":
            cols = [np.column_stack([c, s, z]), np.column_stack([-s, c, z]),
                    np.column_stack([z, z, o])]
        else:
            th = np.arctan2(np.hypot(v[:, 0], v[:, 1]), v[:, 2])
            ct, st = np.cos(th), np.sin(th)
            cols = [np.column_stack([st * c, st * s, ct]), np.column_stack([ct * c, ct * s, -st]),
                    np.column_stack([-s, c, z])]
        local = np.stack(cols, axis=2)               # (n, 3 components, 3 directions)
        return np.einsum("ij,njk->nik", self.R, local)


def _from_points(kind, a, b, c, where):
    z = b - a
    y = np.cross(z, c - a)
    if not (np.linalg.norm(z) > 0 and np.linalg.norm(y) > 1e-12 * np.linalg.norm(z) *
            max(np.linalg.norm(c - a), 1e-300)):
        raise InputError(f"{where}: the points A, B, C do not define a system (B = A, or C on "
                         "the z axis A-B)")
    z = z / np.linalg.norm(z)
    y = y / np.linalg.norm(y)
    return System(kind, a, np.column_stack([np.cross(y, z), y, z]))


def resolve(cords: list, grids: dict, where: str):
    """Defines every system and puts every grid in the basic system.

    ``cords``: ``(cid, kind, rid or None, values, file:line)`` with ``values`` the nine numbers
    of ``A, B, C`` (CORD2) or ``None`` and ``rid`` the three grid ids (CORD1);
    ``grids``: ``ids, cp, x (in CP), cd, lines`` arrays. Returns ``(xyz in basic, frames)``
    with ``frames`` a dict grid row -> 3x3 (only grids whose CD is not the basic system)."""
    systems = {0: System("R", np.zeros(3), np.eye(3))}
    seen = {}
    for cid, _, _, _, at in cords:
        if cid in seen or cid == 0:
            raise InputError(f"{at}: coordinate system {cid} is defined "
                             f"{'again (first at ' + seen[cid] + ')' if cid in seen else 'as 0 (the basic system)'}")
        seen[cid] = at
    ids, cp, x, cd, lines = grids["ids"], grids["cp"], grids["x"], grids["cd"], grids["lines"]
    row = {int(g): k for k, g in enumerate(ids)}
    xyz = np.full((len(ids), 3), np.nan)
    done = np.zeros(len(ids), dtype=bool)
    todo = list(cords)
    while True:
        progress = False
        for sid in np.unique(cp[~done]):
            if int(sid) in systems:
                sel = ~done & (cp == sid)
                xyz[sel] = systems[int(sid)].to_basic(x[sel])
                done |= sel
                progress = True
        left = []
        for item in todo:
            cid, kind, rid, vals, at = item
            if vals is not None and rid in systems:
                p = systems[rid].to_basic(np.reshape(vals, (3, 3)))
                systems[cid] = _from_points(kind, p[0], p[1], p[2], at)
                progress = True
            elif vals is None and all(g in row and done[row[g]] for g in rid):
                p = xyz[[row[g] for g in rid]]
                systems[cid] = _from_points(kind, p[0], p[1], p[2], at)
                progress = True
            else:
                left.append(item)
        todo = left
        if not progress:
            break
    if not done.all():
        k = int(np.flatnonzero(~done)[0])
        raise InputError(f"{lines[k]}: GRID {ids[k]} has CP {cp[k]}, a coordinate system that "
                         "is not defined (no CORD card, or one that depends on itself)")
    if todo:
        cid, _, rid, vals, at = todo[0]
        what = (f"its reference system {rid}" if vals is not None else
                f"its grids {', '.join(map(str, rid))}")
        raise InputError(f"{at}: coordinate system {cid}: {what} not defined")
    frames = {}
    for sid in np.unique(cd):
        if int(sid) == 0:
            continue
        if int(sid) not in systems:
            k = int(np.flatnonzero(cd == sid)[0])
            raise InputError(f"{lines[k]}: GRID {ids[k]} has CD {cd[k]}, a coordinate system "
                             f"that is not defined ({where})")
        sel = np.flatnonzero(cd == sid)
        for k, T in zip(sel, systems[int(sid)].frames(xyz[sel])):
            frames[int(k)] = T
    return xyz, frames
