"""Units in every output of the command line (docs/outputs.md): each readable table header and
"name = value" line gives its unit, readable numbers are rounded; each JSON output holds a
``units`` object naming the SI unit of every quantity it holds; the doe's ``.meta.json`` and
Parquet schema name the unit of each column. Also the verdicts: ``hcf_reason`` and the warning
above F_lim."""
from __future__ import annotations

import json
import re

import pytest

import udmap.cli.commands as COMMANDS
import udmap.cli.output as OUTPUT
from fe_case_fixtures import export, run, work  # noqa: F401  (fixtures)
from fmu_harness import CASE
from udmap.cli import main
from udmap.cli.units import UNITS

SI = {"N", "m", "rad", "Hz", "Pa", "N m", "N m/rad", "s"}
# The traveling wave's fields (docs/outputs.md): ibpa_deg in degrees, the counts engine_order
# and blades as 1.
SI |= {"deg", "1"}
#: JSON fields that are counts, codes or flags: no unit.
COUNTS = {"regime", "harmonics", "branch", "part", "steps", "iterations", "aft_calls", "n_full",
          "n_reduced", "gamma_dof", "exc_dof"}
#: Readable columns and head lines without a unit.
NO_UNIT = {"regime", "hcf_ok", "hcf_reason", "branch", "H", "jump", "mode", "lift_off",
           "harmonics", "variant", "cached"}

RUNS = {
    "table": ["table", CASE, "--gammas", "1e-5,1e-4,1e-3,3e-3"],
    "backbone": ["backbone", CASE, "--forces", "1,5,25"],
    "backbone_h3": ["backbone", CASE, "--forces", "2", "--harmonics", "3"],
    "curves": ["curves", CASE, "--forces", "2", "--layers", "12"],
    "response": ["response", CASE, "--forces", "1,5", "--freq", "196"],
    "hbm": ["hbm", CASE, "--forces", "2"],
    "dti": ["dti", CASE, "--forces", "5", "--freq", "196"],
}


def _run(args, capsys, monkeypatch):
    """(readable stdout, the headers of its tables, stderr, JSON)."""
    headers = []
    real = OUTPUT.print_rows

    def recording(header, *rest, **kw):
        headers.append(list(header))
        return real(header, *rest, **kw)
    monkeypatch.setattr(OUTPUT, "print_rows", recording)
    monkeypatch.setattr(COMMANDS, "print_rows", recording)
    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    assert status == 0, err
    status = main([str(a) for a in args] + ["--json"])
    text, _ = capsys.readouterr()
    assert status == 0
    return out, headers, err, json.loads(text)


def check_readable(out: str, headers: list) -> None:
    assert headers
    for header in headers:
        for h in header:
            assert h in out
            assert re.search(r"\[[^\]]+\]$", h) or h in NO_UNIT, f"no unit: {h!r}"
    for line in out.splitlines():
        m = re.match(r"^\s*(\S+) = (\S+)(?: (.+))?$", line)
        if m:
            key, _, unit = m.groups()
            if key not in NO_UNIT:
                assert unit, f"no unit: {line!r}"
    # rounded: no number with more than 6 significant digits
    for number in re.findall(r"(?<![\w.])-?\d+\.?\d*(?:e[+-]\d+)?", out):
        digits = re.sub(r"e.*", "", number).replace("-", "").replace(".", "").lstrip("0")
        assert len(digits.rstrip("0") if "." not in number else digits) <= 6, number


def check_json(data: dict) -> None:
    units = data["units"]
    assert set(units.values()) <= SI
    assert all(UNITS[k] == u for k, u in units.items())
    assert isinstance(data["warnings"], list)

    def walk(node, key=None):
        if isinstance(node, dict):
            for k, v in node.items():
                if k != "units":
                    walk(v, k)
        elif isinstance(node, list):
            for v in node:
                walk(v, key)
        elif isinstance(node, float):
            assert key in units, f"no unit for {key}"
        elif isinstance(node, int) and not isinstance(node, bool):
            assert key in COUNTS or key in units, f"no unit for {key}"
    walk(data)


@pytest.mark.parametrize("name", sorted(RUNS))
def test_every_quantity_has_its_unit(name, capsys, monkeypatch):
    out, headers, _, data = _run(RUNS[name], capsys, monkeypatch)
    check_readable(out, headers)
    check_json(data)


def test_reduce_gives_its_units(work, capsys, monkeypatch):  # noqa: F811
    d = work[0]
    out, headers, _, data = _run(["reduce", d / "case.json", "--out", d / "r.json"], capsys,
                                 monkeypatch)
    check_readable(out, headers)
    check_json(data)
    assert data["units"]["freqs_full"] == "Hz"


def test_readable_rounded_json_full(capsys, monkeypatch):
    out, _, _, data = _run(RUNS["backbone"], capsys, monkeypatch)
    F_lim = data["F_lim"]
    assert f"F_lim = {F_lim:.4g} N" in out and repr(F_lim) not in out
    assert len(repr(F_lim)) > 10                          # JSON keeps every digit
    assert "sigma_a [MPa]" in out and data["units"]["sigma_a"] == "Pa"


