"""The shared real exports (EXUDYN test data, tests/data/fe/real, LICENSE-EXUDYN.txt) as blades:
the ANSYS rotor clamped at z = 0 with its disc as the platform, the Abaqus block clamped at x = 0
with the slab 1.6 <= x <= 2 as the platform, both with the bending axis. Their sections are
symmetric, so the first bending mode is a repeated pair, of which only one combination rocks the
platform: ``reduce`` judges the platform on the band's mode shapes (the pair's eigenspace
whole), matches the full model with the same rigid platform (an independent scipy build) to
1e-6, and ``backbone`` runs between the bare and the stuck frequency."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as la

import fe_reference as ref
from udmap.case.fe import validate_fe
from udmap.cli import main
from udmap.fe import read_fe

REAL = Path(__file__).resolve().parents[1] / "data" / "fe" / "real"
CASES = {"ansys_rotor": REAL / "ansys" / "rotor_case.json",
         "abaqus_block": REAL / "abaqus" / "block_case.json"}
# first bending pair with the rigid platform [Hz] (measured: full model, 9 digits)
FIRST = {"ansys_rotor": 33.8327838, "abaqus_block": 85.2933081}


def run(args, capsys):
    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("UDMAP_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path


def _in_box(fe, box):
    lo, hi = np.array(box[0], float), np.array(box[1], float)
    inside = np.all((fe.node_xyz >= lo - 1e-9) & (fe.node_xyz <= hi + 1e-9), axis=1)
    return sorted(set(fe.node_ids[inside].tolist()) & set(fe.dof_node.tolist()))


def full_frequencies(case_path):
    """The full model with the rigid platform and the clamp, dense eigen-solve (scipy)."""
    case = json.loads(case_path.read_text())
    blade = validate_fe(case["blade"], case_path.parent)
    fe = read_fe(blade, "/")
    rig = ref.rigid_platform(fe, _in_box(fe, blade["platform"]["box"]),
                             blade["platform"]["ref_point"], blade["platform"]["axis"],
                             blade["excitation"]["node"], blade["excitation"]["direction"],
                             clamp_nodes=_in_box(fe, blade["clamp"]["box"]))
    w = la.eigh(rig.K.toarray(), rig.M.toarray(), eigvals_only=True)
    return np.sqrt(w) / (2 * np.pi), case


@pytest.mark.parametrize("name", sorted(CASES))
def test_fixture_reduces_with_its_repeated_pair(name, cache, capsys):
    full, case = full_frequencies(CASES[name])
    # the symmetric section: the first mode is a pair (equal to rounding)
    assert full[1] == pytest.approx(full[0], rel=1e-9) and full[2] > 1.5 * full[0]
    assert full[0] == pytest.approx(FIRST[name], rel=1e-8)
    status, out, err = run(["reduce", CASES[name], "--out", cache / "red" / "r.json", "--json"],
                           capsys)
    assert status == 0, err
    info = json.loads(out)
    fr, ff = np.array(info["freqs_reduced"]), np.array(info["freqs_full"])
    top = 3 * case["analysis"]["f_max"]
    np.testing.assert_allclose(ff, full[full <= top], rtol=1e-9)
    np.testing.assert_allclose(fr, ff, rtol=1e-6)
    # the pair lies in the band: reduce says that the analyses will refuse such a band
    a = case["analysis"]
    in_band = [f for f in fr if a["f_min"] <= f <= a["f_max"]]
    assert len(in_band) == 2
    assert any("holds 2 modes of the reduced blade" in w and "narrow the band" in w
               for w in info.get("warnings", [])), info.get("warnings")
    print(f"{name}: full {ff.tolist()} Hz, reduced {fr.tolist()} Hz, "
          f"largest relative difference {np.max(np.abs(fr / ff - 1)):.1e}")


@pytest.mark.parametrize("name", sorted(CASES))
def test_fixture_backbone_between_bare_and_stuck(name, cache, capsys):
    shutil.copytree(CASES[name].parent, cache / "case")
    path = cache / "case" / CASES[name].name
    case = json.loads(path.read_text())
    assert run(["reduce", path, "--out", cache / "red" / "r.json"], capsys)[0] == 0
    red = json.loads((cache / "red" / "r.json").read_text())
    K = np.loadtxt(cache / "red" / red["blade"]["K"], skiprows=2)
    M = np.loadtxt(cache / "red" / red["blade"]["M"], skiprows=2)
    n = int(round((np.sqrt(8 * K.size + 1) - 1) / 2))
    Kd, Md = np.zeros((n, n)), np.zeros((n, n))
    jj, ii = np.triu_indices(n)
    order = np.lexsort((ii, jj))
    Kd[ii[order], jj[order]] = K
    Md[ii[order], jj[order]] = M
    Kd, Md = Kd + np.tril(Kd, -1).T, Md + np.tril(Md, -1).T
    g = red["blade"]["gamma_dof"] - 1
    Kd[g, g] += case["damper"]["kt"]
    w, phi = la.eigh(Kd, Md)
    # the partner of the pair does not rock the platform and stays: the stuck mode is the
    # lowest one that turns gamma_P
    turns = np.abs(phi[g]) > 1e-6 * np.abs(phi[g]).max()
    stuck = np.sqrt(w[turns][0]) / (2 * np.pi)
    assert stuck > 1.05 * FIRST[name]
    forces = {"ansys_rotor": "0.01,0.1,1", "abaqus_block": "10,1000,3000"}[name]
    status, out, err = run(["backbone", path, "--forces", forces, "--json"], capsys)
    assert status == 0, err
    bb = json.loads(out)
    assert bb["f1_bare"] == pytest.approx(FIRST[name], rel=1e-8)
    f_res = np.array([p["f_res"] for p in bb["points"]])
    # the damper stiffens the pair's rocking combination: between bare and stuck (to the
    # damping's shift of a resonance), falling as the damper slips more
    assert np.all(f_res > bb["f1_bare"]) and np.all(f_res <= stuck * (1 + 1e-3))
    assert np.all(np.diff(f_res) < 0)
    assert f_res[0] == pytest.approx(stuck, rel=1e-3)
    print(f"{name}: bare {bb['f1_bare']:.6f} Hz, stuck {stuck:.6f} Hz, f_res {f_res.tolist()}")


def test_platform_that_does_not_move_in_the_pair_is_refused(cache, capsys):
    # the rotor's twist about its own axis z: neither mode of the bending pair turns the disc
    shutil.copytree(CASES["ansys_rotor"].parent, cache / "case")
    path = cache / "case" / "rotor_case.json"
    case = json.loads(path.read_text())
    case["blade"]["platform"]["axis"] = [0, 0, 1]
    path.write_text(json.dumps(case))
    status, out, err = run(["reduce", path, "--out", cache / "red" / "r.json"], capsys)
    assert status == 2
    assert ("blade.platform.axis: the platform rotation gamma_P about this axis does not move "
            "in the band's mode(s) at 33.8328, 33.8328 Hz (their share of gamma_P's static "
            "flexibility is ") in err and "rotorAnsysNodalCoordinates.txt" in err
    assert not (cache / "red").exists()
