"""udmap.Model (layered force mapping, backbone, limit force, response at a frequency) and the
CLI commands backbone, curves and response: the one-DOF Jenkins oscillator of PHYSICS.md 8
through Matrix Market files, every curve and response point against the scalar equation
evaluated here in numpy, blade A's JSON against the contract of INTERFACES.md, the unbounded
answer without damping, and the exit statuses."""
import copy
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from udmap import InputError, PhysicsError
from udmap.blade import Blade
from udmap.case import build_blade, build_model
from udmap.damper import Damper
from udmap.model import Model

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "blade_a.json"
KT, SLIP, C_VISC = 0.25, 0.2, 0.01
PUBLISHED = [(0.05, 0.946956, 1.106824), (0.1, 1.214018, 1.083677), (0.3, 7.279801, 1.007341)]


def jenkins(a):
    """Jenkins describing function (PHYSICS.md 2.4), written out again."""
    a = np.asarray(a, dtype=float)
    a_s = SLIP / KT
    beta = np.arccos(np.clip(1 - 2 * a_s / np.maximum(a, a_s), -1, 1))
    k = KT / np.pi * (beta - np.sin(2 * beta) / 2) + 1j * 4 * SLIP / (np.pi * a) * (1 - a_s / a)
    return np.where(a <= a_s, KT + 0j, k)


def residual(a, omega, F):
    """(a |1 + k(a) H| - F |H|)/(F |H|) for the oscillator, H = 1/(1 - w^2 + i c w)."""
    H = 1 / (1 - omega ** 2 + 1j * C_VISC * omega)
    return (a * np.abs(1 + jenkins(a) * H) - F * np.abs(H)) / (F * np.abs(H))


@pytest.fixture(scope="module")
def oscillator(tmp_path_factory):
    d = tmp_path_factory.mktemp("oscillator")
    for name, value in (("M", 1.0), ("K", 1.0), ("C", C_VISC)):
        (d / f"{name}.mtx").write_text("%%MatrixMarket matrix coordinate real symmetric\n"
                                      f"1 1 1\n1 1 {value!r}\n")
    blade = Blade.matrices(d / "M.mtx", d / "K.mtx", 1, 1, C=d / "C.mtx")
    damper = Damper.jenkins(KT, SLIP)
    return Model(blade, damper, 0.8 / (2 * np.pi), 1.4 / (2 * np.pi))


def test_oscillator_published_peaks(oscillator):
    points = oscillator.backbone([F for F, _, _ in PUBLISHED])
    for p, (F, amp, omega) in zip(points, PUBLISHED):
        assert p["F_E"] == F
        assert p["gamma_P"] == pytest.approx(amp, rel=1e-6)
        assert 2 * np.pi * p["f_res"] == pytest.approx(omega, rel=1e-6)
        assert p["roots"] == [p["gamma_P"]]
        assert abs(residual(p["gamma_P"], 2 * np.pi * p["f_res"], F)) < 1e-11
    assert oscillator.limit_force() == pytest.approx(4 * SLIP / np.pi, rel=1e-14)
    assert [p["regime"] for p in points] == [2, 2, 3]
    assert points[2]["regime_name"] == "at or above F_lim" and not points[2]["hcf_ok"]
    assert points[0]["sigma_a"] is None  # no stress rows


def test_oscillator_backbone_curve_limits(oscillator):
    F_bb, f_res = oscillator.backbone_curve([1e-3, 1e3])
    assert 2 * np.pi * f_res[0] == pytest.approx(np.sqrt(1.25), rel=1e-4)
    assert 2 * np.pi * f_res[1] == pytest.approx(1.0, rel=1e-4)
    w = np.sqrt(1.25 - C_VISC ** 2 / 2)  # stuck: linear oscillator with k = 1.25
    assert F_bb[0] == pytest.approx(1e-3 * abs(1.25 - w ** 2 + 1j * C_VISC * w), rel=1e-12)


def test_oscillator_curves_and_response_on_the_equation(oscillator):
    forces = [0.05, 0.1, 0.3]
    curves = oscillator.curves(forces, layers=40)
    for c, (F, amp, _) in zip(curves, PUBLISHED):
        assert c["F_E"] == F
        assert len(c["f"]) == len(c["gamma_P"]) == len(c["branch"]) > 60
        assert np.max(np.abs(residual(c["gamma_P"], 2 * np.pi * c["f"], F))) < 1e-9
        assert np.max(c["gamma_P"]) == pytest.approx(amp, rel=1e-6)
        assert list(c["branch"]).count(2) == 1
        # path order: the lower branch rises to the peak, the upper one falls from it
        top = int(np.argmax(c["gamma_P"]))
        assert np.all(np.diff(c["f"][:top + 1]) > 0) and np.all(np.diff(c["f"][top:]) > 0)
    for p in oscillator.response(1.05 / (2 * np.pi), forces):
        assert p["f_res"] == pytest.approx(1.05 / (2 * np.pi), rel=1e-15)
        assert np.max(np.abs(residual(np.array(p["roots"]), 1.05, p["F_E"]))) < 1e-11
    with pytest.raises(InputError, match="f_exc"):     # beyond 3 f_max
        oscillator.response(1.0, [0.1])
    with pytest.raises(InputError, match="F_E"):
        oscillator.backbone([0.1, -1.0])


