"""Design of experiments on the kernel (blade A): the same rows serially, on two worker processes,
two threads and a Dask LocalCluster of two workers; rows equal to the backbone of the case edited
by hand, F_adm checked against a fine scan of the backbone and against the stuck range's
proportionality; failing designs recorded while the run completes; kill and resume give the file
of an uninterrupted run and leave no process behind."""
import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from udmap.case import build_blade, build_damper, build_model, load_case, validate
from udmap.doe import admissible_grid, run_doe

ROOT = Path(__file__).resolve().parents[2]
BLADE_A = ROOT / "cases" / "blade_a.json"
CASE = load_case(BLADE_A)
FORCES = "1,2.5,4,8"
VARY = ["mu=0.15:0.6", "CF=500:1500"]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    out = tmp_path_factory.mktemp("doe") / "serial.csv"
    summary = run_doe(CASE, VARY, 32, out, forces=FORCES, workers=1, progress=False)
    assert summary["written"] == 32 and summary["executor"] == "serial"
    return out


@pytest.mark.parametrize("options", [{"workers": 2}, {"workers": 2, "threads": True},
                                     {"dask": "local:2"}], ids=["processes", "threads", "dask"])
def test_parallel_runs_write_the_serial_file_bit_for_bit(serial, tmp_path, options):
    out = tmp_path / "par.csv"
    # small chunks, so that the workers interleave and finish out of order
    summary = run_doe(CASE, VARY, 32, out, forces=FORCES, chunk=3, progress=False, **options)
    assert summary["workers"] == 2 and summary["computed"] == 32
    assert out.read_bytes() == serial.read_bytes()


def test_serial_file_is_complete_and_ok(serial):
    rows = _rows(serial)
    assert [int(r["design"]) for r in rows] == list(range(32))
    assert all(r["status"] == "ok" for r in rows), [r["message"] for r in rows]
    mu = [float(r["mu"]) for r in rows]
    cf = [float(r["CF"]) for r in rows]
    assert 0.15 <= min(mu) and max(mu) <= 0.6 and 500 <= min(cf) and max(cf) <= 1500
    # a Sobol net: one design in each of the 32 slices of each range
    assert sorted(int((m - 0.15) / 0.45 * 32) for m in mu) == list(range(32))
    assert sorted(int((c - 500) / 1000 * 32) for c in cf) == list(range(32))


def _by_hand(edits):
    """blade_a.json edited as a user would, loaded and validated like any case."""
    data = json.loads(BLADE_A.read_text())
    for path, value in edits.items():
        node = data
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
    return validate(data, ROOT / "cases")


def _leaf(path):
    node = {"blade": CASE.blade, "damper": CASE.damper, "analysis": CASE.analysis}
    for key in path:
        node = node[key]
    return node


def _check_rows_against_backbone(rows, names, paths, forces):
    """Recomputes each row from a hand-edited case (fresh blade, damper and model) and returns
    how F_adm was found per row: 'half' (F_lim/2 admissible) or the regime at the crossing."""
    kinds = []
    for row in rows:
        case = _by_hand({p: (int(row[n]) if isinstance(_leaf(p), int) else float(row[n]))
                         for n, p in zip(names, paths)})
        blade, damper = build_blade(case), build_damper(case)
        model = build_model(case, blade, damper)
        F_lim = model.limit_force()
        assert float(row["F_lim"]) == pytest.approx(F_lim, rel=1e-8)
        for key in ("gamma_b", "M_max", "M_min"):
            assert float(row[key]) == pytest.approx(getattr(damper, key), rel=1e-8)
        assert row["lift_off"] == ("true" if damper.lift_off else "false")
        for p, label in zip(model.backbone([float(f) for f in forces]), forces):
            for key in ("gamma_P", "f_res", "sigma_a"):
                assert float(row[f"{key}@{label}"]) == pytest.approx(p[key], rel=1e-8)
            assert row[f"hcf_ok@{label}"] == ("true" if p["hcf_ok"] else "false")
        # F_adm: the largest force up to F_lim/2 whose resonant stress is admissible
        F_adm, s_all, F_half = float(row["F_adm"]), case.analysis["sigma_all"], 0.5 * F_lim
        at = model.backbone([F_adm])[0]
        if F_adm < F_half * (1 - 1e-12):
            assert at["sigma_a"] == pytest.approx(s_all, rel=1e-8)
            # every force above it up to F_lim/2 fails, on a scan 20 times finer than the
            # solver's own samples
            scan = np.geomspace(F_adm * 1.001, F_half, 300)
            assert all(p["sigma_a"] > s_all for p in model.backbone(scan))
            kinds.append(at["regime_name"])
        else:
            assert F_adm == pytest.approx(F_half, rel=1e-14) and at["sigma_a"] <= s_all
            kinds.append("half")
    return kinds


