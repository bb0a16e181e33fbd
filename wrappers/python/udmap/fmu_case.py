"""``udmap fmu CASE --out NAME.fmu [--fmi 2|3]``: an FMU of the user's case.

The generic FMU (``udmap.fmu_path``) is re-used as it is: the same binary, which finds the case
in ``resources/udmap-case.txt`` at instantiation (fmu/case.h) and reads the blade's matrices
and the damper through the kernel's own readers. What changes is the description: the case's
own instantiation token (a hash of the case's content and of the generic FMU's token), start
values from the case, the variables that do not apply to the case's blade and damper left out,
and a documentation page that says which blade and damper the FMU holds. Variable names and
behaviour are those of ``build/udmap.fmu``.

Any blade kind that reduces to ``beam`` or ``matrices`` (a ``fe`` case is reduced to its
``matrices`` case first) and any damper kind (``asymmetric``, ``jenkins``, a measured
``table``) are accepted.
"""
from __future__ import annotations

import hashlib
import html
import json
import os
import tempfile
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

from .case import Case, beam_params, flat_params, load_case
from .errors import InputError
from .locate import fmu_path
from .parameters import CASE_ITEMS, CHOICE_CODES, FMU_KIND_VARIABLES

# the FMU variables of a beam blade and of an asymmetric damper (from kernel/parameters.toml)
BEAM = list(FMU_KIND_VARIABLES[("blade", "beam")])
ASYMMETRIC = list(FMU_KIND_VARIABLES[("damper", "asymmetric")])
MATRIX_FILES = ("M", "K", "C", "stress_K", "stress_M")


def matrices_case(case: Case) -> Case:
    """The case with a blade the FMU can hold (``beam`` or ``matrices``): a ``fe`` blade is
    reduced to its ``matrices`` case (the reduction of ``udmap reduce``)."""
    kind = case.blade["kind"]
    if kind in ("beam", "matrices"):  # load_case has already reduced an fe blade to matrices
        return case
    raise InputError(f"blade.kind {kind!r} cannot go into an FMU")


def starts_and_absent(case: Case) -> tuple[dict, set]:
    """Start values of the variables from the case, and the variables that do not apply."""
    b, d, a = case.blade, case.damper, case.analysis
    starts = {"f_min": a["f_min"], "f_max": a["f_max"], "sigma_all": a["sigma_all"],
              "harmonics": 0 if a["harmonics"] == "auto" else a["harmonics"]}
    absent: set[str] = set()
    if b["kind"] == "beam":
        starts.update(beam_params(b))
    else:
        absent.update(BEAM)
        if b.get("C"):
            absent.add("zeta")  # explicit damping: zeta is not used
        else:
            starts["zeta"] = b.get("zeta") or 0.0
    if d["kind"] == "asymmetric":
        starts.update(flat_params(d, "damper", "asymmetric"))
    else:
        absent.update(ASYMMETRIC)
    # the traveling wave (PHYSICS.md 2.6): the FMU takes it as integers, blades and engine_order
    if a.get("blades") is not None:
        starts["blades"] = int(a["blades"])
        starts["engine_order"] = int(a.get("engine_order") or 0)
    elif float(a.get("ibpa_deg") or 0.0) % 360.0 != 0.0:
        raise InputError("analysis.ibpa_deg: the FMU takes the traveling wave as its integer "
                         "parameters blades and engine_order; give analysis.blades and "
                         "analysis.engine_order in the case instead")
    return starts, absent


def _token(generic_token: str, case_text: str, files: dict[str, bytes]) -> str:
    h = hashlib.sha256(generic_token.encode() + b"\0" + case_text.encode())
    for name in sorted(files):
        h.update(b"\0" + name.encode() + b"\0" + hashlib.sha256(files[name]).digest())
    x = h.hexdigest()
    return f"{{{x[:8]}-{x[8:12]}-{x[12:16]}-{x[16:20]}-{x[20:32]}}}"


def _items(data: dict, where: tuple) -> list[str]:
    """The lines "name value" of the case-file items of the section or kind `where` (section,
    kind) whose validated fields are `data` (fmu/case.c reads them)."""
    lines = []
    for name, kind in CASE_ITEMS[where]:
        x = data.get(name)
        if x is None:  # an optional field the case does not give
            continue
        if kind == "choice":
            x = CHOICE_CODES[(*where, name)][x]
        lines.append(f"{name} {float(x)!r}" if kind == "real" else f"{name} {int(x)}")
    return lines


