"""The FMUs at an engine order (PHYSICS.md 2.6, INTERFACES.md "FMU"): integer parameters
blades and engine_order select the traveling wave; the outputs are the kernel's traveling-wave
peak (the Python model at the same phase), EO = 0 and EO = N are the in-phase answer."""
from __future__ import annotations

import pytest

from fmu_harness import CASE, OK, Instance
from udmap.case import build_blade, build_damper, load_case
from udmap.model import Model


@pytest.fixture(scope="module")
def models():
    case = load_case(str(CASE))
    blade, damper = build_blade(case), build_damper(case)
    return {ibpa: Model(blade, damper, 150.0, 230.0, ibpa_deg=ibpa).backbone([5.0])[0]
            for ibpa in (0.0, 90.0, -90.0)}


@pytest.mark.parametrize("version", [2, 3])
def test_engine_orders(version, models):
    inst = Instance(version)
    assert inst.setup() == OK
    for eo, ibpa in ((1, 90.0), (3, -90.0), (4, 0.0), (0, 0.0)):
        assert inst.set(F_E=5.0, blades=4, engine_order=eo) == OK
        st, out = inst.outputs()
        assert st == OK, inst.messages()
        ref = models[ibpa]
        for key in ("gamma_P", "f_res", "sigma_a"):
            assert out[key] == pytest.approx(ref[key], rel=1e-12), (eo, key)
    inst.free()
