"""NASTRAN: ``DMIG`` matrices (punch file) and ``GRID`` cards (bulk data).

Bulk data cards in small field (8-character fields), large field (``DMIG*``/``GRID*``, 16-character
fields, continuation lines starting with ``*``) or free field (comma separated), after the MSC/NX
Quick Reference Guide. ``DMIG`` header ``NAME "0" IFO TIN TOUT POLAR - NCOL``; column entries
``NAME GJ CJ - G1 C1 A1 B1 G2 C2 A2 B2 ...``. Symmetric matrices (``IFO = 6``) give each
off-diagonal term once, below or above the diagonal. Reals may use the NASTRAN short forms
(``1.5+3``, ``-2.-4``) and ``D`` exponents. The stiffness is the ``DMIG`` whose name starts with
``K``, the mass the one starting with ``M`` (or the names given in ``blade.dmig``; when a punch
holds several, the error lists the names found). Card names in any case; tabs (to the next
8-column field, as NASTRAN reads them); ``$`` comments; ``INCLUDE 'file'`` statements (nested);
in a whole input file only the bulk data (after ``BEGIN BULK``, up to ``ENDDATA``) is read.

Coordinate systems (``nastran_coords``): ``GRID`` positions given in their ``CP`` system are put
in the basic system; the matrices of a grid with a ``CD`` system are in that grid's frame, so
their translation and rotation blocks are rotated to the basic system,
``K_basic = B^T K B`` with ``B`` = ``T^T`` on each such grid's blocks (``T``: the grid's frame
axes in basic). A frame block can only be rotated whole: a grid with a ``CD`` frame other than
the basic axes must carry all three components of a block it has in the matrices.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import scipy.sparse as sp

from ..errors import InputError
from ._text import include_target, read_text
from .model import FEModel, make_model
from .nastran_coords import resolve


def real(token: str) -> float:
    t = token.strip().upper().replace("D", "E")
    if "E" not in t:
        t = re.sub(r"(?<=[0-9.])([+-])", r"E\1", t, count=1)
    return float(t)


def _untab(line: str) -> str:
    """Tabs end a field: the text after a tab starts in the next field (8 columns, 16 in the
    data fields of a large-field card), a field filled to its end is not skipped."""
    if "\t" not in line:
        return line
    segs = line.split("\t")
    large = segs[0][:8].strip().endswith("*") or segs[0].startswith("*")
    out = ""
    for seg in segs[:-1]:
        out += seg
        width = 16 if large and len(out) >= 8 else 8
        start = 0 if len(out) < 8 else 8
        used = (len(out) - start) % width
        if used or not seg:
            out += " " * ((width - used) if len(out) >= 8 or not large else 8 - len(out))
    return out + segs[-1]


def _lines(path, field: str):
    """``(file, line number, line)`` of a NASTRAN input file with its ``INCLUDE 'file'``
    statements replaced by the files' lines (nested; the quoted name may go on over several
    lines; a relative name is looked up beside the main file, then beside the including
    one)."""
    main = Path(path)
    main_dir = main.resolve().parent

    def walk(p: Path, chain):
        lines = read_text(p, field).split("\n")
        k = 0
        while k < len(lines):
            raw, lineno = lines[k], k + 1
            k += 1
            if raw[:7].upper() != "INCLUDE" or raw[7:8].strip():
                yield p, lineno, raw
                continue
            text = raw[7:].split("$", 1)[0].strip()
            if text.startswith("'"):      # the name ends at the closing quote
                while text.count("'") < 2 and k < len(lines):
                    text, k = text + lines[k].strip(), k + 1
                name = text[1:].split("'", 1)[0]
            else:
                name = text
            target = include_target(name, main_dir, p, chain, f"{field}: {p}:{lineno}",
                                    "INCLUDE")
            yield from walk(target, chain + (target,))

    yield from walk(main, (main.resolve(),))


def cards(path, field: str):
    """Yields ``(name, [fields 2..9 of every line, concatenated], "file:line")``."""
    current = None
    lines = list(_lines(path, field))
    start = next((k + 1 for k, (_, _, raw) in enumerate(lines)
                  if raw.strip().upper().replace(" ", "").startswith("BEGINBULK")), 0)
    for at_file, lineno, raw in lines[start:]:
        line = raw.split("$", 1)[0].rstrip()
        if not line.strip():
            continue
        if line.strip().upper().startswith("ENDDATA"):
            break
        if "," in line[:80]:      # free field: a line may also hold more than 8 data fields
            items = [q.strip() for q in line.split(",")]
            head, data = items[0], items[1:]
            if len(data) > 8 and data[8].startswith("+"):
                data = data[:8]   # field 10: the continuation marker
        else:
            line = _untab(line)
            if line[:8].strip().endswith("*") or line.startswith("*"):
                head = line[:8].strip()
                data = [line[8 + 16 * k:24 + 16 * k].strip() for k in range(4)]
            else:
                head = line[:8].strip()
                data = [line[8 + 8 * k:16 + 8 * k].strip() for k in range(8)]
        is_cont = head == "" or head.startswith("+") or head.startswith("*")
        if is_cont:
            if current is None:
                raise InputError(f"{field}: {at_file}:{lineno}: continuation line without a "
                                 "card")
            current[1].extend(data)
            continue
        if current is not None:
            yield current
        current = (head.rstrip("*").upper(), list(data), f"{at_file}:{lineno}")
    if current is not None:
        yield current


def _int(v, default=0):
    return int(v) if v else default


def read_grids(path, field="blade.files.bdf", lines=None):
    """Grid ids, their positions in the basic system, and the frames (row -> 3x3 axes in basic)
    of the grids whose ``CD`` is a local system; ``lines`` (a dict), if given, gets each grid's
    ``"field: file:line"``."""
    ids, cp, x, cd, where = [], [], [], [], []
    cords, dflt = [], ["", ""]
    for name, f, at in cards(path, field):
        f = f + [""] * 16
        try:
            if name == "GRDSET":
                dflt = [f[1], f[5]]
            elif name == "GRID":
                ids.append(int(f[0]))
                cp.append(_int(f[1] or dflt[0]))
                x.append([real(v) if v else 0.0 for v in f[2:5]])
                cd.append(_int(f[5] or dflt[1]))
                where.append(f"{field}: {at}")
            elif name in ("CORD2R", "CORD2C", "CORD2S"):
                cords.append((int(f[0]), name[-1], _int(f[1]), [real(v) if v else 0.0
                                                               for v in f[2:11]],
                              f"{field}: {at}"))
            elif name in ("CORD1R", "CORD1C", "CORD1S"):
                for k in (0, 4):
                    if f[k]:
                        cords.append((int(f[k]), name[-1], tuple(int(v) for v in f[k + 1:k + 4]),
                                      None, f"{field}: {at}"))
        except ValueError:
            raise InputError(f"{field}: {at}: bad {name} card {f[:11]}") from None
    if not ids:
        raise InputError(f"{field}: {path}: no GRID cards")
    grids = {"ids": np.array(ids, dtype=np.int64), "cp": np.array(cp, dtype=np.int64),
             "x": np.array(x, dtype=float).reshape(-1, 3), "cd": np.array(cd, dtype=np.int64),
             "lines": where}
    xyz, frames = resolve(cords, grids, f"{field}: {path}")
    if lines is not None:
        lines.update(zip(ids, where))
    return grids["ids"], xyz, frames


def to_basic(A, pairs, frames, node_ids, where, lines=None):
    """``B^T A B``: the rows and columns of grids with a local ``CD`` frame rotated to basic."""
    if not frames:
        return A
    row = {int(g): k for k, g in enumerate(node_ids)}
    index = {p: k for k, p in enumerate(pairs)}
    n = len(pairs)
    B = sp.identity(n, format="lil")
    for (g, c0) in {(g, 1 + 3 * ((c - 1) // 3)) for g, c in pairs}:
        T = frames.get(row.get(g, -1))
        if T is None or np.array_equal(T, np.eye(3)):
            continue
        have = [index.get((g, c0 + k)) for k in range(3)]
        if None in have:
            kind = "translations" if c0 == 1 else "rotations"
            at = (lines or {}).get(g, where)
            raise InputError(f"{at}: GRID {g} has a local CD frame but the matrices hold "
                             f"only components {', '.join(str(c0 + k) for k in range(3) if have[k] is not None)} "
                             f"of its {kind}: a frame block can only be rotated to the basic "
                             "system whole (export the matrices with all three, or the grid "
                             "with CD 0)")
        for a in range(3):
            for b in range(3):
                B[have[a], have[b]] = T[b, a]
    B = sp.csr_matrix(B)
    return sp.csr_matrix(B.T @ A @ B)


def read_dmig(path, field="blade.files.pch"):
    """All ``DMIG`` matrices of a file: name -> (ifo, [(gj, cj, gi, ci, value)])."""
    mats = {}
    for name, f, at in cards(path, field):
        if name != "DMIG":
            continue
        try:
            mname = f[0].upper()
            if f[1] == "0":
                mats.setdefault(mname, [int(f[2]), []])[0] = int(f[2])
                if f[3] not in ("1", "2") or (len(f) > 5 and f[5] not in ("", "0")):
                    raise InputError(f"{field}: {at}: DMIG {mname}: only real "
                                     "(TIN 1 or 2, not POLAR) matrices are supported")
                continue
            if mname not in mats:
                raise InputError(f"{field}: {at}: DMIG {mname} column before its "
                                 "header")
            gj, cj = int(f[1]), int(f[2] or 1)
            rest = f[4:]
            for k in range(0, len(rest) - 2, 4):
                if not rest[k]:
                    continue
                mats[mname][1].append((gj, cj, int(rest[k]), int(rest[k + 1] or 1),
                                       real(rest[k + 2])))
        except (ValueError, IndexError):
            raise InputError(f"{field}: {at}: bad DMIG card {f}") from None
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
    lines = {}
    node_ids, xyz, frames = read_grids(files["bdf"], lines=lines)
    where = f"blade.files ({files['pch']}, {files['bdf']})"
    out = [to_basic(A, pairs, frames, node_ids, where, lines) for A in out]
    return make_model(out[0], out[1], [p[0] for p in pairs], [p[1] for p in pairs], node_ids,
                      xyz, where=where)