def _case_file(case: Case, starts: dict, absent: set, files: dict) -> str:
    """resources/udmap-case.txt without its token line (fmu/case.h)."""
    b, d, a = case.blade, case.damper, case.analysis
    lines = [f"blade {b['kind']}"]
    if b["kind"] == "matrices":
        for key in MATRIX_FILES:
            if b.get(key):
                files[f"{key}.mtx"] = Path(b[key]).read_bytes()
                lines.append(f"{key} {key}.mtx")
        lines += _items(b, ("blade", "matrices"))
    lines.append(f"damper {d['kind']}")
    if d["kind"] == "jenkins":
        lines += _items(d, ("damper", "jenkins"))
    elif d["kind"] == "table":
        if d.get("delta_M") is not None:
            lines.append(f"delta_M {float(d['delta_M'])!r}")
        lines.append(f"table {len(d['rows'])}")
        lines += [" ".join(repr(float(x)) for x in row) for row in d["rows"]]
    lines += _items(a, ("analysis", None))
    lines += [f"start {k} {float(v)!r}" for k, v in sorted(starts.items())]
    lines += [f"absent {k}" for k in sorted(absent)]
    return "\n".join(lines) + "\n"


def _value_text(x, integer: bool) -> str:
    return str(int(x)) if integer else repr(float(x))


def _description(xml: bytes, fmi: int, token: str, starts: dict, absent: set,
                 what: str) -> tuple[bytes, list]:
    """The generic description with the case's token, starts, description, and without the
    absent variables (FMI 2 indices renumbered). Also returns the kept variables' rows."""
    root = ET.fromstring(xml)
    root.set("guid" if fmi == 2 else "instantiationToken", token)
    root.set("description", f"{root.get('description')}. {what}")
    mv = root.find("ModelVariables")
    old_index, new_index, rows = {}, {}, []
    for i, v in enumerate(list(mv), start=1):
        name, vr = v.get("name"), int(v.get("valueReference"))
        old_index[i] = vr
        if name in absent:
            mv.remove(v)
            continue
        new_index[vr] = len(new_index) + 1
        typed = v[0] if fmi == 2 else v
        if name in starts:
            integer = typed.tag in ("Integer", "Int32")
            typed.set("start", _value_text(starts[name], integer))
        rows.append((name, v.get("causality"), typed.get("start", ""), typed.get("unit", ""),
                     v.get("description", "")))
    kept_vrs = set(new_index)
    for u in root.iter():
        if u.get("dependencies") is None:
            continue
        deps = u.get("dependencies").split()
        kinds = (u.get("dependenciesKind") or "").split() or [None] * len(deps)
        keep = []
        for dep, kind in zip(deps, kinds):
            vr = old_index[int(dep)] if fmi == 2 else int(dep)
            if vr in kept_vrs:
                keep.append((str(new_index[vr]) if fmi == 2 else dep, kind))
        u.set("dependencies", " ".join(d for d, _ in keep))
        if u.get("dependenciesKind") is not None:
            u.set("dependenciesKind", " ".join(k for _, k in keep))
    if fmi == 2:
        for u in root.find("ModelStructure").iter("Unknown"):
            u.set("index", str(new_index[old_index[int(u.get("index"))]]))
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root), rows


def _what(case: Case, source: str) -> str:
    b, d = case.blade, case.damper
    blade = ("the built-in beam blade" if b["kind"] == "beam" else
             f"a matrices blade ({Path(b['K']).name}, gamma_P at DOF {b['gamma_dof']}, "
             f"excitation at DOF {b['exc_dof']})")
    damper = {"asymmetric": "an asymmetric flat/curved damper",
              "jenkins": f"a rotational Jenkins damper (kt = {d.get('kt')}, "
                         f"M_slip = {d.get('M_slip')})",
              "table": f"a measured damper table ({len(d.get('rows', []))} rows)"}[d["kind"]]
    return f"Case {source}: {blade} with {damper}"


