"""udmap.hbm: the standard method and the time integration through the Python API.

One-DOF oscillator of PHYSICS.md 8 (imported as Matrix Market files with an explicit C): the
single-harmonic peaks against the published values and the closed form (k(a) of PHYSICS.md 2.4
in g~ = H/(1 + k H), peak at the exact root of d|g~|/domega, F_bb(a) = F solved by Brent here
with scipy); time integration against the standard method converged in H. Blade A with a
rotational Jenkins damper: condensed and full variants agree, the curve contains the peak,
errors for a table damper and a band without resonance."""
import math

import numpy as np
import pytest
import scipy.io
from scipy.optimize import brentq

from udmap import Blade, InputError, PhysicsError
from udmap import hbm
from udmap.case import contact_from_section

JENKINS_OSC = {"kind": "jenkins", "kt": 0.25, "M_slip": 0.2}
JENKINS_A = {"kind": "jenkins", "kt": 3000.0, "M_slip": 1.35}
W = 1 / (2 * math.pi)  # rad/s -> Hz


def osc():
    """The oscillator's Jenkins contact (a new one per call, as the case section gave)."""
    return contact_from_section(JENKINS_OSC)


def jenkins_a():
    """Blade A's rotational Jenkins contact."""
    return contact_from_section(JENKINS_A)


@pytest.fixture(scope="module")
def oscillator(tmp_path_factory):
    d = tmp_path_factory.mktemp("osc")
    for name, v in (("M", 1.0), ("K", 1.0), ("C", 0.01)):
        scipy.io.mmwrite(str(d / f"{name}.mtx"), np.array([[v]]), symmetry="symmetric")
    return Blade.matrices(d / "M.mtx", d / "K.mtx", 1, 1, C=d / "C.mtx")


def closed_form_peak(F):
    def k(a):
        a_s = 0.8
        if a <= a_s:
            return complex(0.25, 0)
        b = math.acos(1 - 2 * a_s / a)
        return complex(0.25 / math.pi * (b - math.sin(2 * b) / 2),
                       4 * 0.2 / (math.pi * a) * (1 - a_s / a))

    def peak(a):
        kk = k(a)
        w = brentq(lambda w: -4 * w * (1 + kk.real - w * w) + 0.02 * (kk.imag + 0.01 * w),
                   0.9, 1.2, xtol=1e-15)
        return w, a * abs(1 + kk.real - w * w + 1j * (kk.imag + 0.01 * w))

    a = brentq(lambda a: peak(a)[1] - F, 0.81, 20, xtol=1e-15)
    return a, peak(a)[0]


@pytest.mark.parametrize("variant", ["condensed", "full"])
def test_oscillator_peaks(oscillator, variant):
    published = {0.05: (0.946956, 1.106824), 0.1: (1.214018, 1.083677), 0.3: (7.279801, 1.007341)}
    pts = hbm.hbm(oscillator, osc(), 0.8 * W, 1.3 * W, list(published), variant=variant)
    for p, (F, (amp, om)) in zip(pts, published.items()):
        assert p["F_E"] == F
        assert p["gamma_P"] == pytest.approx(amp, rel=1e-6)
        assert 2 * math.pi * p["f_res"] == pytest.approx(om, rel=1e-6)
        a, w = closed_form_peak(F)
        assert p["gamma_P"] == pytest.approx(a, rel=1e-10)
        assert 2 * math.pi * p["f_res"] == pytest.approx(w, rel=1e-8)
        assert p["roots"] == [pytest.approx(p["gamma_P"], rel=1e-12)]
        assert p["iterations"] > 0 and p["aft_calls"] > 0 and p["seconds"] >= 0


def test_oscillator_time_integration(oscillator):
    ref = hbm.hbm_response(oscillator, osc(), 0.8 * W, 1.08 * W, [0.1], harmonics=15)[0]
    d = hbm.dti(oscillator, osc(), [0.1], freq=1.08 * W, steps_per_period=1024)[0]
    assert set(d) >= {"F_E", "f", "gamma_1", "sigma_1", "gamma_max"}
    assert d["gamma_1"] == pytest.approx(ref["gamma_P"], rel=2e-5)
    assert d["gamma_max"] == pytest.approx(ref["gamma_max"], rel=2e-5)
    assert d["ss_error"] < 1e-7


def test_blade_a_variants_and_curve(blade_a_beam):
    c = hbm.hbm(blade_a_beam, jenkins_a(), 150, 230, [1.0, 5.0])
    f = hbm.hbm(blade_a_beam, jenkins_a(), 150, 230, [1.0, 5.0], variant="full")
    for pc, pf in zip(c, f):
        for key in ("gamma_P", "f_res", "sigma_a", "u_E"):
            assert pf[key] == pytest.approx(pc[key], rel=1e-8)
        assert math.isfinite(pc["sigma_a"]) and pc["sigma_a"] > 0
    curve = hbm.hbm_curve(blade_a_beam, jenkins_a(), 150, 230, 5.0)
    assert curve["f"][0] == pytest.approx(150) and curve["f"][-1] == pytest.approx(230)
    assert np.all(curve["gamma_1"] <= c[1]["gamma_P"] * (1 + 1e-12))
    i = int(np.argmax(curve["gamma_1"]))
    assert curve["gamma_1"][i] == pytest.approx(c[1]["gamma_P"], rel=1e-2)
    h3 = hbm.hbm(blade_a_beam, jenkins_a(), 150, 230, [5.0], harmonics=3, sigma_all=80e6)[0]
    assert len(h3["gamma_h"]) == 3 and h3["gamma_h"][0] == h3["gamma_P"]
    assert h3["gamma_h"][1] < 1e-12 * h3["gamma_P"] < h3["gamma_h"][2]


