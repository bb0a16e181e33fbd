"""The command line ``python3 -m udmap`` (INTERFACES.md "Command line").

Exit status: 0 success, 2 bad input (arguments, case file), 3 physics failure (jammed damper,
no resonance in the band), 4 numerical failure.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

from ._lib import InputError, PhysicsError, UdmapError

REGIME_NAMES = {0: "stuck", 1: "partial slip", 2: "full slip", 3: "at or above F_lim"}
POINT_FIELDS = ("F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "regime",
                "hcf_ok", "roots", "gamma_max", "sigma_max", "harmonics")


def _float_list(text: str) -> list[float]:
    """Parses 'a,b,c' into positive finite floats (argparse type)."""
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected comma-separated numbers, got {text!r}")
    if not values:
        raise argparse.ArgumentTypeError("expected at least one number")
    for v in values:
        if not (math.isfinite(v) and v > 0):
            raise argparse.ArgumentTypeError(f"values must be positive finite numbers, got {v}")
    return values


def _positive(text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}")
    if not (math.isfinite(v) and v > 0):
        raise argparse.ArgumentTypeError(f"must be a positive finite number, got {text}")
    return v


def _positive_int(text: str) -> int:
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer, got {text!r}")
    if v < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text}")
    return v


def _harmonics(text: str):
    """--harmonics H|auto (argparse type): an integer 1..64 or "auto"."""
    if text == "auto":
        return text
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer 1..64 or 'auto', got {text!r}")
    if not 1 <= v <= 64:
        raise argparse.ArgumentTypeError(f"must be an integer 1..64 or 'auto', got {text}")
    return v


def _with_harmonics(case, args):
    """The case with --harmonics (if given) overriding analysis.harmonics."""
    if getattr(args, "harmonics", None) is not None:
        case.analysis["harmonics"] = args.harmonics
    return case


def _finite(x):
    """JSON has no infinity or NaN: such values become null."""
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def _point_json(p: dict) -> dict:
    """A response point in the contract's field order; unbounded answers are null with a flag."""
    out = {}
    unbounded = bool(p.get("unbounded", False))
    for key in POINT_FIELDS:
        value = p.get(key)
        if unbounded and key not in ("F_E", "regime", "hcf_ok"):
            value = None if key != "roots" else []
        out[key] = [_finite(v) for v in value] if isinstance(value, list) else _finite(value)
    out["regime_name"] = REGIME_NAMES.get(p.get("regime"), "")
    if unbounded:
        out["unbounded"] = True
        out["message"] = p.get("message") or (
            "F_E >= F_lim with zeta = 0: friction cannot bound the response (unbounded)")
    for key, value in p.items():  # extras (iterations, seconds, ...)
        if key not in out and key not in ("unbounded", "message"):
            out[key] = _finite(value)
    return out


def _emit(args, data: dict, table) -> None:
    if args.json:
        try:  # all or nothing: a non-finite number is a numerical failure, not half a file
            text = json.dumps(data, indent=2, allow_nan=False)
        except ValueError:
            raise UdmapError("a result is not a finite number", 4) from None
        sys.stdout.write(text + "\n")
    else:
        table(data)


def _print_rows(header: list[str], rows: list[list], fmt: list[str]) -> None:
    widths = [max(len(h), 12) for h in header]
    print("  ".join(h.rjust(w) for h, w in zip(header, widths)))
    for row in rows:
        cells = []
        for value, f, w in zip(row, fmt, widths):
            cells.append(("-" if value is None else format(value, f)).rjust(w))
        print("  ".join(cells))


def _print_points(data: dict) -> None:
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
    _print_rows(header, rows, fmt)
    if jump:
        print("jump: gamma_P sits at a jump gamma_c of k(gamma), k interpolated between its "
              "one-sided values (PHYSICS.md 2.5)")


