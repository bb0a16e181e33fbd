"""The varied parameters of a design of experiments: their names (dotted paths into the case,
or the flat FMU names), their ranges and scales, and a case with some of them set."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Sequence

from ..case import Case, validate
from ..errors import InputError

SECTIONS = ("blade", "damper", "analysis")
#: A common factor of the asymmetric damper's four contact stiffnesses (kn_flat, kt_flat,
#: kn_curved, kt_curved; 1 = the case's values): a design parameter of its own, not a case
#: field. Designs that differ only in it and CF share one tracing (PHYSICS.md 2.3).
STIFFNESS_SCALE = "stiffness_scale"
STIFFNESS_SCALE_PATH = ("damper", STIFFNESS_SCALE)
STIFFNESS_FIELDS = ("kn_flat", "kt_flat", "kn_curved", "kt_curved")
# Numeric leaves that are identifiers or data, not design parameters.
_NOT_PARAMETERS = {("blade", "gamma_dof"), ("blade", "exc_dof"), ("blade", "u_dof"),
                   ("blade", "v_dof")}


@dataclass(frozen=True)
class Parameter:
    """One varied parameter: ``name`` as the user wrote it (the output column), ``path`` into
    the case dictionaries, ``lo``/``hi`` bounds, ``scale`` 'linear' or 'log', and ``integer``
    0 (real), 1 (integer) or 2 (even integer)."""
    name: str
    path: tuple
    lo: float
    hi: float
    scale: str = "linear"
    integer: int = 0

    @property
    def dotted(self) -> str:
        """The path as text, e.g. ``damper.flat_points[0][1]``."""
        out = self.path[0]
        for key in self.path[1:]:
            out += f"[{key}]" if isinstance(key, int) else f".{key}"
        return out

    def cast(self, x: float):
        """The value a design uses for the sample ``x`` (rounded for integer parameters)."""
        if self.integer == 2:
            return 2 * int(round(x / 2.0))
        if self.integer == 1:
            return int(round(x))
        return float(x)


def _leaves(node, path=()):
    """Yields (path, value) for every numeric leaf of a case section."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key in ("kind", "rows", "file", "name"):
                continue
            yield from _leaves(value, path + (key,))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from _leaves(value, path + (i,))
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        if path not in _NOT_PARAMETERS:
            yield path, node


def parameter_names(case: Case) -> dict[str, tuple]:
    """Every name a parameter of ``case`` can be varied by, mapped to its path: the dotted paths
    (``damper.flat_points.0.1`` spelled ``damper.flat_points[0][1]``) and the FMU names."""
    names: dict[str, tuple] = {}
    sections = {"blade": case.blade, "damper": case.damper, "analysis": case.analysis}
    for section, data in sections.items():
        for path, _ in _leaves(data, (section,)):
            names[Parameter("", path, 0, 0).dotted] = path
    # FMU names (INTERFACES.md "FMU"): underscores for the beam parts, flatN_x/curved_y for the
    # damper contact points, the other scalars of every section by their own names.
    for section, data in sections.items():
        for key, value in data.items():
            if isinstance(value, dict):
                for sub, v in value.items():
                    if isinstance(v, (int, float)) and not isinstance(v, bool):
                        names.setdefault(f"{key}_{sub}", (section, key, sub))
            elif isinstance(value, (int, float)) and not isinstance(value, bool):
                if (section, key) not in _NOT_PARAMETERS:
                    names.setdefault(key, (section, key))
    if "flat_points" in case.damper:
        for i in range(len(case.damper["flat_points"])):
            for j, axis in enumerate("xy"):
                names[f"flat{i + 1}_{axis}"] = ("damper", "flat_points", i, j)
    if "curved_point" in case.damper:
        for j, axis in enumerate("xy"):
            names[f"curved_{axis}"] = ("damper", "curved_point", j)
    if case.damper.get("kind") == "asymmetric":
        names[STIFFNESS_SCALE] = STIFFNESS_SCALE_PATH
        names["damper." + STIFFNESS_SCALE] = STIFFNESS_SCALE_PATH
    return names


def resolve_name(case: Case, name: str) -> tuple:
    """The path of parameter ``name`` in ``case``; InputError listing the known names if none."""
    names = parameter_names(case)
    if name in names:
        return names[name]
    # Dotted spellings: damper.flat_points.0.1, flat_points[0][1], airfoil.h (section implied).
    norm = re.sub(r"\[(\d+)\]", r".\1", name)
    tokens = tuple(int(t) if t.isdigit() else t for t in norm.split(".") if t != "")
    candidates = [tokens] if tokens and tokens[0] in SECTIONS else [
        (s,) + tokens for s in SECTIONS]
    found = [p for p in candidates if p in names.values()]
    if len(found) == 1:
        return found[0]
    if len(found) > 1:
        raise InputError(f"--vary {name}: ambiguous, say which section: "
                         + ", ".join(Parameter("", p, 0, 0).dotted for p in found))
    flat = sorted(n for n in names if "." not in n and "[" not in n)
    raise InputError(f"--vary {name}: not a parameter of this case (names: {', '.join(flat)}; "
                     "or a dotted path such as damper.mu or blade.airfoil.h)")


