"""Stress test of the mapping path (damper table, backbone, response, curves) over extreme but
legal inputs (issue: stability stress tests): friction 1e-4..2, centrifugal load 1e-3..1e5 N,
contact stiffness ratios 1e-3..1e3, amplitudes 1e-12..1 rad, blade damping 0 and 1e-5, forces
just below, at and above F_lim, a band without resonance. Every call returns finite numbers or
raises a udmap error with a message and status 2, 3 or 4: no crash, hang or NaN."""
import math

import numpy as np
import pytest

from udmap import Blade, Damper, UdmapError
from udmap.case import beam_params, load_case
from udmap.model import Model

CASE = load_case()
D = CASE.damper
GAMMAS = np.array([1e-12, 1e-9, 1e-6, 1e-4, 3e-4, 5e-4, 1e-3, 1e-2, 0.1, 1.0])


def damper(**changes):
    d = dict(D, **changes)
    keys = ("CF", "mu", "pitch", "y_P", "beta_L_deg", "beta_R_deg", "flat_points",
            "curved_point", "kn_flat", "kt_flat", "kn_curved", "kt_curved")
    return Damper.asymmetric(**{k: d[k] for k in keys})


def finite_points(points):
    """Finite numbers, or (unbounded answers only) None with regime 3 and a message."""
    for p in points:
        assert math.isfinite(p["F_E"])
        if p.get("unbounded"):
            assert p["regime"] == 3 and p["message"] and not p["roots"]
            continue
        for key in ("gamma_P", "f_res", "sigma_a", "u_E", "k_re", "k_im"):
            assert math.isfinite(p[key]), (key, p)
        assert all(math.isfinite(r) for r in p["roots"])


def expect_finite_or_error(fn):
    try:
        return fn()
    except UdmapError as exc:
        assert str(exc) and exc.status in (2, 3, 4), exc
        return None


@pytest.fixture(scope="module", params=[0.002, 1e-5, 0.0], ids=["zeta2e-3", "zeta1e-5", "zeta0"])
def blade(request):
    b = Blade.beam(**dict(beam_params(CASE.blade), zeta=request.param))
    b.test_zeta = request.param
    return b


@pytest.mark.parametrize("mu", [1e-4, 0.01, 0.3, 0.9, 2.0])
@pytest.mark.parametrize("CF", [1e-3, 900.0, 1e5])
def test_friction_and_load(blade, mu, CF):
    d = expect_finite_or_error(lambda: damper(mu=mu, CF=CF))
    if d is None:
        return
    k = d.stiffness(GAMMAS)
    assert np.all(np.isfinite(k)) and np.all(k.imag >= 0)
    for value in (d.gamma_b, d.gamma_s, d.M_max, d.M_min, d.k_stuck):
        assert math.isfinite(value)
    m = expect_finite_or_error(lambda: Model(blade, d, 150.0, 230.0))
    if m is None:
        return
    F_lim = m.limit_force()
    assert math.isfinite(F_lim) and F_lim > 0
    forces = [1e-6, 1.0, 0.999 * F_lim, F_lim, 1.001 * F_lim, 10 * F_lim]
    pts = expect_finite_or_error(lambda: m.backbone(forces))
    if pts is not None:
        finite_points(pts)
        if blade.test_zeta == 0.0:  # at and above F_lim without damping: unbounded
            assert all(p["unbounded"] for p in pts[3:]), pts[3:]
    pts = expect_finite_or_error(lambda: m.response(197.0, forces))
    if pts is not None:
        finite_points(pts)


@pytest.mark.parametrize("ratio", [1e-3, 1e-1, 1e1, 1e3])
def test_stiffness_ratios(blade, ratio):
    # normal against tangential stiffness, and flat against curved side
    for changes in ({"kt_flat": D["kn_flat"] * ratio, "kt_curved": D["kn_curved"] * ratio},
                    {"kn_curved": D["kn_flat"] * ratio, "kt_curved": D["kt_flat"] * ratio}):
        d = expect_finite_or_error(lambda: damper(**changes))
        if d is None:
            continue
        assert np.all(np.isfinite(d.stiffness(GAMMAS)))
        m = expect_finite_or_error(lambda: Model(blade, d, 150.0, 230.0))
        if m is not None:
            pts = expect_finite_or_error(lambda: m.backbone([0.5, 5.0, 50.0]))
            if pts is not None:
                finite_points(pts)


def test_band_without_resonance_is_a_physics_error(blade):
    m = Model(blade, damper(), 100.0, 150.0)
    with pytest.raises(UdmapError) as info:
        m.backbone([1.0])
    assert info.value.status == 3 and "no resonance" in str(info.value)


def test_curves_at_extremes(blade):
    m = Model(blade, damper(), 150.0, 230.0)
    F_lim = m.limit_force()
    curves = expect_finite_or_error(lambda: m.curves([1e-3, 1.0, 0.99 * F_lim], layers=50))
    if curves is not None:
        for c in curves:
            assert np.all(np.isfinite(c["f"])) and np.all(np.isfinite(c["gamma_P"]))
