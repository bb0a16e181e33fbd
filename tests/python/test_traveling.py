"""Traveling waves, the inputs (PHYSICS.md 2.6, INTERFACES.md "Traveling waves"): the phase of
analysis.blades/engine_order or analysis.ibpa_deg (and --blades/--engine-order/--ibpa) as it
reaches the kernel's Analysis struct, the bad inputs of issue 19 (exit 2 naming the field), the
outputs' fields and warnings, the platform rows of the beam and of a matrices blade (u_dof,
v_dof) through the C API, and DOE variables. The answers at phi != 0 are the kernel's (not
tested here)."""
from __future__ import annotations

import csv
import json

import numpy as np
import pytest

import udmap.model as MODEL
from fmu_harness import CASE
from udmap import Blade
from udmap.case import build_blade, load_case
from udmap.case.traveling import ibpa_of, normalised_deg
from udmap.cli import main
from udmap.doe import run_doe
from udmap.errors import InputError

#: Blade A's beam DOFs: gamma_P is DOF 16, the platform's w_P DOF 15 (1-based).
BEAM_W_P = 15


def _main(args, capsys):
    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.fixture
def analyses(monkeypatch):
    """The ibpa_deg of every Analysis struct given to udmap_new_model."""
    seen = []
    real = MODEL._capi.new_model

    def spy(err, blade, damper, analysis, out):
        seen.append(analysis._obj.ibpa_deg)
        return real(err, blade, damper, analysis, out)
    monkeypatch.setattr(MODEL._capi, "new_model", spy)
    return seen


@pytest.mark.parametrize("n,eo,deg", [(24, 0, 0.0), (24, 24, 0.0), (24, 48, 0.0), (24, 1, 15.0),
                                      (24, 23, -15.0), (24, 12, 180.0), (24, 13, -165.0),
                                      (4, 1, 90.0), (4, 3, -90.0), (4, 5, 90.0), (7, 3, 3 * 360 / 7)])
def test_phase_of_an_engine_order(n, eo, deg):
    phi = ibpa_of(n, eo)
    assert phi == deg and -180 < phi <= 180
    assert str(phi) != "-0.0"


@pytest.mark.parametrize("given,deg", [(0, 0.0), (-360, 0.0), (360, 0.0), (270, -90.0),
                                       (-180, 180.0), (180, 180.0), (-15, -15.0), (345, -15.0)])
def test_given_phase_normalised(given, deg):
    assert normalised_deg(given) == deg and str(normalised_deg(given)) != "-0.0"


@pytest.mark.parametrize("extra,args,wave", [
    ({}, [], (None, None, 0.0)),
    ({"blades": 24, "engine_order": 23}, [], (23, 24, -15.0)),
    ({"blades": 24}, [], (0, 24, 0.0)),                          # blades alone: EO 0
    ({"ibpa_deg": 30}, [], (None, None, 30.0)),
    ({}, ["--blades", "24", "--engine-order", "23"], (23, 24, -15.0)),
    ({"blades": 24, "engine_order": 1}, ["--engine-order", "6"], (6, 24, 90.0)),
    ({"blades": 24, "engine_order": 6}, ["--blades", "4"], (6, 4, 180.0)),
    ({"blades": 24, "engine_order": 1}, ["--ibpa=-4e1"], (None, None, -40.0)),
    ({"ibpa_deg": 30}, ["--blades", "4", "--engine-order", "1"], (1, 4, 90.0)),
])
@pytest.mark.parametrize("command", ["backbone", "response"])
def test_the_analysis_struct_gets_the_phase(extra, args, wave, command, write_case, analyses,
                                            capsys):
    path = write_case(analysis=extra)
    more = ["--freq", "196"] if command == "response" else []
    status, out, err = _main([command, path, "--forces", "2", "--json", *more, *args], capsys)
    assert status == 0, err
    data = json.loads(out)
    assert analyses == [wave[2]]
    assert (data["engine_order"], data["blades"], data["ibpa_deg"]) == wave
    assert data["units"]["ibpa_deg"] == "deg"
    assert data["warnings"] == []            # the asymmetric damper depends on phi


