"""Jumps of the describing function (PHYSICS.md 2.5) and F_lim_backbone (PHYSICS.md 5).

- Blade A with mu = 0.3639798354357481, CF = 1178.4721311181784: k(gamma) jumps at
  gamma_c = 1.0335e-3 rad (a contact that stays closed below it opens above it). The one-sided
  values are checked against loops traced at gamma_c (1 -+ 1e-9) and integrated here; forces
  inside the jump give gamma_P = gamma_c and k on the segment [k-, k+] whose layer peaks at F_E
  (recomputed here from the bare receptances), and every result is the same for rtol 1e-10,
  1e-12 and 1e-14 (to 1e-9; before, sigma_a at 4 N was 1.77e8 or 2.32e8 Pa depending on rtol).
- mu = 0.6 without structural damping: the backbone levels off at F_lim_backbone = 0.5627 F_lim,
  which equals the level extrapolated from F_bb at 1e3 and 1e4 gamma_b (F_bb - F_inf ~ 1/gamma
  there) to 1e-6; unbounded and hcf_ok switch at F_lim_backbone and 0.5 F_lim_backbone.
- Blade A itself has no jump and F_lim_backbone = F_lim exactly.
"""
import copy
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import minimize_scalar

from udmap.case import build_blade, build_damper, build_model, load_case

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "blade_a.json"
MU_C, CF_C = 0.3639798354357481, 1178.4721311181784
FORCES = [3.5, 4.0, 4.5]


def loop_k(damper, gamma, n=1 << 16):
    """k of the loop traced at gamma, by the trapezoidal rule of PHYSICS.md 2.2."""
    tau, M = damper.loop(gamma, n)
    h = 2 * np.pi / n
    return (np.sum(M * np.cos(tau)) - 1j * np.sum(M * np.sin(tau))) * h / (np.pi * gamma)


def test_jump_located_with_one_sided_values(write_case):
    case = load_case(write_case("liftoff", {"mu": MU_C, "CF": CF_C}))
    damper = build_damper(case)
    jumps = damper.jumps
    assert len(jumps) == 1
    j = jumps[0]
    assert abs(j["gamma_c"] / 1.0335e-3 - 1) < 1e-4
    for side, key in ((-1, "k_minus"), (1, "k_plus")):
        k_ref = loop_k(damper, j["gamma_c"] * (1 + side * 1e-9))
        assert abs(j[key] - k_ref) < 1e-6 * abs(k_ref), (key, j[key], k_ref)
    # a jump, not a steep stretch: 5 % of k between the two sides
    assert abs(j["k_plus"] - j["k_minus"]) > 0.05 * abs(j["k_minus"])
    # the table's own values at both sides of gamma_c
    g = j["gamma_c"]
    assert abs(damper.stiffness(g) - j["k_minus"]) < 1e-9 * abs(j["k_minus"])
    assert abs(damper.stiffness(g * (1 + 1e-12)) - j["k_plus"]) < 1e-6 * abs(j["k_plus"])
    # gamma_c scales with CF like every amplitude (PHYSICS.md 2.3)
    damper.set_CF(2 * CF_C)
    j2 = damper.jumps[0]
    assert abs(j2["gamma_c"] / (2 * g) - 1) < 1e-14
    assert j2["k_minus"] == j["k_minus"] and j2["k_plus"] == j["k_plus"]