def test_three_rows_agree_with_the_backbone_of_the_case_edited_by_hand(serial):
    rows = _rows(serial)
    # one row per way F_adm is found: F_lim/2 admissible (low friction and load, the damper
    # slips early), a crossing in partial slip (lift-off designs: no stuck range), and one
    # where sigma_a is proportional to F_E (stuck)
    half = next(r for r in rows if float(r["F_adm"]) == 0.5 * float(r["F_lim"]))
    slip = next(r for r in rows if r["lift_off"] == "true")
    stuck = next(r for r in rows if r["lift_off"] == "false" and r is not half)
    kinds = _check_rows_against_backbone([half, slip, stuck], ["mu", "CF"],
                                         [("damper", "mu"), ("damper", "CF")],
                                         FORCES.split(","))
    assert kinds == ["half", "partial slip", "stuck"]


def test_blade_and_shape_parameters_agree_with_hand_edited_cases(tmp_path):
    # blade parameters rebuild the blade per design; contact points and log ranges too
    out = tmp_path / "shape.csv"
    vary = ["airfoil.h=0.0035:0.0045", "flat2_y=3.8e-3:4.0e-3", "kt_flat=2e7:8e7:log"]
    run_doe(CASE, vary, 8, out, forces="2", workers=1, method="lhs", seed=5, progress=False)
    rows = _rows(out)
    assert all(r["status"] == "ok" for r in rows), [r["message"] for r in rows]
    _check_rows_against_backbone(rows[:3], ["airfoil.h", "flat2_y", "kt_flat"],
                                 [("blade", "airfoil", "h"), ("damper", "flat_points", 1, 1),
                                  ("damper", "kt_flat")], ["2"])


def test_cf_alone_rescales_one_damper_and_agrees_with_tracing_it_again(tmp_path):
    out = tmp_path / "cf.csv"
    run_doe(CASE, ["CF=300:3000"], 8, out, forces="1,3", workers=1, progress=False)
    rows = _rows(out)
    assert all(r["status"] == "ok" for r in rows), [r["message"] for r in rows]
    _check_rows_against_backbone(rows[:3], ["CF"], [("damper", "CF")], ["1", "3"])


def test_admissible_force_deep_in_the_stuck_range(tmp_path):
    # a tiny allowable stress puts F_adm below every sample of the solver, where sigma_a is
    # proportional to F_E: F_adm = sigma_all / (sigma_a/F_E)_stuck; varying an analysis
    # setting also builds a model per design
    out = tmp_path / "stuck.csv"
    run_doe(CASE, ["sigma_all=2e5:8e5", "mu=0.2:0.3"], 8, out, workers=1, progress=False)
    rows = _rows(out)
    assert all(r["status"] == "ok" for r in rows), [r["message"] for r in rows]
    for r in rows:
        case = _by_hand({("analysis", "sigma_all"): float(r["sigma_all"]),
                         ("damper", "mu"): float(r["mu"])})
        model = build_model(case)
        p = model.backbone([1e-4])[0]
        assert p["regime_name"] == "stuck"
        F_adm = float(r["F_adm"])
        assert 0 < F_adm < admissible_grid(0.5 * float(r["F_lim"]))[0]
        assert F_adm == pytest.approx(case.analysis["sigma_all"] / (p["sigma_a"] / 1e-4),
                                      rel=1e-9)


def test_admissible_force_without_structural_damping(tmp_path):
    # zeta = 0: a stuck damper bounds nothing, so even the smallest force drives the blade to
    # the slip amplitude, where sigma_a is about 68 MPa on blade A: with sigma_all = 60 MPa no
    # force is admissible (F_adm = 0, said in the message), with 80 MPa the crossing is found
    out = tmp_path / "zeta0.csv"
    run_doe(CASE, ["zeta=0:0.002", "sigma_all=6e7:8e7"], 4, out, method="grid", forces="1",
            workers=1, progress=False)
    rows = {(float(r["zeta"]), float(r["sigma_all"])): r for r in _rows(out)}
    assert all(r["status"] == "ok" for r in rows.values())
    none, some = rows[(0.0, 6e7)], rows[(0.0, 8e7)]
    model = build_model(_by_hand({("blade", "zeta"): 0.0}))
    assert float(none["F_adm"]) == 0.0 and "F_adm = 0" in none["message"]
    assert model.backbone([1e-8])[0]["sigma_a"] > 6e7
    F_adm = float(some["F_adm"])
    assert 0 < F_adm < 1.0 and some["message"] == ""
    assert model.backbone([F_adm])[0]["sigma_a"] == pytest.approx(8e7, rel=1e-8)
    # with blade A's damping 60 MPa is reached while the damper is stuck, at the force that
    # the stuck range's proportionality gives; 80 MPa in partial slip, at a larger force
    stuck = build_model(CASE).backbone([1e-4])[0]["sigma_a"] / 1e-4
    assert float(rows[(0.002, 6e7)]["F_adm"]) == pytest.approx(6e7 / stuck, rel=1e-9)
    assert float(rows[(0.002, 8e7)]["F_adm"]) > 8e7 / stuck


