"""Output of the command line: JSON (the contract's field order, all or nothing) or tables."""
from __future__ import annotations

import json
import math
import sys

from ..errors import UdmapError
from ..model import REGIME_NAMES
from .units import UNITS, cell, header as header_of, rounded, units_of, value_text

POINT_FIELDS = ("F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "regime",
                "hcf_ok", "roots", "gamma_max", "sigma_max", "harmonics")

def finite(x):
    """JSON has no infinity or NaN: such values become null."""
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def point_json(p: dict) -> dict:
    """A response point in the contract's field order; unbounded answers are null with a flag."""
    out = {}
    unbounded = bool(p.get("unbounded", False))
    for key in POINT_FIELDS:
        value = p.get(key)
        if unbounded and key not in ("F_E", "regime", "hcf_ok"):
            value = None if key != "roots" else []
        out[key] = [finite(v) for v in value] if isinstance(value, list) else finite(value)
    out["regime_name"] = REGIME_NAMES.get(p.get("regime"), "")
    if unbounded:
        out["unbounded"] = True
        out["message"] = p.get("message") or (
            "F_E >= F_lim with zeta = 0: friction cannot bound the response (unbounded)")
    for key, value in p.items():  # extras (iterations, seconds, ...)
        if key not in out and key not in ("unbounded", "message"):
            out[key] = finite(value)
    return out


def hcf_reason(p: dict, F_lim, sigma_all) -> str:
    """Why a point passes or fails the HCF criterion (PHYSICS.md 5): its stress (sigma_a, or
    sigma_max with more than one harmonic) at most sigma_all, and F_E at most 0.5 F_lim; by how
    much each failing criterion is exceeded, or the margins when both hold."""
    stress = p.get("hcf_stress") or "sigma_a"
    half = 0.5 * F_lim if _known(F_lim) else None
    failed, margins = [], []
    if half is None:
        failed.append("F_lim unknown: F_E <= 0.5 F_lim cannot be checked")
    elif p["F_E"] > half:
        failed.append(f"F_E {rounded(p['F_E'])} N above 0.5 F_lim {rounded(half)} N by "
                      f"{rounded(100 * (p['F_E'] / half - 1), 3)} %")
    else:
        margins.append(f"F_E at {rounded(100 * p['F_E'] / half, 3)} % of 0.5 F_lim")
    s = p.get(stress)
    if p.get("unbounded"):
        failed.append("response unbounded (F_E at or above F_lim, no structural damping)")
    elif s is None or sigma_all is None:
        margins.append(f"{stress} not checked (no stress rows)")
    elif s > sigma_all:
        failed.append(f"{stress} {rounded(s / 1e6)} MPa above sigma_all "
                      f"{rounded(sigma_all / 1e6)} MPa by {rounded(100 * (s / sigma_all - 1), 3)} %")
    else:
        margins.append(f"{stress} at {rounded(100 * s / sigma_all, 3)} % of sigma_all")
    if p.get("hcf_ok"):
        return "ok: " + ", ".join(margins)
    return "; ".join(failed) if failed else "not admissible"


def _known(F_lim) -> bool:
    """F_lim is known (the kernel gives the largest double when it cannot be computed)."""
    return F_lim is not None and math.isfinite(F_lim) and F_lim < 1e300


def add_verdicts(data: dict, F_lim, sigma_all, F_lim_multi=None) -> None:
    """hcf_reason on every point of `data`; a warning per force at or above F_lim. The points
    are judged against `F_lim` (their own ``F_lim`` if they have one), those with more than one
    harmonic against `F_lim_multi` when given, as the kernel judges them."""
    for p in data["points"]:
        limit = p.get("F_lim", F_lim)
        if F_lim_multi is not None and (p.get("harmonics") or 1) > 1:
            limit = F_lim_multi
        p["hcf_reason"] = hcf_reason(p, limit, sigma_all)
        if _known(limit) and p["F_E"] >= limit:
            add_warning(data, f"F_E = {rounded(p['F_E'])} N is at or above F_lim = "
                              f"{rounded(limit)} N: the damper slips all the cycle and cannot "
                              "limit the response any more (not admissible)")


def add_warning(data: dict, text: str) -> None:
    data.setdefault("warnings", [])
    if text not in data["warnings"]:
        data["warnings"].append(text)


