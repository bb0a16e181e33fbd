#!/usr/bin/env python3
"""Writes the files generated from udmap's parameter table (kernel/parameters.toml).

    python3 cmake/generate_parameters.py            # rewrite the checked-in files
    python3 cmake/generate_parameters.py --check    # regenerate into a temporary directory and
                                                    # fail if a checked-in file differs
    python3 cmake/generate_parameters.py --out DIR  # write the files under DIR

The generated files (paths relative to the source root) are listed in OUTPUTS; wrappers/c/udmap.h
is generated only between its "generated:begin NAME" and "generated:end NAME" markers. Standard
library only (Python 3.11: tomllib).
"""
from __future__ import annotations

import argparse
import difflib
import json
import sys
import tempfile
import textwrap
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TABLE = "kernel/parameters.toml"
ME = "cmake/generate_parameters.py"
PYTHON = "wrappers/python/udmap/parameters.py"
C_HEADER = "wrappers/c/udmap.h"
FMU_HEADER = "fmu/parameters.h"
LEGACY = "kernel/src/api/legacy/parameters.f90"
C_TYPES = "kernel/src/api/c/parameters.f90"
OUTPUTS = (PYTHON, C_HEADER, FMU_HEADER, LEGACY, C_TYPES)
STAMP = f"generated from {TABLE} by {ME}: do not edit; edit the table and run {ME}"


