"""Shared fixtures of the Python tests: blade A (its beam parameters, its case file, and the
kernel objects built from it), case files written to a test's temporary directory, and the
generic FMUs of this build."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from fmu_harness import CASE, FMUS
from udmap import Blade
from udmap.case import build_blade, build_damper, build_model, load_case

ROOT = Path(__file__).resolve().parents[2]
#: Blade A's beam (cases/blade_a.json) with the C API's parameter names (Blade.beam).
BLADE_A_BEAM = dict(E=170e9, rho=8200.0, zeta=0.002, neck_L=0.020, neck_h=0.008, neck_b=0.020,
                    platform_L=0.010, platform_m=0.021, platform_J=1.4e-6, airfoil_L=0.120,
                    airfoil_h=0.004, airfoil_b=0.030, neck_elements=8, airfoil_elements=24)


@pytest.fixture
def blade_a_params() -> dict:
    """A fresh copy of blade A's beam parameters (Blade.beam keywords)."""
    return dict(BLADE_A_BEAM)


@pytest.fixture(scope="module")
def blade_a_beam() -> Blade:
    """Blade A's beam as a kernel blade."""
    return Blade.beam(**BLADE_A_BEAM)


@pytest.fixture(scope="module")
def blade_a():
    """Blade A's case file with its kernel blade, damper and model: (case, blade, damper,
    model)."""
    case = load_case(CASE)
    blade, damper = build_blade(case), build_damper(case)
    return case, blade, damper, build_model(case, blade, damper)


@pytest.fixture
def write_case(tmp_path):
    """Writes blade A's case with some fields replaced into the test's directory:
    ``write_case(name, damper=None, blade=None, analysis=None)`` (dicts updating those
    sections); returns the path of ``name.json``."""
    def write(name: str = "case", damper: dict | None = None, blade: dict | None = None,
              analysis: dict | None = None) -> Path:
        data = json.loads(CASE.read_text())
        data["damper"].update(damper or {})
        data["blade"].update(blade or {})
        data["analysis"].update(analysis or {})
        path = tmp_path / f"{name}.json"
        path.write_text(json.dumps(data))
        return path
    return write


@pytest.fixture(scope="session")
def fmus() -> dict:
    """The generic FMUs of this build: {2: udmap.fmu, 3: udmap-fmi3.fmu}."""
    return dict(FMUS)
