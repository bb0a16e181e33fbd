"""Plausibility warnings in a design of experiments (docs/doe.md, "Summary"): counted per kind
over the designs, in the run summary and in FILE.meta.json, with the CSV as it was (no column
added, the same bytes whatever the counts). Each count is checked against the designs' own
values: gamma_b from the CSV, the platform mass and the band from the sampled parameters."""
from __future__ import annotations

import csv
import json
import subprocess
import sys
from pathlib import Path

from udmap.case import build_blade, build_damper, build_model, load_case
from udmap.case.plausibility import GAMMA_B_MAX, plausibility_checks
from udmap.doe import run_doe, with_values

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "blade_a.json"
#: Neck and airfoil of blade A [kg]: rho (b h L of the neck + b h L of the airfoil).
REST = 8200.0 * (0.020 * 0.008 * 0.020 + 0.030 * 0.004 * 0.120)


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _meta(path):
    return json.loads(Path(str(path) + ".meta.json").read_text())


def test_gamma_b_counted_from_the_kernel_outputs_of_one_chunk_call(tmp_path):
    # stiffness_scale alone: the designs go to the kernel in chunks (udmap_model_designs)
    out = tmp_path / "k.csv"
    s = run_doe(str(CASE), ["stiffness_scale=0.0005:1:log"], 48, out, forces="2", workers=1,
                progress=False)
    rows = _rows(out)
    big = sum(float(r["gamma_b"]) > GAMMA_B_MAX for r in rows)
    assert 0 < big < len(rows)
    # every check of each design, the stuck peak included (udmap_model_designs_warnings),
    # counted as the single case with that design's stiffnesses gets them
    expected = {}
    for r in rows:
        case = load_case(str(CASE))
        for k in ("kn_flat", "kt_flat", "kn_curved", "kt_curved"):
            case.damper[k] *= float(r["stiffness_scale"])
        blade, damper = build_blade(case), build_damper(case)
        for kind in {k for k, _ in plausibility_checks(case, blade, damper,
                                                        build_model(case, blade, damper))}:
            expected[kind] = expected.get(kind, 0) + 1
    assert expected["gamma_b_large"] == big and expected.get("stuck_shift", 0) > 0
    assert s["warnings"] == expected and s["warnings_designs"] == 48
    meta = _meta(out)
    assert meta["warnings"] == expected and meta["warnings_designs"] == 48
    assert "warnings" not in rows[0] and list(rows[0])[-2:] == ["status", "message"]
    # the kind is the one a single case with those stiffnesses gets, text and all
    case = load_case(str(CASE))
    r = next(r for r in rows if float(r["gamma_b"]) > GAMMA_B_MAX)
    for k in ("kn_flat", "kt_flat", "kn_curved", "kt_curved"):
        case.damper[k] *= float(r["stiffness_scale"])
    kinds = dict(plausibility_checks(case, build_blade(case), build_damper(case)))
    assert "were the contact stiffnesses given in N/mm?" in kinds["gamma_b_large"]


def test_platform_mass_and_band_counted_per_design_and_csv_unchanged(tmp_path):
    # blade and band parameters vary: designs one by one, the blade checks per design
    out = tmp_path / "p.csv"
    s = run_doe(str(CASE), ["platform_m=0.01:1:log", "f_max=160:300"], 40, out, forces="2",
                workers=1, progress=False)
    rows = _rows(out)
    heavy = sum(float(r["platform_m"]) > REST for r in rows)
    # the bare first mode moves with the platform mass: the blade of each design decides
    base = load_case(str(CASE))
    missed = 0
    expected = {}
    for r in rows:
        case = with_values(base, [("blade", "platform", "m"), ("analysis", "f_max")],
                           (float(r["platform_m"]), float(r["f_max"])))
        blade, damper = build_blade(case), build_damper(case)
        f1 = float(blade.natural_frequencies(1)[0])
        missed += not case.analysis["f_min"] <= f1 <= case.analysis["f_max"]
        # the design's every check, the stuck peak included, as the single case gets them
        for kind in {k for k, _ in plausibility_checks(case, blade, damper,
                                                        build_model(case, blade, damper))}:
            expected[kind] = expected.get(kind, 0) + 1
    assert 0 < heavy < len(rows) and 0 < missed < len(rows)
    assert expected["platform_mass"] == heavy
    assert expected["band_misses_mode"] >= missed  # the bare mode, or else the stuck one
    assert s["warnings"] == expected
    assert _meta(out)["warnings"] == s["warnings"]
    # the same run again (two workers): the same file byte for byte, the same counts
    again = tmp_path / "q.csv"
    s2 = run_doe(str(CASE), ["platform_m=0.01:1:log", "f_max=160:300"], 40, again, forces="2",
                 workers=2, progress=False)
    assert again.read_bytes() == out.read_bytes() and s2["warnings"] == s["warnings"]


def test_blade_a_has_no_warning_and_the_cli_prints_the_counts(tmp_path):
    out = tmp_path / "a.csv"
    s = run_doe(str(CASE), ["mu=0.2:0.6"], 16, out, forces="2", workers=1, progress=False)
    assert s["warnings"] == {} and _meta(out)["warnings"] == {}
    r = subprocess.run([sys.executable, "-m", "udmap", "doe", str(CASE), "--vary",
                        "platform_m=21:22", "--samples", "4", "--forces", "2", "--workers", "1",
                        "--out", str(tmp_path / "g.csv")], capture_output=True, text=True,
                       cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert "plausibility warnings: platform_mass 4 (of 4 designs" in r.stdout, r.stdout


def test_a_resumed_run_continues_the_recorded_counts(tmp_path):
    out = tmp_path / "r.csv"
    s = run_doe(str(CASE), ["stiffness_scale=0.0005:1:log"], 24, out, forces="2", workers=1,
                progress=False)
    assert s["warnings"]["gamma_b_large"] > 0
    # nothing left to compute: the counts are the recorded ones, not zero
    again = run_doe(str(CASE), ["stiffness_scale=0.0005:1:log"], 24, out, forces="2",
                    workers=1, progress=False, resume=True)
    assert again["computed"] == 0
    assert again["warnings"] == s["warnings"] and again["warnings_designs"] == 24
    assert _meta(out)["warnings"] == s["warnings"]


def test_the_doe_threshold_is_the_kernels():
    # gamma_b scales as 1/kappa with a common factor kappa of the contact stiffnesses
    # (PHYSICS.md 2.3): just above and just below GAMMA_B_MAX, the kernel agrees
    case = load_case(str(CASE))
    blade = build_blade(case)
    kappa0 = build_damper(case).gamma_b / GAMMA_B_MAX
    for factor, above in ((1 - 1e-6, True), (1 + 1e-6, False)):
        c = load_case(str(CASE))
        for k in ("kn_flat", "kt_flat", "kn_curved", "kt_curved"):
            c.damper[k] *= kappa0 * factor
        damper = build_damper(c)
        assert (damper.gamma_b > GAMMA_B_MAX) == above
        kinds = [k for k, _ in plausibility_checks(c, blade, damper)]
        assert ("gamma_b_large" in kinds) == above, (factor, damper.gamma_b)
