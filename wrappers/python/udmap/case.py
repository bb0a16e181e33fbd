"""Case files (INTERFACES.md "Case files"): loading and validation.

A case is JSON with sections ``blade``, ``damper`` and ``analysis``. Validation is complete
before anything is computed, and it is driven by one table, :data:`SCHEMA`: every field with its
type, its allowed range (physical bounds, README "Case files"), its unit and its default.
Unknown or missing fields, wrong JSON types (a list, an object, ``null`` or a Boolean where a
number or a string belongs), an unknown ``kind``, NaN and values outside the allowed range raise
:class:`InputError` naming the field by its dotted path and, for numbers, the allowed range:
``blade.E must be in [1e6, 1e13] Pa, got 1e300``.
"""
from __future__ import annotations

import copy
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ._lib import InputError
from .parameters import CHOICE_CODES, FIELDS, FLAT_NAMES, TOP_LEVEL as _TOP_LEVEL

#: The embedded default case (blade A with its asymmetric damper).
DEFAULT_CASE = Path(__file__).resolve().parent / "data" / "blade_a.json"

#: Kernel codes of analysis.eigen_method.
EIGEN_METHODS = CHOICE_CODES[("analysis", None, "eigen_method")]

REQUIRED = "required"   # default marker: the field must be given
OPTIONAL = "optional"   # default marker: the field may be absent (no value is filled in)


@dataclass(frozen=True)
class Field:
    """One row of the schema.

    ``type``: ``real`` (a finite number in ``[lo, hi]``, or ``(lo, hi)`` when ``open``),
    ``int`` (an integer in ``[lo, hi]``, even if ``even``), ``point`` (``[x, y]``, each a real in
    ``[lo, hi]``), ``points`` (a list of ``count`` points), ``choice`` (one of ``choices``),
    ``harmonics`` (``1``, an integer in ``[lo, hi]`` or ``"auto"``), ``path`` (a file name
    relative to the case file) or ``text`` (a string). ``default``: :data:`REQUIRED`,
    :data:`OPTIONAL` or the value filled in when the field is absent.
    """
    type: str
    lo: float | None = None
    hi: float | None = None
    unit: str = ""
    default: Any = REQUIRED
    doc: str = ""
    open: bool = False
    even: bool = False
    count: int = 0
    choices: tuple = ()


#: The schema: (section, kind) -> {dotted field name: Field}. ``kind`` is None for sections
#: without kinds. Its rows come from the parameter table kernel/parameters.toml (through the
#: generated udmap.parameters): adding a field is one row there.
SCHEMA: dict[tuple, dict[str, Field]] = {}
for section, kind, name, keywords in FIELDS:
    SCHEMA.setdefault((section, kind), {})[name] = Field(**keywords)
del section, kind, name, keywords
#: Top-level fields besides the sections.
TOP_LEVEL = {name: Field(**keywords) for name, keywords in _TOP_LEVEL}
SECTIONS = ("blade", "damper", "analysis")
#: Analysis settings with their defaults (None: required), from the schema.
ANALYSIS_DEFAULTS: dict[str, Any] = {
    k: (None if f.default == REQUIRED else f.default)
    for k, f in SCHEMA[("analysis", None)].items() if f.default != OPTIONAL}


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


class _NonFinite(float):
    """A NaN or Infinity literal of the JSON text, kept so that the field it sits in is named."""

    def __new__(cls, text: str):
        obj = super().__new__(cls, text.replace("Infinity", "inf"))
        obj.text = text
        return obj


def fmt_number(x) -> str:
    """Numbers in messages: 15 significant digits, in exponent form outside [1e-4, 1e5) without
    '+' and leading zeros (1e6, 2.5e-5), NaN/inf as such; the FMU formats them the same way."""
    if isinstance(x, _NonFinite):
        return x.text
    if isinstance(x, int) and not isinstance(x, bool):
        if abs(x) < 10**15:
            return str(x)
        digits = str(abs(x))
        return f"{'-' if x < 0 else ''}{digits[0]}.{digits[1:4]}e{len(digits) - 1}"
    x = float(x)
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    if x != 0 and not 1e-4 <= abs(x) < 1e5:
        mantissa, _, exp = f"{x:.14e}".partition("e")
        return f"{mantissa.rstrip('0').rstrip('.')}e{int(exp)}"
    return f"{x:.15g}"