def emit(args, data: dict, table) -> None:
    """Prints `data`: JSON with its ``units`` and ``warnings``, or the readable table; the
    warnings also on stderr."""
    data.setdefault("warnings", [])
    for text in data["warnings"]:
        print(f"udmap: warning: {text}", file=sys.stderr)
    if args.json:
        data.pop("units", None)  # last, after the warnings
        data["units"] = units_of(data)
        try:  # all or nothing: a non-finite number is a numerical failure, not half a file
            text = json.dumps(data, indent=2, allow_nan=False)
        except ValueError:
            raise UdmapError("a result is not a finite number", 4) from None
        sys.stdout.write(text + "\n")
    else:
        table(data)


#: The traveling wave's fields (PHYSICS.md 2.6); engine_order and blades are null when the
#: phase is given as ibpa_deg, and then left out of the readable head.
WAVE_KEYS = ("engine_order", "blades", "ibpa_deg")


def print_head(data: dict, skip=()) -> None:
    """The scalar fields of `data` as "name = value unit" lines."""
    items = {k: v for k, v in data.items()
             if k not in ("points", "curves", "units", "warnings", *skip)
             and not isinstance(v, (list, dict)) and not (k in WAVE_KEYS and v is None)}
    width = max((len(k) for k in items), default=0)
    for k, v in items.items():
        print(f"{k:>{width}} = {value_text(k, v)}")


def print_rows(header: list[str], rows: list[list], fmt: list[str] | None = None,
               left: int = 0) -> None:
    """A table: cells are numbers (rounded by `fmt`: a format spec, or a field name for
    units.cell) or text; the last `left` columns are left-aligned."""
    widths = [max(len(h), 12) for h in header]
    lines = [header]
    for row in rows:
        cells = []
        for i, value in enumerate(row):
            f = fmt[i] if fmt else None
            if value is None or isinstance(value, str):
                cells.append("-" if value is None else value)
            elif f in UNITS or f == "":
                cells.append(cell(f, value))
            else:
                cells.append(format(value, f))
        lines.append(cells)
    for cells in lines:
        widths = [max(w, len(c)) for w, c in zip(widths, cells)]
    n = len(header) - left
    for cells in lines:
        print("  ".join([c.rjust(w) for c, w in zip(cells[:n], widths[:n])]
                        + [c.ljust(w) for c, w in zip(cells[n:], widths[n:])]).rstrip())


def print_points(data: dict) -> None:
    print_head(data)
    points = data["points"]
    multi = any((p.get("harmonics") or 1) > 1 for p in points)
    jump = any(p.get("jump") for p in points)
    f_key = "f_exc" if "f_exc" in data else "f_res"
    keys = ["F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im"]
    header = [header_of(k) for k in keys]
    header[2] = header_of(f_key)
    if multi:
        # multi-harmonic layers: hcf_ok compares sigma_max with sigma_all
        keys += ["gamma_max", "sigma_max"]
        header += [header_of("gamma_max"), header_of("sigma_max")]
    rows = []
    for p in points:
        if p.get("unbounded"):
            row = [p["F_E"]] + ["unbounded"] * (len(keys) - 1)
        else:
            row = [p.get(k) for k in keys]
        rows.append(row)
    fmt = list(keys)
    extra = []
    if multi:
        extra.append(("H", lambda p: str(p.get("harmonics") or 1)))
    if jump:
        extra.append(("jump", lambda p: str(bool(p.get("jump")))))
    extra += [("regime", lambda p: p["regime_name"]), ("hcf_ok", lambda p: str(p["hcf_ok"])),
              ("hcf_reason", lambda p: p.get("hcf_reason", ""))]
    header += [name for name, _ in extra]
    fmt += [""] * len(extra)
    for row, p in zip(rows, points):
        row += [get(p) for _, get in extra]
    print_rows(header, rows, fmt, left=3)
    if any(p.get("unbounded") for p in points):
        print("unbounded: F_E at or above F_lim with zeta = 0, friction cannot bound the "
              "response")
    if jump:
        print("jump: gamma_P sits at a jump gamma_c of k(gamma), k interpolated between its "
              "one-sided values (PHYSICS.md 2.5)")
