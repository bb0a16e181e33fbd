"""The main job (``make demo``, ``python3 -m udmap demo``): blade A with its damper, everything
a designer needs from the mapping, written to ``out/demo/`` as PNG plots and CSV data, with a
summary table on stdout.

Files:
  gg_design_diagram.png/.csv   peak stress vs proof force, F_lim, 0.5 F_lim, sigma_all marked
  gamma_P_vs_F_E.png           peak platform rotation vs force (log-log), gamma_s, gamma_b marked
  f_res_vs_F_E.png             resonance frequency vs force
  response_curves.png/.csv     response curves for the demo forces over the band, with backbone
  backbone.csv                 the peaks for the demo forces (the summary table)
  backbone_curve.csv           F_bb(gamma) and its frequency
  stiffness.png/.csv           k_Re, k_Im vs gamma (the damper table), gamma_b marked
  harmonics.png/.csv           GG diagram and gamma_P vs F_E with the single-harmonic method and
                               with multi-harmonic layers at automatic H side by side
                               (PHYSICS.md 4.1; dampers with a contact model)
  summary.json                 the summary as JSON
"""
from __future__ import annotations

import copy
import csv
import json
import math
from pathlib import Path

import numpy as np

from . import plots
from .case import Case, build_blade, build_damper, build_model, load_case, validate
from .nodal import sweep
from .progress import Progress

DEMO_FORCES = tuple(float(f) for f in range(1, 11))
#: The wheel of the demo's nodal-diameter sweep and its forces [N].
DEMO_BLADES = 24
DEMO_NODAL_FORCES = (2.0, 5.0, 10.0)


def _as_case(case):
    if case is None:
        return load_case(None)
    if isinstance(case, Case):
        return case
    if isinstance(case, (str, Path)):
        return load_case(case)
    if isinstance(case, dict):
        return validate(copy.deepcopy(case))
    raise TypeError("run_demo: case must be a Case, a case dict, a path or None")


def _write_csv(path: Path, header: list[str], rows, comment: str = "") -> None:
    with open(path, "w", newline="") as fh:
        if comment:
            for line in comment.splitlines():
                fh.write(f"# {line}\n")
        w = csv.writer(fh)
        w.writerow(header)
        for row in rows:
            w.writerow(["" if (v is None or (isinstance(v, float) and not math.isfinite(v)))
                        else (repr(v) if isinstance(v, float) else v) for v in row])


def _undamped_twin(case, damper):
    """The same case without structural damping (zeta = 0), or None if the blade has an
    explicit C or no damping already."""
    b = case.blade
    if b.get("zeta", 0.0) == 0.0 or (b["kind"] == "matrices" and b.get("C")):
        return None
    twin = copy.deepcopy(case)
    twin.blade["zeta"] = 0.0
    blade0 = build_blade(twin)
    return build_model(twin, blade0, damper), blade0


def _knows_platform(case) -> bool:
    """The blade knows its platform translations (traveling waves need them)."""
    b = case.blade
    return b["kind"] == "beam" or (b["kind"] == "matrices" and b.get("u_dof") is not None) or \
        (b["kind"] == "fe" and b.get("platform", {}).get("tangent") is not None)


#: The units of summary.json's quantities (docs/outputs.md).
SUMMARY_UNITS = {key: unit for unit, keys in (
    ("N", ("F_lim", "F_E")), ("rad", ("gamma_b", "gamma_s", "gamma_P", "gamma_max")),
    ("Hz", ("f1_bare", "f_stuck", "f_res")), ("Pa", ("sigma_all", "sigma_a", "sigma_max")),
    ("m", ("u_E",)), ("N m", ("M_max", "M_min")), ("N m/rad", ("k_re", "k_im")),
    ("deg", ("ibpa_deg",)), ("1", ("blades", "engine_order", "nodal_diameter")))
    for key in keys}


