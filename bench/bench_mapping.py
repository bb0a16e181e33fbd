#!/usr/bin/env python3
"""Benchmark of the mapping's hot paths on blade A (make bench): compiles
bench/mapping_timing.c against the built library, runs it on the case's blade and damper, and
writes records (INTERFACES.md "Benchmark output"):

  backbone / gg10                 the 10 peaks F_E = 1..10 N from the damper parameters on
                                  (damper tracing, backbone table, roots): goal < 150 us
  backbone / gg10_damper_built    the same with the damper (its stiffness table) already built:
                                  backbone table and roots, goal < 50 us
  backbone / gg10_cached          the same with the backbone table cached too (new forces only)
  mapping / gg10                  response curves for the 10 forces (the case's layers) from the
                                  damper parameters on, the peaks read off the mapped points

Errors are relative to a reference backbone with rtol = 1e-14 and 4 times the amplitude grid.
Usage: bench_mapping.py [--json FILE] [--repeats N] [--case PATH]
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "wrappers" / "python"))
sys.path.insert(0, str(ROOT / "bench"))

from timing import record  # noqa: E402
from udmap.case import beam_params, load_case  # noqa: E402

GOALS = {"gg10": 150e-6, "gg10_damper_built": 50e-6}


def build_dir() -> Path:
    env = os.environ.get("UDMAP_BUILD_DIR")
    return Path(env) if env else ROOT / "build"


def compile_timer(tmp: Path) -> Path:
    lib = build_dir() / "kernel"
    exe = tmp / "mapping_timing"
    cc = shutil.which("cc") or shutil.which("gcc")
    subprocess.run([cc, "-O2", "-std=c99", "-D_POSIX_C_SOURCE=199309L",
                    "-I", str(ROOT / "wrappers" / "c"), str(ROOT / "bench" / "mapping_timing.c"),
                    "-o", str(exe), "-L", str(lib), "-ludmap", f"-Wl,-rpath,{lib}", "-lm"],
                   check=True)
    return exe


def stdin_for(case, repeats: int) -> str:
    b = beam_params(case.blade)
    beam = " ".join(str(b[k]) for k in ("E", "rho", "zeta", "neck_L", "neck_h", "neck_b",
                                        "platform_L", "platform_m", "platform_J", "airfoil_L",
                                        "airfoil_h", "airfoil_b", "neck_elements",
                                        "airfoil_elements"))
    d = case.damper
    (f1x, f1y), (f2x, f2y) = d["flat_points"]
    cx, cy = d["curved_point"]
    damper = " ".join(str(v) for v in (d["CF"], d["mu"], d["pitch"], d["y_P"], d["beta_L_deg"],
                                       d["beta_R_deg"], f1x, f1y, f2x, f2y, cx, cy, d["kn_flat"],
                                       d["kt_flat"], d["kn_curved"], d["kt_curved"]))
    a = case.analysis
    return (f"beam {beam}\nasymmetric {damper}\n"
            f"band {a['f_min']} {a['f_max']} {a['sigma_all']} {a['layers']} {repeats}\n")


def max_rel(x, ref) -> float:
    return max(abs(a / b - 1) for a, b in zip(x, ref))


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", type=Path, default=None)
    ap.add_argument("--repeats", type=int, default=201)
    ap.add_argument("--case", type=Path, default=ROOT / "cases" / "blade_a.json")
    args = ap.parse_args()
    case = load_case(args.case)
    if case.blade["kind"] != "beam" or case.damper["kind"] != "asymmetric":
        raise SystemExit("bench_mapping: needs a beam blade with an asymmetric damper")
    with tempfile.TemporaryDirectory() as tmp:
        exe = compile_timer(Path(tmp))
        out = subprocess.run([str(exe)], input=stdin_for(case, args.repeats), text=True,
                             capture_output=True)
    if out.returncode != 0:
        raise SystemExit(f"bench_mapping: timing program failed:\n{out.stderr}")
    runs = {r["name"]: r for r in map(json.loads, out.stdout.splitlines())}
    ref = runs["reference"]
    records = []
    for name, method, setting in (("backbone_cold", "backbone", "gg10"),
                                  ("backbone_damper_built", "backbone", "gg10_damper_built"),
                                  ("backbone_cached", "backbone", "gg10_cached"),
                                  ("mapping_cold", "mapping", "gg10")):
        r = runs[name]
        timing = {k: r[k] for k in ("seconds_median", "seconds_min", "seconds_max", "repeats")}
        extra = {"goal_seconds": GOALS[setting]} if method == "backbone" and setting in GOALS \
            else {}
        if method == "mapping":
            extra["layers"] = case.analysis["layers"]
        records.append(record(case.name, method, setting, timing,
                              error_gamma_P=max_rel(r["gamma_P"], ref["gamma_P"]),
                              error_sigma_a=max_rel(r["sigma_a"], ref["sigma_a"]),
                              error_f_res=max_rel(r["f_res"], ref["f_res"]), **extra))
    for rec in records:
        goal = f" (goal {rec['goal_seconds'] * 1e6:.0f} us)" if "goal_seconds" in rec else ""
        print(f"  {rec['method']:>9} {rec['setting']:<18} median {rec['seconds_median'] * 1e6:9.1f}"
              f" us, min {rec['seconds_min'] * 1e6:9.1f} us{goal}; errors gamma_P "
              f"{rec['error_gamma_P']:.1e}, sigma_a {rec['error_sigma_a']:.1e}, f_res "
              f"{rec['error_f_res']:.1e}")
    if args.json:
        args.json.write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
