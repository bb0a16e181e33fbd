"""Design-of-experiments output layout: the outputs ``--outputs`` chooses from, the header of a run,
the units of its columns and the text of a cell. Below both writers (the CSV and its Parquet
copy in :mod:`udmap.doe.io`, Parquet alone in :mod:`udmap.doe.arrow`)."""
from __future__ import annotations

import math
import re

from ..errors import InputError
from ..parameters import FIELDS

SUMMARY_COLUMNS = ("F_lim", "F_lim_backbone", "gamma_b", "M_max", "M_min", "lift_off")
FORCE_FIELDS = ("gamma_P", "f_res", "sigma_a", "hcf_ok", "jump")
#: The outputs ``--outputs`` chooses from (per-force fields for every force), in column order.
OUTPUTS = SUMMARY_COLUMNS + FORCE_FIELDS + ("F_adm",)


def parse_outputs(text) -> list[str] | None:
    """``--outputs F_adm,sigma_a,...`` (or a list) into the chosen output names, None for the
    default (all of :data:`OUTPUTS`); an unknown name is an InputError naming it and the valid
    ones."""
    if text is None:
        return None
    items = [s.strip() for s in text.split(",")] if isinstance(text, str) else list(text)
    items = [s for s in items if s != ""]
    if not items:
        raise InputError(f"--outputs: expected at least one of {', '.join(OUTPUTS)}")
    for name in items:
        if name not in OUTPUTS:
            raise InputError(f"--outputs: unknown output {name!r} (valid: {', '.join(OUTPUTS)})")
    chosen = [name for name in OUTPUTS if name in items]
    return None if chosen == list(OUTPUTS) else chosen


def output_names(spec: dict) -> tuple:
    """The outputs of a run, in column order (all of them by default)."""
    return tuple(spec.get("outputs") or OUTPUTS)


def columns(spec: dict) -> list[str]:
    """The header: design, the varied parameters by name, F_lim, F_lim_backbone, gamma_b,
    M_max, M_min, lift_off, per force F gamma_P@F, f_res@F, sigma_a@F, hcf_ok@F, jump@F (gamma_P
    at a jump of k, PHYSICS.md 2.5), then F_adm, status, message; of the outputs only the
    chosen ones (``--outputs``)."""
    out = output_names(spec)
    cols = ["design"] + [p["name"] for p in spec["params"]] + \
        [c for c in SUMMARY_COLUMNS if c in out]
    for label in spec["labels"]:
        cols += [f"{field}@{label}" for field in FORCE_FIELDS if field in out]
    return cols + (["F_adm"] if "F_adm" in out else []) + ["status", "message"]


#: SI units of the computed columns (docs/outputs.md); per-force columns take their field's.
COLUMN_UNITS = {"F_lim": "N", "F_lim_backbone": "N", "gamma_b": "rad", "M_max": "N m",
                "M_min": "N m", "gamma_P": "rad", "f_res": "Hz", "sigma_a": "Pa", "F_adm": "N"}


def _si(unit: str) -> str:
    """A unit of the parameter table in the outputs' spelling: ``N.m/rad`` -> ``N m/rad``,
    ``kg.m2`` -> ``kg m^2``."""
    return re.sub(r"([a-zA-Z])(\d)", r"\1^\2", unit.replace(".", " "))


def parameter_unit(spec: dict, path) -> str:
    """The unit of a varied parameter (``1`` for a dimensionless one), from the parameter
    table (kernel/parameters.toml)."""
    section = path[0]
    kind = spec[section].get("kind") if section != "analysis" else None
    name = ".".join(str(k) for k in path[1:] if not isinstance(k, int))
    for sec, knd, field, kw in FIELDS:
        if sec == section and knd == kind and field == name:
            return _si(kw["unit"]) if kw.get("unit") else "1"
    return "1"


def column_units(spec: dict) -> dict:
    """Column -> unit of the CSV (``.meta.json`` ``units``, the Parquet field metadata);
    columns without a unit (design, flags, status, message) are left out."""
    units = {p["name"]: parameter_unit(spec, path)
             for p, path in zip(spec["params"], spec["paths"])}
    out = output_names(spec)
    units.update({c: COLUMN_UNITS[c] for c in SUMMARY_COLUMNS if c in COLUMN_UNITS and c in out})
    for label in spec["labels"]:
        units.update({f"{f}@{label}": COLUMN_UNITS[f] for f in FORCE_FIELDS
                      if f in COLUMN_UNITS and f in out})
    if "F_adm" in out:
        units["F_adm"] = COLUMN_UNITS["F_adm"]
    return units


def cell(value) -> str:
    """One CSV cell: repr for floats (exact round trip), true/false, '' for missing/non-finite."""
    t = type(value)
    if t is float:  # the common case first
        return repr(value) if value - value == 0.0 else ""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return repr(float(value)) if math.isfinite(value) else ""
    if isinstance(value, str):
        return " ".join(value.splitlines())
    try:  # numpy scalars
        return cell(value.item())
    except AttributeError:
        return cell(str(value))


def frames(data: bytes, tag: bytes):
    """The complete frames ``TAG START COUNT BYTES\\n`` + body of a staged file (the CSV's
    journal, the Parquet-alone staging), in file order: ``(start, count, offset of the body,
    body)``; the first frame that is cut or malformed ends them."""
    pos = 0
    while True:
        end = data.find(b"\n", pos)
        if end < 0:
            return
        head = data[pos:end].split()
        try:
            name, start, count, size = head[0], int(head[1]), int(head[2]), int(head[3])
        except (IndexError, ValueError):
            return
        body = data[end + 1:end + 1 + size]
        if name != tag or len(body) != size:
            return
        yield start, count, end + 1, body
        pos = end + 1 + size