def run_demo(case=None, outdir="out/demo", forces=DEMO_FORCES, quiet: bool = False) -> dict:
    """Runs the demo on ``case`` (a Case, a case dict, a path, or None for the embedded blade
    A) and writes the plots and CSV files into ``outdir``. Returns the summary as a dict."""
    case = _as_case(case)
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    a = case.analysis
    forces = np.asarray(forces, dtype=float)

    with Progress(9, "demo") as bar:
        blade = build_blade(case)
        damper = build_damper(case)
        model = build_model(case, blade, damper)
        F_lim = model.limit_force()
        f1 = float(blade.natural_frequencies(1)[0])
        bar.update()

        # the design diagrams: peaks over a dense range of proof forces
        F_grid = np.unique(np.concatenate([np.geomspace(1e-3 * F_lim, 1.2 * F_lim, 160),
                                           np.linspace(0.01 * F_lim, 1.2 * F_lim, 120)]))
        grid_pts = model.backbone(F_grid)
        twin = _undamped_twin(case, damper)
        grid0 = []
        if twin is not None:
            F0 = F_grid[F_grid < 0.995 * F_lim]
            grid0 = twin[0].backbone(F0)
        bar.update()

        # the demo forces: peaks and response curves
        points = model.backbone(forces)
        bar.update()
        curves = model.curves(forces, layers=a.get("layers", 200))
        bar.update()

        # the backbone line and the stiffness table
        finite = [p["gamma_P"] for p in points if not p["unbounded"]]
        g_top = 2 * max(finite) if finite else 10 * damper.gamma_b
        g_low = damper.gamma_s if damper.gamma_s > 0 else 1e-2 * damper.gamma_b
        g_line = np.geomspace(min(g_low, 0.3 * min(finite)) if finite else g_low, g_top, 240)
        F_bb, f_bb = model.backbone_curve(g_line)
        stuck_F, stuck_f = model.backbone_curve([1e-3 * g_low])
        # G1: the base cycle reached at the peak (gamma_P = gamma_b); G2: F_E = 0.5 F_lim
        F_G1 = float(model.backbone_curve([damper.gamma_b])[0][0])
        G1_point, G2_point = model.backbone([F_G1, 0.5 * F_lim])
        g_k = np.geomspace(1e-2 * damper.gamma_b, 1e2 * damper.gamma_b, 240)
        k = np.asarray(damper.stiffness(g_k), dtype=complex)
        bar.update()

        # CSV
        _write_csv(out / "gg_design_diagram.csv",
                   ["F_E_N", "gamma_P_rad", "f_res_Hz", "sigma_a_Pa", "u_E_m", "k_re_Nm_per_rad",
                    "k_im_Nm_per_rad", "regime", "hcf_ok", "gamma_P_zeta0_rad",
                    "f_res_zeta0_Hz", "sigma_a_zeta0_Pa"],
                   [[p["F_E"], p["gamma_P"], p["f_res"], p["sigma_a"], p["u_E"], p["k_re"],
                     p["k_im"], p["regime"], int(p["hcf_ok"])] +
                    ([grid0[i]["gamma_P"], grid0[i]["f_res"], grid0[i]["sigma_a"]]
                     if i < len(grid0) else [None, None, None])
                    for i, p in enumerate(grid_pts)],
                   f"{case.name}: peaks of the non-linear response (backbone) vs proof force\n"
                   f"F_lim = {F_lim!r} N, sigma_all = {a['sigma_all']!r} Pa; regime 0 stuck, "
                   "1 partial slip, 2 full slip, 3 F_E >= F_lim; zeta0 columns: same blade "
                   "without structural damping (empty where unbounded)")
        _write_csv(out / "backbone.csv",
                   ["F_E_N", "gamma_P_rad", "f_res_Hz", "sigma_a_Pa", "u_E_m", "k_re_Nm_per_rad",
                    "k_im_Nm_per_rad", "regime", "regime_name", "hcf_ok", "unbounded", "roots_rad"],
                   [[p["F_E"], p["gamma_P"], p["f_res"], p["sigma_a"], p["u_E"], p["k_re"],
                     p["k_im"], p["regime"], p["regime_name"], int(p["hcf_ok"]),
                     int(p["unbounded"]), " ".join(repr(r) for r in p["roots"])] for p in points],
                   f"{case.name}: resonance peaks for the demo forces")
        _write_csv(out / "response_curves.csv",
                   ["F_E_N", "f_Hz", "gamma_P_rad", "sigma_a_Pa", "branch", "part"],
                   [[c["F_E"], float(f), float(g), float(s), int(b), int(pt)]
                    for c in curves for f, g, s, b, pt in
                    zip(c["f"], c["gamma_P"], c["sigma_a"], c["branch"], c["part"])],
                   "non-linear response curves by amplitude layered force mapping, path order;\n"
                   "branch 0 below the layer's peak frequency, 1 above, 2 on the backbone; "
                   "part 1 main curve, 2... detached parts")
        _write_csv(out / "backbone_curve.csv", ["gamma_rad", "F_bb_N", "f_res_Hz"],
                   zip(g_line.tolist(), F_bb.tolist(), f_bb.tolist()),
                   "backbone: F_bb(gamma) = gamma / max_f |g~(f; gamma)| and the peak frequency")
        _write_csv(out / "stiffness.csv", ["gamma_rad", "k_re_Nm_per_rad", "k_im_Nm_per_rad"],
                   zip(g_k.tolist(), k.real.tolist(), k.imag.tolist()),
                   f"damper complex stiffness (first harmonic); gamma_b = {damper.gamma_b!r} rad, "
                   f"gamma_s = {damper.gamma_s!r} rad, M_max = {damper.M_max!r} N m, "
                   f"M_min = {damper.M_min!r} N m, lift_off = {bool(damper.lift_off)}")
        bar.update()

        # plots
        ok = [not p["unbounded"] for p in grid_pts]
        F_ok = F_grid[ok]
        sel0 = [p for p in grid0 if not p["unbounded"]]
        plots.gg_diagram(F_ok, [p["sigma_a"] for p, o in zip(grid_pts, ok) if o], F_lim,
                         a["sigma_all"], out / "gg_design_diagram.png",
                         zeta=case.blade.get("zeta"),
                         F_E_undamped=[p["F_E"] for p in sel0] if sel0 else None,
                         sigma_a_undamped=[p["sigma_a"] for p in sel0] if sel0 else None,
                         F_marked=[p["F_E"] for p in points if not p["unbounded"]],
                         sigma_marked=[p["sigma_a"] for p in points if not p["unbounded"]],
                         G1=(G1_point["F_E"], G1_point["sigma_a"]),
                         G2=(G2_point["F_E"], G2_point["sigma_a"]))
        plots.gamma_vs_force(F_ok, [p["gamma_P"] for p, o in zip(grid_pts, ok) if o], F_lim,
                             damper.gamma_s, damper.gamma_b, out / "gamma_P_vs_F_E.png",
                             regime=[p["regime"] for p, o in zip(grid_pts, ok) if o],
                             F_E_undamped=[p["F_E"] for p in sel0] if sel0 else None,
                             gamma_undamped=[p["gamma_P"] for p in sel0] if sel0 else None)
        plots.fres_vs_force(F_ok, [p["f_res"] for p, o in zip(grid_pts, ok) if o], F_lim,
                            out / "f_res_vs_F_E.png", f_stuck=float(stuck_f[0]), f_bare=f1,
                            F_E_undamped=[p["F_E"] for p in sel0] if sel0 else None,
                            f_undamped=[p["f_res"] for p in sel0] if sel0 else None)
        plots.response_curves(curves, points, a["f_min"], a["f_max"],
                              out / "response_curves.png", backbone_curve=(g_line, f_bb))
        plots.stiffness(g_k, k, damper.gamma_b, out / "stiffness.png", gamma_s=damper.gamma_s)
        bar.update()

        # the single-harmonic premise against multi-harmonic layers (automatic H) at the demo
        # forces below F_lim
        harm = []
        if case.damper["kind"] in ("asymmetric", "jenkins"):
            F_h = forces[forces < F_lim] if len(forces) else forces
            model.set_harmonics("auto", a.get("harmonic_tol", 1e-3))
            harm = model.backbone(F_h) if len(F_h) else []
            model.set_harmonics(a.get("harmonics", 1) if a.get("harmonics", 1) != "auto"
                                else "auto", a.get("harmonic_tol", 1e-3))
            ok1 = [p for p in grid_pts if not p["unbounded"] and p["F_E"] < F_lim]
            okh = [p for p in harm if not p["unbounded"]]
            if okh:
                plots.harmonics_side_by_side(
                    [p["F_E"] for p in ok1], [p["sigma_a"] for p in ok1],
                    [p["gamma_P"] for p in ok1], [p["F_E"] for p in okh],
                    [p["sigma_a"] for p in okh], [p["sigma_max"] for p in okh],
                    [p["gamma_P"] for p in okh], F_lim, a["sigma_all"],
                    out / "harmonics.png", harmonics=[p["harmonics"] for p in okh])
                single = {p["F_E"]: p for p in points}
                _write_csv(out / "harmonics.csv",
                           ["F_E_N", "harmonics", "gamma_P_rad", "sigma_a_Pa", "f_res_Hz",
                            "gamma_max_rad", "sigma_max_Pa", "gamma_P_H1_rad",
                            "sigma_a_H1_Pa", "f_res_H1_Hz"],
                           [[p["F_E"], p["harmonics"], p["gamma_P"], p["sigma_a"], p["f_res"],
                             p["gamma_max"], p["sigma_max"], single[p["F_E"]]["gamma_P"],
                             single[p["F_E"]]["sigma_a"], single[p["F_E"]]["f_res"]]
                            for p in okh],
                           f"{case.name}: peaks with multi-harmonic layers (automatic H, "
                           "PHYSICS.md 4.1) beside the single-harmonic method (H1 columns)")
        bar.update()

        # every nodal diameter of a wheel of DEMO_BLADES blades (PHYSICS.md 2.6)
        nodal = None
        if case.damper["kind"] == "asymmetric" and _knows_platform(case):
            F_n = [F for F in DEMO_NODAL_FORCES if F < F_lim]
            nodal = sweep(blade, damper, a | {"harmonics": 1}, DEMO_BLADES, F_n)
            _write_csv(out / "nodal.csv",
                       ["engine_order", "ibpa_deg", "nodal_diameter", "F_E_N", "gamma_P_rad",
                        "f_res_Hz", "sigma_a_Pa", "F_lim_N", "hcf_ok", "worst"],
                       [[p["engine_order"], p["ibpa_deg"], p["nodal_diameter"], p["F_E"],
                         p["gamma_P"], p["f_res"], p["sigma_a"], p["F_lim"], p["hcf_ok"],
                         p["worst"]] for p in nodal["points"]],
                       f"{case.name}: the peaks of every engine order on a wheel of "
                       f"{DEMO_BLADES} blades (traveling waves, PHYSICS.md 2.6, H = 1)")
            plots.nodal_sweep(nodal, a["sigma_all"], out / "nodal.png")
        bar.update()

    summary = {"case": case.name, "F_lim": F_lim, "gamma_b": damper.gamma_b,
               "gamma_s": damper.gamma_s, "M_max": damper.M_max, "M_min": damper.M_min,
               "f1_bare": f1, "f_stuck": float(stuck_f[0]), "lift_off": bool(damper.lift_off),
               "sigma_all": a["sigma_all"],
               "G1": {"F_E": G1_point["F_E"], "gamma_P": G1_point["gamma_P"],
                      "sigma_a": G1_point["sigma_a"], "f_res": G1_point["f_res"]},
               "G2": {"F_E": G2_point["F_E"], "gamma_P": G2_point["gamma_P"],
                      "sigma_a": G2_point["sigma_a"], "f_res": G2_point["f_res"]},
               "points": [{k: p[k] for k in ("F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re",
                                             "k_im", "regime", "regime_name", "hcf_ok",
                                             "unbounded")} for p in points],
               "points_auto_harmonics": [{k: p[k] for k in ("F_E", "gamma_P", "f_res",
                                                            "sigma_a", "gamma_max",
                                                            "sigma_max", "harmonics",
                                                            "hcf_ok")}
                                         for p in harm if not p["unbounded"]]}
    if nodal is not None:
        summary["nodal"] = {"blades": DEMO_BLADES, "worst": nodal["worst"]}
    summary["units"] = SUMMARY_UNITS  # SI, as every JSON output (docs/outputs.md)
    (out / "summary.json").write_text(json.dumps(summary, indent=1, allow_nan=False) + "\n")
    if not quiet:
        print_summary(summary, out)
    return summary