def test_backbone_in_the_jump_independent_of_rtol(write_case):
    results = {}
    for rtol in (1e-10, 1e-12, 1e-14):
        case = load_case(write_case(f"r{rtol}", {"mu": MU_C, "CF": CF_C},
                                   analysis={"rtol": rtol}))
        blade, damper = build_blade(case), build_damper(case)
        model = build_model(case, blade, damper)
        results[rtol] = model.backbone(FORCES)
    ref = results[1e-14]
    keys = ("gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im")
    for rtol, pts in results.items():
        for p, q in zip(pts, ref):
            for key in keys:
                assert abs(p[key] - q[key]) <= 1e-9 * abs(q[key]), (rtol, p["F_E"], key)
            assert p["jump"] == q["jump"]
    assert [p["jump"] for p in ref] == [True, True, False]

    # independent recomputation of the jump points from the bare receptances
    gamma_c = damper.jumps[0]["gamma_c"]
    km, kp = damper.jumps[0]["k_minus"], damper.jumps[0]["k_plus"]
    for p in ref[:2]:
        assert p["gamma_P"] == gamma_c and p["roots"] == [gamma_c]
        k = complex(p["k_re"], p["k_im"])
        s = ((k - km) * np.conj(kp - km)).real / abs(kp - km) ** 2
        assert 0 < s < 1
        assert abs(k - (km + s * (kp - km))) < 1e-9 * abs(k)

        def minus_g(f):
            return -abs(blade.layer_response(np.array([f]), k)[0][0])

        opt = minimize_scalar(minus_g, bracket=(p["f_res"] - 0.5, p["f_res"], p["f_res"] + 0.5),
                              tol=1e-12)
        assert abs(opt.x - p["f_res"]) < 1e-6 * p["f_res"]
        F_peak = gamma_c / -opt.fun
        assert abs(F_peak / p["F_E"] - 1) < 1e-9
        _, s_t, u_t = blade.layer_response(np.array([p["f_res"]]), k)
        assert abs(p["F_E"] * abs(s_t[0]) / p["sigma_a"] - 1) < 1e-9
        assert abs(p["F_E"] * abs(u_t[0]) / p["u_E"] - 1) < 1e-9
    # below and above the jump the ordinary roots
    F_below, _ = model.backbone_curve([gamma_c * (1 - 1e-9), gamma_c * (1 + 1e-9)])
    assert F_below[0] < 3.5 and F_below[1] > 4.0
    assert ref[2]["gamma_P"] > gamma_c


def test_cli_json_jump_and_table(write_case):
    path = write_case("liftoff", {"mu": MU_C, "CF": CF_C})
    env_cmd = [sys.executable, "-m", "udmap"]
    out = subprocess.run(env_cmd + ["backbone", str(path), "--forces", "3.5,4.5", "--json"],
                         capture_output=True, text=True, check=True)
    data = json.loads(out.stdout)
    assert [p["jump"] for p in data["points"]] == [True, False]
    assert data["F_lim_backbone"] <= data["F_lim"]
    out = subprocess.run(env_cmd + ["table", str(path), "--gammas", "1e-3,2e-3", "--json"],
                         capture_output=True, text=True, check=True)
    data = json.loads(out.stdout)
    assert len(data["jumps"]) == 1 and abs(data["jumps"][0]["gamma_c"] / 1.0335e-3 - 1) < 1e-4
    out = subprocess.run(env_cmd + ["backbone", str(path), "--forces", "3.5,4.5"],
                         capture_output=True, text=True, check=True)
    assert "jump" in out.stdout


def test_limit_force_backbone_with_lift_off(write_case):
    path = write_case("mu06", {"mu": 0.6}, {"zeta": 0.0}, {"sigma_all": 1e10})
    case = load_case(path)
    blade, damper = build_blade(case), build_damper(case)
    model = build_model(case, blade, damper)
    F_lim, F_bb_lim = model.limit_force(), model.limit_force_backbone()
    assert damper.lift_off
    assert 0.55 * F_lim < F_bb_lim < 0.57 * F_lim
    # F_bb approaches its level like 1/gamma: Richardson from 1e3 and 1e4 gamma_b
    gb = damper.gamma_b
    F, _ = model.backbone_curve([1e3 * gb, 1e4 * gb, 1e5 * gb])
    assert np.all(np.diff(F) > 0) and F[-1] < F_bb_lim
    level = (10 * F[1] - F[0]) / 9
    assert abs(level / F_bb_lim - 1) < 1e-6, (level, F_bb_lim)
    level2 = (10 * F[2] - F[1]) / 9
    assert abs(level2 / F_bb_lim - 1) < 1e-7
    # unbounded (zeta = 0) and hcf_ok follow the smaller limit
    pts = model.backbone([0.49 * F_bb_lim, 0.51 * F_bb_lim, 0.999 * F_bb_lim,
                          1.001 * F_bb_lim, 0.9 * F_lim])
    assert [p["hcf_ok"] for p in pts] == [True, False, False, False, False]
    assert [p["unbounded"] for p in pts] == [False, False, False, True, True]
    assert pts[2]["gamma_P"] > 100 * gb


def test_blade_a_unchanged(tmp_path):
    case = load_case(CASE)
    blade, damper = build_blade(case), build_damper(case)
    model = build_model(case, blade, damper)
    assert damper.jumps == []
    assert model.limit_force_backbone() == model.limit_force()
    assert not any(p["jump"] for p in model.backbone([1, 5, 10]))