def get_value(case_dicts: dict, path: tuple):
    node = case_dicts[path[0]]
    for key in path[1:]:
        node = node[key]
    return node


def _set_copied(root: dict, path: tuple, value) -> dict:
    """A copy of ``root`` with the leaf at ``path`` set; only the containers on the path are
    copied (the rest is shared, never modified)."""
    top = dict(root)
    node = top
    for key in path[:-1]:
        child = node[key]
        child = dict(child) if isinstance(child, dict) else list(child)
        node[key] = child
        node = child
    node[path[-1]] = value
    return top


def case_sections(case: Case) -> dict:
    return {"blade": case.blade, "damper": case.damper, "analysis": case.analysis}


def with_values(case: Case, paths: Sequence[tuple], values: Sequence) -> Case:
    """``case`` with the parameters at ``paths`` set to ``values`` (no validation, no deep copy:
    the untouched parts are shared with ``case``)."""
    sections = case_sections(case)
    scale = None
    for path, value in zip(paths, values):
        if path == STIFFNESS_SCALE_PATH:
            scale = value
            continue
        sections[path[0]] = _set_copied(sections[path[0]], path[1:], value)
    if scale is not None:  # after the stiffnesses themselves, if they vary too
        damper = dict(sections["damper"])
        for name in STIFFNESS_FIELDS:
            damper[name] = damper[name] * scale
        sections["damper"] = damper
    return Case(blade=sections["blade"], damper=sections["damper"],
                analysis=sections["analysis"], name=case.name, base_dir=case.base_dir)


def validation_dict(case: Case) -> dict:
    """The case as the input dictionary :func:`validate` accepts."""
    data = case.to_dict()
    if data["damper"].get("kind") == "table":
        data["damper"].pop("rows", None)
    return data


def parse_vary(case: Case, specs: Sequence) -> list[Parameter]:
    """Parses ``NAME=LO:HI[:log]`` items (strings with commas allowed, or (name, lo, hi) tuples)
    into parameters, validating the case at both ends of every range: a bad name, range or value
    raises InputError naming it."""
    items = []
    for spec in specs:
        if isinstance(spec, str):
            items.extend(s.strip() for s in spec.split(",") if s.strip())
        else:
            items.append(tuple(spec))
    if not items:
        raise InputError("--vary: at least one NAME=LO:HI is needed")
    params: list[Parameter] = []
    for item in items:
        if isinstance(item, tuple):
            name, lo, hi, *rest = item
            scale = rest[0] if rest else "linear"
            text = f"{name}={lo}:{hi}"
        else:
            text = item
            name, sep, rng = item.partition("=")
            parts = rng.split(":")
            if not sep or not name.strip() or len(parts) not in (2, 3):
                raise InputError(f"--vary {item}: expected NAME=LO:HI or NAME=LO:HI:log")
            name = name.strip()
            scale = parts[2].strip() if len(parts) == 3 else "linear"
            try:
                lo, hi = float(parts[0]), float(parts[1])
            except ValueError:
                raise InputError(f"--vary {item}: LO and HI must be numbers") from None
        try:
            lo, hi = float(lo), float(hi)
        except (TypeError, ValueError):
            raise InputError(f"--vary {text}: LO and HI must be numbers") from None
        if scale not in ("linear", "log"):
            raise InputError(f"--vary {text}: the scale must be 'log' or omitted, got {scale!r}")
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise InputError(f"--vary {text}: LO and HI must be finite")
        if not lo < hi:
            raise InputError(f"--vary {text}: LO must be below HI")
        if scale == "log" and not lo > 0:
            raise InputError(f"--vary {text}: a log range needs LO > 0")
        path = resolve_name(case, name)
        current = 1.0 if path == STIFFNESS_SCALE_PATH else get_value(case_sections(case), path)
        integer = 0
        if isinstance(current, int):
            integer = 2 if path == ("blade", "airfoil", "elements") else 1
        p = Parameter(name=name, path=path, lo=lo, hi=hi, scale=scale, integer=integer)
        for other in params:
            if other.path == p.path:
                raise InputError(f"--vary {name}: the same parameter as {other.name} "
                                 f"({p.dotted})")
        # Every check of a single value is an interval, so both ends valid means all valid.
        for end in (lo, hi):
            try:
                validate(validation_dict(with_values(case, [path], [p.cast(end)])),
                         case.base_dir)
            except InputError as exc:
                raise InputError(f"--vary {text}: {exc}") from None
        params.append(p)
    return params
