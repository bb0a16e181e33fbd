"""Stress test of the multi-harmonic layers (PHYSICS.md 4.1): friction coefficients, centrifugal
loads and face angles across their range, lift-off designs, forces up to near F_lim, and blades
whose second mode sits near 5 or 4.5 times the resonance or is crossed by 2 or 3 times it over
the forces (a strongly amplified harmonic). Every call returns finite numbers or a clear error
naming the harmonic count and the layer (status 3 or 4), never a NaN or a hang; at the crossings
the layers still equal the standard method with the same harmonics."""
import copy
import math

import pytest

from udmap import PhysicsError, UdmapError
from udmap.case import build_blade, build_contact, build_damper, load_case
from udmap.model import Model

DESIGNS = [
    ("mu 0.1", {"damper": {"mu": 0.1}}),
    ("mu 0.8", {"damper": {"mu": 0.8}}),
    ("CF 300", {"damper": {"CF": 300.0}}),
    ("CF 2500", {"damper": {"CF": 2500.0}}),
    ("lift-off (mu 0.5)", {"damper": {"mu": 0.5}}),
    ("beta_L 30, beta_R 60", {"damper": {"beta_L_deg": 30.0, "beta_R_deg": 60.0}}),
    ("beta_L 60, beta_R 30", {"damper": {"beta_L_deg": 60.0, "beta_R_deg": 30.0}}),
    ("mode 2 near 5 f_res (neck_L 0.04)", {"blade": {"neck": {"L": 0.04}}}),
    ("mode 2 near 4.5 f_res (platform_J 2e-4)", {"blade": {"platform": {"J": 2e-4}}}),
    # f2 / f_res goes from 2.94 to 3.05 over the forces: 3 f_res crosses the second mode
    ("mode 2 crosses 3 f_res (platform_J 6e-4)", {"blade": {"platform": {"J": 6e-4}}}),
    # f2 / f_res goes from 1.90 to 2.03: 2 f_res crosses the second mode
    ("mode 2 crosses 2 f_res (platform_J 1.6e-3)", {"blade": {"platform": {"J": 1.6e-3}}}),
]


def _merge(d, upd):
    for k, v in upd.items():
        if isinstance(v, dict):
            _merge(d[k], v)
        else:
            d[k] = v


def _finite(p):
    return all(isinstance(p[k], float) and math.isfinite(p[k])
               for k in ("gamma_P", "f_res", "sigma_a", "gamma_max", "sigma_max"))


@pytest.mark.parametrize("name,change", DESIGNS, ids=[d[0] for d in DESIGNS])
def test_finite_or_clear_error(name, change):
    case = load_case()
    case = copy.deepcopy(case)
    _merge(case.blade, change.get("blade", {}))
    _merge(case.damper, change.get("damper", {}))
    blade, damper = build_blade(case), build_damper(case)
    a = case.analysis
    # the band follows the first mode (it must hold the resonance and no other mode)
    f1 = float(blade.natural_frequencies(1)[0])
    model = Model(blade, damper, 0.8 * f1, 1.25 * f1, harmonics=3)
    F_lim = model.limit_force()
    forces = [0.05 * F_lim, 0.3 * F_lim, 0.6 * F_lim, 0.9 * F_lim]
    for harmonics in (3, "auto") if "mode 2" in name else (3,):
        model.set_harmonics(harmonics)
        try:
            points = model.backbone(forces)
        except PhysicsError as exc:
            assert "resonance" in str(exc) or "H =" in str(exc)
            continue
        except UdmapError as exc:
            msg = str(exc)
            assert exc.status in (3, 4) and "H =" in msg and "gamma" in msg, msg
            continue
        for p in points:
            assert p["unbounded"] or _finite(p), (name, p)
            if not p["unbounded"]:
                assert p["harmonics"] >= 3
                assert 0.8 * f1 < p["f_res"] < 1.25 * f1
                assert p["gamma_max"] > 0 and p["sigma_max"] >= 0
    assert a["sigma_all"] > 0


@pytest.mark.parametrize("J", [6e-4, 1.6e-3], ids=["3 f_res", "2 f_res"])
def test_crossing_equals_standard_method(J):
    # where 3 (or 2) f_res meets the second mode, the third (second) harmonic is resonant: the
    # layers at H = 3 still give the standard method's peak with the same harmonics (1e-6)
    from udmap import hbm
    case = copy.deepcopy(load_case())
    case.blade["platform"]["J"] = J
    blade, damper = build_blade(case), build_damper(case)
    f1 = float(blade.natural_frequencies(1)[0])
    model = Model(blade, damper, 0.8 * f1, 1.25 * f1, harmonics=3)
    F = 0.6 * model.limit_force()
    p = model.backbone([F])[0]
    r = hbm.hbm(blade, build_contact(case), 0.8 * f1, 1.25 * f1, [F], harmonics=3, harmonic0=1,
                warm_start=2, full_band=0)[0]
    for key in ("gamma_P", "sigma_a", "f_res"):
        assert p[key] == pytest.approx(r[key], rel=1e-6), key
    # the resonant harmonic is large: the single-harmonic peak is off by several per cent
    model.set_harmonics(1)
    assert abs(model.backbone([F])[0]["gamma_P"] / p["gamma_P"] - 1) > 0.01
