"""Traveling waves through the Python and command-line faces (PHYSICS.md 2.6): the admissible
force at a phase, the standard method at a phase against the layered backbone, and what is
refused rather than answered in phase."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from udmap.case import build_blade, build_damper, load_case
from udmap.errors import InputError
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


def test_response_is_refused_not_answered_in_phase(wave):
    _, _, model = wave
    with pytest.raises(InputError, match="ibpa_deg"):
        model.response(196.0, [2.0])


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
