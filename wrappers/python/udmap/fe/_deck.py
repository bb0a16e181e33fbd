"""Abaqus and CalculiX input decks: keyword lines (``*KEYWORD, OPTION=value``, any case), data
lines, ``**`` comments, ``*INCLUDE, INPUT=file`` (nested; a relative path is looked up beside
the main deck, where the FE code runs, then beside the including file), the ``*NODE`` blocks and
the element types of the ``*ELEMENT`` blocks."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import InputError
from ._text import include_target, text_lines


def keyword(line: str):
    """``(KEYWORD, {OPTION: value})`` of a keyword line: names upper case, blanks inside a name
    collapsed, option values as written (quotes removed)."""
    parts = line[1:].split(",")
    key = " ".join(parts[0].split()).upper()
    opts = {}
    for part in parts[1:]:
        name, _, value = part.partition("=")
        if name.strip():
            opts[" ".join(name.split()).upper()] = value.strip().strip("\"'")
    return key, opts


def deck_lines(path, field: str):
    """``(file, line number, line)`` of every keyword and data line of a deck and its *INCLUDE
    files, in reading order (comments and blank lines left out)."""
    main_dir = Path(path).resolve().parent

    def walk(p: Path, chain):
        for lineno, line in text_lines(p, field):
            s = line.strip()
            if not s or s.startswith("**"):
                continue
            if s.startswith("*"):
                key, opts = keyword(s)
                if key == "INCLUDE":
                    target = include_target(opts.get("INPUT", ""), main_dir, p, chain,
                                            f"{field}: {p}:{lineno}", "*INCLUDE")
                    yield from walk(target, chain + (target,))
                    continue
            yield p, lineno, s

    yield from walk(Path(path), (Path(path).resolve(),))


def parse_deck_nodes(path, field: str):
    """Node ids and coordinates of the ``*NODE`` blocks (node lines ``id, x, y, z``; missing
    coordinates are 0) of a deck and its *INCLUDE files."""
    ids, xyz = [], []
    in_node = False
    for p, lineno, s in deck_lines(path, field):
        if s.startswith("*"):
            in_node = keyword(s)[0] == "NODE"
            continue
        if not in_node:
            continue
        parts = [q for q in s.split(",") if q.strip()]
        try:
            ids.append(int(parts[0]))   # (Abaqus may add a normal after x, y, z)
            c = [float(q.replace("D", "E").replace("d", "e")) for q in parts[1:4]]
        except (ValueError, IndexError):
            raise InputError(f"{field}: {p}:{lineno}: expected 'id, x, y, z', got "
                             f"{s!r}") from None
        xyz.append(c + [0.0] * (3 - len(c)))
    if not ids:
        raise InputError(f"{field}: {path}: no *NODE lines (in the deck or its *INCLUDE files)")
    return np.array(ids, dtype=np.int64), np.array(xyz, dtype=float).reshape(-1, 3)


def element_types(path, field: str) -> dict:
    """Element type (upper case) -> number of elements, from the ``*ELEMENT`` blocks."""
    out = {}
    etype = None
    for _, _, s in deck_lines(path, field):
        if s.startswith("*"):
            key, opts = keyword(s)
            etype = opts.get("TYPE", "").upper() if key == "ELEMENT" else None
            continue
        if etype and not s.rstrip().endswith(","):
            out[etype] = out.get(etype, 0) + 1
    return out