def cmd_table(args) -> None:
    from .case import build_damper, load_case
    import numpy as np
    case = load_case(args.case)
    damper = build_damper(case)
    gammas = np.asarray(args.gammas)
    k = damper.stiffness(gammas)
    data = {"gamma_b": damper.gamma_b, "gamma_s": damper.gamma_s, "M_max": damper.M_max,
            "M_min": damper.M_min, "k_stuck": damper.k_stuck, "lift_off": bool(damper.lift_off),
            "points": [{"gamma": float(g), "k_re": float(kk.real), "k_im": float(kk.imag)}
                       for g, kk in zip(gammas, k)],
            # PHYSICS.md 2.5: k jumps at gamma_c; at gamma_c itself k is k(gamma_c-)
            "jumps": [{"gamma_c": j["gamma_c"], "k_re_minus": j["k_minus"].real,
                       "k_im_minus": j["k_minus"].imag, "k_re_plus": j["k_plus"].real,
                       "k_im_plus": j["k_plus"].imag} for j in damper.jumps]}

    def table(d):
        for key in ("gamma_b", "gamma_s", "M_max", "M_min", "k_stuck", "lift_off"):
            print(f"{key:>8} = {d[key]}")
        _print_rows(["gamma [rad]", "k_re [N m/rad]", "k_im [N m/rad]"],
                    [[p["gamma"], p["k_re"], p["k_im"]] for p in d["points"]],
                    [".6e", ".8g", ".8g"])
        if d["jumps"]:
            print(f"k(gamma) jumps at {len(d['jumps'])} amplitude(s) gamma_c (PHYSICS.md 2.5):")
            _print_rows(["gamma_c [rad]", "k_re(gamma_c-)", "k_im(gamma_c-)", "k_re(gamma_c+)",
                         "k_im(gamma_c+)"],
                        [[j["gamma_c"], j["k_re_minus"], j["k_im_minus"], j["k_re_plus"],
                          j["k_im_plus"]] for j in d["jumps"]],
                        [".10e", ".8g", ".8g", ".8g", ".8g"])
    _emit(args, data, table)


def _summary(model, blade, damper) -> dict:
    return {"F_lim": model.limit_force(), "F_lim_backbone": model.limit_force_backbone(),
            "gamma_b": damper.gamma_b, "gamma_s": damper.gamma_s,
            "f1_bare": float(blade.natural_frequencies(1)[0]),
            "lift_off": bool(damper.lift_off)}


def cmd_backbone(args) -> None:
    from .case import build_blade, build_damper, build_model, load_case
    case = _with_harmonics(load_case(args.case), args)
    blade, damper = build_blade(case), build_damper(case)
    model = build_model(case, blade, damper)
    data = _summary(model, blade, damper)
    data["points"] = [_point_json(p) for p in model.backbone(args.forces)]
    _emit(args, data, _print_points)


def cmd_response(args) -> None:
    from .case import build_blade, build_damper, build_model, load_case
    case = _with_harmonics(load_case(args.case), args)
    a = case.analysis
    if not a["f_min"] <= args.freq <= a["f_max"]:
        raise InputError(f"--freq {args.freq} Hz is outside the band [analysis.f_min, "
                         f"analysis.f_max] = [{a['f_min']}, {a['f_max']}] Hz of the case")
    blade, damper = build_blade(case), build_damper(case)
    model = build_model(case, blade, damper)
    data = _summary(model, blade, damper)
    data["f_exc"] = args.freq
    data["points"] = [_point_json(dict(p, jump=False))
                      for p in model.response(args.freq, args.forces)]
    _emit(args, data, _print_points)


def cmd_curves(args) -> None:
    from .case import build_model, load_case
    case = _with_harmonics(load_case(args.case), args)
    model = build_model(case)
    layers = args.layers or case.analysis["layers"]
    curves = model.curves(args.forces, layers=layers)
    data = {"curves": [{"F_E": c["F_E"], "f": [float(x) for x in c["f"]],
                        "gamma_P": [float(x) for x in c["gamma_P"]],
                        "sigma_a": [_finite(float(x)) for x in c["sigma_a"]],
                        "branch": [int(x) for x in c["branch"]],
                        "part": [int(x) for x in c["part"]]} for c in curves]}

    def table(d):
        for c in d["curves"]:
            print(f"F_E = {c['F_E']} N: {len(c['f'])} points")
            _print_rows(["f [Hz]", "gamma_P [rad]", "sigma_a [MPa]", "branch"],
                        [[f, g, None if s is None else s / 1e6, b]
                         for f, g, s, b in zip(c["f"], c["gamma_P"], c["sigma_a"], c["branch"])],
                        [".6f", ".6e", ".4f", "d"])
    _emit(args, data, table)