def test_hcf_reason_and_warning_above_F_lim(capsys, monkeypatch):
    out, _, err, data = _run(RUNS["backbone"], capsys, monkeypatch)
    p1, p5, p25 = data["points"]
    assert p1["hcf_reason"] == "sigma_a 99.63 MPa above sigma_all 80 MPa by 24.5 %"
    assert p25["hcf_reason"].startswith("F_E 25 N above 0.5 F_lim 10.84 N by 131 %; sigma_a")
    assert p1["hcf_reason"] in out and p25["hcf_reason"] in out
    assert data["warnings"] == ["F_E = 25 N is at or above F_lim = 21.68 N: the damper slips all "
                                "the cycle and cannot limit the response any more (not "
                                "admissible)"]
    assert "udmap: warning: F_E = 25 N is at or above F_lim" in err
    out, _, err, data = _run(RUNS["response"], capsys, monkeypatch)
    ok = data["points"][0]
    assert ok["hcf_ok"] and ok["hcf_reason"].startswith("ok: F_E at 9.23 % of 0.5 F_lim")
    assert data["warnings"] == [] and "warning" not in err
    # the excitation frequency is f_exc in the table, JSON keeps f_res on the points
    assert "f_exc [Hz]" in out and "f_res [Hz]" not in out
    assert data["f_exc"] == 196.0 and data["points"][0]["f_res"] == 196.0


def test_unbounded_in_words(write_case, capsys, monkeypatch):
    path = write_case("undamped", blade={"zeta": 0.0})
    out, _, err, data = _run(["backbone", path, "--forces", "30"], capsys, monkeypatch)
    row = [line for line in out.splitlines() if line.strip().startswith("30 ")][0]
    assert "unbounded" in row and " - " not in row
    p = data["points"][0]
    assert p["unbounded"] and "response unbounded" in p["hcf_reason"]
    assert data["warnings"] and "F_lim" in err


def test_doe_meta_and_parquet_units(tmp_path):
    out = tmp_path / "d.csv"
    assert main(["doe", str(CASE), "--vary", "mu=0.2:0.6,platform_m=0.01:0.05",
                 "--samples", "4", "--forces", "2", "--workers", "1", "--out", str(out)]) == 0
    meta = json.loads((tmp_path / "d.csv.meta.json").read_text())
    assert meta["units"] == {"mu": "1", "platform_m": "kg", "F_lim": "N", "F_lim_backbone": "N",
                             "gamma_b": "rad", "M_max": "N m", "M_min": "N m",
                             "gamma_P@2": "rad", "f_res@2": "Hz", "sigma_a@2": "Pa",
                             "F_adm": "N"}
    header = out.read_text().splitlines()[0]
    assert header == ("design,mu,platform_m,F_lim,F_lim_backbone,gamma_b,M_max,M_min,lift_off,"
                      "gamma_P@2,f_res@2,sigma_a@2,hcf_ok@2,jump@2,F_adm,status,message")
    import pyarrow.parquet as pq  # installed by make deps (PY_PACKAGES)
    schema = pq.read_schema(tmp_path / "d.parquet")
    assert schema.names == header.split(",")
    for name, unit in meta["units"].items():
        assert schema.field(name).metadata == {b"unit": unit.encode()}
    assert schema.field("status").metadata is None
    assert pq.read_table(tmp_path / "d.parquet").num_rows == 4


@pytest.mark.parametrize("damper,extra", [
    ({}, []), ({}, ["--harmonics", "3"]), ({"mu": 0.6}, []), ({"mu": 0.6}, ["--harmonics", "2"]),
    ({}, ["hbm"])])
def test_hcf_reason_agrees_with_hcf_ok(damper, extra, write_case, capsys):
    """On blade A and a lift-off variant (F_lim_backbone < F_lim), one to several harmonics and
    harmonic balance: the reason is "ok: ..." exactly when hcf_ok holds, and a warning comes
    exactly with the forces at or above F_lim (regime 3)."""
    path = write_case("c", damper=damper)
    command = "hbm" if extra == ["hbm"] else "backbone"
    forces = "0.3,3,11,24" if command == "hbm" else "0.3,1,3,6,9,11,15,20,21.5,24"
    args = [command, str(path), "--forces", forces, "--json"]
    assert main(args + ([] if command == "hbm" else extra)) == 0
    data = json.loads(capsys.readouterr()[0])
    for p in data["points"]:
        assert p["hcf_reason"].startswith("ok: ") == p["hcf_ok"], p
    above = [p["F_E"] for p in data["points"] if p["regime"] == 3]
    assert len(data["warnings"]) == len(above)
    assert all(f"F_E = {F:g} N" in w for F, w in zip(above, data["warnings"]))


def test_curves_without_a_known_F_lim(tmp_path, capsys):
    """A measured table without delta_M has no F_lim: curves answers as before, no warning."""
    from fmu_harness import write_matrices_table_case
    path = write_matrices_table_case(tmp_path)
    data = json.loads(path.read_text())
    del data["damper"]["delta_M"]
    path.write_text(json.dumps(data))
    assert main(["curves", str(path), "--forces", "2,5", "--layers", "8", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["warnings"] == [] and "warning" not in err


def test_demo_summary_gives_its_units(tmp_path):
    from udmap.demo import run_demo
    run_demo(None, tmp_path, forces=[1.0, 30.0], quiet=True)
    check_json(dict(json.loads((tmp_path / "summary.json").read_text()), warnings=[]))
