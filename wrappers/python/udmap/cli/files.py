"""``--out DIR`` and ``--plot`` of ``backbone``, ``curves``, ``response`` and ``hbm``: the
command's CSV (SI, full precision), its JSON (as ``--json`` prints it, with ``units``) and a plot,
each written whole or not at all with the user's umask (docs/outputs.md)."""
from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

from ..errors import InputError, UdmapError
from ..fmu_case import write_atomic

#: The CSV columns of a point of backbone, response and hbm (JSON fields, SI).
#: The traveling wave's columns (the output's own fields, the same on every row).
WAVE_COLUMNS = ("engine_order", "blades", "ibpa_deg")
POINT_COLUMNS = ("F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "gamma_max",
                 "sigma_max", "regime", "regime_name", "hcf_ok", "hcf_reason", "unbounded",
                 "jump") + WAVE_COLUMNS
CURVE_COLUMNS = ("F_E", "f", "gamma_P", "sigma_a", "branch", "part") + WAVE_COLUMNS


def add_file_options(p) -> None:
    p.add_argument("--out", metavar="DIR", default=None,
                   help="also write DIR/COMMAND.csv and DIR/COMMAND.json (created if missing)")
    p.add_argument("--plot", action="store_true", help="with --out: also DIR/COMMAND.png")
    p.add_argument("--force", action="store_true", help="overwrite existing files in DIR")


def check_out(args, name: str) -> list[Path] | None:
    """The files `name` will write in --out (refused, before any work, when one exists without
    --force); None without --out."""
    if getattr(args, "plot", False) and not getattr(args, "out", None):
        raise InputError("--plot needs --out DIR")
    if not getattr(args, "out", None):
        return None
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise InputError(f"--out {out} is not a directory")
    paths = [out / f"{name}.csv", out / f"{name}.json"]
    if args.plot:
        paths.append(out / f"{name}.png")
    existing = [str(p) for p in paths if p.exists()]
    if existing and not args.force:
        raise InputError(f"--out {out}: {', '.join(existing)} exist(s): pass --force to "
                         "overwrite")
    return paths


def _cell(x) -> str:
    if x is None:
        return ""
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, float):
        return repr(x) if math.isfinite(x) else ""
    return str(x)


def csv_text(columns, rows) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(columns)
    for row in rows:
        w.writerow([_cell(x) for x in row])
    return buf.getvalue()


def point_rows(data: dict) -> list[list]:
    wave = [data.get(c) for c in WAVE_COLUMNS]
    return [[p.get(c, False if c in ("unbounded", "jump") else None)
             for c in POINT_COLUMNS[:-len(WAVE_COLUMNS)]] + wave for p in data["points"]]


def curve_rows(data: dict) -> list[list]:
    wave = [data.get(c) for c in WAVE_COLUMNS]
    return [[c["F_E"], *row, *wave] for c in data["curves"]
            for row in zip(c["f"], c["gamma_P"], c["sigma_a"], c["branch"], c["part"])]


def write_outputs(paths: list[Path], data: dict, columns, rows, plot=None) -> list[str]:
    """Writes the CSV, the JSON and (when asked) the plot ``plot(path)``; returns their paths."""
    try:
        text = json.dumps(data, indent=2, allow_nan=False) + "\n"
    except ValueError:
        raise UdmapError("a result is not a finite number", 4) from None
    try:
        paths[0].parent.mkdir(parents=True, exist_ok=True)
        write_atomic(paths[0], lambda p: p.write_text(csv_text(columns, rows)))
        write_atomic(paths[1], lambda p: p.write_text(text))
        if len(paths) > 2 and plot is not None:
            write_atomic(paths[2], plot)
    except OSError as exc:
        raise InputError(f"--out {paths[0].parent}: {exc.strerror or exc}") from None
    return [str(p) for p in paths]