def _show(value) -> str:
    """A JSON value as the user wrote it, shortened."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return fmt_number(value)
    try:
        text = json.dumps(value, allow_nan=True, default=str)
    except (ValueError, RecursionError):
        text = type(value).__name__
    return text if len(text) <= 60 else text[:57] + "..."


def range_text(f: Field) -> str:
    """``[lo, hi] unit`` (round brackets for excluded bounds)."""
    a, b = ("(", ")") if f.open else ("[", "]")
    text = f"{a}{fmt_number(f.lo)}, {fmt_number(f.hi)}{b}"
    return f"{text} {f.unit}" if f.unit else text


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _in_range(x, f: Field) -> bool:
    try:
        x = float(x)
    except OverflowError:  # an integer beyond the double range
        return False
    if f.open:
        return f.lo < x < f.hi
    return f.lo <= x <= f.hi


def _check_real(path: str, value, f: Field) -> float:
    if not _is_number(value):
        raise InputError(f"{path} must be a number in {range_text(f)}, got {_show(value)}")
    if isinstance(value, _NonFinite):
        raise InputError(f"{path}: {value.text} is not a valid number in a case file (allowed: "
                         f"{range_text(f)})")
    if not _in_range(value, f):
        raise InputError(f"{path} must be in {range_text(f)}, got {fmt_number(value)}")
    return float(value)


def _whole(value) -> bool:
    """An integer, or a float with an integer value (JSON 8.0)."""
    if isinstance(value, bool):
        return False
    return isinstance(value, int) or (isinstance(value, float) and math.isfinite(value)
                                      and value.is_integer())


def _check_int(path: str, value, f: Field) -> int:
    what = "an even integer" if f.even else "an integer"
    if not _whole(value):
        raise InputError(f"{path} must be {what} in {range_text(f)}, got {_show(value)}")
    if not _in_range(value, f) or (f.even and int(value) % 2):
        raise InputError(f"{path} must be {what} in {range_text(f)}, got {fmt_number(value)}")
    return int(value)


def _check_point(path: str, value, f: Field) -> list:
    if not (isinstance(value, list) and len(value) == 2):
        raise InputError(f"{path} must be a point [x, y] with coordinates in {range_text(f)}, "
                         f"got {_show(value)}")
    return [_check_real(f"{path}[{i}]", x, f) for i, x in enumerate(value)]


def _check_points(path: str, value, f: Field) -> list:
    if not (isinstance(value, list) and len(value) == f.count):
        raise InputError(f"{path} must be {f.count} points [[x, y], ...] with coordinates in "
                         f"{range_text(f)}, got {_show(value)}")
    return [_check_point(f"{path}[{i}]", p, f) for i, p in enumerate(value)]


def _check_choice(path: str, value, f: Field) -> str:
    if not (isinstance(value, str) and value in f.choices):
        raise InputError(f"{path} must be one of {', '.join(f.choices)}, got {_show(value)}")
    return value


def _check_harmonics(path: str, value, f: Field):
    if value == "auto" and isinstance(value, str):
        return value
    if _whole(value) and (value == 1 or _in_range(value, f)):
        return int(value)
    raise InputError(f"{path} must be 1, an integer in {range_text(f)} or \"auto\", got "
                     f"{_show(value)}")


def _check_path(path: str, value, f: Field) -> str:
    if not isinstance(value, str) or not value or "\0" in value:
        raise InputError(f"{path} must be a file path (string), got {_show(value)}")
    return value


def _check_text(path: str, value, f: Field) -> str:
    if not isinstance(value, str):
        raise InputError(f"{path} must be a string, got {_show(value)}")
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:  # a lone surrogate escape (\ud800) would fail in plots, files
        raise InputError(f"{path} must be valid Unicode text, got {_show(value)}") from None
    return value


_CHECKS = {"real": _check_real, "int": _check_int, "point": _check_point,
           "points": _check_points, "choice": _check_choice, "harmonics": _check_harmonics,
           "path": _check_path, "text": _check_text}


def check_field(path: str, value, f: Field):
    """Validates one value against its schema row; returns it normalised."""
    return _CHECKS[f.type](path, value, f)


def _object(path: str, value) -> dict:
    if not isinstance(value, dict):
        raise InputError(f"{path} must be an object, got {_show(value)}")
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
        raise InputError(f"{section}.kind must be one of {', '.join(kinds)}, got {_show(kind)}")
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
        raise InputError(f"case must be a JSON object, got {_show(data)}")
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
            # an FE blade has its own checks (udmap.fe.case): files, node sets, directions
            from .fe.case import validate_fe
            sections[section] = validate_fe(raw, base_dir)
            sections[section]["kind"] = "fe"
        else:
            kind = _kind_of(section, raw)
            sections[section] = _check_section(section, raw, SCHEMA[(section, kind)])
            sections[section]["kind"] = kind
    blade, damper, analysis = sections["blade"], sections["damper"], sections["analysis"]

    if blade["kind"] == "matrices":
        for key in ("M", "K", "C", "stress_K", "stress_M"):
            if key in blade:
                blade[key] = _resolve(f"blade.{key}", blade[key], base_dir)
    if damper["kind"] == "table":
        damper["file"] = _resolve("damper.file", damper["file"], base_dir)
        damper["rows"] = read_table_csv(Path(damper["file"]))
    if not analysis["f_max"] > analysis["f_min"]:
        raise InputError(f"analysis.f_max ({analysis['f_max']}) must exceed analysis.f_min "
                         f"({analysis['f_min']})")
    fe = None
    if blade["kind"] == "fe":
        # Every command works on the reduced matrices blade (reduced once, cached by content).
        from .fe.case import resolve
        blade, fe = resolve(blade, analysis)
    return Case(blade=blade, damper=damper, analysis=analysis, name=top["name"],
                base_dir=base_dir, fe=fe)


#: Rows of a damper table: gamma [rad] and |k| [N m/rad] bounds.
TABLE_GAMMA = Field("real", 1e-12, 1.0, "rad")
TABLE_K = Field("real", 0.0, 1e15, "N.m/rad")


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
        if not _in_range(values[0], TABLE_GAMMA) or values[2] < 0 or not all(
                _in_range(abs(v), TABLE_K) for v in values[1:]):
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


def schema_markdown() -> str:
    """The schema as the Markdown table of the README ("Case files"; a test keeps them equal)."""
    lines = ["| field | type | allowed | default | meaning |", "| --- | --- | --- | --- | --- |"]
    for (section, kind), spec in SCHEMA.items():
        for name, f in spec.items():
            where = f"`{section}.{name}`" + (f" ({kind})" if kind else "")
            if f.type in ("real", "int", "point", "points"):
                allowed = range_text(f)
                kind_text = {"real": "number", "int": "even integer" if f.even else "integer",
                             "point": "[x, y]", "points": f"{f.count} points"}[f.type]
            elif f.type == "harmonics":
                allowed, kind_text = f"1, {range_text(f)} or `auto`", "integer or `auto`"
            elif f.type == "choice":
                allowed, kind_text = ", ".join(f"`{c}`" for c in f.choices), "string"
            else:
                allowed, kind_text = "an existing file", "path"
            default = {REQUIRED: "required", OPTIONAL: "optional"}.get(f.default) \
                if isinstance(f.default, str) and f.default in (REQUIRED, OPTIONAL) else \
                f"`{f.default}`" if isinstance(f.default, str) else fmt_number(f.default)
            lines.append(f"| {where} | {kind_text} | {allowed} | {default} | {f.doc} |")
    return "\n".join(lines) + "\n"


def loads_case(text: str, base_dir: Path | str = ".", source: str = "case") -> Case:
    """Parses and validates the JSON text of a case; ``source`` names it in messages. NaN and
    Infinity literals are kept until validation, so that the message names their field."""
    try:
        data = json.loads(text, parse_constant=_NonFinite)
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


def flat_params(data: dict, section: str, kind=None) -> dict:
    """The values of a validated section (of this kind) under the flat names of the C structs
    and the FMU (neck_L, flat1_x, ...; kernel/parameters.toml), absent optional fields left out."""
    out = {}
    for flat, dotted, coordinate in FLAT_NAMES[(section, kind)]:
        node = data
        for part in dotted.split("."):
            node = node.get(part) if isinstance(node, dict) else None
        if node is not None:
            for i in coordinate:
                node = node[i]
            out[flat] = node
    return out


def beam_params(blade: dict) -> dict:
    """The flat parameter names of the C API / FMU (neck_L, ...) for a beam blade section."""
    return flat_params(blade, "blade", "beam")


def build_blade(case: Case):
    """The kernel blade of a case."""
    from .blade import Blade
    b = case.blade
    if b["kind"] == "beam":
        return Blade.beam(**beam_params(b))
    return Blade.matrices(b["M"], b["K"], b["gamma_dof"], b["exc_dof"], zeta=b["zeta"],
                          C=b.get("C"), stress_K=b.get("stress_K"), stress_M=b.get("stress_M"))


def build_damper(case: Case):
    """The kernel damper (stiffness table) of a case."""
    from .damper import Damper
    d = case.damper
    if d["kind"] == "asymmetric":
        keys = ("CF", "mu", "pitch", "y_P", "beta_L_deg", "beta_R_deg", "flat_points",
                "curved_point", "kn_flat", "kt_flat", "kn_curved", "kt_curved")
        return Damper.asymmetric(**{k: d[k] for k in keys})
    if d["kind"] == "jenkins":
        return Damper.jenkins(d["kt"], d["M_slip"])
    rows = d["rows"]
    return Damper.table([r[0] for r in rows], [r[1] for r in rows], [r[2] for r in rows],
                        delta_M=d.get("delta_M"))


def build_model(case: Case, blade=None, damper=None):
    """The kernel model (blade + damper over the band) of a case."""
    from .model import Model
    a = case.analysis
    blade = blade if blade is not None else build_blade(case)
    damper = damper if damper is not None else build_damper(case)
    return Model(blade, damper, a["f_min"], a["f_max"], sigma_all=a["sigma_all"],
                 rtol=a["rtol"], grid_per_decade=a["grid_per_decade"],
                 eigen_method=EIGEN_METHODS[a["eigen_method"]], dense_max=a["dense_max"],
                 sweep_points=a["sweep_points"], harmonics=a["harmonics"],
                 harmonic_tol=a["harmonic_tol"])
