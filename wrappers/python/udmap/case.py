"""Case files (INTERFACES.md "Case files"): loading and validation.

A case is JSON with sections ``blade``, ``damper`` and ``analysis``. Validation is complete
before anything is computed: unknown or missing fields, wrong types, non-finite numbers and
out-of-range values raise :class:`InputError` naming the field by its dotted path.
"""
from __future__ import annotations

import copy
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ._lib import InputError

#: The embedded default case (blade A with its asymmetric damper).
DEFAULT_CASE = Path(__file__).resolve().parent / "data" / "blade_a.json"

# Per-kind field specifications: name -> (check, required, default).
# Checks: "pos" > 0, "nonneg" >= 0, "real" finite, "int_pos" integer >= 1, "point" [x, y],
# "points2" two points, "path" a file path relative to the case, "angle" in (0, 90) degrees.
_BEAM = {
    "E": "pos", "rho": "pos", "zeta": "nonneg",
    "neck": {"L": "pos", "h": "pos", "b": "pos", "elements": "int_pos"},
    "platform": {"L": "pos", "m": "pos", "J": "pos"},
    "airfoil": {"L": "pos", "h": "pos", "b": "pos", "elements": "int_even"},
}
_MATRICES = {"M": "path", "K": "path", "C": "path?", "gamma_dof": "int_pos",
             "exc_dof": "int_pos", "stress_K": "path?", "stress_M": "path?", "zeta": "nonneg?"}
_ASYMMETRIC = {
    "CF": "pos", "mu": "pos", "pitch": "pos", "y_P": "real",
    "beta_L_deg": "angle", "beta_R_deg": "angle",
    "flat_points": "points2", "curved_point": "point",
    "kn_flat": "pos", "kt_flat": "pos", "kn_curved": "pos", "kt_curved": "pos",
}
_JENKINS = {"kt": "pos", "M_slip": "pos"}
_TABLE = {"file": "path", "delta_M": "pos?"}
#: Analysis settings with their defaults (None: required).
ANALYSIS_DEFAULTS: dict[str, Any] = {
    "f_min": None,            # lower band edge [Hz]
    "f_max": None,            # upper band edge [Hz]
    "sigma_all": 80e6,        # allowable alternating stress [Pa]
    "rtol": 1e-12,            # relative tolerance of peak and root refinement
    "grid_per_decade": 24,    # backbone amplitude grid density for root bracketing
    "layers": 200,            # amplitude layers of the response curves (before adaptive refinement)
    "eigen_method": "auto",   # eigenvalue start: auto, direct (zggev/ARPACK) or modal (secular)
    "dense_max": 200,         # largest ndof solved densely by zggev; larger ones use ARPACK
    "sweep_points": 400,      # bare-blade frequency samples for bracketing curve crossings
}
#: Kernel codes of analysis.eigen_method.
EIGEN_METHODS = {"auto": 0, "direct": 1, "modal": 2}
_ANALYSIS = {"f_min": "pos", "f_max": "pos", "sigma_all": "pos?", "rtol": "pos?",
             "grid_per_decade": "int_pos?", "layers": "int_pos?", "eigen_method": "eigen?",
             "dense_max": "int_pos?", "sweep_points": "int_pos?"}


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


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _check_value(path: str, value, check: str):
    """Validates one value; returns it normalised (float/int/list/Path string)."""
    if check in ("pos", "nonneg", "real", "angle"):
        if not _is_number(value):
            raise InputError(f"{path} must be a number, got {json.dumps(value)}")
        v = float(value)
        if not math.isfinite(v):
            raise InputError(f"{path} must be a finite number, got {value}")
        if check == "pos" and not v > 0:
            raise InputError(f"{path} must be positive, got {value}")
        if check == "nonneg" and not v >= 0:
            raise InputError(f"{path} must be non-negative, got {value}")
        if check == "angle" and not 0 < v < 90:
            raise InputError(f"{path} must be an angle in degrees between 0 and 90, got {value}")
        return v
    if check in ("int_pos", "int_even"):
        if isinstance(value, bool) or not (isinstance(value, int) or
                                           (isinstance(value, float) and value.is_integer())):
            raise InputError(f"{path} must be an integer, got {json.dumps(value)}")
        v = int(value)
        if v < 1:
            raise InputError(f"{path} must be at least 1, got {value}")
        if check == "int_even" and v % 2:
            raise InputError(f"{path} must be even (E is the node at mid-length), got {value}")
        return v
    if check == "point":
        if not (isinstance(value, list) and len(value) == 2):
            raise InputError(f"{path} must be a point [x, y], got {json.dumps(value)}")
        return [_check_value(f"{path}[{i}]", x, "real") for i, x in enumerate(value)]
    if check == "points2":
        if not (isinstance(value, list) and len(value) == 2):
            raise InputError(f"{path} must be two points [[x, y], [x, y]], got {json.dumps(value)}")
        return [_check_value(f"{path}[{i}]", p, "point") for i, p in enumerate(value)]
    if check == "eigen":
        if value not in EIGEN_METHODS:
            raise InputError(f"{path} must be one of {', '.join(EIGEN_METHODS)}, got "
                             f"{json.dumps(value)}")
        return value
    if check == "path":
        if not isinstance(value, str) or not value:
            raise InputError(f"{path} must be a file path (string), got {json.dumps(value)}")
        return value
    raise AssertionError(check)