def num(x) -> str:
    """A number as a literal of Python and C: ints as such, floats as their shortest exact form
    (exponent form outside [1e-4, 1e5))."""
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise TypeError(f"not a number: {x!r}")
    if isinstance(x, int):
        return str(x)
    if x == 0 or 1e-4 <= abs(x) < 1e5:
        return repr(x)
    for digits in range(17):
        text = f"{x:.{digits}e}"
        if float(text) == x:
            break
    mantissa, exponent = text.split("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return f"{mantissa}e{int(exponent)}"


def c_string(text: str, indent: str, width: int = 96) -> list[str]:
    """A C string literal, split into concatenated pieces of at most `width` columns."""
    text = text.replace("\\", "\\\\").replace('"', '\\"')
    room = width - len(indent) - 5
    pieces = textwrap.wrap(text, room, drop_whitespace=False, break_on_hyphens=False) or [""]
    return [f'{indent}"{p}"' for p in pieces]


class Table:
    """The parsed table, with the lookups the writers share."""

    def __init__(self, data: dict, root: Path):
        self.fields = data["field"]
        self.top_level = data["top_level"]
        self.structs = data["struct"]
        for s in self.structs:
            s.setdefault("kind", None)
        self.legacy = data["legacy"]
        self.fmu = data["fmu"]
        self.kinds_module = data["fortran"]["kinds_module"]
        self.flat = {}        # (section, kind) -> [(flat name, field, index, fortran component)]
        self.by_flat = {}     # flat name -> (field, index), the first section and kind with it
        for f in self.fields:
            f.setdefault("kind", None)
            names = f.get("flat", [f["name"].replace(".", "_")])
            fortran = f.get("fortran", names)
            rows = self.flat.setdefault((f["section"], f["kind"]), [])
            for i, (n, ft) in enumerate(zip(names, fortran)):
                rows.append((n, f, i, ft))
                self.by_flat.setdefault(n, (f, i))
        with open(root / self.fmu["starts"], encoding="utf-8") as fh:
            self.reference = json.load(fh)

    def flat_of(self, section, kind) -> dict:
        return {n: (f, i, ft) for n, f, i, ft in self.flat[(section, kind)]}

    def reference_value(self, field: dict, index: int):
        """The value of a field (coordinate `index` of a point) in the reference case, or the
        field's default."""
        node = self.reference.get(field["section"], {})
        for part in field["name"].split("."):
            node = node.get(part) if isinstance(node, dict) else None
        if node is None:
            return field["default"]
        for i in _coordinate(field, index):
            node = node[i]
        return node


# ---------------------------------------------------------------- Python

def _py(value) -> str:
    if value is None or isinstance(value, str):
        return repr(value)
    if isinstance(value, bool):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return "(" + ", ".join(_py(v) for v in value) + ("," if len(value) == 1 else "") + ")"
    return num(value)


def _py_str(text: str, indent: str, room: int) -> str:
    """A string literal, as implicitly concatenated pieces on lines of at most `room`."""
    if len(repr(text)) <= room:
        return repr(text)
    pieces = textwrap.wrap(text, room - 3, drop_whitespace=False, break_on_hyphens=False)
    return ("(" + f"\n{indent} ".join(repr(p) for p in pieces) + ")")


def _wrap_py(head: str, items: list[str], indent: str, tail: str) -> list[str]:
    """`head` then the comma-separated items then `tail`, on lines of at most 99 columns
    (continued four columns in)."""
    line = f"{indent}{head}{', '.join(items)}{tail}"
    if len(line) <= 99:
        return [line]
    out, current = [], f"{indent}{head}"
    for k, item in enumerate(items):
        piece = item + (", " if k < len(items) - 1 else tail)
        first = piece.split("\n")[0].rstrip()
        if len(current) + len(first) > 99 and current.strip():
            out.append(current.rstrip())
            current = indent + "    "
        current += piece
    out.append(current.rstrip())
    return out


def _field_items(f: dict, indent: str) -> list[str]:
    """udmap.case.Field keyword arguments of a table row."""
    keys = (("type", "type"), ("min", "lo"), ("max", "hi"), ("unit", "unit"),
            ("default", "default"), ("open", "open"), ("even", "even"), ("count", "count"),
            ("choices", "choices"))
    items = [f"{py}={_py(f[k])}" for k, py in keys if k in f]
    if "doc" in f:
        items.append("doc=" + _py_str(f["doc"], indent + "    ", 99 - len(indent) - 14))
    return items


def _coordinate(f: dict, i: int) -> tuple:
    """The indices of coordinate i of a point ([x, y]) or points ([[x, y], ...]) field."""
    return {"point": (i,), "points": (i // 2, i % 2)}.get(f["type"], ())


def python_module(t: Table) -> str:
    out = ['"""The parameter table for Python: udmap.case.SCHEMA\'s rows (FIELDS, TOP_LEVEL: '
           'keyword',
           "arguments of udmap.case.Field), the flat names of the C structs, FMU variables and",
           "plain arrays, the items of the FMU's case file and the ctypes structures of the C",
           "structs of wrappers/c/udmap.h.", ""]
    out += textwrap.wrap(STAMP[0].upper() + STAMP[1:] + ".", 95)
    out += ['"""', "import ctypes", "", ""]
    out.append("#: The case-file fields in schema order: (section, kind, dotted name, Field "
               "keywords).")
    out.append("FIELDS = (")
    for f in t.fields:
        head = f"({_py(f['section'])}, {_py(f['kind'])}, {_py(f['name'])}, dict("
        out += _wrap_py(head, _field_items(f, "    "), "    ", ")),")
    out.append(")")
    out.append("#: Top-level fields besides the sections: (name, Field keywords).")
    out.append("TOP_LEVEL = (")
    for f in t.top_level:
        out += _wrap_py(f"({_py(f['name'])}, dict(", _field_items(f, "    "), "    ", ")),")
    out.append(")")
    out.append("#: The kernel's codes of the choice fields: (section, kind, name) -> "
               "{choice: code}.")
    out.append("CHOICE_CODES = {")
    for f in t.fields:
        if f["type"] == "choice":
            codes = ", ".join(f"{_py(c)}: {i}" for i, c in enumerate(f["choices"]))
            out.append(f"    ({_py(f['section'])}, {_py(f['kind'])}, {_py(f['name'])}): "
                       f"{{{codes}}},")
    out.append("}")
    out.append("#: The flat names (C structs, FMU variables, plain arrays) of each section and "
               "kind:")
    out.append("#: (section, kind) -> ((flat name, dotted field name, indices of the coordinate), "
               "...).")
    out.append("FLAT_NAMES = {")
    for (section, kind), rows in t.flat.items():
        items = [f"({_py(n)}, {_py(f['name'])}, {_py(_coordinate(f, i))})"
                 for n, f, i, _ in rows]
        out += _wrap_py(f"({_py(section)}, {_py(kind)}): (", items, "    ", "),")
    out.append("}")
    out.append("#: Items of the FMU's resources/udmap-case.txt (fmu/case.c): (section, kind) ->")
    out.append("#: ((name, type), ...).")
    out.append("CASE_ITEMS = {")
    for (section, kind) in t.flat:
        items = [(f["name"], f["type"]) for f in t.fields
                 if (f["section"], f["kind"]) == (section, kind) and "case_item" in f]
        if items:
            out += _wrap_py(f"({_py(section)}, {_py(kind)}): (",
                            [f"({_py(n)}, {_py(ty)})" for n, ty in items],
                            "    ", "),")
    out.append("}")
    out.append("#: FMU variables that only a blade or damper of this kind has (the others leave "
               "them out).")
    out.append("FMU_KIND_VARIABLES = {")
    kinds_of = {}
    for (section, kind), rows in t.flat.items():
        for n, *_ in rows:
            kinds_of.setdefault(n, []).append((section, kind))
    for (section, kind), rows in t.flat.items():
        if kind is None:
            continue
        names = [v["field"] for v in t.fmu["variable"] if "field" in v
                 and kinds_of.get(v["field"]) == [(section, kind)]]
        if names:
            out += _wrap_py(f"({_py(section)}, {_py(kind)}): (",
                            [_py(n) for n in names], "    ", "),")
    out.append("}")
    for s in t.structs:
        out += ["", "", f"class {s['ctypes']}(ctypes.Structure):",
                f'    """{s["name"]} (wrappers/c/udmap.h)."""', "", "    _fields_ = ["]
        flat = t.flat_of(s["section"], s["kind"])
        for line in s["lines"]:
            out += [f"        ({_py(n)}, {_ctype(flat[n][0])})," for n in line]
        out.append("    ]")
    return "\n".join(out) + "\n"


def _is_int(f: dict) -> bool:
    """Whether a field is an int of the C structs."""
    return f["type"] in ("int", "choice", "harmonics")


def _ctype(f: dict) -> str:
    return "ctypes.c_int" if _is_int(f) else "ctypes.c_double"


# ---------------------------------------------------------------- C header blocks

def c_struct(t: Table, s: dict) -> list[str]:
    flat = t.flat_of(s["section"], s["kind"])
    out = ["typedef struct {"]
    comments = s.get("comments", {})
    for line in s["lines"]:
        types = {"int" if _is_int(flat[n][0]) else "double" for n in line}
        if len(types) != 1:
            raise SystemExit(f"{TABLE}: struct {s['name']}: one type per line, got {line}")
        decl = f"  {types.pop()} {', '.join(line)};"
        text = comments.get(line[0])
        if not text:
            out.append(decl)
            continue
        column = s["comment_column"]
        out.append(f"{decl:<{column}}/* {text[0]}" + (" */" if len(text) == 1 else ""))
        out += [" " * (column + 3) + t + (" */" if k == len(text) - 2 else "")
                for k, t in enumerate(text[1:])]
    out.append(f"}} {s['name']};")
    return out


def c_header(t: Table, text: str) -> str:
    for s in t.structs:
        begin = f"/* generated:begin {s['name']} (from {TABLE}: do not edit) */\n"
        end = f"/* generated:end {s['name']} */\n"
        if text.count(begin) != 1 or text.count(end) != 1:
            raise SystemExit(f"{C_HEADER}: needs the marker lines\n{begin}{end}once each")
        i, j = text.index(begin) + len(begin), text.index(end)
        text = text[:i] + "\n".join(c_struct(t, s)) + "\n" + text[j:]
    return text


# ---------------------------------------------------------------- FMU

FLAGS = (("open", "OPEN"), ("even", "EVEN"))
FMU_TYPES = {"real": "REAL", "point": "REAL", "points": "REAL", "int": "INTEGER",
             "harmonics": "INTEGER"}


def fmu_rows(t: Table) -> list[dict]:
    """The FMU variables with every column filled."""
    rows = []
    for v in t.fmu["variable"]:
        if "field" in v:
            f, i = t.by_flat[v["field"]]
            row = {"name": v["field"], "type": FMU_TYPES[f["type"]], "unit": f.get("unit", ""),
                   "start": t.reference_value(f, i), "min": f.get("min"), "max": f.get("max"),
                   "flags": " | ".join(c for k, c in FLAGS if f.get(k)) or "0"}
            row.update({k: v[k] for k in ("type", "min", "max", "start") if k in v})
        else:
            row = {"unit": "", "start": 0.0, "min": None, "max": None, "flags": "0"}
            row.update(v)
        row.update(causality=v["causality"], group=v["group"], doc=v["doc"])
        rows.append(row)
    return rows


def _c_num(x) -> str:
    if x is None:
        return "NOLIMIT"
    return num(float(x)) if not isinstance(x, bool) else str(int(x))


def fmu_header(t: Table) -> str:
    out = ["/*", " * The FMU's variable table and the items of its case file (fmu/case.h).",
           " * fmu/variables.h documents the columns of UDMAP_VARIABLE_TABLE."]
    out += [" * " + line for line in textwrap.wrap(STAMP[0].upper() + STAMP[1:] + ".", 92)]
    out += [" */",
           "#ifndef UDMAP_FMU_PARAMETERS_H", "#define UDMAP_FMU_PARAMETERS_H", "",
           "#define UDMAP_VARIABLE_TABLE(X) \\"]
    rows = fmu_rows(t)
    for k, r in enumerate(rows):
        start = str(r["start"]) if r["type"] == "INTEGER" and isinstance(r["start"], int) \
            else _c_num(r["start"])
        out.append(f"  X({r['name']}, {r['type']}, {r['causality']}, {r['group']}, "
                   f"\"{r['unit']}\", {start}, {_c_num(r['min'])}, {_c_num(r['max'])}, "
                   f"{r['flags']}, \\")
        pieces = c_string(r["doc"], "    ")
        last = k == len(rows) - 1
        for j, p in enumerate(pieces):
            end = j == len(pieces) - 1
            out.append(p + (")" + ("" if last else " \\") if end else " \\"))
    out += ["", "/* Items of resources/udmap-case.txt (fmu/case.h) that are case-file fields:",
            " * X(key, member of CaseConfig, conversion of the number read). */",
            "#define UDMAP_CASE_ITEMS(X) \\"]
    items = [f for f in t.fields if "case_item" in f]
    for k, f in enumerate(items):
        cast = "(double)" if f["type"] == "real" else "(int)"
        tail = "" if k == len(items) - 1 else " \\"
        out.append(f"  X(\"{f['name']}\", {f['case_item']}, {cast}){tail}")
    out += ["", "#endif /* UDMAP_FMU_PARAMETERS_H */"]
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------- Fortran

def _fortran_wrap(line: str, indent: str = "    ") -> list[str]:
    """Free-form continuation at 100 columns (split after ", ")."""
    out = []
    while len(line) > 100:
        cut = line.rindex(", ", 0, 97) + 1
        out.append(line[:cut] + " &")
        line = indent + "& " + line[cut:].lstrip()
    return out + [line]


def _constructor(lhs: str, type_name: str, pairs: list[tuple[str, str]]) -> list[str]:
    """`lhs = type_name(component=value, ...)`, a keyword structure constructor; the array
    components (pairs named `name(i)` or `name(i,j)`, listed in array element order) become
    one array value each. Lines break between values only."""
    groups: dict[str, list] = {}
    for comp, value in pairs:
        base, _, index = comp.partition("(")
        groups.setdefault(base, []).append((index.rstrip(")"), value))
    atoms = []
    for base, entries in groups.items():
        if entries[0][0] == "":
            atoms.append(f"{base}={entries[0][1]},")
            continue
        order = [tuple(int(x) for x in i.split(",")) for i, _ in entries]
        assert order == sorted(order, key=lambda k: k[::-1]), f"{base}: not in element order"
        shape = [max(k[d] for k in order) for d in range(len(order[0]))]
        values = [v + "," for _, v in entries]
        values[-1] = values[-1][:-1] + "]"
        if len(shape) == 1:
            values[0], values[-1] = f"{base}=[" + values[0], values[-1] + ","
        else:
            values[0] = f"{base}=reshape([" + values[0]
            values[-1] += f", [{', '.join(map(str, shape))}]),"
        atoms += values
    atoms[-1] = atoms[-1][:-1] + ")"
    out, line = [], f"    {lhs} = {type_name}(" + atoms[0]
    for atom in atoms[1:]:
        if len(line) + 1 + len(atom) > 98:
            out.append(line + " &")
            line = "      & " + atom
        else:
            line += " " + atom
    return out + [line]


def legacy_module(t: Table) -> str:
    structs = {(s["section"], s["kind"]): s for s in t.structs}
    uses, publics, decls, funcs = {}, [], [], []
    for a in t.legacy:
        kind = a.get("kind")
        flat = t.flat_of(a["section"], kind)
        what = f"{a['section']}" + (f" ({kind})" if kind else "")
        decls.append(f"  !> {a['array']}({len(a['entries'])}), the {what}: its length and the "
                     "index of each entry.")
        decls.append(f"  integer, parameter :: {a['length']} = {len(a['entries'])}")
        publics.append(a["length"])
        if "required" in a:
            nreq = 0
            for n in a["entries"]:
                if flat[n][0].get("default", "required") != "required":
                    break
                nreq += 1
            decls.append(f"  !> The least length of {a['array']}: its entries without "
                         "defaults.")
            decls.append(f"  integer, parameter :: {a['required']} = {nreq}")
            publics.append(a["required"])
        names = [f"{a['prefix']}_{n.upper()}" for n in a["entries"]]
        publics += names
        decls += _fortran_wrap("  integer, parameter :: " + ", ".join(
            f"{c} = {k}" for k, c in enumerate(names, start=1)))
        s = structs.get((a["section"], kind))
        if s and "legacy_function" in a:
            uses.setdefault(s["fortran_module"], []).append(s["fortran_type"])
            publics.append(a["legacy_function"])
            body = [f"  !> The {s['fortran_type']} of the array {a['array']} (whole-number "
                    "entries rounded).",
                    f"  pure function {a['legacy_function']}(a) result(p)",
                    f"    real(c_double), intent(in) :: a({a['length']})",
                    f"    type({s['fortran_type']}) :: p"]
            pairs = []
            for n, c in zip(a["entries"], names):
                f, _, comp = flat[n]
                pairs.append((comp, f"nint(a({c}))" if _is_int(f) else f"real(a({c}), wp)"))
            body += _constructor("p", s["fortran_type"], pairs)
            body.append(f"  end function {a['legacy_function']}")
            funcs.append(body)
    out = ["!> The plain-array layout of the legacy API: the arrays hold the fields of the C "
           "structs",
           "!> in their order (wrappers/c/udmap.h)."]
    out += ["!> " + line for line in textwrap.wrap(STAMP[0].upper() + STAMP[1:] + ".", 92)]
    out += [
           "module udmap_api_legacy_parameters",
           "  use, intrinsic :: iso_c_binding, only: c_double",
           f"  use {t.kinds_module}, only: wp"]
    out += [f"  use {m}, only: {', '.join(ts)}" for m, ts in uses.items()]
    out += ["  implicit none", "  private"]
    out += _fortran_wrap("  public :: " + ", ".join(publics))
    out += [""] + decls + ["", "contains"]
    for body in funcs:
        out += [""] + body
    out.append("end module udmap_api_legacy_parameters")
    return "\n".join(out) + "\n"


def c_types_module(t: Table) -> str:
    uses, publics, body = {}, [], []
    for s in t.structs:
        flat = t.flat_of(s["section"], s["kind"])
        uses.setdefault(s["fortran_module"], []).append(s["fortran_type"])
        publics += [s["fortran"], s["from_c"]] + ([s["to_c"]] if "to_c" in s else [])
        body += ["", f"  !> struct {s['name']} (wrappers/c/udmap.h).",
                 f"  type, bind(C) :: {s['fortran']}"]
        for line in s["lines"]:
            kind = "integer(c_int)" if _is_int(flat[line[0]][0]) else "real(c_double)"
            body.append(f"    {kind} :: {', '.join(line)}")
        body.append(f"  end type {s['fortran']}")
    funcs = []
    for s in t.structs:
        flat = t.flat_of(s["section"], s["kind"])
        funcs += ["", f"  !> The kernel's {s['fortran_type']} of the C struct {s['name']}.",
                  f"  pure function {s['from_c']}(c) result(p)",
                  f"    type({s['fortran']}), intent(in) :: c",
                  f"    type({s['fortran_type']}) :: p"]
        funcs += _constructor("p", s["fortran_type"], [
            (flat[n][2], f"int(c%{n})" if _is_int(flat[n][0]) else f"c%{n}")
            for line in s["lines"] for n in line])
        funcs.append(f"  end function {s['from_c']}")
        if "to_c" not in s:
            continue
        funcs += ["", f"  !> The C struct {s['name']} of the kernel's {s['fortran_type']}.",
                  f"  pure function {s['to_c']}(p) result(c)",
                  f"    type({s['fortran_type']}), intent(in) :: p",
                  f"    type({s['fortran']}) :: c"]
        funcs += _constructor("c", s["fortran"], [
            (n, f"int(p%{flat[n][2]}, c_int)" if _is_int(flat[n][0])
             else f"real(p%{flat[n][2]}, c_double)")
            for line in s["lines"] for n in line])
        funcs.append(f"  end function {s['to_c']}")
    out = ["!> The C API's parameter structs in Fortran and their conversion to the kernel's "
           "types."]
    out += ["!> " + line for line in textwrap.wrap(STAMP[0].upper() + STAMP[1:] + ".", 92)]
    out += ["module udmap_api_c_parameters",
           "  use, intrinsic :: iso_c_binding, only: c_double, c_int"]
    out += [f"  use {m}, only: {', '.join(ts)}" for m, ts in uses.items()]
    out += ["  implicit none", "  private"]
    out += _fortran_wrap("  public :: " + ", ".join(publics))
    out += body + ["", "contains"] + funcs + ["end module udmap_api_c_parameters"]
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------- driver

def generate(root: Path) -> dict[str, str]:
    """Generated path -> text."""
    with open(root / TABLE, "rb") as fh:
        t = Table(tomllib.load(fh), root)
    return {PYTHON: python_module(t),
            C_HEADER: c_header(t, (root / C_HEADER).read_text(encoding="utf-8")),
            FMU_HEADER: fmu_header(t),
            LEGACY: legacy_module(t),
            C_TYPES: c_types_module(t)}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", type=Path, help="write under this directory, not the source root")
    p.add_argument("--check", action="store_true",
                   help="fail if a checked-in generated file is not current")
    p.add_argument("--root", type=Path, default=ROOT,
                   help="the source tree (default: this script's checkout)")
    args = p.parse_args(argv)
    root = args.root
    files = generate(root)
    if args.check:
        stale = []
        with tempfile.TemporaryDirectory() as tmp:
            for path, text in files.items():
                (Path(tmp) / path).parent.mkdir(parents=True, exist_ok=True)
                (Path(tmp) / path).write_text(text, encoding="utf-8")
                fresh = (Path(tmp) / path).read_text(encoding="utf-8")
                current = (root / path).read_text(encoding="utf-8") \
                    if (root / path).is_file() else ""
                if fresh != current:
                    stale.append(path)
                    sys.stdout.writelines(difflib.unified_diff(
                        current.splitlines(True), fresh.splitlines(True),
                        f"{path} (checked in)", f"{path} (from {TABLE})", n=1))
        if stale:
            print(f"\nnot current with {TABLE}: {', '.join(stale)}\n"
                  f"regenerate with: python3 {ME} (or make parameters), then commit the files")
            return 1
        print(f"{len(files)} generated files are current with {TABLE}")
        return 0
    out = args.out or root
    for path, text in files.items():
        target = out / path
        target.parent.mkdir(parents=True, exist_ok=True)
        if not target.is_file() or target.read_text(encoding="utf-8") != text:
            target.write_text(text, encoding="utf-8")
            print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
