"""The case-file schema (INTERFACES.md "Case files"): every field with its type, its allowed
range (physical bounds, README "Case files"), its unit and its default, in one table,
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

#: Kernel codes of analysis.eigen_method.
EIGEN_METHODS = {"auto": 0, "direct": 1, "modal": 2}

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


def _real(lo, hi, unit, doc, default=REQUIRED, open=False):
    return Field("real", lo, hi, unit, default, doc, open=open)


def _int(lo, hi, doc, default=REQUIRED, even=False):
    return Field("int", lo, hi, "", default, doc, even=even)


# Shared bounds (why these numbers: README "Case files", valid ranges).
_LENGTH = (1e-4, 3.0)        # m: beam lengths, micro-turbines to beyond the longest LP blades
_SECTION = (1e-5, 1.0)       # m: section height and width
_COORD = (-1.0, 1.0)         # m: damper geometry, coordinates from the damper's centre of gravity
_CONTACT = (1e2, 1e12)       # N/m: contact stiffness per contact point
_ZETA = (0.0, 0.5)           # damping ratio of the first mode, well below critical
_BAND = (1e-3, 1e6)          # Hz

#: The schema: (section, kind) -> {dotted field name: Field}. ``kind`` is None for sections
#: without kinds. Adding a field is one line here; nested objects are spelled with dots.
SCHEMA: dict[tuple, dict[str, Field]] = {
    ("blade", "beam"): {
        "E": _real(1e6, 1e13, "Pa", "Young's modulus: elastomers to beyond diamond (1.2e12)"),
        "rho": _real(1e2, 3e4, "kg/m3", "density: foams to beyond osmium (22600)"),
        "zeta": _real(*_ZETA, "", "damping ratio of the first bare-blade mode, up to half "
                  "critical"),
        "neck.L": _real(*_LENGTH, "m", "neck length: micro-turbines to beyond the longest "
                        "steam-turbine blades"),
        "neck.h": _real(*_SECTION, "m", "neck section height (bending direction)"),
        "neck.b": _real(*_SECTION, "m", "neck section width"),
        "neck.elements": _int(1, 1000, "neck beam elements (the first modes converge with a few)"),
        "platform.L": _real(1e-5, 1.0, "m", "platform length"),
        "platform.m": _real(1e-6, 1e3, "kg", "platform mass: 1 mg to 1 t"),
        "platform.J": _real(1e-15, 1e2, "kg.m2", "platform rotary inertia about P: those masses "
                            "at 30 um to 0.3 m"),
        "airfoil.L": _real(*_LENGTH, "m", "airfoil length"),
        "airfoil.h": _real(*_SECTION, "m", "airfoil section height (bending direction)"),
        "airfoil.b": _real(*_SECTION, "m", "airfoil section width"),
        "airfoil.elements": _int(2, 1000, "airfoil beam elements (even: E is a node)", even=True),
    },
    ("blade", "matrices"): {
        "M": Field("path", doc="mass matrix (Matrix Market)"),
        "K": Field("path", doc="stiffness matrix (Matrix Market)"),
        "C": Field("path", default=OPTIONAL, doc="damping matrix (Matrix Market)"),
        "gamma_dof": _int(1, 10**8, "DOF of the platform rotation (1-based)"),
        "exc_dof": _int(1, 10**8, "DOF of the excitation (1-based)"),
        "stress_K": Field("path", default=OPTIONAL, doc="stress row, stiffness part"),
        "stress_M": Field("path", default=OPTIONAL, doc="stress row, mass part"),
        "zeta": _real(*_ZETA, "", "damping ratio of the first bare-blade mode", default=0.0),
    },
    ("damper", "asymmetric"): {
        "CF": _real(1e-3, 1e6, "N", "centrifugal load on the damper (real dampers: 10 N to "
                    "10 kN)"),
        "mu": _real(1e-4, 10.0, "", "friction coefficient (dry metals: 0.1 to 1.5; large values "
                    "jam the damper: status 3)"),
        "pitch": _real(1e-6, 1.0, "m", "distance between the platform centres"),
        "y_P": _real(*_COORD, "m", "radial coordinate of the platform centres (damper geometry: "
                     "within 1 m of its centre of gravity)"),
        "beta_L_deg": _real(0.0, 90.0, "deg", "left face inclination", open=True),
        "beta_R_deg": _real(0.0, 90.0, "deg", "right face inclination", open=True),
        "flat_points": Field("points", *_COORD, "m", doc="flat-side contact points", count=2),
        "curved_point": Field("point", *_COORD, "m", doc="curved-side contact point"),
        "kn_flat": _real(*_CONTACT, "N/m", "normal stiffness, flat side (soft polymer to stiffer "
                           "than a 1 m steel cube)"),
        "kt_flat": _real(*_CONTACT, "N/m", "tangential stiffness, flat side"),
        "kn_curved": _real(*_CONTACT, "N/m", "normal stiffness, curved side"),
        "kt_curved": _real(*_CONTACT, "N/m", "tangential stiffness, curved side"),
    },
    ("damper", "jenkins"): {
        "kt": _real(1e-6, 1e12, "N.m/rad", "stuck stiffness (wide: non-dimensional models too)"),
        "M_slip": _real(1e-9, 1e9, "N.m", "slip moment"),
    },
    ("damper", "table"): {
        "file": Field("path", doc="CSV gamma,k_re,k_im"),
        "delta_M": _real(1e-12, 1e9, "N.m", "moment swing for extrapolation", default=OPTIONAL),
    },
    ("analysis", None): {
        "f_min": _real(*_BAND, "Hz", "lower edge of the band in which the resonance is sought "
                      "(1 mHz: non-dimensional models)"),
        "f_max": _real(*_BAND, "Hz", "upper edge of the band"),
        "sigma_all": _real(1e3, 1e10, "Pa", "allowable alternating stress of the HCF check (up to "
                          "beyond any material's strength)", default=80e6),
        "rtol": _real(1e-15, 1e-3, "", "relative tolerance of peak and root refinement (kernel "
                      "limits, as below)", default=1e-12),
        "grid_per_decade": _int(2, 1000, "amplitude grid on which backbone roots are "
                                "bracketed", default=24),
        "layers": _int(4, 100000, "amplitude layers of the response curves (refined "
                      "adaptively)", default=200),
        "eigen_method": Field("choice", default="auto", choices=tuple(EIGEN_METHODS),
                              doc="eigenvalue start: direct (zggev; ARPACK for large models) "
                              "or modal (secular equation)"),
        "dense_max": _int(1, 100000, "largest number of DOFs solved densely by zggev", default=200),
        "sweep_points": _int(16, 1000000, "bare-blade frequency samples for bracketing "
                             "curve crossings",
                             default=400),
        "harmonics": Field("harmonics", 2, 64, default=1,
                           doc="1, harmonics 0..H, or auto (PHYSICS.md 4.1)"),
        "harmonic_tol": _real(1e-10, 0.1, "", "relative change that stops harmonics auto "
                              "(the kernel's limits)", default=1e-3),
    },
}
#: Top-level fields besides the sections.
TOP_LEVEL = {"name": Field("text", default="case", doc="case name"),
             "description": Field("text", default=OPTIONAL, doc="free text")}
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
