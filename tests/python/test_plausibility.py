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

from udmap.case import build_model, load_case

ROOT = Path(__file__).resolve().parents[2]
CASE = json.loads((ROOT / "cases" / "blade_a.json").read_text())


def run(tmp_path, change, *args):
    data = json.loads(json.dumps(CASE))
    change(data)
    path = tmp_path / "case.json"
    path.write_text(json.dumps(data))
    r = subprocess.run([sys.executable, "-m", "udmap", "backbone", str(path), "--forces", "2",
                        "--json", *args], capture_output=True, text=True, cwd=ROOT)
    return r, path


def test_blade_a_has_no_warning(tmp_path):
    r, _ = run(tmp_path, lambda d: None)
    assert r.returncode == 0 and json.loads(r.stdout)["warnings"] == []


@pytest.mark.parametrize("change, needle", [
    (lambda d: d["blade"]["platform"].update(m=21.0),
     "blade.platform.m = 21 kg is heavier than the rest of the blade"),
    (lambda d: d["damper"].update(kn_flat=60e3, kt_flat=40e3, kn_curved=80e3, kt_curved=50e3),
     "were the contact stiffnesses given in N/mm?"),
])
def test_unit_mistakes_warn_and_keep_the_results(tmp_path, change, needle):
    r, path = run(tmp_path, change)
    assert r.returncode == 0, r.stderr
    data = json.loads(r.stdout)
    assert any(needle in w for w in data["warnings"]), data["warnings"]
    assert needle in r.stderr
    ref = build_model(load_case(str(path))).backbone([2.0])[0]
    assert data["points"][0]["gamma_P"] == ref["gamma_P"]
    assert data["points"][0]["sigma_a"] == ref["sigma_a"]


@pytest.mark.parametrize("change, status, needle", [
    (lambda d: d["blade"]["platform"].update(J=1.4), 2, "was it given in kg mm^2?"),
    (lambda d: d["analysis"].update(f_min=10.0, f_max=100.0), 3,
     "misses the first mode (bare first mode at 187.1 Hz"),
])
def test_failures_that_a_unit_explains_carry_the_hint(tmp_path, change, status, needle):
    r, _ = run(tmp_path, change)
    assert r.returncode == status and needle in r.stderr, r.stderr