def print_summary(summary: dict, out: Path) -> None:
    """The short summary table of the demo."""
    print(f"udmap demo: {summary['case']}")
    print(f"  F_lim    = {summary['F_lim']:.4f} N    (0.5 F_lim = {0.5 * summary['F_lim']:.4f} N)")
    print(f"  gamma_b  = {summary['gamma_b']:.4e} rad   gamma_s = {summary['gamma_s']:.4e} rad")
    print(f"  f bare   = {summary['f1_bare']:.3f} Hz   f stuck = {summary['f_stuck']:.3f} Hz"
          f"   lift-off: {'yes' if summary['lift_off'] else 'no'}")
    for name in ("G1", "G2"):
        g = summary[name]
        s = "-" if g["sigma_a"] is None else f"{g['sigma_a'] / 1e6:.2f} MPa"
        print(f"  {name}       : F_E = {g['F_E']:.4g} N, gamma_P = {g['gamma_P']:.4e} rad, "
              f"sigma_a = {s}, f_res = {g['f_res']:.3f} Hz")
        if name == "G1" and g["F_E"] > summary["F_lim"]:
            print(f"             G1 lies above F_lim = {summary['F_lim']:.4g} N: the base cycle "
                  "(gamma_b) is reached only where friction no longer bounds the response "
                  "(the plateaus are reached by partial slip first; PHYSICS.md 2.3, 5)")
    print(f"  {'F_E [N]':>8} {'gamma_P [rad]':>14} {'f_res [Hz]':>11} {'sigma_a [MPa]':>13} "
          f"{'u_E [mm]':>9}  {'regime':<16} HCF")
    for p in summary["points"]:
        if p["unbounded"]:
            print(f"  {p['F_E']:8.3g} {'unbounded':>14} {'-':>11} {'-':>13} {'-':>9}  "
                  f"{p['regime_name']:<16} no")
            continue
        s = "-" if p["sigma_a"] is None else f"{p['sigma_a'] / 1e6:13.2f}"
        print(f"  {p['F_E']:8.3g} {p['gamma_P']:14.4e} {p['f_res']:11.3f} {s:>13} "
              f"{1e3 * p['u_E']:9.4f}  {p['regime_name']:<16} {'ok' if p['hcf_ok'] else 'no'}")
    if "nodal" in summary:
        for w in summary["nodal"]["worst"]:
            print(f"  {summary['nodal']['blades']} blades, F_E = {w['F_E']:g} N: worst engine order "
                  f"{w['engine_order']} (nodal diameter {w['nodal_diameter']}, "
                  f"sigma_max = {w['sigma_max'] / 1e6:.2f} MPa)")
    print(f"  written to {out}/")