def cmd_hbm(args) -> None:
    from .case import build_blade, load_case
    from . import hbm
    case = load_case(args.case)
    blade = build_blade(case)
    a = case.analysis
    points = hbm.hbm(blade, case.damper, a["f_min"], a["f_max"], args.forces,
                     harmonics=args.harmonics, variant=args.variant, sigma_all=a["sigma_all"])
    data = {"harmonics": args.harmonics, "variant": args.variant,
            "points": [_point_json(p) for p in points]}
    _emit(args, data, _print_points)


def cmd_dti(args) -> None:
    from .case import build_blade, load_case
    from . import hbm
    case = load_case(args.case)
    blade = build_blade(case)
    a = case.analysis
    if args.freq is not None and not a["f_min"] <= args.freq <= a["f_max"]:
        raise InputError(f"--freq {args.freq} Hz is outside the band [analysis.f_min, "
                         f"analysis.f_max] = [{a['f_min']}, {a['f_max']}] Hz of the case")
    points = hbm.dti(blade, case.damper, args.forces, freq=args.freq, peak=args.peak,
                     f_min=a["f_min"], f_max=a["f_max"])
    data = {"points": [{k: _finite(p[k]) for k in ("F_E", "f", "gamma_1", "sigma_1", "gamma_max")}
                       for p in points]}

    def table(d):
        _print_rows(["F_E [N]", "f [Hz]", "gamma_1 [rad]", "sigma_1 [MPa]", "gamma_max [rad]"],
                    [[p["F_E"], p["f"], p["gamma_1"],
                      None if p["sigma_1"] is None else p["sigma_1"] / 1e6, p["gamma_max"]]
                     for p in d["points"]], [".4g", ".6f", ".6e", ".4f", ".6e"])
    _emit(args, data, table)


def cmd_reduce(args) -> None:
    """Writes the reduced ``matrices`` case of an ``fe`` case (files beside ``--out``)."""
    import os
    import shutil
    from .case import load_case
    out = Path(args.out)
    if out.suffix.lower() != ".json":
        raise InputError(f"--out must name a .json case file, got {args.out}")
    if not out.parent.is_dir():
        raise InputError(f"--out: directory not found: {out.parent}")
    case = load_case(args.case)
    if case.fe is None:
        raise InputError(f"blade.kind: reduce needs an 'fe' blade ({args.case})")
    raw = json.loads(Path(args.case).read_text())
    src = Path(case.fe["cache_dir"])
    blade = {"kind": "matrices"}
    moves = []
    for key, name in case.fe["files"].items():
        target = out.parent / f"{out.stem}_{name}"
        tmp = target.with_name(f".{target.name}.tmp")
        shutil.copyfile(src / name, tmp)
        moves.append((tmp, target))
        blade[key] = target.name
    blade.update(gamma_dof=case.blade["gamma_dof"], exc_dof=case.blade["exc_dof"],
                 zeta=case.blade["zeta"])
    damper = dict(raw["damper"])
    if damper.get("kind") == "table":
        damper["file"] = os.path.relpath(case.damper["file"], out.parent.resolve())
    new = {"name": raw.get("name", case.name),
           "description": f"Platform Centred Reduction of {Path(args.case).name} "
                          f"({case.fe['n_full']} DOFs -> {case.fe['n_reduced']})",
           "blade": blade, "damper": damper, "analysis": raw["analysis"]}
    tmp = out.with_name(f".{out.name}.tmp")
    tmp.write_text(json.dumps(new, indent=2) + "\n")
    moves.append((tmp, out))
    for a, b in moves:          # the case file last: it is complete only with its matrices
        os.replace(a, b)
    data = {"out": str(out), "n_full": case.fe["n_full"], "n_reduced": case.fe["n_reduced"],
            "gamma_dof": case.blade["gamma_dof"], "exc_dof": case.blade["exc_dof"],
            "cached": case.fe["cached"], "freqs_full": case.fe["freqs_full"],
            "freqs_reduced": case.fe["freqs_reduced"]}

    def table(d):
        print(f"wrote {d['out']}: {d['n_full']} DOFs reduced to {d['n_reduced']} "
              f"(gamma_dof {d['gamma_dof']}, exc_dof {d['exc_dof']}"
              f"{', from the cache' if d['cached'] else ''})")
        ff, fr = d["freqs_full"], d["freqs_reduced"]
        rows = [[i + 1, ff[i] if i < len(ff) else None, fr[i] if i < len(fr) else None,
                 (fr[i] - ff[i]) / ff[i] if i < min(len(ff), len(fr)) and ff[i] > 0 else None]
                for i in range(max(len(ff), len(fr)))]
        _print_rows(["mode", "full [Hz]", "reduced [Hz]", "rel. diff"], rows,
                    ["d", ".9g", ".9g", ".2e"])
    _emit(args, data, table)


