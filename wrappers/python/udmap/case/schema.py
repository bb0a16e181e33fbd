"""The case-file schema (INTERFACES.md "Case files"): every field with its type, its allowed
range (physical bounds, docs/case-files.md), its unit and its default, in one table,
:data:`SCHEMA`, and the checks of one value against its row.

A value outside its row raises :class:`~udmap.errors.InputError` naming the field by its dotted
path and, for numbers, the allowed range: ``blade.E must be in [1e6, 1e13] Pa, got 1e300``.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from ..errors import InputError
from ..parameters import CHOICE_CODES, FIELDS, FLAT_NAMES, TOP_LEVEL as _TOP_LEVEL

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
    relative to the case file) or ``text`` (a string); for the ``fe`` blade (whose coordinates
    and units come from the FE model, so that only finiteness and signs are checked):
    ``finite`` (a finite number; at least ``lo``, or above it when ``open``), ``vec3``
    (``[x, y, z]`` of finite numbers, not the zero vector if ``nonzero``) and ``node`` (a node id).
    ``default``: :data:`REQUIRED`, :data:`OPTIONAL` or the value filled in when the field is
    absent.
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
    nonzero: bool = False


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


class NonFinite(float):
    """A NaN or Infinity literal of the JSON text, kept so that the field it sits in is named."""

    def __new__(cls, text: str):
        obj = super().__new__(cls, text.replace("Infinity", "inf"))
        obj.text = text
        return obj


def fmt_number(x) -> str:
    """Numbers in messages: 15 significant digits, in exponent form outside [1e-4, 1e5) without
    '+' and leading zeros (1e6, 2.5e-5), NaN/inf as such; the FMU formats them the same way."""
    if isinstance(x, NonFinite):
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


def show_value(value) -> str:
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


def in_range(x, f: Field) -> bool:
    try:
        x = float(x)
    except OverflowError:  # an integer beyond the double range
        return False
    if f.open:
        return f.lo < x < f.hi
    return f.lo <= x <= f.hi


def _check_real(path: str, value, f: Field) -> float:
    if not _is_number(value):
        raise InputError(f"{path} must be a number in {range_text(f)}, got {show_value(value)}")
    if isinstance(value, NonFinite):
        raise InputError(f"{path}: {value.text} is not a valid number in a case file (allowed: "
                         f"{range_text(f)})")
    if not in_range(value, f):
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
        raise InputError(f"{path} must be {what} in {range_text(f)}, got {show_value(value)}")
    if not in_range(value, f) or (f.even and int(value) % 2):
        raise InputError(f"{path} must be {what} in {range_text(f)}, got {fmt_number(value)}")
    return int(value)


def _check_point(path: str, value, f: Field) -> list:
    if not (isinstance(value, list) and len(value) == 2):
        raise InputError(f"{path} must be a point [x, y] with coordinates in {range_text(f)}, "
                         f"got {show_value(value)}")
    return [_check_real(f"{path}[{i}]", x, f) for i, x in enumerate(value)]


def _check_points(path: str, value, f: Field) -> list:
    if not (isinstance(value, list) and len(value) == f.count):
        raise InputError(f"{path} must be {f.count} points [[x, y], ...] with coordinates in "
                         f"{range_text(f)}, got {show_value(value)}")
    return [_check_point(f"{path}[{i}]", p, f) for i, p in enumerate(value)]


def _check_choice(path: str, value, f: Field) -> str:
    if not (isinstance(value, str) and value in f.choices):
        raise InputError(f"{path} must be one of {', '.join(f.choices)}, got {show_value(value)}")
    return value


def _check_harmonics(path: str, value, f: Field):
    if value == "auto" and isinstance(value, str):
        return value
    if _whole(value) and (value == 1 or in_range(value, f)):
        return int(value)
    raise InputError(f"{path} must be 1, an integer in {range_text(f)} or \"auto\", got "
                     f"{show_value(value)}")


def _check_path(path: str, value, f: Field) -> str:
    if not isinstance(value, str) or not value or "\0" in value:
        raise InputError(f"{path} must be a file path (string), got {show_value(value)}")
    return value


def _check_text(path: str, value, f: Field) -> str:
    if not isinstance(value, str):
        raise InputError(f"{path} must be a string, got {show_value(value)}")
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:  # a lone surrogate escape (\ud800) would fail in plots, files
        raise InputError(f"{path} must be valid Unicode text, got {show_value(value)}") from None
    return value


def _check_finite(path: str, value, f: Field) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(f"{path} must be a finite number, got {json.dumps(value)}")
    if f.lo is not None and f.open and not value > f.lo:
        raise InputError(f"{path} must be positive, got {value}")
    if f.lo is not None and not f.open and float(value) < f.lo:
        raise InputError(f"{path} must be non-negative, got {float(value)}")
    return float(value)


def _check_vec3(path: str, value, f: Field) -> list:
    if not (isinstance(value, list) and len(value) == 3):
        raise InputError(f"{path} must be three numbers [x, y, z], got {json.dumps(value)}")
    out = [_check_finite(f"{path}[{i}]", x, Field("finite")) for i, x in enumerate(value)]
    if f.nonzero and not sum(x * x for x in out) > 0:
        raise InputError(f"{path} has zero length: it must give a direction")
    return out


def _check_node(path: str, value, f: Field) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise InputError(f"{path} must be a node id (integer), got {json.dumps(value)}")
    return value


_CHECKS = {"real": _check_real, "int": _check_int, "point": _check_point,
           "points": _check_points, "choice": _check_choice, "harmonics": _check_harmonics,
           "path": _check_path, "text": _check_text, "finite": _check_finite,
           "vec3": _check_vec3, "node": _check_node}


def check_field(path: str, value, f: Field):
    """Validates one value against its schema row; returns it normalised."""
    return _CHECKS[f.type](path, value, f)


#: Rows of a damper table: gamma [rad] and |k| [N m/rad] bounds.
TABLE_GAMMA = Field("real", 1e-12, 1.0, "rad")
TABLE_K = Field("real", 0.0, 1e15, "N.m/rad")

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
