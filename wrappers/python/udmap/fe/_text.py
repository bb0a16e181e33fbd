"""Text parsing shared by the readers: the one way every export file is opened (gzip, CRLF, BOM),
numbers (also with decimal commas), sparse triplets, Matrix Market files, symmetric storage."""
from __future__ import annotations

import gzip
import io
import re
import zlib
from pathlib import Path

import numpy as np
import scipy.sparse as sp

from ..errors import InputError


def open_text(path: Path, field: str):
    """Every file of every format is opened here: a text stream with universal newlines (CRLF and
    CR read as LF), a UTF-8 byte-order mark dropped, undecodable bytes replaced, and gunzipped
    when the file is gzip-compressed (told by its first bytes, whatever its name; a ``.gz`` name
    on a file that is not gzip is an error)."""
    p = Path(path)
    try:
        raw = open(p, "rb")
        magic = raw.peek(2)[:2] if hasattr(raw, "peek") else b""
    except OSError as exc:
        raise InputError(f"{field}: cannot read {path}: {exc.strerror}") from None
    if magic == b"\x1f\x8b":
        stream = gzip.GzipFile(fileobj=raw, mode="rb")
    elif p.suffix.lower() == ".gz":
        raw.close()
        raise InputError(f"{field}: {path}: named .gz but not gzip-compressed")
    else:
        stream = raw
    return io.TextIOWrapper(stream, encoding="utf-8-sig", errors="replace", newline=None)


def read_text(path: Path, field: str) -> str:
    """The whole text of an export file (see :func:`open_text`)."""
    try:
        with open_text(path, field) as f:
            return f.read()
    except (OSError, EOFError, zlib.error) as exc:
        raise InputError(f"{field}: {path}: cannot read it as text ({exc})") from None


def text_lines(path: Path, field: str):
    """``(line number, line)`` of an export file, tabs as spaces, trailing blanks removed."""
    for lineno, line in enumerate(read_text(path, field).split("\n"), 1):
        yield lineno, line.replace("\t", " ").rstrip()


#: Deepest nesting of include files (deeper is taken for a loop).
MAX_INCLUDE_DEPTH = 16


def include_target(name: str, main_dir: Path, including: Path, chain: tuple, where: str,
                   what: str) -> Path:
    """The file ``name`` that an include statement ``what`` at ``where`` names (no name is an
    error: "``what`` without a file name"): a relative path is looked
    up beside the main file (where the FE code runs), then beside the including file; a file
    that includes itself (through others, or nested deeper than MAX_INCLUDE_DEPTH) is an
    error."""
    if not name:
        raise InputError(f"{where}: {what} without a file name")
    cands = [Path(name)] if Path(name).is_absolute() else [main_dir / name, including.parent / name]
    target = next((c.resolve() for c in cands if c.is_file()), None)
    if target is None:
        raise InputError(f"{where}: {what} file {name} not found (looked in "
                         f"{', '.join(map(str, cands))})")
    if target in chain or len(chain) > MAX_INCLUDE_DEPTH:
        raise InputError(f"{where}: {what} {name} includes itself (directly or through other "
                         "files)")
    return target


def number(token: str) -> float:
    """A float, also written with a decimal comma (``0,15``, ``1,e-001``) or a Fortran ``D``."""
    t = token.strip().replace(",", ".").replace("D", "E").replace("d", "e")
    if t.endswith("."):
        t += "0"
    t = re.sub(r"\.([eE])", r".0\1", t)
    return float(t)


def symmetric_from_triplets(rows, cols, vals, n: int, field: str) -> sp.csr_matrix:
    """Full symmetric storage from triplets (1-based) holding one triangle or both.

    One triangle is mirrored; a term whose mirror is not given is mirrored (so one triangle in
    any DOF order works); both given, they are taken as they are (checked symmetric later)."""
    rows = np.asarray(rows, dtype=np.int64) - 1
    cols = np.asarray(cols, dtype=np.int64) - 1
    vals = np.asarray(vals, dtype=float)
    if len(rows) and (rows.min() < 0 or cols.min() < 0 or rows.max() >= n or cols.max() >= n):
        raise InputError(f"{field}: an index is outside the {n} x {n} matrix")
    A = sp.coo_matrix((vals, (rows, cols)), shape=(n, n)).tocsr()
    A.sum_duplicates()
    upper, lower = np.any(rows < cols), np.any(rows > cols)
    if upper and lower:   # full storage, or one triangle of another order (Abaqus labelled)
        C = A.tocoo()
        off = C.row != C.col
        r, c, v = C.row[off].astype(np.int64), C.col[off].astype(np.int64), C.data[off]
        lone = ~np.isin(c * n + r, r * n + c)
        if not lone.any():
            return A
        return sp.csr_matrix(A + sp.coo_matrix((v[lone], (c[lone], r[lone])), shape=(n, n)))
    off = sp.triu(A, 1) if upper else sp.tril(A, -1)
    return sp.csr_matrix(A + off.T)


