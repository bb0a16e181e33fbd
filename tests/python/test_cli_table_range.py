"""`table --gammas` above the valid range (1 rad) answers as before, with a warning that names
the range and the likely unit mistake (issue: gamma typed in degrees)."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def table(*gammas: str):
    r = subprocess.run([sys.executable, "-m", "udmap", "table", "cases/blade_a.json", "--gammas",
                        ",".join(gammas), "--json"], capture_output=True, text=True, cwd=ROOT,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout), r.stderr


def test_gamma_above_one_rad_warns_and_keeps_the_numbers():
    inside, err_inside = table("1e-3", "0.5")
    outside, err_outside = table("1e-3", "0.5", "2")
    assert inside["warnings"] == [] and "warning" not in err_inside
    assert len(outside["warnings"]) == 1
    text = outside["warnings"][0]
    assert "outside the valid range 1e-12 to 1 rad" in text and "degrees" in text
    assert text in err_outside
    assert outside["points"][:2] == inside["points"]       # the same numbers, bit for bit
    assert outside["points"][2]["gamma"] == 2.0 and outside["points"][2]["k_re"] > 0
