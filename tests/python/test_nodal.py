"""udmap nodal (PHYSICS.md 2.6, INTERFACES.md "Command line"): the sweep over every engine order
of a wheel, its worst engine order per force, its files; the in-phase family is the backbone's
own answer, bit for bit."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from udmap.nodal import ibpa_of, nodal_diameter

ROOT = Path(__file__).resolve().parents[2]
CASE = str(ROOT / "cases" / "blade_a.json")


def run(*args: str):
    return subprocess.run([sys.executable, "-m", "udmap", *args], capture_output=True,
                          text=True, cwd=ROOT)


@pytest.fixture(scope="module")
def sweep4(tmp_path_factory):
    out = tmp_path_factory.mktemp("nodal")
    r = run("nodal", CASE, "--blades", "4", "--forces", "2,5", "--json", "--out", str(out),
            "--plot")
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout), out


def test_phase_of_every_engine_order():
    assert [ibpa_of(eo, 4) for eo in range(6)] == [0.0, 90.0, 180.0, -90.0, 0.0, 90.0]
    assert [nodal_diameter(eo, 24) for eo in (0, 1, 12, 13, 23, 24)] == [0, 1, 12, 11, 1, 0]


def test_sweep_fields_and_worst(sweep4):
    data, _ = sweep4
    assert data["blades"] == 4
    pts = data["points"]
    assert [(p["engine_order"], p["ibpa_deg"], p["nodal_diameter"]) for p in pts[::2]] == \
        [(0, 0.0, 0), (1, 90.0, 1), (2, 180.0, 2), (3, -90.0, 1)]
    assert data["units"]["ibpa_deg"] == "deg" and data["units"]["sigma_a"] == "Pa"
    for w in data["worst"]:
        rows = [p for p in pts if p["F_E"] == w["F_E"]]
        assert max(rows, key=lambda p: p["sigma_max"])["engine_order"] == w["engine_order"]
        assert sum(p["worst"] for p in rows) == 1
    # forward and backward waves differ: the damper is not mirror-symmetric
    eo1 = [p for p in pts if p["engine_order"] == 1]
    eo3 = [p for p in pts if p["engine_order"] == 3]
    assert all(abs(a["f_res"] - b["f_res"]) > 1e-3 for a, b in zip(eo1, eo3))
    # F_lim(phi) differs from the in-phase formula's but stays close on blade A
    flim = {p["engine_order"]: p["F_lim"] for p in pts}
    assert flim[1] != flim[0] and abs(flim[1] / flim[0] - 1) < 0.05


def test_in_phase_family_is_the_backbone(sweep4):
    data, _ = sweep4
    r = run("backbone", CASE, "--forces", "2,5", "--json")
    assert r.returncode == 0, r.stderr
    bb = json.loads(r.stdout)["points"]
    eo0 = [p for p in data["points"] if p["engine_order"] == 0]
    for a, b in zip(eo0, bb):
        assert (a["gamma_P"], a["f_res"], a["sigma_a"]) == (b["gamma_P"], b["f_res"], b["sigma_a"])


def test_files(sweep4):
    data, out = sweep4
    assert (out / "nodal.png").stat().st_size > 10000
    lines = (out / "nodal.csv").read_text().splitlines()
    assert lines[0].startswith("engine_order,ibpa_deg,nodal_diameter,F_E")
    assert len(lines) == 1 + len(data["points"])
    assert json.loads((out / "nodal.json").read_text())["worst"] == data["worst"]


@pytest.mark.parametrize("blades", ["1", "10001"])
def test_blades_out_of_range(blades):
    r = run("nodal", CASE, "--blades", blades, "--forces", "2")
    assert r.returncode == 2 and "blades" in r.stderr


def test_threads_give_the_same_sweep():
    """The engine orders run on threads (the kernel keeps no global state): the same numbers,
    bit for bit, on one thread and on three."""
    from udmap.case import build_blade, build_damper, load_case
    from udmap.nodal import sweep
    case = load_case(CASE)
    blade, damper = build_blade(case), build_damper(case)
    a = case.analysis | {"harmonics": 1}
    assert sweep(blade, damper, a, 4, [2.0], workers=1) == \
        sweep(blade, damper, a, 4, [2.0], workers=3)