def test_errors(blade_a_beam):
    with pytest.raises(InputError, match="table"):
        hbm.hbm(blade_a_beam, contact_from_section({"kind": "table", "file": "k.csv"}), 150, 230, [1.0])
    with pytest.raises(PhysicsError, match="no resonance"):
        hbm.hbm(blade_a_beam, jenkins_a(), 200, 230, [1.0])
    with pytest.raises(InputError, match="F_E"):
        hbm.hbm(blade_a_beam, jenkins_a(), 150, 230, [-1.0])
    with pytest.raises(InputError, match="harmonics"):
        hbm.hbm(blade_a_beam, jenkins_a(), 150, 230, [1.0], harmonics=65)
    with pytest.raises(InputError, match="freq"):
        hbm.dti(blade_a_beam, jenkins_a(), [1.0])


def test_blade_a_asymmetric_against_backbone():
    """Acceptance: with H = 1 the standard method's peaks on blade A with its asymmetric damper
    agree with the backbone (amplitude layered mapping, independent code path: stiffness table
    and layer peaks) to 1e-6 in gamma_P, f_res and sigma_a, for both variants; same regime."""
    from udmap.case import build_blade, build_contact, build_damper, load_case
    from udmap.model import Model
    case = load_case()
    blade = build_blade(case)
    a = case.analysis
    damper = build_damper(case)  # the kernel damper (stiffness table) of the case
    bb = Model(blade, damper, a["f_min"], a["f_max"]).backbone([1.0, 5.0, 10.0])
    for variant in ("condensed", "full"):
        pts = hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"], [1.0, 5.0, 10.0],
                      variant=variant, sigma_all=a["sigma_all"], damper=damper)
        for p, b in zip(pts, bb):
            for key in ("gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im"):
                assert p[key] == pytest.approx(b[key], rel=1e-6), (variant, key, p["F_E"])
            assert p["regime"] == b["regime"] and p["hcf_ok"] == b["hcf_ok"]
            assert not p["lift_off"]
    # three harmonics: a different (model-error) answer, near but not equal
    h3 = hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"], [5.0], harmonics=3,
                 damper=damper)[0]
    assert 0.02 < abs(h3["gamma_P"] / bb[1]["gamma_P"] - 1) < 0.15


@pytest.mark.parametrize("variant", ["condensed", "full"])
def test_blade_a_warm_start(variant):
    """Warm starts (each force climbs from the previous force's peak; with 2 the first force
    from the stuck linear peak) find the same peaks as the band sweep for the GG diagram of
    blade A (F_E = 1..10 N: partial and full slip), to the Newton tolerance, with far fewer
    AFT evaluations (the sweep crosses the band for every force)."""
    from udmap.case import build_blade, build_contact, build_damper, load_case
    case = load_case()
    blade = build_blade(case)
    a = case.analysis
    F = list(range(1, 11))
    cold = hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"], F, variant=variant,
                   damper=build_damper(case))
    for level in (1, 2):
        warm = hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"], F, variant=variant,
                       warm_start=level, damper=build_damper(case))
        for pw, pc in zip(warm, cold):
            for key in ("gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im"):
                assert pw[key] == pytest.approx(pc[key], rel=1e-8), (level, key, pw["F_E"])
            assert pw["regime"] == pc["regime"]
            assert pw["roots"] == [pw["gamma_P"]]
        assert sum(p["aft_calls"] for p in warm) < 0.4 * sum(p["aft_calls"] for p in cold)
        # from the second force on, a few steps instead of a band crossing
        assert all(p["steps"] < 10 for p in warm[1:])


def test_warm_start_oscillator_and_errors(oscillator):
    """One-DOF oscillator: warm-started peaks equal the published ones (PHYSICS.md 8) also in
    a descending force order; a band without resonance is still an error (the climb leaves
    the band, the sweep fallback reports it); warm_start outside 0..2 is an input error."""
    published = {0.3: (7.279801, 1.007341), 0.1: (1.214018, 1.083677), 0.05: (0.946956, 1.106824)}
    pts = hbm.hbm(oscillator, osc(), 0.8 * W, 1.3 * W, list(published), warm_start=2)
    for p, (F, (amp, om)) in zip(pts, published.items()):
        assert p["F_E"] == F
        assert p["gamma_P"] == pytest.approx(amp, rel=1e-6)
        assert 2 * math.pi * p["f_res"] == pytest.approx(om, rel=1e-6)
    with pytest.raises(PhysicsError, match="no resonance"):
        hbm.hbm(oscillator, osc(), 1.2 * W, 1.5 * W, [0.05, 0.1], warm_start=2)
    with pytest.raises(InputError, match="warm_start"):
        hbm.hbm(oscillator, osc(), 0.8 * W, 1.3 * W, [0.05, 0.1], warm_start=3)
