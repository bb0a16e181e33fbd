"""The ``doe`` subcommand of the command line."""
from __future__ import annotations

import argparse
import json
import sys

from .. import doe
from ..case import load_case
from ..doe import METHODS, run_doe
from ..errors import InputError
from ..case.traveling import apply_options
from .args import add_wave_options, harmonics_arg


def add_doe_parser(sub) -> argparse.ArgumentParser:
    """Adds the ``doe`` subcommand to the CLI's subparsers."""
    h = ("design of experiments: sample damper, blade and analysis parameters, compute F_lim, "
         "the resonances and the admissible force of every design")
    p = sub.add_parser("doe", help=h, description=h + ". " + doe.__doc__.split("\n\n")[-1],
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("case", metavar="CASE", help="case file (JSON)")
    p.add_argument("--vary", action="append", required=True, metavar="NAME=LO:HI[,...]",
                   help="parameters and ranges, comma-separated or repeated; NAME=LO:HI:log "
                        "for a logarithmic scale")
    p.add_argument("--samples", type=int, required=True, metavar="N",
                   help="number of designs (grid: k^d)")
    p.add_argument("--method", choices=METHODS, default="sobol",
                   help="scrambled Sobol (default), Latin hypercube, or full grid")
    p.add_argument("--forces", default=None, metavar="F1,...",
                   help="forces F_E [N] with per-force columns gamma_P@F, f_res@F, sigma_a@F, "
                        "hcf_ok@F, jump@F")
    p.add_argument("--seed", type=int, default=0, help="sampling seed (default 0)")
    p.add_argument("--harmonics", default=None, metavar="H|auto",
                   help="harmonics of the platform rotation: 1 (single-harmonic), H (harmonics "
                        "0..H in multi-harmonic layers) or auto; overrides analysis.harmonics "
                        "(with H > 1 hcf_ok and F_adm take sigma_max)")
    add_wave_options(p)
    g = p.add_mutually_exclusive_group()
    g.add_argument("--workers", type=int, default=None, metavar="K",
                   help="worker processes (default: all cores; 1 runs serially)")
    g.add_argument("--threads", type=int, default=None, metavar="K",
                   help="worker threads instead of processes (the kernel releases the GIL)")
    g.add_argument("--dask", default=None, metavar="local:K|tcp://HOST:PORT",
                   help="run on Dask distributed: a local cluster of K worker processes or "
                        "the scheduler at an address")
    p.add_argument("--chunk", type=int, default=None, metavar="C",
                   help="designs per task and per write (default: from N and the workers)")
    p.add_argument("--out", required=True, metavar="FILE",
                   help="output CSV (a Parquet copy FILE.parquet when pyarrow is installed; "
                        "FILE.meta.json describes the run for --resume)")
    p.add_argument("--outputs", default=None, metavar="NAME,...",
                   help="the output columns: any of " + ", ".join(doe.OUTPUTS) +
                        " (per-force ones for every force; default all); the kernel computes "
                        "only what they need")
    p.add_argument("--format", choices=doe.FORMATS, default="csv",
                   help="csv (default; a Parquet copy too when pyarrow is installed) or "
                        "parquet (FILE written as Parquet alone)")
    p.add_argument("--resume", action="store_true",
                   help="continue an interrupted run in FILE")
    p.add_argument("--force", action="store_true", help="overwrite an existing FILE")
    p.add_argument("--plot", action="store_true",
                   help="write design-space plots next to FILE (PNG)")
    p.add_argument("--json", action="store_true", help="print the run summary as JSON")
    p.set_defaults(func=cmd_doe)
    return p


def cmd_doe(args) -> None:
    """The ``doe`` subcommand."""
    if args.samples < 1:
        raise InputError(f"--samples must be at least 1, got {args.samples}")
    for opt in ("workers", "threads", "chunk"):
        v = getattr(args, opt)
        if v is not None and v < 1:
            raise InputError(f"--{opt} must be at least 1, got {v}")
    case = load_case(args.case)
    if args.harmonics is not None:
        try:
            case.analysis["harmonics"] = harmonics_arg(args.harmonics)
        except argparse.ArgumentTypeError as exc:
            raise InputError(f"--harmonics: {exc}") from None
    apply_options(case, args.blades, args.engine_order, args.ibpa)
    summary = run_doe(
        case, args.vary, args.samples, args.out, method=args.method,
        forces=args.forces, seed=args.seed,
        workers=args.threads if args.threads is not None else args.workers,
        threads=args.threads is not None, dask=args.dask, chunk=args.chunk,
        resume=args.resume, overwrite=args.force, plot=args.plot, outputs=args.outputs,
        format=args.format)
    if summary["interrupted"]:
        print(f"udmap: interrupted: {summary['written']} of {summary['designs']} designs are in "
              f"{summary['out']} (finished chunks waiting for an earlier one in "
              f"{summary['out']}.pending); run again with --resume to continue", file=sys.stderr)
        raise SystemExit(130)
    if args.json:
        json.dump(summary, sys.stdout, indent=2, allow_nan=False)
        sys.stdout.write("\n")
        return
    rate = summary["designs_per_second"]
    recovered = f", {summary['recovered']} recovered" if summary["recovered"] else ""
    print(f"{summary['designs']} designs in {summary['out']} "
          f"({summary['computed']} computed{recovered} in {summary['seconds']:.2f} s, "
          f"{summary['traces']} damper tracing" + ("s" if summary["traces"] != 1 else "")
          + (f", {rate:.0f} designs/s, {summary['workers']} {summary['executor']} worker"
             + ("s" if summary["workers"] > 1 else "") if rate else "") + ")")
    print("status: " + ", ".join(f"{k} {v}" for k, v in sorted(summary["status"].items())))
    if summary["warnings"]:
        print("plausibility warnings: " + ", ".join(
            f"{k} {v}" for k, v in summary["warnings"].items()) +
            f" (of {summary['warnings_designs']} designs; docs/case-files.md, \"Plausibility\")")
    for label, share in summary.get("hcf_share", {}).items():
        print(f"hcf_ok at F_E = {label} N: {100 * share:.1f} % of the designs")
    if summary.get("parquet") and summary["parquet"] != summary["out"]:
        print(f"parquet: {summary['parquet']}")
    for path in summary.get("plots", []):
        print(f"plot: {path}")
