"""Stress test of the traveling-wave peaks (PHYSICS.md 2.6, issue: "Robust"): the interblade
phase on a fine grid over [0, 360) deg with designs of other friction, centrifugal load, face
angles and a lift-off design. Every answer is finite, or an error with status 3 or 4 whose
message names phi and the layer; never a NaN, never a hang."""
from __future__ import annotations

import math

import numpy as np
import pytest

from udmap import Damper
from udmap.errors import UdmapError
from udmap.model import Model
from conftest import BLADE_A_BEAM
from udmap import Blade

#: Blade A's damper (cases/blade_a.json) with the C API's parameter names.
DAMPER_A = dict(CF=900.0, mu=0.3, pitch=0.026, y_P=0.006, beta_L_deg=45.0, beta_R_deg=45.0,
                flat_points=[[-6.724e-3, -1.724e-3], [-1.068e-3, 3.932e-3]],
                curved_point=[3.268e-3, 1.768e-3], kn_flat=60e6, kt_flat=40e6,
                kn_curved=80e6, kt_curved=50e6)


def lift_off_design() -> dict:
    f = np.array(DAMPER_A["flat_points"])
    mid, half = f.mean(axis=0), (f[1] - f[0]) / 2
    return dict(DAMPER_A, flat_points=[list(mid - half / 2), list(mid + half / 2)])


DESIGNS = {"blade A": DAMPER_A, "mu 0.15": dict(DAMPER_A, mu=0.15),
           "mu 0.6, CF 300": dict(DAMPER_A, mu=0.6, CF=300.0),
           "faces 35/55 deg, CF 1500": dict(DAMPER_A, beta_L_deg=35.0, beta_R_deg=55.0, CF=1500.0),
           "lift-off": lift_off_design()}


@pytest.fixture(scope="module")
def blade():
    return Blade.beam(**BLADE_A_BEAM)


@pytest.mark.parametrize("name", list(DESIGNS))
def test_phase_grid(blade, name):
    damper = Damper.asymmetric(**DESIGNS[name])
    answered = 0
    for ibpa in np.arange(0.0, 360.0, 15.0):
        model = Model(blade, damper, 150.0, 230.0, ibpa_deg=float(ibpa))
        try:
            F_lim = model.limit_force()
            points = model.backbone([1.0, 5.0])
        except UdmapError as exc:
            assert exc.status in (3, 4), (ibpa, exc.status, str(exc))
            assert "phi" in str(exc) and "gamma" in str(exc), str(exc)
            continue
        assert math.isfinite(F_lim) and F_lim > 0
        for p in points:
            for key in ("gamma_P", "f_res", "sigma_a", "u_E"):
                assert math.isfinite(p[key]) and p[key] > 0, (name, ibpa, key, p[key])
            assert 150.0 < p["f_res"] < 230.0
        answered += 1
    # the damper designs of blade A's family all have a resonance in the band
    assert answered >= 20, (name, answered)