@pytest.mark.parametrize("extra,args,field", [
    ({"blades": 24, "engine_order": 2.5}, [], "analysis.engine_order must be an integer"),
    ({}, ["--blades", "24", "--engine-order", "2.5"], "--engine-order must be an integer"),
    ({"blades": 1, "engine_order": 1}, [], "analysis.blades must be an integer in [2, 10000]"),
    ({"blades": 10001, "engine_order": 1}, [], "analysis.blades must be an integer in [2, "),
    ({}, ["--blades", "1", "--engine-order", "0"], "--blades must be an integer in [2, 10000]"),
    ({}, ["--blades", "10001"], "--blades must be an integer in [2, 10000]"),
    ({"blades": 24, "engine_order": 1, "ibpa_deg": 15}, [],
     "analysis.ibpa_deg and analysis.engine_order exclude each other"),
    ({"blades": 24, "ibpa_deg": 0}, [], "analysis.ibpa_deg and analysis.blades exclude"),
    ({}, ["--ibpa", "15", "--engine-order", "1", "--blades", "24"],
     "--ibpa and --engine-order exclude each other"),
    ({"engine_order": 3}, [], "analysis.engine_order needs analysis.blades"),
    ({}, ["--engine-order", "3"], "--engine-order needs --blades"),
    ({"ibpa_deg": 400}, [], "analysis.ibpa_deg must be in [-360, 360] deg"),
    ({}, ["--ibpa", "nan"], "--ibpa must be a finite number"),
])
@pytest.mark.parametrize("command", ["backbone", "response", "curves", "hbm", "dti"])
def test_bad_phase_inputs_exit_2_naming_the_field(extra, args, field, command, write_case,
                                                  analyses, capsys):
    path = write_case(analysis=extra)
    more = {"response": ["--freq", "196"], "dti": ["--freq", "196"],
            "curves": ["--layers", "8"]}.get(command, [])
    status, out, err = _main([command, path, "--forces", "2", "--json", *more, *args], capsys)
    assert status == 2 and out == "" and analyses == []
    assert field in err


def test_the_doe_takes_the_wave(write_case, tmp_path, analyses, capsys):
    # --blades with engine_order as a DOE variable: each design's phase reaches the kernel
    out = tmp_path / "eo.csv"
    status, _, err = _main(["doe", write_case(), "--blades", "4", "--vary", "engine_order=0:3",
                            "--samples", "4", "--method", "grid", "--workers", "1", "--out",
                            out], capsys)
    assert status == 0, err
    with open(out, newline="") as f:
        eos = [int(float(r["engine_order"])) for r in csv.DictReader(f)]
    assert sorted(eos) == [0, 1, 2, 3]
    assert sorted(analyses) == sorted(ibpa_of(4, eo) for eo in eos) == [-90.0, 0.0, 90.0, 180.0]
    # bad ends of a range name the field
    for vary, field in (("engine_order=0:2000000", "analysis.engine_order must be an integer"),
                        ("blades=1:8", "analysis.blades must be an integer in [2, 10000]")):
        status, _, err = _main(["doe", write_case(analysis={"blades": 4}), "--vary", vary,
                                "--samples", "2", "--workers", "1", "--out",
                                tmp_path / "bad.csv"], capsys)
        assert status == 2 and field in err and not (tmp_path / "bad.csv").exists()
    status, _, err = _main(["doe", write_case(), "--ibpa", "15", "--engine-order", "1",
                            "--vary", "mu=0.2:0.4", "--samples", "2", "--out",
                            tmp_path / "bad.csv"], capsys)
    assert status == 2 and "--ibpa and --engine-order exclude each other" in err


def test_doe_designs_whose_phase_needs_u_dof(exported, tmp_path, analyses):
    # both ends of engine_order=0:4 on 4 blades are in phase, the designs between are not: a
    # matrices blade without u_dof fails those designs as input errors, naming blade.u_dof
    data = json.loads(CASE.read_text())
    data["blade"] = {"kind": "matrices", "M": str(exported / "M.mtx"),
                     "K": str(exported / "K.mtx"), "gamma_dof": 16, "exc_dof": 39}
    data["analysis"]["blades"] = 4
    path = tmp_path / "m.json"
    path.write_text(json.dumps(data))
    out = tmp_path / "m.csv"
    summary = run_doe(load_case(path), ["engine_order=0:4"], 5, out, method="grid", workers=1,
                      progress=False)
    assert summary["status"] == {"ok": 2, "input": 3}
    with open(out, newline="") as f:
        rows = {int(float(r["engine_order"])): r for r in csv.DictReader(f)}
    assert all(rows[eo]["status"] == "input" and "blade.u_dof" in rows[eo]["message"]
               for eo in (1, 2, 3))
    assert analyses == [0.0, 0.0]


