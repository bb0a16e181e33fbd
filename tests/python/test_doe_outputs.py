"""Design of experiments, issue 22: the outputs chosen by --outputs (the kernel computes only the
stages they need, the values equal the default run's), one kernel call per chunk
(udmap_model_designs, bit for bit the single calls), the vectorised writer (the bytes of the
row-by-row one), --format parquet (Parquet alone, the CSV's values), and designs that share a
tracing (CF and stiffness_scale, PHYSICS.md 2.3: the scaling laws, the trace count)."""
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq  # installed by make deps (PY_PACKAGES)
import pytest

from udmap.case import build_blade, build_damper, build_model, load_case
from udmap.damper import Damper
from udmap.doe import (OUTPUTS, ChunkRows, Output, columns, design_values, format_chunk,
                       format_rows, make_spec, parse_forces, parse_vary, read_csv, run_chunk,
                       run_doe, unit_sample, with_values)
from udmap.errors import InputError
from udmap.doe.worker import _AsymmetricBlocks
from udmap.model import DesignBatch

ROOT = Path(__file__).resolve().parents[2]
CASE = load_case(ROOT / "cases" / "blade_a.json")
FORCES = "1,3,6"
VARY = ["mu=0.15:0.6", "CF=500:1500"]  # above mu ~ 0.35 contacts lift off: jumps of k


def _read(path):
    """The rows of a doe CSV as dicts."""
    header, rows = read_csv(path)
    return [dict(zip(header, r)) for r in rows]


@pytest.fixture(scope="module")
def default_run(tmp_path_factory):
    """32 designs with every output (blade A, mu and CF, three forces)."""
    out = tmp_path_factory.mktemp("outputs") / "all.csv"
    return out, run_doe(CASE, VARY, 32, out, forces=FORCES, workers=1, progress=False)


@pytest.mark.parametrize("outputs", ["F_adm", "F_lim", "F_lim,gamma_b,lift_off",
                                     "sigma_a,jump", "hcf_ok,F_adm,M_min"])
def test_chosen_outputs_are_the_default_runs_columns(default_run, tmp_path, outputs):
    out = tmp_path / "some.csv"
    summary = run_doe(CASE, VARY, 32, out, forces=FORCES, workers=1, progress=False,
                      outputs=outputs)
    chosen = outputs.split(",")
    header = next(csv.reader(open(out)))
    expect = ["design", "mu", "CF"] + [c for c in OUTPUTS[:6] if c in chosen]
    for label in FORCES.split(","):
        expect += [f"{f}@{label}" for f in OUTPUTS[6:11] if f in chosen]
    expect += (["F_adm"] if "F_adm" in chosen else []) + ["status", "message"]
    assert header == expect
    full = _read(default_run[0])
    some = _read(out)
    assert [r["status"] for r in some] == ["ok"] * 32
    lifted = 0
    for a, b in zip(full, some):
        for c in header:
            assert b[c] == a[c], (c, a[c], b[c])  # the same text: the same doubles
        lifted += a["lift_off"] == "true"
    assert 0 < lifted < 32
    assert summary["traces"] == 32


