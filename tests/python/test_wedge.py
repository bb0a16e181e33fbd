"""The wedge edges from the command line and the DOE: the neutral wedge mu = tan(beta) is status
3 with a message naming mu and the angle (DOE: status physics with that message); blade A's
damper with both faces at 5 and 89 degrees (loops that shake down only asymptotically) gives
finite answers, at 10 degrees status 3 naming mu and the angles (the limit loops change their
topology from one amplitude to the next); the DOE carries F_lim_backbone and jump@F. The loops themselves are
checked against brute-force cycling in tests/fortran/test_damper_wedge.f90."""
import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from udmap.case import load_case
from udmap.doe import run_doe

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "blade_a.json"


def udmap(*args):
    return subprocess.run([sys.executable, "-m", "udmap", *map(str, args)],
                          capture_output=True, text=True)


def test_neutral_wedge_is_status_3_naming_mu_and_angle(write_case):
    path = write_case("neutral", dict(mu=math.tan(math.radians(45.0))))
    out = udmap("backbone", path, "--forces", "1,5", "--json")
    assert out.returncode == 3, out.stderr
    assert "mu = 1.0" in out.stderr and "beta_R_deg = 45" in out.stderr
    assert "neutral wedge" in out.stderr and "Traceback" not in out.stderr
    # 1e-7 away from tan(beta) the damper is an ordinary one
    out = udmap("backbone", write_case("near", dict(mu=1 - 1e-7)), "--forces", "1",
                "--json")
    assert out.returncode == 0, out.stderr


@pytest.mark.parametrize("beta", [5.0, 10.0, 89.0])
def test_asymptotic_shakedown_gives_answers(beta, write_case):
    path = write_case(f"b{beta}", dict(beta_L_deg=beta, beta_R_deg=beta))
    out = udmap("backbone", path, "--forces", "1,5", "--json")
    if beta == 10.0:
        # the limit loops change their topology from one amplitude to the next
        assert out.returncode == 3, out.stderr
        assert "only asymptotically" in out.stderr and "mu = 0.3" in out.stderr
        assert "beta_L = 10.0" in out.stderr and "Traceback" not in out.stderr
        return
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert 0 < data["F_lim_backbone"] <= data["F_lim"]
    for p in data["points"]:
        assert all(math.isfinite(p[k]) for k in ("gamma_P", "f_res", "sigma_a", "u_E"))


def test_doe_records_neutral_wedge_as_physics_and_jumps(tmp_path, write_case):
    out = tmp_path / "neutral.csv"
    summary = run_doe(load_case(CASE), ["mu=0.99999999999:1.00000000001"], 4, out,
                      forces="1", workers=1, progress=False)
    assert summary["written"] == 4
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        assert row["status"] == "physics"
        assert "neutral wedge" in row["message"] and "mu = " in row["message"]
        assert "beta_R_deg = 45" in row["message"]

    # the lift-off case: the jump at 3.5 and 4 N, F_adm against the smaller limit
    lift = load_case(write_case("lift", dict(mu=0.3639798354357481, CF=1178.4721311181784)))
    out = tmp_path / "lift.csv"
    run_doe(lift, ["mu=0.3639798354357481:0.36397983543574815"], 2, out,
            forces="3.5,4,4.5", workers=1, progress=False)
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        assert row["status"] == "ok", row["message"]
        assert [row[f"jump@{F}"] for F in ("3.5", "4", "4.5")] == ["true", "true", "false"]
        F_lim, F_bb = float(row["F_lim"]), float(row["F_lim_backbone"])
        assert F_bb < F_lim
        assert float(row["F_adm"]) <= 0.5 * F_bb * (1 + 1e-12)
