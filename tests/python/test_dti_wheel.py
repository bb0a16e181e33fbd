"""The whole wheel in time (PHYSICS.md 2.6, 7) through Python and the command line: in phase
(EO = 0) the wheel is the single blade; a traveling wave of blade A (N = 4, EO = 1) stays one
(blade_spread and phase_spread below 1e-6); ``udmap dti --blades N --engine-order EO`` reports
"blade_spread"; bad wheels exit with status 2 naming the option or field."""
from __future__ import annotations

import json
import math

import pytest

from udmap import hbm
from udmap.case import build_blade, build_contact, load_case
from udmap.cli import main

CASE = "cases/blade_a.json"
FAST = dict(steps_per_period=64, ss_tol=1e-7)


@pytest.fixture(scope="module")
def blade_a():
    case = load_case(CASE)
    return build_blade(case), case


def test_in_phase_is_the_single_blade(blade_a):
    blade, case = blade_a
    one = hbm.dti(blade, build_contact(case), [5.0], freq=196.0, **FAST)[0]
    wheel = hbm.dti_wheel(blade, build_contact(case), [5.0], 3, 0, freq=196.0, **FAST)[0]
    for k in ("gamma_1", "sigma_1", "gamma_max"):
        assert wheel[k] == pytest.approx(one[k], rel=1e-9)
    assert wheel["phi"] == 0.0 and wheel["blades"] == 3
    assert wheel["blade_spread"] < 1e-10 and wheel["phase_spread"] < 1e-10


def test_traveling_wave_stays_traveling(blade_a):
    blade, case = blade_a
    w = hbm.dti_wheel(blade, build_contact(case), [2.0], 4, 1, freq=197.5, **FAST)[0]
    assert w["phi"] == pytest.approx(math.pi / 2, abs=1e-15)
    assert w["blade_spread"] < 1e-6 and w["phase_spread"] < 1e-6
    one = hbm.dti(blade, build_contact(case), [2.0], freq=197.5, **FAST)[0]
    assert abs(w["gamma_1"] - one["gamma_1"]) > 1e-3 * one["gamma_1"]   # not the in-phase wave


def test_cli_blade_spread(capsys):
    assert main(["dti", CASE, "--forces", "5", "--freq", "196", "--blades", "2",
                 "--engine-order", "0", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    p = data["points"][0]
    assert data["blades"] == 2 and data["engine_order"] == 0
    assert p["blade_spread"] < 1e-10 and p["phase_spread"] < 1e-10
    # the in-phase single blade of the same case (docs/outputs.md dti row)
    assert main(["dti", CASE, "--forces", "5", "--freq", "196", "--json"]) == 0
    single = json.loads(capsys.readouterr().out)["points"][0]
    assert p["gamma_1"] == pytest.approx(single["gamma_1"], rel=1e-9)
    assert "blade_spread" not in single


@pytest.mark.parametrize("extra, needle", [
    (["--blades", "1", "--engine-order", "0"], "--blades"),
    (["--engine-order", "1"], "--engine-order needs --blades"),
    (["--blades", "4", "--engine-order", "-1"], "--engine-order"),
    (["--blades", "101", "--engine-order", "1"], "blades must be in 2..100"),
])
def test_cli_bad_wheel(extra, needle, capsys):
    assert main(["dti", CASE, "--forces", "5", "--freq", "196", *extra]) == 2
    assert needle in capsys.readouterr().err


def test_cli_phase_without_blades(tmp_path, capsys):
    case = json.loads(open(CASE).read())
    case["analysis"]["ibpa_deg"] = 90.0
    path = tmp_path / "a90.json"
    path.write_text(json.dumps(case))
    assert main(["dti", str(path), "--forces", "5", "--freq", "196"]) == 2
    assert "ibpa_deg" in capsys.readouterr().err
