#!/usr/bin/env python3
"""Design of experiments over the friction coefficient and the centrifugal load of blade A's
damper: which designs pass the HCF criterion, and which give the largest admissible force for
the least centrifugal load (the Pareto front).

    PYTHONPATH=wrappers/python python3 examples/doe_mu_cf.py [OUT_DIR]

The same run from the command line:

    python3 -m udmap doe cases/blade_a.json --vary mu=0.1:0.8,CF=300:1500 --samples 512 \
        --forces 2,4,6 --out out/examples/doe_mu_cf.csv --plot
"""
import csv
import sys
from pathlib import Path

from udmap.case import load_case
from udmap.doe import run_doe
from udmap.doe.plot import pareto_front

ROOT = Path(__file__).resolve().parents[1]


def main():
    out_dir = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "out" / "examples"
    out = out_dir / "doe_mu_cf.csv"

    summary = run_doe(load_case(ROOT / "cases" / "blade_a.json"), ["mu=0.1:0.8", "CF=300:1500"],
                      512, out, forces="2,4,6", seed=1, overwrite=True, plot=True)
    print(f"{summary['designs']} designs in {summary['seconds']:.1f} s on {summary['workers']} "
          f"{summary['executor']} worker(s); status: {summary['status']}")
    for force, share in summary["hcf_share"].items():
        print(f"  passing at F_E = {force} N: {100 * share:.0f} %")

    with open(out, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    cf = [float(r["CF"]) for r in rows]
    f_adm = [float(r["F_adm"]) for r in rows]
    print("Pareto front (least CF for the largest admissible force):")
    print(f"  {'CF [N]':>8} {'mu':>6} {'F_lim [N]':>10} {'F_adm [N]':>10}")
    for i in pareto_front(cf, f_adm):
        r = rows[i]
        print(f"  {cf[i]:8.1f} {float(r['mu']):6.3f} {float(r['F_lim']):10.3f} {f_adm[i]:10.3f}")
    for path in summary["plots"]:
        print(f"plot: {path}")


if __name__ == "__main__":  # worker processes may import this file
    main()
