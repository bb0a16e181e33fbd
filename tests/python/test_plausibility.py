"""Plausibility warnings (udmap.case.plausibility): a case inside every range but typed in
another unit gets a warning naming the quantity and the likely unit error, in the JSON
``warnings`` and on stderr, and its results stay what the kernel computes; a failure that a unit
mistake explains carries the hint. Blade A has none."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from udmap.case import build_blade, build_damper, build_model, load_case
from udmap.model import WARNING_KINDS, plausibility_warnings

ROOT = Path(__file__).resolve().parents[2]
CASE = json.loads((ROOT / "cases" / "blade_a.json").read_text())


def run(tmp_path, change, *args, command=("backbone", "--forces", "2")):
    data = json.loads(json.dumps(CASE))
    change(data)
    path = tmp_path / "case.json"
    path.write_text(json.dumps(data))
    r = subprocess.run([sys.executable, "-m", "udmap", command[0], str(path), *command[1:],
                        "--json", *args], capture_output=True, text=True, cwd=ROOT)
    return r, path


def test_blade_a_has_no_warning(tmp_path):
    r, _ = run(tmp_path, lambda d: None)
    assert r.returncode == 0 and json.loads(r.stdout)["warnings"] == []


def _stiffnesses_in_n_per_mm(d):
    d["damper"].update(kn_flat=60e3, kt_flat=40e3, kn_curved=80e3, kt_curved=50e3)


# one case per example of the issue; the texts are the kernel's (mapping/plausibility.f90)
@pytest.mark.parametrize("change, needle", [
    (lambda d: d["blade"]["platform"].update(m=21.0),
     "blade.platform.m = 21 kg is heavier than the rest of the blade (0.1443 kg of neck and "
     "airfoil): was it given in grams? (21 g would be 0.021 kg)"),
    (_stiffnesses_in_n_per_mm,
     "the base-cycle amplitude gamma_b = 0.5483 rad is above 0.01 rad (the contacts deflect by "
     "degrees before they slip): were the contact stiffnesses given in N/mm? (kn_flat = 6e+04 "
     "N/m; 1 N/mm = 1e3 N/m)"),
    (_stiffnesses_in_n_per_mm,
     "the stuck damper shifts the first frequency by 0.0137 % (187.1 Hz bare, 187.1 Hz stuck), "
     "outside 0.1 % to 100 %: are the contact stiffnesses or the blade in another unit?"),
])
def test_unit_mistakes_warn_and_keep_the_results(tmp_path, change, needle):
    r, path = run(tmp_path, change)
    assert r.returncode == 0, r.stderr
    data = json.loads(r.stdout)
    assert needle in data["warnings"], data["warnings"]
    assert f"udmap: warning: {needle}" in r.stderr
    ref = build_model(load_case(str(path))).backbone([2.0])[0]
    assert data["points"][0]["gamma_P"] == ref["gamma_P"]
    assert data["points"][0]["sigma_a"] == ref["sigma_a"]


def test_band_missing_the_stuck_mode_names_the_frequencies_found(tmp_path):
    # the bare mode (187.1 Hz) in the band, the stuck one (above 195 Hz) not: no resonance in
    # the band, and the failure says which mode the band misses
    r, _ = run(tmp_path, lambda d: d["analysis"].update(f_max=195.0),
               command=("response", "--freq", "190", "--forces", "2"))
    assert r.returncode == 3, r.stderr
    assert "no resonance in the band" in r.stderr
    assert ("(plausibility: the band [analysis.f_min, analysis.f_max] = [150, 195] Hz misses "
            "the first mode (bare first mode at 187.1 Hz, no stuck peak inside the band): are "
            "the band or the blade in other units (Hz for rad/s, mm-t-s for SI)?)") in r.stderr


def test_warnings_of_the_objects_name_their_kinds():
    case = load_case(str(ROOT / "cases" / "blade_a.json"))
    case.blade["platform"]["m"] = 21.0
    blade, damper = build_blade(case), build_damper(case)
    assert [k for k, _ in plausibility_warnings(blade, 150.0, 230.0, damper)] == \
        ["platform_mass"]
    assert [k for k, _ in build_model(case, blade, damper).warnings()] == ["platform_mass"]
    assert set(WARNING_KINDS) == {"platform_mass", "platform_inertia", "gamma_b_large",
                                  "stuck_shift", "band_misses_mode"}


@pytest.mark.parametrize("change, status, needle", [
    (lambda d: d["blade"]["platform"].update(J=1.4), 2, "was it given in kg mm^2?"),
    (lambda d: d["analysis"].update(f_min=10.0, f_max=100.0), 3,
     "misses the first mode (bare first mode at 187.1 Hz"),
])
def test_failures_that_a_unit_explains_carry_the_hint(tmp_path, change, status, needle):
    r, _ = run(tmp_path, change)
    assert r.returncode == status and needle in r.stderr, r.stderr