def test_blade_a_backbone_and_curves(blade_a):
    case, blade, damper, model = blade_a
    F_lim = model.limit_force()
    forces = [1.0, 2.0, 5.0]
    points = model.backbone(forces)
    for p in points:
        assert set(p) >= {"F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "regime",
                          "hcf_ok", "roots", "unbounded"}
        assert p["roots"] == sorted(p["roots"]) and p["gamma_P"] == p["roots"][-1]
        assert case.analysis["f_min"] < p["f_res"] < case.analysis["f_max"]
        assert p["hcf_ok"] == (p["F_E"] <= 0.5 * F_lim and p["sigma_a"] <= case.analysis["sigma_all"])
        k = damper.stiffness(np.array([p["gamma_P"]]))[0]
        assert (p["k_re"], p["k_im"]) == pytest.approx((k.real, k.imag), rel=1e-12)
    curves = model.curves(forces, layers=60)
    for c, p in zip(curves, points):
        main = c["part"] == 1
        assert np.max(c["gamma_P"][main]) == pytest.approx(p["gamma_P"], rel=1e-9)
        turning = c["branch"] == 2
        assert np.any(np.isclose(c["f"][turning], p["f_res"], rtol=1e-12))
        assert c["f"][0] == pytest.approx(case.analysis["f_min"], rel=1e-14)
    # the response at the peak frequency contains the peak amplitude among its roots
    r = model.response(points[0]["f_res"], [points[0]["F_E"]])[0]
    assert min(abs(np.array(r["roots"]) / points[0]["gamma_P"] - 1)) < 1e-8


def test_unbounded_without_damping(blade_a):
    case, _, damper, _ = blade_a
    undamped = copy.deepcopy(case)
    undamped.blade["zeta"] = 0.0
    model = build_model(undamped, build_blade(undamped), damper)
    F_lim = model.limit_force()
    low, at, high = model.backbone([0.5 * F_lim, F_lim, 2 * F_lim])
    assert not low["unbounded"] and low["gamma_P"] > 0
    for p in (at, high):
        assert p["unbounded"] and p["regime"] == 3 and not p["hcf_ok"]
        assert p["gamma_P"] is None and p["f_res"] is None and p["roots"] == []
        assert "unbounded" in p["message"]


def test_no_resonance_in_band_is_a_physics_error(blade_a):
    case, blade, damper, _ = blade_a
    model = Model(blade, damper, 100.0, 150.0)
    with pytest.raises(PhysicsError, match="no resonance in the band"):
        model.backbone([1.0])


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "udmap", *args], cwd=ROOT, capture_output=True,
                          text=True)


def test_cli_backbone_json_contract():
    r = run_cli("backbone", str(CASE), "--forces", "1,2,5", "--json")
    assert r.returncode == 0, r.stderr
    data = json.loads(r.stdout)
    assert set(data) >= {"F_lim", "gamma_b", "gamma_s", "f1_bare", "lift_off", "points"}
    assert len(data["points"]) == 3
    for p in data["points"]:
        assert set(p) >= {"F_E", "gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im", "regime",
                          "hcf_ok", "roots"}
        assert all(isinstance(p[k], float) for k in ("gamma_P", "f_res", "sigma_a", "u_E"))
        assert p["roots"] == sorted(p["roots"]) and p["roots"][-1] == p["gamma_P"]


def test_cli_curves_and_response():
    r = run_cli("curves", str(CASE), "--forces", "2", "--layers", "30", "--json")
    assert r.returncode == 0, r.stderr
    c = json.loads(r.stdout)["curves"][0]
    assert set(c) >= {"F_E", "f", "gamma_P", "sigma_a", "branch"}
    assert len(c["f"]) == len(c["gamma_P"]) == len(c["sigma_a"]) == len(c["branch"]) > 20
    r = run_cli("response", str(CASE), "--forces", "1,2", "--freq", "190", "--json")
    assert r.returncode == 0, r.stderr
    assert [p["f_res"] for p in json.loads(r.stdout)["points"]] == [190.0, 190.0]


def test_cli_unbounded_is_null_with_message(write_case):
    path = write_case("undamped", blade={"zeta": 0.0})
    F_lim = json.loads(run_cli("backbone", str(path), "--forces", "1", "--json").stdout)["F_lim"]
    r = run_cli("backbone", str(path), "--forces", f"{2 * F_lim}", "--json")
    assert r.returncode == 0, r.stderr
    p = json.loads(r.stdout)["points"][0]
    assert p["unbounded"] is True and p["gamma_P"] is None and p["message"]


def test_cli_exit_statuses(write_case):
    assert run_cli("backbone", str(CASE), "--forces", "-1").returncode == 2
    assert run_cli("backbone", str(CASE)).returncode == 2
    assert run_cli("response", str(CASE), "--forces", "1", "--freq", "700").returncode == 2
    path = write_case("band", analysis=dict(f_min=100.0, f_max=150.0))
    r = run_cli("backbone", str(path), "--forces", "1")
    assert r.returncode == 3 and "no resonance" in r.stderr


def test_demo_writes_plots_and_data(tmp_path):
    from udmap.demo import run_demo
    summary = run_demo(None, tmp_path, forces=[1.0, 5.0], quiet=True)
    for name in ("gg_design_diagram", "gamma_P_vs_F_E", "f_res_vs_F_E", "response_curves",
                 "stiffness"):
        assert (tmp_path / f"{name}.png").stat().st_size > 10000
    for name in ("gg_design_diagram", "response_curves", "stiffness", "backbone",
                 "backbone_curve"):
        assert (tmp_path / f"{name}.csv").stat().st_size > 100
    assert summary["F_lim"] > 0 and len(summary["points"]) == 2
    assert json.loads((tmp_path / "summary.json").read_text())["F_lim"] == summary["F_lim"]
