"""``--out DIR`` and ``--plot`` of backbone, curves, response and hbm (docs/outputs.md): the CSV
(SI, full precision, the JSON's numbers), the JSON (what --json prints) and the plot; DIR made
when missing; existing files refused without --force; files written with the user's umask."""
from __future__ import annotations

import csv
import json
import os
import stat

import pytest

from fmu_harness import CASE
from udmap.cli import main

RUNS = {
    "backbone": ["--forces", "1,5,25"],
    "curves": ["--forces", "2,5", "--layers", "12"],
    "response": ["--forces", "0.5,2,8", "--freq", "196"],
    "hbm": ["--forces", "2"],
}


def _untimed(data: dict) -> dict:
    """The JSON without the timing of hbm's points."""
    for p in data.get("points", []):
        p.pop("seconds", None)
    return data


def _main(args, capsys):
    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.parametrize("command", sorted(RUNS))
def test_out_and_plot_write_csv_json_and_png(command, tmp_path, capsys):
    d = tmp_path / "new" / "dir"                                  # created when missing
    old = os.umask(0o027)
    try:
        status, out, err = _main([command, CASE, *RUNS[command], "--out", d, "--plot"], capsys)
    finally:
        os.umask(old)
    assert status == 0, err
    for ext in ("csv", "json", "png"):
        path = d / f"{command}.{ext}"
        assert f"wrote {path}" in out
        assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert (d / f"{command}.png").stat().st_size > 10000
    assert sorted(p.name for p in d.iterdir()) == [f"{command}.{e}" for e in ("csv", "json",
                                                                             "png")]
    status, text, _ = _main([command, CASE, *RUNS[command], "--json"], capsys)
    assert status == 0
    data = json.loads(text)
    assert _untimed(json.loads((d / f"{command}.json").read_text())) == _untimed(data)
    with open(d / f"{command}.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    if command == "curves":
        flat = [(c["F_E"], f, g) for c in data["curves"] for f, g in zip(c["f"], c["gamma_P"])]
        assert [(float(r["F_E"]), float(r["f"]), float(r["gamma_P"])) for r in rows] == flat
    else:
        assert len(rows) == len(data["points"])
        for r, p in zip(rows, data["points"]):
            assert float(r["F_E"]) == p["F_E"]
            assert float(r["gamma_P"]) == p["gamma_P"]               # full precision
            assert float(r["sigma_a"]) == p["sigma_a"]
            assert r["hcf_ok"] == ("true" if p["hcf_ok"] else "false")
            assert r["hcf_reason"] == p["hcf_reason"]


def test_out_refuses_to_overwrite_without_force(tmp_path, capsys):
    args = ["backbone", CASE, "--forces", "1", "--out", tmp_path]
    assert _main(args, capsys)[0] == 0
    before = (tmp_path / "backbone.json").read_text()
    status, out, err = _main(["backbone", CASE, "--forces", "2", "--out", tmp_path], capsys)
    assert status == 2 and out == "" and "pass --force" in err
    assert (tmp_path / "backbone.json").read_text() == before
    status, _, err = _main(["backbone", CASE, "--forces", "2", "--out", tmp_path, "--force"],
                           capsys)
    assert status == 0, err
    assert json.loads((tmp_path / "backbone.json").read_text())["points"][0]["F_E"] == 2.0
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


def test_plot_needs_out(capsys):
    status, out, err = _main(["backbone", CASE, "--forces", "1", "--plot"], capsys)
    assert status == 2 and "--plot needs --out" in err


def test_curves_plot_without_a_backbone_line(tmp_path, capsys):
    """A measured table without delta_M: the backbone beyond the table's last row is not
    known; the curves are plotted without it."""
    from fmu_harness import write_matrices_table_case
    path = write_matrices_table_case(tmp_path)
    data = json.loads(path.read_text())
    del data["damper"]["delta_M"]
    path.write_text(json.dumps(data))
    status, _, err = _main(["curves", path, "--forces", "2,5", "--layers", "8", "--out",
                            tmp_path / "o", "--plot"], capsys)
    assert status == 0, err
    assert (tmp_path / "o" / "curves.png").stat().st_size > 10000


def test_response_beyond_the_band_up_to_three_f_max(capsys):
    # The band [150, 230] Hz is where the resonance is sought; a response is answered up to
    # 3 f_max (690 Hz), where the blade's receptances hold: stuck at 2 N, linear, so gamma_P
    # is F_E |H_gE / (1 + k H_gg)| of the blade at that frequency.
    from udmap.case import build_blade, build_damper, load_case
    status, out, _ = _main(["response", CASE, "--forces", "2", "--freq", "400", "--json"], capsys)
    assert status == 0
    p = json.loads(out)["points"][0]
    case = load_case(str(CASE))
    r = build_blade(case).receptances(400.0)
    k = build_damper(case).k_stuck
    want = 2.0 * abs(r["gE"]) / abs(1 + k * r["gg"])
    assert p["f_res"] == 400.0 and p["regime"] == 0          # stuck
    assert p["gamma_P"] == pytest.approx(want, rel=1e-10)
    status, _, err = _main(["response", CASE, "--forces", "2", "--freq", "700"], capsys)
    assert status == 2
    assert "--freq 700.0 Hz is beyond the reach of the blade: (0, 690] Hz" in err
