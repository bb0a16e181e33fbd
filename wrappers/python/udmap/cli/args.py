"""Argument types of the command line (argparse ``type=`` functions)."""
from __future__ import annotations

import argparse
import math


def float_list(text: str) -> list[float]:
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


def positive(text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}")
    if not (math.isfinite(v) and v > 0):
        raise argparse.ArgumentTypeError(f"must be a positive finite number, got {text}")
    return v


def positive_int(text: str) -> int:
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer, got {text!r}")
    if v < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text}")
    return v


def harmonics_arg(text: str):
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


def add_wave_options(p) -> None:
    """``--blades N --engine-order EO`` or ``--ibpa DEG``: the traveling wave (PHYSICS.md 2.6),
    overriding the case's; checked with the case (udmap.case.traveling), as text here."""
    p.add_argument("--blades", default=None, metavar="N",
                   help="blades N of the wheel (with --engine-order; overrides analysis.blades)")
    p.add_argument("--engine-order", dest="engine_order", default=None, metavar="EO",
                   help="engine order EO (integer, taken modulo N): the interblade phase "
                        "2 pi EO/N; overrides analysis.engine_order")
    p.add_argument("--ibpa", default=None, metavar="DEG",
                   help="interblade phase angle [deg] instead of --blades/--engine-order "
                        "(overrides analysis.ibpa_deg)")
