"""Output of the command line: JSON (the contract's field order, all or nothing) or tables."""
from __future__ import annotations

import json
import math
import sys

from ..errors import UdmapError
from ..model import REGIME_NAMES

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


def emit(args, data: dict, table) -> None:
    if args.json:
        try:  # all or nothing: a non-finite number is a numerical failure, not half a file
            text = json.dumps(data, indent=2, allow_nan=False)
        except ValueError:
            raise UdmapError("a result is not a finite number", 4) from None
        sys.stdout.write(text + "\n")
    else:
        table(data)


def print_rows(header: list[str], rows: list[list], fmt: list[str]) -> None:
    widths = [max(len(h), 12) for h in header]
    print("  ".join(h.rjust(w) for h, w in zip(header, widths)))
    for row in rows:
        cells = []
        for value, f, w in zip(row, fmt, widths):
            cells.append(("-" if value is None else format(value, f)).rjust(w))
        print("  ".join(cells))


def print_points(data: dict) -> None:
    head = {k: v for k, v in data.items() if k != "points"}
    for k, v in head.items():
        print(f"{k:>10} = {v}")
    multi = any((p.get("harmonics") or 1) > 1 for p in data["points"])
    jump = any(p.get("jump") for p in data["points"])
    header = ["F_E [N]", "gamma_P [rad]", "f_res [Hz]", "sigma_a [MPa]", "u_E [m]",
              "k_re", "k_im", "regime", "hcf_ok"]
    fmt = [".4g", ".6e", ".6f", ".4f", ".4e", ".6g", ".6g", "s", "s"]
    rows = [[p["F_E"], p["gamma_P"], p["f_res"],
             None if p["sigma_a"] is None else p["sigma_a"] / 1e6, p["u_E"],
             p["k_re"], p["k_im"], p["regime_name"], str(p["hcf_ok"])]
            for p in data["points"]]
    if multi:
        # multi-harmonic layers: hcf_ok compares sigma_max with sigma_all
        header += ["H", "gamma_max [rad]", "sigma_max [MPa]"]
        fmt += ["d", ".6e", ".4f"]
        for row, p in zip(rows, data["points"]):
            row += [p.get("harmonics") or 1, p.get("gamma_max"),
                    None if p.get("sigma_max") is None else p["sigma_max"] / 1e6]
    if jump:
        header.append("jump")
        fmt.append("s")
        for row, p in zip(rows, data["points"]):
            row.append(str(bool(p.get("jump"))))
    print_rows(header, rows, fmt)
    if jump:
        print("jump: gamma_P sits at a jump gamma_c of k(gamma), k interpolated between its "
              "one-sided values (PHYSICS.md 2.5)")
