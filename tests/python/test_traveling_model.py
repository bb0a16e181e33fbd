"""Traveling waves through the Python and command-line faces (PHYSICS.md 2.6): the admissible
force, the response and the response curves at a phase, and the standard method at a phase
against the layered backbone."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from udmap.case import build_blade, build_damper, load_case
from udmap.model import Model

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def wave():
    case = load_case(str(ROOT / "cases" / "blade_a.json"))
    blade, damper = build_blade(case), build_damper(case)
    return blade, damper, Model(blade, damper, 150.0, 230.0, ibpa_deg=90.0)


def test_admissible_force_at_a_phase(wave):
    _, _, model = wave
    F_lim = min(model.limit_force(), model.limit_force_backbone())
    assert F_lim == model.limit_force()  # at phi /= 0 F_lim(phi) is the backbone's supremum
    F_adm = model.admissible_force(F_lim, 80e6, 1e-10)
    assert 0 < F_adm < 0.5 * F_lim
    assert model.backbone([F_adm])[0]["sigma_a"] == pytest.approx(80e6, rel=1e-6)


def test_response_at_the_peak_frequency_is_the_peak(wave):
    """The peak lies on the response curve: at f_res the response to F_E is gamma_P (its
    largest root), the same equations solved the other way round."""
    _, _, model = wave
    peak = model.backbone([3.0])[0]
    resp = model.response(peak["f_res"], [3.0])[0]
    assert resp["gamma_P"] == pytest.approx(peak["gamma_P"], rel=1e-6)
    assert resp["sigma_a"] == pytest.approx(peak["sigma_a"], rel=1e-6)
    assert resp["roots"] == sorted(resp["roots"]) and resp["gamma_P"] == resp["roots"][-1]
    below = model.response(0.99 * peak["f_res"], [3.0])[0]
    assert below["gamma_P"] < peak["gamma_P"]


def test_curves_at_a_phase_pass_through_the_response_and_the_peak(wave):
    """Every point of a response curve at a phase is a root of the response at its frequency;
    the curve's turning point is the backbone's peak."""
    _, _, model = wave
    curve = model.curves([2.0], layers=8)[0]
    peak = model.backbone([2.0])[0]
    branch = [int(b) for b in curve["branch"]]
    turning = [k for k, b in enumerate(branch) if b == 2]
    assert len(turning) == 1 and curve["gamma_P"][turning[0]] == peak["gamma_P"]
    assert branch == [0] * turning[0] + [2] + [1] * (len(branch) - turning[0] - 1)
    for k in (2, 6, 10, 14):
        f, g = curve["f"][k], curve["gamma_P"][k]
        if not 150.0 < f < 230.0:
            continue
        roots = model.response(f, [2.0])[0]["roots"]
        assert min(abs(r / g - 1) for r in roots) < 1e-7, (k, f, g, roots)


def test_hbm_at_a_phase_equals_the_backbone(tmp_path):
    case = json.loads((ROOT / "cases" / "blade_a.json").read_text())
    case["analysis"]["ibpa_deg"] = -90.0
    path = tmp_path / "wave.json"
    path.write_text(json.dumps(case))

    def run(*args):
        r = subprocess.run([sys.executable, "-m", "udmap", *args, str(path), "--forces", "5",
                            "--json"], capture_output=True, text=True, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        return json.loads(r.stdout)["points"][0]
    layered, standard = run("backbone"), run("hbm")
    for key in ("gamma_P", "f_res", "sigma_a"):
        assert standard[key] == pytest.approx(layered[key], rel=1e-6), key


def test_backbone_curve_at_a_phase_passes_through_the_peaks(wave):
    """F_bb(gamma) at a phase is the traveling wave's: at a peak's gamma_P it gives that peak's
    force and frequency (not the in-phase curve's)."""
    _, _, model = wave
    peaks = model.backbone([2.0, 8.0])
    F_bb, f_res = model.backbone_curve([p["gamma_P"] for p in peaks])
    for p, F, f in zip(peaks, F_bb, f_res):
        assert F == pytest.approx(p["F_E"], rel=1e-8)
        assert f == pytest.approx(p["f_res"], rel=1e-6)  # the peak frequency to ~1e-7


def test_force_table_at_a_phase_answers_as_the_exact_points(wave):
    """The force table at a phase (opt-in: udmap_model_set_force_table): a range covered in
    advance holds every force of it, no later force of the range adds a point, and the points
    agree with exact ones to the table's tolerance (harmonic_tol/1000 = 1e-6), with the same
    regime, hcf verdict and harmonics. A force outside the range is exact."""
    blade, damper, exact = wave
    tabled = Model(blade, damper, 150.0, 230.0, ibpa_deg=90.0)
    tabled.set_force_table(True)
    tabled.cover_forces(2.0, 2.4)
    info = tabled.force_table_info()
    assert info["points"] > 0 and info["leaves"] > 0
    forces = list(np.random.default_rng(7).uniform(2.0, 2.4, 12)) + [3.5]
    worst = 0.0
    for F in forces:
        p, q = tabled.backbone([F])[0], exact.backbone([F])[0]
        assert (p["regime"], p["hcf_ok"], p["harmonics"]) == (q["regime"], q["hcf_ok"],
                                                              q["harmonics"])
        for key in ("gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "gamma_max"):
            worst = max(worst, abs(p[key] / q[key] - 1))
        if F == 3.5:  # outside (first force of its level-0 panel): the exact point itself
            assert p == q
    assert tabled.force_table_info()["points"] == info["points"]
    assert worst <= 1e-6
