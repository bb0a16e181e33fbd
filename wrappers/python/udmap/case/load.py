"""Case files (INTERFACES.md "Case files"): loading and validation.

A case is JSON with sections ``blade``, ``damper`` and ``analysis``. Validation is complete
before anything is computed, and it is driven by one table, :data:`udmap.case.schema.SCHEMA`.
Unknown or missing fields, wrong JSON types (a list, an object, ``null`` or a Boolean where a
number or a string belongs), an unknown ``kind``, NaN and values outside the allowed range raise
:class:`InputError` naming the field by its dotted path and, for numbers, the allowed range:
``blade.E must be in [1e6, 1e13] Pa, got 1e300``. An ``fe`` blade is validated and reduced by
:mod:`udmap.case.fe`.
"""
from __future__ import annotations

import copy
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError
from . import traveling
from .schema import (OPTIONAL, REQUIRED, SCHEMA, SECTIONS, TABLE_GAMMA, TABLE_K, TOP_LEVEL, Field,
                     NonFinite, check_field, in_range, range_text, show_value)

#: The embedded default case (blade A with its asymmetric damper).
DEFAULT_CASE = Path(__file__).resolve().parent.parent / "data" / "blade_a.json"

@dataclass
class Case:
    """A validated case: plain dictionaries plus the directory relative paths refer to."""
    blade: dict
    damper: dict
    analysis: dict
    name: str = "case"
    base_dir: Path = field(default_factory=Path.cwd)
    #: For an ``fe`` blade: the validated ``fe`` section and its reduction (frequencies of the
    #: full and reduced model, cache directory); ``blade`` is then the reduced ``matrices`` blade.
    fe: dict | None = None

    def to_dict(self) -> dict:
        return {"name": self.name, "blade": copy.deepcopy(self.blade),
                "damper": copy.deepcopy(self.damper), "analysis": copy.deepcopy(self.analysis)}


def _object(path: str, value) -> dict:
    if not isinstance(value, dict):
        raise InputError(f"{path} must be an object, got {show_value(value)}")
    return value


def _check_section(section: str, data: dict, spec: dict[str, Field], extra=("kind",)) -> dict:
    """Validates ``data`` against the rows of one (section, kind) of the schema."""
    tree: dict = {}  # the nesting the dotted names describe: name -> subtree or Field
    for name, f in spec.items():
        node = tree
        *parents, leaf = name.split(".")
        for p in parents:
            node = node.setdefault(p, {})
        node[leaf] = f

    def walk(path: str, data, node: dict, allowed_extra=()) -> dict:
        data = _object(path, data)
        allowed = list(node) + list(allowed_extra)
        for key in data:
            if key not in allowed:
                raise InputError(f"{path}.{key}: unknown field (allowed: "
                                 f"{', '.join(sorted(allowed))})")
        out = {}
        for key, sub in node.items():
            where = f"{path}.{key}"
            if isinstance(sub, dict):
                if key not in data:
                    raise InputError(f"{where}: missing field")
                out[key] = walk(where, data[key], sub)
            elif key not in data or (data[key] is None and sub.default != REQUIRED):
                if sub.default == REQUIRED:
                    raise InputError(f"{where}: missing field")
                if sub.default != OPTIONAL:  # absent or null: the default
                    out[key] = copy.deepcopy(sub.default)
            else:
                out[key] = check_field(where, data[key], sub)
        return out

    return walk(section, data, tree, extra)


def _kind_of(section: str, data: dict) -> str:
    kinds = [k for s, k in SCHEMA if s == section] + (["fe"] if section == "blade" else [])
    kind = data.get("kind")
    if not (isinstance(kind, str) and kind in kinds):
        raise InputError(f"{section}.kind must be one of {', '.join(kinds)}, got "
                         f"{show_value(kind)}")
    return kind


def _resolve(where: str, name: str, base_dir: Path) -> str:
    p = Path(name)
    p = p if p.is_absolute() else base_dir / p
    try:
        found = p.is_file()
    except (OSError, ValueError):
        found = False
    if not found:
        raise InputError(f"{where}: file not found: {p}")
    return str(p)