def test_ibpa_deg_as_a_doe_variable(write_case, tmp_path, analyses):
    summary = run_doe(load_case(write_case()), ["ibpa_deg=-90:90"], 3, tmp_path / "phi.csv",
                      method="grid", workers=1, progress=False)
    assert summary["status"] == {"ok": 3}
    assert sorted(analyses) == [-90.0, 0.0, 90.0]


def test_outputs_carry_the_wave_in_json_table_and_csv(write_case, tmp_path, capsys):
    path = write_case(analysis={"blades": 24, "engine_order": 25})
    status, out, err = _main(["backbone", path, "--forces", "2", "--out", tmp_path / "o"],
                             capsys)
    assert status == 0, err
    assert "engine_order = 25" in out and "blades = 24" in out and "ibpa_deg = 15 deg" in out
    data = json.loads((tmp_path / "o" / "backbone.json").read_text())
    assert (data["engine_order"], data["blades"], data["ibpa_deg"]) == (25, 24, 15.0)
    assert data["units"]["engine_order"] == data["units"]["blades"] == "1"
    with open(tmp_path / "o" / "backbone.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert rows and all((r["engine_order"], r["blades"], r["ibpa_deg"]) == ("25", "24", "15.0")
                        for r in rows)
    # in phase: null counts, empty CSV cells, the head line without them
    status, out, err = _main(["backbone", CASE, "--forces", "2", "--out", tmp_path / "p"],
                             capsys)
    assert status == 0 and "ibpa_deg = 0 deg" in out and "engine_order" not in out
    with open(tmp_path / "p" / "backbone.csv", newline="") as f:
        row = next(csv.DictReader(f))
    assert (row["engine_order"], row["blades"], row["ibpa_deg"]) == ("", "", "0.0")


@pytest.mark.parametrize("kind", ["jenkins", "table"])
def test_a_phase_free_damper_warns(kind, tmp_path, capsys):
    data = json.loads(CASE.read_text())
    data["damper"] = {"kind": "jenkins", "kt": 1.0e5, "M_slip": 1.0}
    if kind == "table":
        (tmp_path / "k.csv").write_text("gamma,k_re,k_im\n1e-6,1.0e5,0\n1e-4,5.0e4,2.0e4\n"
                                        "1e-2,1.0e3,5.0e2\n")
        data["damper"] = {"kind": "table", "file": "k.csv", "delta_M": 0.5}
    data["analysis"].update(blades=24, engine_order=6)
    path = tmp_path / "j.json"
    path.write_text(json.dumps(data))
    for command in ("backbone", "hbm") if kind == "jenkins" else ("backbone",):
        status, out, err = _main([command, path, "--forces", "0.5", "--json"], capsys)
        assert status == 0, err
        warnings = json.loads(out)["warnings"]
        assert any(f"does not change a {kind} damper" in w and "ibpa_deg = 90 deg" in w
                   for w in warnings), warnings
        assert "udmap: warning: the interblade phase" in err
    # in phase: no such warning
    status, out, _ = _main(["backbone", path, "--forces", "0.5", "--json", "--ibpa", "0"],
                           capsys)
    assert status == 0 and not any("interblade" in w for w in json.loads(out)["warnings"])


# ---------------------------------------------------------------------------- platform rows

def test_beam_rows_through_the_c_api(blade_a_beam):
    rows = blade_a_beam.platform_rows()
    assert rows is not None
    u, v = rows
    expected = np.zeros(blade_a_beam.ndof)
    expected[BEAM_W_P - 1] = -1.0                          # u_P = -w_P
    assert np.array_equal(u, expected) and np.array_equal(v, np.zeros(blade_a_beam.ndof))


@pytest.fixture(scope="module")
def exported(tmp_path_factory, blade_a_beam):
    d = tmp_path_factory.mktemp("exported")
    blade_a_beam.export(d)
    return d


