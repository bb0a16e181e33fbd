"""The command line ``python3 -m udmap`` (INTERFACES.md "Command line").

Exit status: 0 success, 2 bad input (arguments, case file), 3 physics failure (jammed damper,
no resonance in the band), 4 numerical failure.
"""
from __future__ import annotations

import argparse
import sys

from .. import version
from ..errors import InputError, PhysicsError, UdmapError
from ..fmu_case import add_fmu_parser
from .args import add_wave_options, float_list, harmonics_arg, positive, positive_int
from .commands import (cmd_backbone, cmd_curves, cmd_demo, cmd_dti, cmd_hbm, cmd_reduce,
                       cmd_response, cmd_table)
from .doe import add_doe_parser
from .nodal import add_nodal_parser
from .files import add_file_options


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
            p.add_argument("--forces", type=float_list, required=True,
                           help="excitation force amplitudes F_E [N], comma-separated")
        p.add_argument("--json", action="store_true", help="print JSON on stdout")
        p.set_defaults(func=func)
        return p

    p = add("table", cmd_table, "damper stiffness k(gamma) and base cycle", forces=False)
    p.add_argument("--gammas", type=float_list, required=True,
                   help="rotation amplitudes [rad], comma-separated")
    harmonics_help = ("harmonics of the platform rotation: 1 (the single-harmonic method), H "
                      "(harmonics 0..H in multi-harmonic layers) or auto; overrides "
                      "analysis.harmonics")
    p = add("backbone", cmd_backbone, "resonance peaks (backbone) for each force")
    add_file_options(p)
    add_wave_options(p)
    p.add_argument("--harmonics", type=harmonics_arg, default=None, metavar="H|auto",
                   help=harmonics_help)
    p = add("curves", cmd_curves, "non-linear response curves by amplitude-layered mapping")
    add_file_options(p)
    add_wave_options(p)
    p.add_argument("--layers", type=positive_int, default=None,
                   help="number of amplitude layers (default from the case, 200)")
    p.add_argument("--harmonics", type=harmonics_arg, default=None, metavar="H|auto",
                   help=harmonics_help)
    p = add("response", cmd_response, "response at a given excitation frequency")
    add_file_options(p)
    add_wave_options(p)
    p.add_argument("--freq", type=positive, required=True, help="excitation frequency [Hz]")
    p.add_argument("--harmonics", type=harmonics_arg, default=None, metavar="H|auto",
                   help=harmonics_help)
    p = add("hbm", cmd_hbm, "standard convergence-based method (harmonic balance)")
    add_file_options(p)
    add_wave_options(p)
    p.add_argument("--harmonics", type=positive_int, default=1, help="harmonics 1..H (default 1)")
    p.add_argument("--variant", choices=("condensed", "full"), default="condensed",
                   help="Newton on the damper DOF after condensation, or on all DOFs")
    p = add("dti", cmd_dti, "direct time integration to steady state")
    add_wave_options(p)
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--freq", type=positive, help="excitation frequency [Hz]")
    g.add_argument("--peak", action="store_true", help="search the frequency of the largest "
                   "first harmonic near the single-harmonic peak")
    _add_wheel_options(p)
    p = add("reduce", cmd_reduce, "Platform Centred Reduction of an fe case to a matrices case",
            forces=False)
    p.add_argument("--out", required=True, help="the reduced case file (JSON) to write; its "
                   "matrices are written beside it")
    p = sub.add_parser("demo", help="the main job on the embedded default (make demo)")
    p.add_argument("case", metavar="CASE", nargs="?", default=None,
                   help="case file (default: the embedded blade A)")
    p.add_argument("--out", default="out/demo", help="output directory (default out/demo)")
    p.set_defaults(func=cmd_demo)
    add_nodal_parser(sub)
    add_doe_parser(sub)
    add_fmu_parser(sub)
    return parser


def _add_wheel_options(p) -> None:
    """--blades N --engine-order EO (the whole wheel in time), unless already there."""
    for flag, kw in (("--blades", dict(metavar="N", help="blades of the wheel (2..10000): "
                                       "integrate the whole wheel")),
                     ("--engine-order", dict(dest="engine_order", metavar="EO",
                                             help="engine order: interblade phase 2 pi EO/N"))):
        try:
            p.add_argument(flag, type=int, default=None, **kw)
        except argparse.ArgumentError:   # already an option of every command
            pass


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.version:
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
