#!/usr/bin/env python3
"""Agreement and model error of the standard method on blade A (make bench), PHYSICS.md 6-7:

  - H = 1 against the backbone (the same equations, independent code paths: contact model and
    AFT against stiffness table and layer peaks), both variants, F_E = 0.3 (stuck), 1, 5, 10 N;
  - H = 3, 5 and 33 (condensed): the peaks of the first harmonic of gamma_P converging in H,
    and the single-harmonic model error H = 1 against H = 33;
  - with --with-dti (or UDMAP_BENCH_DTI=1; about 12-33 s per force): the time integration
    (Newmark to steady state, its own peak search) at F_E = 0.3, 1, 2, 5, 10 N against H = 33
    (within 1 % in gross slip?), H = 1 and H = 5 against it in gamma_1 and in the total peak of
    gamma(t), the partial-slip force (loading history: the time integration starts from rest)
    and the stuck one (linear: they must agree to the integration error).

Timed through Python (the kernel calls take milliseconds to seconds, the wrapper overhead is
negligible). Records: standard_condensed / standard_full "H1_vs_backbone" (errors against the
backbone), standard_condensed "H3", "H5", "H1" (errors against H = 33, the most accurate
solution of the same equations), and with the time integration dti "peaks" (errors against
H = 33 in gross slip). The full table goes to out/bench/model_error.json; a run with the time
integration also writes docs/bench/model_error_dti.json, which docs/benchmarks.md keeps quoting
until the next such run.
Usage: bench_model_error.py [--json FILE] [--with-dti]
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "wrappers" / "python"))
sys.path.insert(0, str(ROOT / "bench"))

from timing import record  # noqa: E402
from udmap import hbm  # noqa: E402
from udmap.case import build_blade, build_contact, build_damper, load_case  # noqa: E402
from udmap.model import Model  # noqa: E402

OUT = ROOT / "out" / "bench"
DOCS = ROOT / "docs" / "bench"
F_BACKBONE = [0.3, 1.0, 5.0, 10.0]
F_HARMONICS = [0.3, 1.0, 2.0, 5.0, 10.0]
HARMONICS = [1, 3, 5, 33]
KEYS = ("gamma_P", "f_res", "sigma_a")


def rel(a: float, b: float) -> float:
    return a / b - 1.0


def timed(fn, repeats: int = 1):
    """fn() repeated; returns (last result, timing dict of INTERFACES.md)."""
    samples, out = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        samples.append(time.perf_counter() - t0)
    samples.sort()
    return out, {"seconds_median": samples[len(samples) // 2], "seconds_min": samples[0],
                 "seconds_max": samples[-1], "repeats": repeats}


def machine() -> dict:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else None
    return {"date": datetime.date.today().isoformat(), "nproc": os.cpu_count(), "cpu": cpu,
            "load_1min": load}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--json", type=Path, default=None)
    ap.add_argument("--with-dti", action="store_true",
                    default=os.environ.get("UDMAP_BENCH_DTI", "") not in ("", "0"))
    args = ap.parse_args()
    case = load_case(ROOT / "cases" / "blade_a.json")
    a = case.analysis
    blade = build_blade(case)
    damper = build_damper(case)
    model = Model(blade, damper, a["f_min"], a["f_max"], sigma_all=a["sigma_all"], rtol=1e-14,
                  grid_per_decade=96)
    info = {"gamma_s": damper.gamma_s, "gamma_b": damper.gamma_b, "F_lim": model.limit_force()}
    bb = {p["F_E"]: p for p in model.backbone(F_BACKBONE)}
    records = []
    table = {"case": case.name, "machine": machine(), "damper": info,
             "h1_vs_backbone": {}, "harmonics": {}}

    # H = 1 against the backbone (kernel defaults: the band swept for every force)
    for variant, method in (("condensed", "standard_condensed"), ("full", "standard_full")):
        pts, t = timed(lambda: hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"],
                                       F_BACKBONE, variant=variant, sigma_all=a["sigma_all"],
                                       damper=build_damper(case)), 3)
        diffs = {}
        for p in pts:
            b = bb[p["F_E"]]
            diffs[str(p["F_E"])] = {k: rel(p[k], b[k]) for k in
                                    ("gamma_P", "f_res", "sigma_a", "u_E")}
            # k against |k| (k_im = 0 when stuck)
            diffs[str(p["F_E"])]["k"] = abs(complex(p["k_re"], p["k_im"]) /
                                            complex(b["k_re"], b["k_im"]) - 1)
            diffs[str(p["F_E"])]["regime_equal"] = p["regime"] == b["regime"]
        worst = {k: max(abs(d[k]) for d in diffs.values()) for k in KEYS}
        table["h1_vs_backbone"][method] = diffs
        records.append(record(case.name, method, "H1_vs_backbone", t,
                              error_gamma_P=worst["gamma_P"], error_sigma_a=worst["sigma_a"],
                              error_f_res=worst["f_res"], forces=F_BACKBONE, harmonics=1,
                              reference="backbone rtol 1e-14"))
        print(f"  H = 1 {variant:>9} vs backbone: largest relative difference "
              f"{max(worst.values()):.1e}")

    # H = 1, 3, 5, 33 (condensed, warm starts: the same peaks as the band sweep)
    peaks, times = {}, {}
    for H in HARMONICS:
        pts, t = timed(lambda: hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"],
                                       F_HARMONICS, harmonics=H, sigma_all=a["sigma_all"],
                                       warm_start=2, damper=build_damper(case)),
                       1 if H > 9 else 3)
        peaks[H] = {p["F_E"]: p for p in pts}
        times[H] = t
    ref = peaks[max(HARMONICS)]
    for H in HARMONICS:
        rows = {}
        for F, p in peaks[H].items():
            r = ref[F]
            rows[str(F)] = {"gamma_1": p["gamma_P"], "f_res": p["f_res"],
                            "gamma_max": p["gamma_max"], "sigma_a": p["sigma_a"],
                            "regime": p["regime"],
                            "vs_H33": {"gamma_1": rel(p["gamma_P"], r["gamma_P"]),
                                       "f_res": rel(p["f_res"], r["f_res"]),
                                       "gamma_max": rel(p["gamma_max"], r["gamma_max"])}}
            if F in bb:
                rows[str(F)]["vs_backbone_gamma_1"] = rel(p["gamma_P"], bb[F]["gamma_P"])
        table["harmonics"][str(H)] = {"seconds": times[H]["seconds_median"], "peaks": rows}
        if H != max(HARMONICS):
            err = {k: max(abs(rel(peaks[H][F][k], ref[F][k])) for F in F_HARMONICS)
                   for k in KEYS}
            records.append(record(case.name, "standard_condensed", f"H{H}", times[H],
                                  error_gamma_P=err["gamma_P"], error_sigma_a=err["sigma_a"],
                                  error_f_res=err["f_res"], forces=F_HARMONICS, harmonics=H,
                                  reference=f"H = {max(HARMONICS)}"))
        print(f"  H = {H:2d}: {times[H]['seconds_median']:.3f} s; gamma_1 vs H = "
              f"{max(HARMONICS)}: " + ", ".join(
                  f"{F:g} N {rows[str(F)]['vs_H33']['gamma_1']:+.2%}" for F in F_HARMONICS))

    if args.with_dti:
        dti = {}
        for F in F_HARMONICS:
            print(f"  time integration at F_E = {F:g} N ...", flush=True)
            (p,), t = timed(lambda: hbm.dti(blade, build_contact(case), [F], peak=True,
                                            f_min=a["f_min"], f_max=a["f_max"]))
            r33, r1, r5 = ref[F], peaks[1][F], peaks[5][F]
            # the harmonic balance has no static harmonic here: compare the peak of gamma(t)
            # about its mean (the time integration has a static offset gamma_0)
            peak = p["gamma_max"] - p["gamma_0"]
            dti[str(F)] = {
                "gamma_1": p["gamma_1"], "f": p["f"], "gamma_max": p["gamma_max"],
                "gamma_0": p["gamma_0"], "seconds": p["seconds"], "periods": p["periods"],
                "runs": p["runs"], "ss_error": p["ss_error"], "regime": r1["regime"],
                "vs_H33": {"gamma_1": rel(p["gamma_1"], r33["gamma_P"]),
                           "f": rel(p["f"], r33["f_res"]),
                           "peak_about_mean": rel(peak, r33["gamma_max"])},
                "H1_vs_dti": {"gamma_1": rel(r1["gamma_P"], p["gamma_1"]),
                              "f": rel(r1["f_res"], p["f"]),
                              "peak_about_mean": rel(r1["gamma_max"], peak)},
                "H5_vs_dti": {"gamma_1": rel(r5["gamma_P"], p["gamma_1"]),
                              "peak_about_mean": rel(r5["gamma_max"], peak)}}
            d = dti[str(F)]
            print(f"    {p['seconds']:.1f} s: vs H = 33 gamma_1 {d['vs_H33']['gamma_1']:+.2e}; "
                  f"H = 1 vs dti gamma_1 {d['H1_vs_dti']['gamma_1']:+.2%}, peak of gamma(t) "
                  f"about its mean {d['H1_vs_dti']['peak_about_mean']:+.2%}", flush=True)
        table["dti"] = dti
        gross = [F for F in F_HARMONICS if ref[F]["regime"] == 2]
        err = {k: max(abs(dti[str(F)]["vs_H33"][k]) for F in gross) for k in ("gamma_1", "f")}
        tot = sum(dti[str(F)]["seconds"] for F in F_HARMONICS)
        records.append(record(case.name, "dti", "peaks_gross_slip",
                              {"seconds_median": tot / len(F_HARMONICS),
                               "seconds_min": min(dti[str(F)]["seconds"] for F in F_HARMONICS),
                               "seconds_max": max(dti[str(F)]["seconds"] for F in F_HARMONICS),
                               "repeats": 1},
                              error_gamma_P=err["gamma_1"], error_sigma_a=None,
                              error_f_res=err["f"], forces=gross,
                              reference=f"H = {max(HARMONICS)}",
                              note="seconds per force (its own peak search)"))
        DOCS.mkdir(parents=True, exist_ok=True)
        (DOCS / "model_error_dti.json").write_text(json.dumps(
            {"machine": table["machine"], "damper": info, "dti": dti,
             "harmonics": table["harmonics"]}, indent=1) + "\n")
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "model_error.json").write_text(json.dumps(table, indent=1) + "\n")
    if args.json:
        args.json.write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