def cmd_demo(args) -> None:
    from .demo import run_demo
    from .case import load_case
    run_demo(load_case(args.case), Path(args.out))


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="udmap", description="Convergence-free mapping of underplatform damper-blade "
        "performance (Gastaldi & Gola, MSSP 2024).")
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    def add(name, func, help_text, forces=True):
        p = sub.add_parser(name, help=help_text, description=help_text)
        p.add_argument("case", metavar="CASE", help="case file (JSON)")
        if forces:
            p.add_argument("--forces", type=_float_list, required=True,
                           help="excitation force amplitudes F_E [N], comma-separated")
        p.add_argument("--json", action="store_true", help="print JSON on stdout")
        p.set_defaults(func=func)
        return p

    p = add("table", cmd_table, "damper stiffness k(gamma) and base cycle", forces=False)
    p.add_argument("--gammas", type=_float_list, required=True,
                   help="rotation amplitudes [rad], comma-separated")
    harmonics_help = ("harmonics of the platform rotation: 1 (the single-harmonic method), H "
                      "(harmonics 0..H in multi-harmonic layers) or auto; overrides "
                      "analysis.harmonics")
    p = add("backbone", cmd_backbone, "resonance peaks (backbone) for each force")
    p.add_argument("--harmonics", type=_harmonics, default=None, metavar="H|auto",
                   help=harmonics_help)
    p = add("curves", cmd_curves, "non-linear response curves by amplitude-layered mapping")
    p.add_argument("--layers", type=_positive_int, default=None,
                   help="number of amplitude layers (default from the case, 200)")
    p.add_argument("--harmonics", type=_harmonics, default=None, metavar="H|auto",
                   help=harmonics_help)
    p = add("response", cmd_response, "response at a given excitation frequency")
    p.add_argument("--freq", type=_positive, required=True, help="excitation frequency [Hz]")
    p.add_argument("--harmonics", type=_harmonics, default=None, metavar="H|auto",
                   help=harmonics_help)
    p = add("hbm", cmd_hbm, "standard convergence-based method (harmonic balance)")
    p.add_argument("--harmonics", type=_positive_int, default=1, help="harmonics 1..H (default 1)")
    p.add_argument("--variant", choices=("condensed", "full"), default="condensed",
                   help="Newton on the damper DOF after condensation, or on all DOFs")
    p = add("dti", cmd_dti, "direct time integration to steady state")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--freq", type=_positive, help="excitation frequency [Hz]")
    g.add_argument("--peak", action="store_true", help="search the frequency of the largest "
                   "first harmonic near the single-harmonic peak")
    p = add("reduce", cmd_reduce, "Platform Centred Reduction of an fe case to a matrices case",
            forces=False)
    p.add_argument("--out", required=True, help="the reduced case file (JSON) to write; its "
                   "matrices are written beside it")
    p = sub.add_parser("demo", help="the main job on the embedded default (make demo)")
    p.add_argument("case", metavar="CASE", nargs="?", default=None,
                   help="case file (default: the embedded blade A)")
    p.add_argument("--out", default="out/demo", help="output directory (default out/demo)")
    p.set_defaults(func=cmd_demo)
    from .doe import add_doe_parser
    add_doe_parser(sub)
    from .fmu_case import add_fmu_parser
    add_fmu_parser(sub)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.version:
        from ._lib import version
        print(version())
        return 0
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        args.func(args)
    except InputError as exc:
        print(f"udmap: error: {exc}", file=sys.stderr)
        return 2
    except PhysicsError as exc:
        print(f"udmap: physics: {exc}", file=sys.stderr)
        return 3
    except UdmapError as exc:
        print(f"udmap: numerical failure: {exc}", file=sys.stderr)
        return exc.status if exc.status else 4
    except BrokenPipeError:
        return 0
    return 0