def _matrices(d, **kw):
    return Blade.matrices(d / "M.mtx", d / "K.mtx", 16, 39, zeta=0.002, **kw)


def test_matrices_rows_from_u_dof_and_v_dof(exported):
    assert _matrices(exported).platform_rows() is None       # unknown without u_dof
    u, v = _matrices(exported, u_dof=15).platform_rows()
    assert np.flatnonzero(u).tolist() == [14] and u[14] == 1.0 and not v.any()
    u, v = _matrices(exported, u_dof=15, v_dof=1).platform_rows()
    assert u[14] == 1.0 and v[0] == 1.0 and np.count_nonzero(u) == np.count_nonzero(v) == 1
    for kw, text in (({"u_dof": 65}, "u_dof must be a DOF number from 1 to 64"),
                     ({"u_dof": 0}, "u_dof must be a DOF number from 1 to 64"),
                     ({"u_dof": 16}, "u_dof must differ from gamma_dof"),
                     ({"u_dof": 15, "v_dof": 15}, "v_dof must differ from u_dof"),
                     ({"v_dof": 3}, "v_dof needs u_dof")):
        with pytest.raises(InputError, match=text):
            _matrices(exported, **kw)


def test_set_platform_rows_checks(exported):
    b = _matrices(exported)
    n = b.ndof
    row = np.linspace(-1, 1, n)
    b.set_platform_rows(row, 2 * row)
    u, v = b.platform_rows()
    assert np.array_equal(u, row) and np.array_equal(v, 2 * row)
    for args, text in (((np.zeros(n),), "u_row is zero"),
                       ((np.r_[np.inf, row[1:]],), "u_row has a non-finite entry"),
                       ((row, np.r_[row[:-1], np.nan]), "v_row has a non-finite entry"),
                       ((row[:-1],), f"u_row must have {n} entries")):
        with pytest.raises(InputError, match=text):
            b.set_platform_rows(*args)
    assert np.array_equal(b.platform_rows()[0], row)       # kept on error


def test_matrices_case_u_dof(exported, tmp_path, write_case, capsys):
    blade = {"kind": "matrices", "M": str(exported / "M.mtx"), "K": str(exported / "K.mtx"),
             "gamma_dof": 16, "exc_dof": 39, "zeta": 0.002}
    data = json.loads(CASE.read_text())
    data["blade"] = blade
    path = tmp_path / "m.json"
    path.write_text(json.dumps(data))
    status, out, err = _main(["backbone", path, "--forces", "2", "--json", "--ibpa", "0"],
                             capsys)
    assert status == 0, err                                  # in phase: not needed
    # phi != 0 without u_dof: on the command line, in the case file
    for args in (["--blades", "24", "--engine-order", "3"], ["--ibpa", "1e-3"]):
        status, out, err = _main(["backbone", path, "--forces", "2", "--json", *args], capsys)
        assert status == 2 and out == "" and "blade.u_dof" in err
    data["analysis"].update(blades=24, engine_order=3)
    path.write_text(json.dumps(data))
    status, out, err = _main(["backbone", path, "--forces", "2", "--json"], capsys)
    assert status == 2 and out == "" and "blade.u_dof" in err
    blade.update(u_dof=15, v_dof=2)
    path.write_text(json.dumps(data))
    u, v = build_blade(load_case(path)).platform_rows()
    assert u[14] == 1.0 and v[1] == 1.0 and np.count_nonzero(u) == np.count_nonzero(v) == 1
    for fields, text in (({"u_dof": 16}, "blade.u_dof must differ from blade.gamma_dof"),
                         ({"v_dof": 15}, "blade.v_dof must differ from blade.u_dof"),
                         ({"u_dof": 0}, "blade.u_dof must be an integer in [1, "),
                         ({"u_dof": 65}, "blade.u_dof must be a DOF number from 1 to 64"),
                         ({"v_dof": 99}, "blade.v_dof must be a DOF number from 1 to 64"),
                         ({"u_dof": 1.5}, "blade.u_dof must be an integer")):
        bad = json.loads(json.dumps(data))
        bad["blade"].update(fields)
        path.write_text(json.dumps(bad))
        status, out, err = _main(["backbone", path, "--forces", "2", "--json"], capsys)
        assert status == 2 and out == "" and text in err, err