def _html(what: str, token: str, fmi: int, rows: list, absent: set) -> bytes:
    e = html.escape
    out = ["<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n",
           f"<title>udmap FMU of a case</title>\n</head>\n<body>\n<h1>udmap FMU of a case</h1>\n",
           f"<p>{e(what)}. FMI {fmi}.0, model exchange and co-simulation, instantiation token "
           f"<code>{e(token)}</code>. Made by <code>udmap fmu</code> from the generic udmap "
           "FMU: the same binary, which reads the case from <code>resources/</code> when it "
           "is instantiated; the variables and their behaviour are those of "
           "<code>udmap.fmu</code>.</p>\n"]
    if absent:
        out.append("<p>Left out (they do not apply to this blade and damper): "
                   + ", ".join(f"<code>{e(n)}</code>" for n in sorted(absent)) + ".</p>\n")
    out.append("<table>\n<tr><th>name</th><th>causality</th><th>start</th><th>unit</th>"
               "<th>description</th></tr>\n")
    for name, caus, start, unit, desc in rows:
        out.append(f"<tr><td><code>{e(name)}</code></td><td>{e(caus or '')}</td><td>{e(start)}"
                   f"</td><td>{e(unit)}</td><td>{e(desc)}</td></tr>\n")
    out.append("</table>\n<p>Licences: <a href=\"licenses/license.txt\">licenses/</a>.</p>\n"
               "</body>\n</html>\n")
    return "".join(out).encode()


def write_atomic(path: Path, writer, prefix: str | None = None) -> Path:
    """Calls ``writer(tmp)`` on a temporary file beside `path`, gives it mode 0666 less the
    umask (as any file the user creates; mkstemp makes it 0600) and renames it to `path`: the
    file is written whole or not at all. Also the command line's --out files."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=prefix or f".{path.stem}-", suffix=path.suffix,
                               dir=path.parent)
    os.close(fd)
    try:
        writer(Path(tmp))
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    return path


def write_case_fmu(case: Case, out: Path, fmi: int = 2, source: str = "") -> Path:
    """Writes the FMU of `case` to `out` (whole or not at all); returns its path."""
    case = matrices_case(case)
    generic = fmu_path(fmi)
    starts, absent = starts_and_absent(case)
    files: dict[str, bytes] = {}
    body = _case_file(case, starts, absent, files)
    with zipfile.ZipFile(generic) as zf:
        entries = {n: zf.read(n) for n in zf.namelist()}
    generic_root = ET.fromstring(entries["modelDescription.xml"])
    generic_token = generic_root.get("guid" if fmi == 2 else "instantiationToken")
    token = _token(generic_token, body, files)
    what = _what(case, source or case.name or "")
    description, rows = _description(entries["modelDescription.xml"], fmi, token, starts,
                                     absent, what)
    entries["modelDescription.xml"] = description
    entries["documentation/index.html"] = _html(what, token, fmi, rows, absent)
    entries["resources/udmap-case.txt"] = (f"# {what}\ntoken {token}\n" + body).encode()
    for name, data in files.items():
        entries[f"resources/{name}"] = data
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)

    def write_zip(tmp: Path) -> None:
        with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as zf:
            for name in sorted(entries):
                if not name.endswith("/"):
                    zf.writestr(name, entries[name])
    write_atomic(out, write_zip, prefix=".udmap-fmu-")
    return out


def cmd_fmu(args) -> None:
    if not args.out.endswith(".fmu"):
        raise InputError(f"--out must name a .fmu file, got {args.out!r}")
    if Path(args.out).exists() and not args.force:
        raise InputError(f"--out {args.out} exists: pass --force to overwrite it")
    case = load_case(args.case)
    path = write_case_fmu(case, Path(args.out), args.fmi, source=Path(args.case).name)
    if args.json:
        print(json.dumps({"fmu": str(path), "fmi": args.fmi}))
    else:
        print(f"wrote {path} (FMI {args.fmi}.0)")


def add_fmu_parser(sub) -> None:
    p = sub.add_parser("fmu", help="an FMU of the case (same interface as build/udmap.fmu)",
                       description="An FMU (model exchange and co-simulation) whose blade and "
                       "damper are the case's: the generic binary with the case in resources/.")
    p.add_argument("case", metavar="CASE", help="case file (JSON)")
    p.add_argument("--out", required=True, help="the FMU to write (NAME.fmu)")
    p.add_argument("--fmi", type=int, choices=(2, 3), default=2, help="FMI version (2 or 3)")
    p.add_argument("--force", action="store_true", help="overwrite an existing --out file")
    p.add_argument("--json", action="store_true", help="print JSON on stdout")
    p.set_defaults(func=cmd_fmu)