def read_triplets(path: Path, field: str, skip_header=True):
    """Whitespace or comma separated ``row col value`` lines; comments start with % # or *."""
    try:   # numpy's C parser for the plain whitespace layout; the loop below names bad lines
        with open_text(path, field) as f:
            a = np.loadtxt(f, comments="%", ndmin=2, dtype=float)
        if a.shape[1] == 3 and np.all(a[:, :2] == np.round(a[:, :2])):
            return a[:, 0].astype(np.int64), a[:, 1].astype(np.int64), a[:, 2].copy()
    except (ValueError, OSError, EOFError, zlib.error):
        pass
    r, c, v = [], [], []
    for lineno, line in text_lines(path, field):
        s = line.strip()
        if not s or s[0] in "%#*" or s.startswith("**"):
            continue
        parts = s.replace(",", " ").split()
        try:
            i, j, x = int(parts[0]), int(parts[1]), float(parts[2].replace("D", "E"))
            if len(parts) != 3:
                raise ValueError
        except (ValueError, IndexError):
            raise InputError(f"{field}: {path}:{lineno}: expected 'row col value', got "
                             f"{line.strip()!r}") from None
        r.append(i)
        c.append(j)
        v.append(x)
    return np.array(r, dtype=np.int64), np.array(c, dtype=np.int64), np.array(v)


def read_mm(path: Path, field: str, vector=False):
    """A Matrix Market file: a sparse symmetric matrix (full storage) or, with ``vector``,
    the entries of an n x 1 / 1 x n array or coordinate matrix as a flat array."""
    lines = read_text(path, field).splitlines()
    if not lines or not lines[0].lower().startswith("%%matrixmarket"):
        raise InputError(f"{field}: {path} is not a Matrix Market file (no %%MatrixMarket "
                         "header)")
    head = lines[0].lower().split()
    if len(head) < 5 or head[1] != "matrix" or head[2] not in ("coordinate", "array"):
        raise InputError(f"{field}: {path}: unsupported header {lines[0].strip()!r}")
    fmt, sym = head[2], head[4]
    if head[3] not in ("real", "integer", "double"):
        raise InputError(f"{field}: {path}: only real or integer matrices, got {head[3]!r}")
    if sym not in ("general", "symmetric"):
        raise InputError(f"{field}: {path}: only general or symmetric storage, got {sym!r}")
    data = [s for s in (x.strip() for x in lines[1:]) if s and not s.startswith("%")]
    if not data:
        raise InputError(f"{field}: {path}: no size line")
    try:
        size = [int(t) for t in data[0].split()]
        body = None
        if not any("," in x for x in data[1:]):
            try:   # numpy's C parser; decimal commas and odd lines take the loop below
                body = np.loadtxt(data[1:], ndmin=2, dtype=float)
            except ValueError:
                body = None
        if body is None:
            body = np.array([[number(t) for t in s.split()] for s in data[1:]], dtype=float)
    except ValueError:
        raise InputError(f"{field}: {path}: a line is not numbers") from None
    nr, nc = size[0], size[1]
    if fmt == "coordinate":
        if len(size) != 3 or (len(body) and body.shape[1] != 3) or len(body) != size[2]:
            raise InputError(f"{field}: {path}: expected {size[-1]} 'row col value' lines")
        body = body.reshape(-1, 3)
        rows, cols, vals = body[:, 0].astype(np.int64), body[:, 1].astype(np.int64), body[:, 2]
    else:
        if len(size) != 2:
            raise InputError(f"{field}: {path}: bad array size line {data[0]!r}")
        vals = body.ravel()
        if sym == "symmetric":
            jj, ii = np.triu_indices(nr)   # column-major lower triangle
            rows, cols = ii + 1, jj + 1
            order = np.lexsort((rows, cols))
            rows, cols = rows[order], cols[order]
        else:
            cols, rows = np.divmod(np.arange(nr * nc), nr)
            rows, cols = rows + 1, cols + 1
        if len(vals) != len(rows):
            raise InputError(f"{field}: {path}: expected {len(rows)} values, got {len(vals)}")
    if vector:
        if min(nr, nc) != 1:
            raise InputError(f"{field}: {path}: expected a vector (n x 1), got {nr} x {nc}")
        out = np.zeros(max(nr, nc))
        np.add.at(out, (rows if nc == 1 else cols) - 1, vals)
        return out
    if nr != nc:
        raise InputError(f"{field}: {path}: the matrix must be square, got {nr} x {nc}")
    if sym == "symmetric" and np.any(rows < cols):
        raise InputError(f"{field}: {path}: symmetric storage holds the lower triangle only")
    return symmetric_from_triplets(rows, cols, vals, nr, field)
