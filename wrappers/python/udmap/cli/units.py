"""Units of the command line's outputs (docs/outputs.md).

JSON and CSV hold SI numbers at full precision: N, m, rad, Hz, Pa, N m, N m/rad, s. A JSON
output names them in its ``units`` object (field -> unit, for the fields it holds). Readable
tables give the unit of every column in its header, stresses in MPa, numbers rounded to the
digits that mean something.
"""
from __future__ import annotations

import math

#: The SI unit of every field of the JSON outputs that has one (the same name, the same unit,
#: wherever it appears).
UNITS = {
    "F_E": "N", "F_lim": "N", "F_lim_backbone": "N", "F_adm": "N",
    "gamma": "rad", "gamma_P": "rad", "gamma_b": "rad", "gamma_s": "rad", "gamma_c": "rad",
    "gamma_max": "rad", "gamma_1": "rad", "gamma_h": "rad", "roots": "rad",
    "f": "Hz", "f_res": "Hz", "f_exc": "Hz", "f1_bare": "Hz", "f_stuck": "Hz", "peak_f": "Hz",
    "freqs_full": "Hz", "freqs_reduced": "Hz",
    "sigma_a": "Pa", "sigma_max": "Pa", "sigma_1": "Pa", "sigma_h": "Pa", "sigma_all": "Pa",
    "u_E": "m",
    "k_re": "N m/rad", "k_im": "N m/rad", "k_stuck": "N m/rad", "k_re_minus": "N m/rad",
    "k_im_minus": "N m/rad", "k_re_plus": "N m/rad", "k_im_plus": "N m/rad",
    "M_max": "N m", "M_min": "N m",
    "seconds": "s", "phase_spread": "rad",
    # the traveling wave (PHYSICS.md 2.6): the phase in degrees, as its name says; the wheel's
    # counts as the dimensionless 1
    "ibpa_deg": "deg", "engine_order": "1", "blades": "1", "nodal_diameter": "1",
}

#: Readable tables show stresses in MPa (JSON and CSV keep Pa).
DISPLAY = {"Pa": ("MPa", 1e-6)}

#: Significant digits of readable numbers, by unit (others: 4).
DIGITS = {"Hz": 6, "N m/rad": 5, "N m": 5}


def unit_of(key: str) -> str | None:
    """The SI unit of a JSON field (None for a count, flag or name)."""
    return UNITS.get(key)


def display_unit(key: str) -> tuple[str | None, float]:
    """(unit shown in readable output, factor from SI) of a field."""
    unit = UNITS.get(key)
    if unit in DISPLAY:
        return DISPLAY[unit]
    return unit, 1.0


def header(key: str, label: str | None = None) -> str:
    """A table header with its unit, e.g. ``sigma_a [MPa]``."""
    unit, _ = display_unit(key)
    label = label or key
    return f"{label} [{unit}]" if unit else label


def units_of(data) -> dict:
    """The ``units`` object of a JSON output: the unit of every field it holds that has one."""
    found: dict = {}

    def walk(node):
        if isinstance(node, dict):
            for k, v in node.items():
                if k in UNITS and k not in found:
                    found[k] = UNITS[k]
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)
    walk(data)
    return {k: found[k] for k in sorted(found)}


def rounded(x, digits: int = 4) -> str:
    """A number with `digits` significant digits, plainly for moderate magnitudes."""
    if x is None:
        return "-"
    if isinstance(x, bool) or isinstance(x, int):
        return str(x)
    x = float(x)
    if not math.isfinite(x):
        return str(x)
    if x == 0.0:
        return "0"
    mag = math.floor(math.log10(abs(x)))
    if -1 <= mag < digits + 2:
        text = f"{x:.{max(digits - 1 - mag, 0)}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text
    return f"{x:.{digits - 1}e}"


def value_text(key: str, x) -> str:
    """A value of field `key` for readable output: rounded, in its display unit, with the unit."""
    unit, factor = display_unit(key)
    if isinstance(x, bool) or x is None or not isinstance(x, (int, float)):
        return str(x)
    text = rounded(x * factor, DIGITS.get(unit, 4))
    return f"{text} {unit}" if unit else text


def cell(key: str, x) -> str:
    """A table cell of field `key`: rounded, in its display unit, without the unit."""
    unit, factor = display_unit(key)
    if x is None:
        return "-"
    return rounded(x * factor, DIGITS.get(unit, 4))