@pytest.mark.parametrize("vary,needle", [
    (["mu=0.2:3.0"], "damper jams"),  # blade A's damper jams above mu ~ 2.1
    # shallow faces shake down only asymptotically: a limit loop for some, for others (no
    # limit, or limits that change topology from amplitude to amplitude) a physics error
    (["beta_L_deg=4:14", "beta_R_deg=4:14"], "only asymptotically"),
], ids=["jam", "ratchet"])
def test_a_design_that_fails_is_recorded_and_the_run_completes(tmp_path, vary, needle):
    out = tmp_path / "fail.csv"
    summary = run_doe(CASE, vary, 16, out, forces="2", workers=2, chunk=2, progress=False)
    rows = _rows(out)
    assert len(rows) == 16 and summary["written"] == 16 and not summary["interrupted"]
    failed = [r for r in rows if r["status"] != "ok"]
    assert failed and len(failed) < 16
    for r in failed:
        assert r["status"] == "physics" and needle in r["message"], r["message"]
        assert r["F_lim"] == "" and r["F_adm"] == "" and r["gamma_P@2"] == ""
    for r in rows:
        if r["status"] == "ok":
            assert float(r["F_adm"]) > 0 and r["message"] == ""
    assert summary["status"] == {"ok": 16 - len(failed), "physics": len(failed)}


def _cli(*args, **kw):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
    return subprocess.Popen([sys.executable, "-m", "udmap", *args], cwd=ROOT, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)


def _children(pid):
    try:
        return [int(c) for c in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def _alive(pid):
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    return "\nState:\tZ" not in status


@pytest.mark.parametrize("workers", ["1", "2"])
def test_kill_and_resume_give_the_uninterrupted_file(tmp_path, workers):
    n = 800
    args = ["doe", "cases/blade_a.json", "--vary", ",".join(VARY), "--samples", str(n),
            "--forces", FORCES, "--chunk", "10", "--workers", workers]
    full, cut = tmp_path / "full.csv", tmp_path / "cut.csv"
    p = _cli(*args, "--out", str(full))
    assert p.wait(timeout=100) == 0, p.stderr.read()
    p = _cli(*args, "--out", str(cut))
    # stop, then kill -9, once a few chunks are on disk, with most of the run still to go
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and p.poll() is None:
        if cut.exists() and cut.read_bytes().count(b"\n") > 31:
            break
        time.sleep(0.005)
    p.send_signal(signal.SIGSTOP)
    workers_pids = _children(p.pid)
    p.send_signal(signal.SIGKILL)
    p.wait(timeout=10)
    p.stdout.close()
    p.stderr.close()
    lines = cut.read_bytes().count(b"\n") - 1
    assert 30 < lines < n, lines
    assert len(workers_pids) == (2 if workers == "2" else 0)
    # the pool's workers notice that their parent is gone and exit
    deadline = time.monotonic() + 10
    while any(_alive(c) for c in workers_pids) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not any(_alive(c) for c in workers_pids)
    r = _cli(*args, "--out", str(cut), "--resume", "--json")
    out, err = r.communicate(timeout=100)
    assert r.returncode == 0, err
    summary = json.loads(out)
    assert summary["resumed_at"] == lines
    assert summary["computed"] + summary["recovered"] + summary["resumed_at"] == n
    assert cut.read_bytes() == full.read_bytes()
    assert not (tmp_path / "cut.csv.pending").exists()


def test_example_prints_the_pareto_front_of_its_file(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "doe_mu_cf.py"), str(tmp_path)],
                       cwd=ROOT, env=env, capture_output=True, text=True, timeout=100)
    assert r.returncode == 0, r.stderr
    from udmap.doe.plot import pareto_front
    rows = [row for row in _rows(tmp_path / "doe_mu_cf.csv") if row["status"] == "ok"]
    assert len(rows) == 512
    front = pareto_front([float(row["CF"]) for row in rows], [float(row["F_adm"]) for row in rows])
    printed = r.stdout.split("Pareto front")[1].splitlines()[2:2 + len(front)]
    for line, i in zip(printed, front):
        cf, mu, F_lim, F_adm = (float(x) for x in line.split())
        assert cf == pytest.approx(float(rows[i]["CF"]), abs=0.05)
        assert F_adm == pytest.approx(float(rows[i]["F_adm"]), abs=5e-4)
    # along the front, more CF buys a larger admissible force
    assert all(float(rows[a]["F_adm"]) < float(rows[b]["F_adm"])
               for a, b in zip(front, front[1:]))
    for kind in ("pairs", "pareto", "pass"):
        assert (tmp_path / f"doe_mu_cf_{kind}.png").stat().st_size > 10000