def test_unknown_output_exit_2_names_it_and_the_valid_ones(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
    r = subprocess.run([sys.executable, "-m", "udmap", "doe", "cases/blade_a.json", "--vary",
                        "mu=0.1:0.5", "--samples", "4", "--outputs", "F_adm,gamma_p",
                        "--out", str(tmp_path / "o.csv")], cwd=ROOT, env=env,
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert "'gamma_p'" in r.stderr and "valid: " + ", ".join(OUTPUTS) in r.stderr
    assert list(tmp_path.iterdir()) == []


def test_vectorised_writer_writes_the_row_writers_bytes():
    params = parse_vary(CASE, ["mu=0.1:0.5", "airfoil.elements=10:30"])
    spec = make_spec(CASE, params, [1.0, 2.5], ["1", "2.5"], 6, "sobol", 0)
    rng = np.random.default_rng(3)
    n, nf = 6, 2
    rows = ChunkRows(n, nf)
    values = [(float(rng.uniform(0.1, 0.5)), int(2 * rng.integers(5, 15))) for _ in range(n)]
    for k in rows.num:
        rows.num[k][:] = rng.lognormal(size=n) * 10.0 ** rng.integers(-9, 9, size=n)
    for k in rows.force:
        rows.force[k][:] = rng.lognormal(size=(n, nf)) * 1e-4
    rows.lift_off[:] = rng.integers(0, 2, size=n)
    for k in rows.flags:
        rows.flags[k][:] = rng.integers(0, 2, size=(n, nf))
    # design 1 failed at its damper, 2 at F_adm, 3 has an unbounded point, 4 odd numbers
    rows.num["F_lim"][1] = rows.num["F_adm"][1] = np.nan
    rows.lift_off[1] = -1
    for k in rows.force:
        rows.force[k][1] = np.nan
    rows.flags["hcf_ok"][1] = rows.flags["jump"][1] = -1
    rows.status[1], rows.message[1] = "physics", 'jammed, "mu" = 2\nsecond line'
    rows.num["F_adm"][2] = np.nan
    rows.status[2], rows.message[2] = "numeric", "F_adm: no convergence"
    rows.force["gamma_P"][3, 1] = rows.force["f_res"][3, 1] = np.nan
    rows.message[3] = "F_E = 2.5 N: unbounded (zeta = 0, ...)"
    rows.num["M_min"][4], rows.num["gamma_b"][4] = -0.0, 1e16
    rows.num["M_max"][4] = np.inf
    dicts = []
    for i in range(n):
        d = {k: (None if np.isnan(v[i]) else float(v[i])) for k, v in rows.num.items()}
        d["lift_off"] = None if rows.lift_off[i] < 0 else bool(rows.lift_off[i])
        if rows.flags["hcf_ok"][i, 0] >= 0:
            for k, v in rows.force.items():
                d[k] = [None if np.isnan(x) else float(x) for x in v[i]]
            d["hcf_ok"] = [bool(x) for x in rows.flags["hcf_ok"][i]]
            d["jump"] = [bool(x) for x in rows.flags["jump"][i]]
        d["status"], d["message"] = rows.status[i], rows.message[i]
        dicts.append(d)
    text, counts = format_chunk(spec, 40, values, rows)
    expect, expect_counts = format_rows(spec, 40, values, dicts)
    assert text == expect
    assert counts == expect_counts
    parsed = list(csv.reader(text.splitlines()))
    assert len(parsed) == n and {len(r) for r in parsed} == {len(columns(spec))}
    assert parsed[1][-1] == 'jammed, "mu" = 2 second line'
    assert parsed[4][5:8] == ["1e+16", "", "-0.0"]


def test_parquet_alone_holds_the_csvs_values(default_run, tmp_path):
    out = tmp_path / "run.parquet"
    run_doe(CASE, VARY, 32, out, forces=FORCES, workers=2, chunk=5, progress=False,
            format="parquet")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.parquet", "run.parquet.meta.json"]
    table = pq.read_table(out).to_pydict()
    rows = _read(default_run[0])
    assert list(table) == list(rows[0])
    for i, r in enumerate(rows):
        for c, v in r.items():
            got = table[c][i]
            if isinstance(got, bool):
                assert got == (v == "true")
            elif isinstance(got, float):
                assert got == float(v), c
            else:
                assert str(got) == v, c
    meta = json.loads((tmp_path / "run.parquet.meta.json").read_text())
    assert meta["traces"] == 32


def test_parquet_alone_resumes_from_its_staged_batches(tmp_path):
    """Parquet alone stages every finished chunk at once, whatever its order: a run cut after
    chunks 3, 5, 6 and 0 of 8 (and in the middle of a frame) resumes from them and writes the
    file of the uninterrupted run; staged batches of another run are refused."""
    full = tmp_path / "full.parquet"
    run_doe(CASE, VARY, 40, full, forces=FORCES, workers=1, chunk=5, progress=False,
            format="parquet")
    params = parse_vary(CASE, VARY)
    values = design_values(params, unit_sample("sobol", 40, len(params), 0))
    spec = make_spec(CASE, params, *parse_forces(FORCES), 40, "sobol", 0, None)
    spec["rows"] = "arrow"
    cut = tmp_path / "cut.parquet"
    staged = tmp_path / "cut.parquet.rows.arrow"
    o = Output(cut, spec, values, format="parquet")
    assert o.open() == 0
    for k in (3, 5, 6, 0):
        start, n, payload, _ = run_chunk(spec, 5 * k, values[5 * k:5 * k + 5])
        o.put(start, n, payload)
    o.close()  # the interruption
    assert o.written == 20 and staged.exists() and not cut.exists()
    with open(staged, "ab") as f:
        f.write(b"#batch 35 5 999\n\xff\xfe")
    summary = run_doe(CASE, VARY, 40, cut, forces=FORCES, workers=1, chunk=5, progress=False,
                      format="parquet", resume=True)
    assert (summary["resumed_at"], summary["recovered"], summary["computed"]) == (5, 15, 20)
    assert pq.read_table(cut).equals(pq.read_table(full))
    assert pq.read_table(cut).schema.equals(pq.read_table(full).schema, check_metadata=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "cut.parquet", "cut.parquet.meta.json", "full.parquet", "full.parquet.meta.json"]
    # a staged batch whose designs have other parameter values belongs to another run
    o = Output(cut, spec, values, format="parquet")
    o.open(overwrite=True)
    _, n, payload, _ = run_chunk(spec, 10, values[:5])  # designs 10..14 with 0..4's values
    o.put(10, n, payload)
    o.close()
    with pytest.raises(InputError, match="holds designs 10..14 of another run"):
        run_doe(CASE, VARY, 40, cut, forces=FORCES, workers=1, chunk=5, progress=False,
                format="parquet", resume=True)


def _blocks(vary, values):
    params = parse_vary(CASE, vary)
    return _AsymmetricBlocks(CASE.damper, [p.path for p in params]).blocks(values)


def _model():
    model = build_model(CASE, build_blade(CASE), Damper.jenkins(1.0, 1e-3))
    model.backbone_curve([1e-4])
    return model


def test_one_call_per_chunk_equals_the_single_calls_bit_for_bit():
    forces = [1.0, 3.0, 6.0]
    values = [(0.2, 700.0), (0.3, 900.0), (0.45, 1100.0), (0.55, 800.0), (3.0, 900.0)]
    blocks = _blocks(["mu=0.1:3", "CF=500:1500"], values)
    model = _model()
    batch = DesignBatch(forces)
    r = batch.run(model, 31, blocks)
    assert r["traces"] == 5 and list(r["status"]) == [0, 0, 0, 0, 3]
    assert r["stage"][4] == 1 and "jams" in batch.message(4)
    for i, (mu, CF) in enumerate(values[:4]):
        case = with_values(CASE, [("damper", "mu"), ("damper", "CF")], [mu, CF])
        damper = build_damper(case)
        model.set_damper(damper)
        info = damper.info()
        F_lim, F_bb = model.limit_force(), model.limit_force_backbone()
        points = model.backbone(forces)
        F_adm = model.admissible_force(min(F_lim, F_bb), 80e6, rtol=1e-12)
        assert (r["gamma_b"][i], r["M_max"][i], r["lift_off"][i]) == \
            (info.gamma_b, info.M_max, info.lift_off)
        assert (r["F_lim"][i], r["F_lim_backbone"][i], r["F_adm"][i]) == (F_lim, F_bb, F_adm)
        for j, p in enumerate(points):
            assert (r["gamma_P"][i, j], r["f_res"][i, j], r["sigma_a"][i, j]) == \
                (p["gamma_P"], p["f_res"], p["sigma_a"])
            assert (r["hcf_ok"][i, j], r["jump"][i, j]) == (p["hcf_ok"], p["jump"])
    assert r["lift_off"][2:4].all() and not r["lift_off"][:2].any()


def test_scaling_laws_of_a_shared_tracing():
    """PHYSICS.md 2.3: with CF times lambda and every contact stiffness times kappa, the
    rescaled tracing of the nominal damper gives what tracing the damper itself gives."""
    forces = [1.0, 3.0, 6.0]
    vary = ["CF=500:1500", "stiffness_scale=0.25:4", "mu=0.1:0.6"]
    values = [(900.0, 1.0, 0.3), (1350.0, 1.0, 0.3), (600.0, 2.5, 0.3), (1200.0, 0.4, 0.3),
              (900.0, 1.0, 0.5), (700.0, 3.0, 0.5)]
    blocks = _blocks(vary, values)
    reference = blocks.copy()
    reference[:4] = blocks[0]
    reference[4:] = blocks[4]
    batch = DesignBatch(forces)
    shared = {k: np.array(v) for k, v in batch.run(_model(), 31, blocks, reference).items()}
    assert shared["traces"] == 2
    own = batch.run(_model(), 31, blocks)
    assert own["traces"] == 6
    assert (shared["status"] == 0).all() and (own["status"] == 0).all()
    for k in ("F_lim", "gamma_b", "M_max", "M_min", "F_lim_backbone"):
        np.testing.assert_allclose(shared[k], own[k], rtol=1e-12, err_msg=k)
    for k in ("gamma_P", "f_res", "sigma_a", "F_adm"):
        np.testing.assert_allclose(shared[k], own[k], rtol=1e-9, err_msg=k)
    # the references themselves: their own tracing, bit for bit
    for k in ("F_lim", "gamma_P", "F_adm"):
        assert (shared[k][[0, 4]] == own[k][[0, 4]]).all()
    # the laws: gamma_b scales with CF/kappa, the plateau moments with CF
    assert shared["gamma_b"][2] == pytest.approx(shared["gamma_b"][0] * (600 / 900) / 2.5,
                                                 rel=1e-14)
    assert shared["M_max"][3] == pytest.approx(shared["M_max"][0] * 1200 / 900, rel=1e-14)
    bad = reference.copy()
    bad[1, 13] *= 1.01  # kt_flat alone: not a common factor
    r = batch.run(_model(), 1, blocks, bad)
    assert r["status"][1] == 2 and "common factor" in batch.message(1)


def test_runs_count_their_tracings(tmp_path):
    # CF and the stiffness factor alone: the nominal damper's tracing serves every design
    out = tmp_path / "k.csv"
    s = run_doe(CASE, ["CF=600:1200", "stiffness_scale=0.5:2"], 64, out, forces="2",
                workers=1, progress=False)
    assert s["traces"] == 1 and s["status"] == {"ok": 64}
    assert json.loads((tmp_path / "k.csv.meta.json").read_text())["traces"] == 1
    # a grid over mu and CF (CF fastest): one tracing per mu, the others rescaled
    out = tmp_path / "g.csv"
    s = run_doe(CASE, ["mu=0.2:0.3", "CF=600:1200"], 16, out, forces="2", method="grid",
                workers=1, progress=False)
    assert s["traces"] == 4 and s["status"] == {"ok": 16}
    # split across two workers and small chunks, each worker traces what it needs
    out2 = tmp_path / "g2.csv"
    s2 = run_doe(CASE, ["mu=0.2:0.3", "CF=600:1200"], 16, out2, forces="2", method="grid",
                 workers=2, chunk=3, progress=False)
    assert out2.read_bytes() == out.read_bytes()
    assert 4 <= s2["traces"] <= 8
    # Sobol over mu and CF: every design its own tracing, as before
    s = run_doe(CASE, VARY, 8, tmp_path / "s.csv", forces="2", workers=1, progress=False)
    assert s["traces"] == 8


@pytest.mark.parametrize("options,needle", [
    ({"outputs": "F_lim"}, "--plot needs the outputs F_adm and hcf_ok"),
    ({"format": "parquet"}, "--plot reads the CSV"),
    ({"format": "feather"}, "--format must be one of csv, parquet"),
    ({"outputs": ""}, "--outputs: expected at least one of F_lim"),
])
def test_options_that_cannot_go_together_stop_before_anything_is_written(tmp_path, options,
                                                                         needle):
    options.setdefault("plot", "format" not in options or options["format"] == "parquet")
    with pytest.raises(InputError, match=needle.replace("(", r"\(")):
        run_doe(CASE, ["mu=0.2:0.3"], 4, tmp_path / "x.csv", forces="2", workers=1,
                progress=False, **options)
    assert list(tmp_path.iterdir()) == []


def test_stiffness_scale_multiplies_the_four_contact_stiffnesses_and_is_validated():
    from udmap.errors import InputError
    (p,) = parse_vary(CASE, ["stiffness_scale=0.5:2"])
    assert p.path == ("damper", "stiffness_scale") and p.integer == 0
    case = with_values(CASE, [("damper", "kn_flat"), p.path], [1e8, 3.0])
    d = case.damper
    assert (d["kn_flat"], d["kt_flat"], d["kn_curved"], d["kt_curved"]) == \
        (3e8, 3 * 40e6, 3 * 80e6, 3 * 50e6)
    assert CASE.damper["kn_flat"] == 60e6  # the case itself unchanged
    with pytest.raises(InputError, match=r"--vary stiffness_scale=0.0:2.0: .*kn_flat"):
        parse_vary(CASE, [("stiffness_scale", 0.0, 2.0)])
