"""NASTRAN: ``DMIG`` matrices (punch file) and ``GRID`` cards (bulk data).

Bulk data cards in small field (8-character fields), large field (``DMIG*``/``GRID*``, 16-character
fields, continuation lines starting with ``*``) or free field (comma separated), after the MSC/NX
Quick Reference Guide. ``DMIG`` header ``NAME "0" IFO TIN TOUT POLAR - NCOL``; column entries
``NAME GJ CJ - G1 C1 A1 B1 G2 C2 A2 B2 ...``. Symmetric matrices (``IFO = 6``) give each
off-diagonal term once, below or above the diagonal. Reals may use the NASTRAN short forms
(``1.5+3``, ``-2.-4``) and ``D`` exponents. The stiffness is the ``DMIG`` whose name starts with
``K``, the mass the one starting with ``M`` (or the names given in ``blade.dmig``). ``GRID``
coordinates must be in the basic system (``CP`` and ``CD`` blank or 0).
"""
from __future__ import annotations

import re

import numpy as np
import scipy.sparse as sp

from ..errors import InputError
from ._text import read_text
from .model import FEModel, make_model


def real(token: str) -> float:
    t = token.strip().upper().replace("D", "E")
    if "E" not in t:
        t = re.sub(r"(?<=[0-9.])([+-])", r"E\1", t, count=1)
    return float(t)


def cards(path, field: str):
    """Yields ``(name, [fields 2..9 of every line, concatenated], first line number)``."""
    current = None
    for lineno, raw in enumerate(read_text(path, field).splitlines(), 1):
        line = raw.rstrip("\n\r")
        if not line.strip() or line.lstrip().startswith("$"):
            continue
        if "," in line[:80]:
            items = [p.strip() for p in line.split(",")]
            head, data = items[0], items[1:9]
        elif line[:8].strip().endswith("*") or line.startswith("*"):
            head = line[:8].strip()
            data = [line[8 + 16 * k:24 + 16 * k].strip() for k in range(4)]
        else:
            head = line[:8].strip()
            data = [line[8 + 8 * k:16 + 8 * k].strip() for k in range(8)]
        is_cont = head == "" or head.startswith("+") or head.startswith("*")
        if is_cont:
            if current is None:
                raise InputError(f"{field}: {path}:{lineno}: continuation line without a card")
            current[1].extend(data)
            continue
        if current is not None:
            yield current
        current = (head.rstrip("*").upper(), list(data), lineno)
    if current is not None:
        yield current


def read_grids(path, field="blade.files.bdf"):
    ids, xyz = [], []
    for name, f, lineno in cards(path, field):
        if name != "GRID":
            continue
        f = f + [""] * 8
        try:
            if f[1] not in ("", "0") or f[5] not in ("", "0"):
                raise InputError(f"{field}: {path}:{lineno}: GRID {f[0]} uses a coordinate "
                                 "system (CP or CD); only the basic system is supported")
            ids.append(int(f[0]))
            xyz.append([real(v) if v else 0.0 for v in f[2:5]])
        except ValueError:
            raise InputError(f"{field}: {path}:{lineno}: bad GRID card {f[:5]}") from None
    if not ids:
        raise InputError(f"{field}: {path}: no GRID cards")
    return np.array(ids, dtype=np.int64), np.array(xyz, dtype=float)


def read_dmig(path, field="blade.files.pch"):
    """All ``DMIG`` matrices of a file: name -> (ifo, [(gj, cj, gi, ci, value)])."""
    mats = {}
    for name, f, lineno in cards(path, field):
        if name != "DMIG":
            continue
        try:
            mname = f[0].upper()
            if f[1] == "0":
                mats.setdefault(mname, [int(f[2]), []])[0] = int(f[2])
                if f[3] not in ("1", "2") or (len(f) > 5 and f[5] not in ("", "0")):
                    raise InputError(f"{field}: {path}:{lineno}: DMIG {mname}: only real "
                                     "(TIN 1 or 2, not POLAR) matrices are supported")
                continue
            if mname not in mats:
                raise InputError(f"{field}: {path}:{lineno}: DMIG {mname} column before its "
                                 "header")
            gj, cj = int(f[1]), int(f[2] or 1)
            rest = f[4:]
            for k in range(0, len(rest) - 2, 4):
                if not rest[k]:
                    continue
                mats[mname][1].append((gj, cj, int(rest[k]), int(rest[k + 1] or 1),
                                       real(rest[k + 2])))
        except (ValueError, IndexError):
            raise InputError(f"{field}: {path}:{lineno}: bad DMIG card {f}") from None
    return mats


def read(files: dict, names: dict | None = None) -> FEModel:
    mats = read_dmig(files["pch"])
    chosen = {}
    for key in ("K", "M"):
        if names and key in names:
            nm = names[key].upper()
            if nm not in mats:
                raise InputError(f"blade.dmig.{key}: no DMIG {nm} in {files['pch']} (found: "
                                 f"{', '.join(sorted(mats)) or 'none'})")
        else:
            cand = [m for m in mats if m.startswith(key)]
            if len(cand) != 1:
                raise InputError(f"blade.files.pch: {files['pch']} needs exactly one DMIG whose "
                                 f"name starts with {key} (found: {', '.join(sorted(mats)) or 'none'}"
                                 f"); name it in blade.dmig.{key}")
            nm = cand[0]
        if mats[nm][0] not in (1, 6):
            raise InputError(f"blade.files.pch: DMIG {nm} has IFO {mats[nm][0]}: K and M must "
                             "be square (IFO 1) or symmetric (IFO 6)")
        chosen[key] = nm
    pairs = sorted({(g, c) for key in chosen for e in mats[chosen[key]][1]
                    for g, c in ((e[0], e[1]), (e[2], e[3]))})
    if any(not 1 <= c <= 6 for _, c in pairs):
        raise InputError(f"blade.files.pch: components must be 1..6 (scalar points are not "
                         "supported)")
    index = {p: k for k, p in enumerate(pairs)}
    n = len(pairs)
    out = []
    for key in ("K", "M"):
        ifo, entries = mats[chosen[key]]
        e = np.array([(index[(a, b)], index[(c, d)], v) for a, b, c, d, v in entries])
        A = sp.coo_matrix((e[:, 2], (e[:, 1].astype(int), e[:, 0].astype(int))),
                          shape=(n, n)).tocsr()   # row Gi, column GJ
        if ifo == 6:
            i, j = e[:, 1].astype(int), e[:, 0].astype(int)
            lo = np.minimum(i, j) * n + np.maximum(i, j)
            if len(np.unique(lo)) != len(lo):
                raise InputError(f"blade.files.pch: DMIG {chosen[key]} (IFO 6) gives a term "
                                 "both below and above the diagonal")
            A = A + sp.triu(A, 1).T + sp.tril(A, -1).T
        out.append(sp.csr_matrix(A))
    node_ids, xyz = read_grids(files["bdf"])
    return make_model(out[0], out[1], [p[0] for p in pairs], [p[1] for p in pairs], node_ids,
                      xyz, where=f"blade.files ({files['pch']}, {files['bdf']})")