def _check_section(path: str, data, spec: dict, optional_kind=False) -> dict:
    if not isinstance(data, dict):
        raise InputError(f"{path} must be an object, got {json.dumps(data)}")
    out = {}
    allowed = set(spec) | ({"kind"} if optional_kind else set())
    for key in data:
        if key not in allowed:
            raise InputError(f"{path}.{key}: unknown field (allowed: {', '.join(sorted(allowed))})")
    for key, check in spec.items():
        sub = f"{path}.{key}"
        if isinstance(check, dict):
            if key not in data:
                raise InputError(f"{sub}: missing field")
            out[key] = _check_section(sub, data[key], check)
            continue
        optional = check.endswith("?")
        check = check.rstrip("?")
        if key not in data or data[key] is None:
            if optional:
                continue
            raise InputError(f"{sub}: missing field")
        out[key] = _check_value(sub, data[key], check)
    return out


def validate(data: dict, base_dir: Path | str = ".") -> Case:
    """Validates a case dictionary; relative file paths are resolved against ``base_dir``."""
    base_dir = Path(base_dir)
    if not isinstance(data, dict):
        raise InputError("case must be a JSON object")
    for key in data:
        if key not in ("name", "blade", "damper", "analysis", "description"):
            raise InputError(f"{key}: unknown top-level field (allowed: name, description, "
                             "blade, damper, analysis)")
    for key in ("blade", "damper", "analysis"):
        if key not in data:
            raise InputError(f"{key}: missing section")

    blade_in = data["blade"]
    if not isinstance(blade_in, dict):
        raise InputError("blade must be an object")
    kind = blade_in.get("kind")
    if kind == "beam":
        blade = _check_section("blade", blade_in, _BEAM, optional_kind=True)
    elif kind == "matrices":
        blade = _check_section("blade", blade_in, _MATRICES, optional_kind=True)
        blade.setdefault("zeta", 0.0)
        for key in ("M", "K", "C", "stress_K", "stress_M"):
            if key in blade:
                p = Path(blade[key])
                p = p if p.is_absolute() else base_dir / p
                if not p.is_file():
                    raise InputError(f"blade.{key}: file not found: {p}")
                blade[key] = str(p)
    elif kind == "fe":
        from .fe.case import validate_fe
        blade = validate_fe(blade_in, base_dir)
    else:
        raise InputError(f"blade.kind must be 'beam', 'matrices' or 'fe', got {json.dumps(kind)}")
    blade["kind"] = kind
    kind_blade = kind

    damper_in = data["damper"]
    if not isinstance(damper_in, dict):
        raise InputError("damper must be an object")
    kind = damper_in.get("kind")
    specs = {"asymmetric": _ASYMMETRIC, "jenkins": _JENKINS, "table": _TABLE}
    if kind not in specs:
        raise InputError("damper.kind must be 'asymmetric', 'jenkins' or 'table', got "
                         f"{json.dumps(kind)}")
    damper = _check_section("damper", damper_in, specs[kind], optional_kind=True)
    damper["kind"] = kind
    if kind == "table":
        p = Path(damper["file"])
        p = p if p.is_absolute() else base_dir / p
        damper["file"] = str(p)
        damper["rows"] = read_table_csv(p)

    analysis = _check_section("analysis", data["analysis"], _ANALYSIS)
    for key, default in ANALYSIS_DEFAULTS.items():
        if default is not None:
            analysis.setdefault(key, default)
    if not analysis["f_max"] > analysis["f_min"]:
        raise InputError(f"analysis.f_max ({analysis['f_max']}) must exceed analysis.f_min "
                         f"({analysis['f_min']})")

    name = data.get("name", "case")
    if not isinstance(name, str):
        raise InputError("name must be a string")
    fe = None
    if kind_blade == "fe":
        # Every command works on the reduced matrices blade (reduced once, cached by content).
        from .fe.case import resolve
        blade, fe = resolve(blade, analysis)
    return Case(blade=blade, damper=damper, analysis=analysis, name=name, base_dir=base_dir,
                fe=fe)


def read_table_csv(path: Path) -> list[tuple[float, float, float]]:
    """Reads a damper table CSV ``gamma,k_re,k_im`` (header optional), checking every row."""
    if not path.is_file():
        raise InputError(f"damper.file: file not found: {path}")
    rows = []
    for lineno, line in enumerate(path.read_text().splitlines(), 1):
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
        if values[0] <= 0 or values[2] < 0:
            raise InputError(f"damper.file {path}:{lineno}: gamma must be positive and k_im "
                             f"non-negative, got {line!r}")
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

    def reject_constant(name):
        raise InputError(f"case file {path}: {name} is not a valid number in a case file")

    try:
        data = json.loads(text, parse_constant=reject_constant)
    except json.JSONDecodeError as exc:
        raise InputError(f"case file {path}: invalid JSON: {exc}") from None
    try:
        return validate(data, path.resolve().parent)
    except InputError as exc:
        blade = data.get("blade") if isinstance(data, dict) else None
        if isinstance(blade, dict) and blade.get("kind") == "fe":
            raise InputError(f"{exc} [case file {path}]") from None
        raise


def beam_params(blade: dict) -> dict:
    """The flat parameter names of the C API / FMU (neck_L, ...) for a beam blade section."""
    p = {"E": blade["E"], "rho": blade["rho"], "zeta": blade["zeta"]}
    for part, keys in (("neck", ("L", "h", "b", "elements")), ("platform", ("L", "m", "J")),
                       ("airfoil", ("L", "h", "b", "elements"))):
        for key in keys:
            p[f"{part}_{key}"] = blade[part][key]
    return p


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
                 sweep_points=a["sweep_points"])