def validate(data: dict, base_dir: Path | str = ".") -> Case:
    """Validates a case dictionary; relative file paths are resolved against ``base_dir``."""
    base_dir = Path(base_dir)
    if not isinstance(data, dict):
        raise InputError(f"case must be a JSON object, got {show_value(data)}")
    for key in data:
        if key not in SECTIONS and key not in TOP_LEVEL:
            raise InputError(f"{key}: unknown top-level field (allowed: "
                             f"{', '.join(list(TOP_LEVEL) + list(SECTIONS))})")
    for key in SECTIONS:
        if key not in data:
            raise InputError(f"{key}: missing section")
    top = {}
    for key, f in TOP_LEVEL.items():
        if key in data:
            top[key] = check_field(key, data[key], f)
        elif f.default not in (REQUIRED, OPTIONAL):
            top[key] = f.default

    sections = {}
    for section in SECTIONS:
        raw = _object(section, data[section])
        kinds = [k for s, k in SCHEMA if s == section]
        if kinds == [None]:
            sections[section] = _check_section(section, raw, SCHEMA[(section, None)], extra=())
        elif section == "blade" and raw.get("kind") == "fe":
            # an FE blade has its own checks (udmap.case.fe): files, node sets, directions
            # imported here: an fe blade needs scipy (and its reduction), a beam or matrices
            # case does not, and every command line call loads a case
            from . import fe as fe_case
            sections[section] = fe_case.validate_fe(raw, base_dir)
            sections[section]["kind"] = "fe"
        else:
            kind = _kind_of(section, raw)
            sections[section] = _check_section(section, raw, SCHEMA[(section, kind)])
            sections[section]["kind"] = kind
    blade, damper, analysis = sections["blade"], sections["damper"], sections["analysis"]
    traveling.settle_analysis(data["analysis"], analysis)

    if blade["kind"] == "matrices":
        _check_platform_dofs(blade)
        for key in ("M", "K", "C", "stress_K", "stress_M"):
            if key in blade:
                blade[key] = _resolve(f"blade.{key}", blade[key], base_dir)
    if damper["kind"] == "table":
        damper["file"] = _resolve("damper.file", damper["file"], base_dir)
        damper["rows"] = read_table_csv(Path(damper["file"]))
    if not analysis["f_max"] > analysis["f_min"]:
        raise InputError(f"analysis.f_max ({analysis['f_max']}) must exceed analysis.f_min "
                         f"({analysis['f_min']})")
    traveling.check_case(Case(blade=blade, damper=damper, analysis=analysis))
    fe = None
    if blade["kind"] == "fe":
        # Every command works on the reduced matrices blade (reduced once, cached by content).
        from . import fe as fe_case  # see above: scipy only for an fe blade
        blade, fe = fe_case.resolve(blade, analysis)
    return Case(blade=blade, damper=damper, analysis=analysis, name=top["name"],
                base_dir=base_dir, fe=fe)


def _check_platform_dofs(blade: dict) -> None:
    """blade.u_dof, blade.v_dof (PHYSICS.md 2.6): v_dof needs u_dof, and the platform's
    translations, its rotation and each other are different DOFs (the upper bound, the number of
    DOFs, is checked when the matrices are read)."""
    u, v = blade.get("u_dof"), blade.get("v_dof")
    if v is not None and u is None:
        raise InputError("blade.v_dof needs blade.u_dof (the circumferential translation)")
    for name, dof in (("u_dof", u), ("v_dof", v)):
        if dof is not None and dof == blade["gamma_dof"]:
            raise InputError(f"blade.{name} must differ from blade.gamma_dof ({dof}): the "
                             "platform rotation is not a translation")
    if u is not None and u == v:
        raise InputError(f"blade.v_dof must differ from blade.u_dof ({u})")


def read_table_csv(path: Path) -> list[tuple[float, float, float]]:
    """Reads a damper table CSV ``gamma,k_re,k_im`` (header optional), checking every row."""
    try:
        text = path.read_text()
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        raise InputError(f"damper.file: cannot read {path}: {exc}") from None
    rows = []
    for lineno, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        parts = [p.strip() for p in line.split(",")]
        try:
            values = [float(p) for p in parts]
        except ValueError:
            if not rows and lineno == 1:
                continue  # header line
            raise InputError(f"damper.file {path}:{lineno}: not three numbers: {line!r}") from None
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise InputError(f"damper.file {path}:{lineno}: expected three finite numbers "
                             f"gamma,k_re,k_im, got {line!r}")
        if not in_range(values[0], TABLE_GAMMA) or values[2] < 0 or not all(
                in_range(abs(v), TABLE_K) for v in values[1:]):
            raise InputError(f"damper.file {path}:{lineno}: gamma must be in "
                             f"{range_text(TABLE_GAMMA)}, |k_re| and k_im in "
                             f"{range_text(TABLE_K)} (k_im non-negative), got {line!r}")
        if rows and values[0] <= rows[-1][0]:
            raise InputError(f"damper.file {path}:{lineno}: gamma must be strictly ascending")
        rows.append(tuple(values))
    if len(rows) < 2:
        raise InputError(f"damper.file {path}: needs at least two rows")
    return rows


def load_case(path: str | Path | None = None) -> Case:
    """Loads and validates a case file (the embedded default when ``path`` is None)."""
    path = Path(path) if path is not None else DEFAULT_CASE
    try:
        text = path.read_text()
    except OSError as exc:
        raise InputError(f"case file {path}: {exc.strerror}") from None
    except (UnicodeDecodeError, ValueError) as exc:
        raise InputError(f"case file {path}: not a UTF-8 text file ({exc})") from None
    return loads_case(text, path.resolve().parent, source=f"case file {path}")


def loads_case(text: str, base_dir: Path | str = ".", source: str = "case") -> Case:
    """Parses and validates the JSON text of a case; ``source`` names it in messages. NaN and
    Infinity literals are kept until validation, so that the message names their field."""
    try:
        data = json.loads(text, parse_constant=NonFinite)
    except json.JSONDecodeError as exc:
        raise InputError(f"{source}: invalid JSON: {exc}") from None
    except RecursionError:
        raise InputError(f"{source}: invalid JSON: nested too deeply") from None
    try:
        return validate(data, base_dir)
    except InputError as exc:
        blade = data.get("blade") if isinstance(data, dict) else None
        if isinstance(blade, dict) and blade.get("kind") == "fe":
            # the fe section names files of its own: say which case they belong to
            raise InputError(f"{exc} [{source}]") from None
        raise
