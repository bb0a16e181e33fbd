"""Design of experiments, the parts before and after the kernel: parameter names and ranges on the
case, sampling, the admissible-force solver, the output format, and resuming a cut file."""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import qmc

from udmap import InputError
from udmap.case import load_case, validate
from udmap import doe
from udmap.doe import layout as doe_layout
from udmap.doe import io as doe_io

ROOT = Path(__file__).resolve().parents[2]
CASE = load_case(ROOT / "cases" / "blade_a.json")


# ------------------------------------------------------------------------------ names

@pytest.mark.parametrize("name,path", [
    ("mu", ("damper", "mu")), ("CF", ("damper", "CF")), ("kt_flat", ("damper", "kt_flat")),
    ("beta_L_deg", ("damper", "beta_L_deg")), ("y_P", ("damper", "y_P")),
    ("neck_L", ("blade", "neck", "L")), ("platform_m", ("blade", "platform", "m")),
    ("airfoil_elements", ("blade", "airfoil", "elements")), ("E", ("blade", "E")),
    ("rho", ("blade", "rho")), ("zeta", ("blade", "zeta")),
    ("flat1_x", ("damper", "flat_points", 0, 0)), ("flat2_y", ("damper", "flat_points", 1, 1)),
    ("curved_x", ("damper", "curved_point", 0)), ("curved_y", ("damper", "curved_point", 1)),
    ("f_min", ("analysis", "f_min")), ("f_max", ("analysis", "f_max")),
    ("sigma_all", ("analysis", "sigma_all")),
    ("airfoil.h", ("blade", "airfoil", "h")), ("blade.airfoil.h", ("blade", "airfoil", "h")),
    ("damper.mu", ("damper", "mu")), ("damper.flat_points[1][0]", ("damper", "flat_points", 1, 0)),
    ("flat_points.0.1", ("damper", "flat_points", 0, 1)),
])
def test_names_resolve_to_case_paths(name, path):
    assert doe.resolve_name(CASE, name) == path


def test_every_fmu_parameter_name_is_known():
    fmu = ("neck_L neck_h neck_b platform_L platform_m platform_J airfoil_L airfoil_h airfoil_b "
           "neck_elements airfoil_elements E rho zeta pitch y_P beta_L_deg beta_R_deg flat1_x "
           "flat1_y flat2_x flat2_y curved_x curved_y f_min f_max sigma_all mu CF kn_flat "
           "kt_flat kn_curved kt_curved").split()
    names = doe.parameter_names(CASE)
    assert [n for n in fmu if n not in names] == []


def test_jenkins_damper_names():
    data = CASE.to_dict()
    data["damper"] = {"kind": "jenkins", "kt": 2.0, "M_slip": 3.0}
    case = validate(data)
    assert doe.resolve_name(case, "M_slip") == ("damper", "M_slip")
    assert doe.resolve_name(case, "kt") == ("damper", "kt")
    with pytest.raises(InputError, match="--vary mu: not a parameter of this case"):
        doe.resolve_name(case, "mu")


def test_unknown_name_is_named_with_the_known_ones():
    with pytest.raises(InputError) as info:
        doe.resolve_name(CASE, "mux")
    assert "--vary mux: not a parameter" in str(info.value)
    assert "kt_flat" in str(info.value)


def test_values_change_only_the_named_leaf():
    paths = [("damper", "flat_points", 1, 0), ("blade", "airfoil", "h"), ("analysis", "f_max")]
    new = doe.with_values(CASE, paths, [-1e-3, 5e-3, 240.0])
    assert new.damper["flat_points"] == [CASE.damper["flat_points"][0], [-1e-3, 3.932e-3]]
    assert new.blade["airfoil"]["h"] == 5e-3 and new.analysis["f_max"] == 240.0
    # the nominal case is untouched
    assert CASE.damper["flat_points"][1] == [-1.068e-3, 3.932e-3]
    assert CASE.blade["airfoil"]["h"] == 0.004 and CASE.analysis["f_max"] == 230.0
    ref = CASE.to_dict()
    ref["damper"]["flat_points"][1][0] = -1e-3
    ref["blade"]["airfoil"]["h"] = 5e-3
    ref["analysis"]["f_max"] = 240.0
    got = new.to_dict()
    assert got == ref


# ------------------------------------------------------------------------------ ranges

def test_vary_parses_lists_tuples_and_log():
    ps = doe.parse_vary(CASE, ["mu=0.1:0.6,CF=500:1500", "kt_flat=1e7:1e8:log"])
    assert [(p.name, p.path, p.lo, p.hi, p.scale) for p in ps] == [
        ("mu", ("damper", "mu"), 0.1, 0.6, "linear"), ("CF", ("damper", "CF"), 500, 1500, "linear"),
        ("kt_flat", ("damper", "kt_flat"), 1e7, 1e8, "log")]
    assert doe.parse_vary(CASE, [("airfoil.h", 3e-3, 5e-3)])[0].path == ("blade", "airfoil", "h")


@pytest.mark.parametrize("vary,needle", [
    ("mu=-0.1:0.6", "--vary mu=-0.1:0.6: damper.mu must be in [0.0001, 10], got -0.1"),
    ("beta_L_deg=30:95", "damper.beta_L_deg must be in (0, 90) deg, got 95"),
    ("neck_h=0:0.01", "blade.neck.h must be in [1e-5, 1] m, got 0"),
    ("zeta=-1:0.1", "blade.zeta must be in [0, 0.5], got -1"),
    ("f_min=100:300", "analysis.f_max (230.0) must exceed analysis.f_min (300.0)"),
    ("mu=0.6:0.1", "--vary mu=0.6:0.1: LO must be below HI"),
    ("mu=0.1", "expected NAME=LO:HI"),
    ("mu=a:b", "LO and HI must be numbers"),
    ("mu=0.1:inf", "LO and HI must be finite"),
    ("y_P=-1e-3:1e-3:log", "a log range needs LO > 0"),
    ("mu=0.1:0.2:cubic", "the scale must be 'log'"),
    ("mu=0.1:0.2,damper.mu=0.2:0.3", "the same parameter as mu"),
    ("nosuch=1:2", "--vary nosuch: not a parameter"),
])
def test_bad_ranges_are_named(vary, needle):
    with pytest.raises(InputError) as info:
        doe.parse_vary(CASE, [vary])
    assert needle in str(info.value)


def test_integer_parameters_are_rounded_airfoil_elements_even():
    p_neck, p_air = doe.parse_vary(CASE, ["neck_elements=2:9", "airfoil_elements=3:41"])
    assert (p_neck.integer, p_air.integer) == (1, 2)
    assert [p_neck.cast(x) for x in (2.0, 2.49, 2.51, 9.0)] == [2, 2, 3, 9]
    assert [p_air.cast(x) for x in (3.0, 4.9, 5.1, 41.0)] == [4, 4, 6, 40]
    values = doe.design_values([p_neck, p_air], doe.unit_sample("lhs", 64, 2, 1))
    assert all(isinstance(a, int) and isinstance(b, int) and b % 2 == 0 for a, b in values)
    assert all(2 <= a <= 9 and 4 <= b <= 40 for a, b in values)


# ------------------------------------------------------------------------------ sampling

def _strata_counts(u, n):
    return [np.bincount(np.floor(u[:, j] * n).astype(int), minlength=n) for j in range(u.shape[1])]


def test_sobol_is_scipy_scrambled_sobol_and_a_net():
    u = doe.unit_sample("sobol", 32, 2, seed=7)
    assert np.array_equal(u, qmc.Sobol(2, rng=7).random(32))
    # first 2^m points of a (scrambled) Sobol sequence in 2D: one point per 1/32 stratum
    # per axis, and per each of the 4 x 8 elementary boxes
    assert all((c == 1).all() for c in _strata_counts(u, 32))
    box = np.floor(u[:, 0] * 4).astype(int) * 8 + np.floor(u[:, 1] * 8).astype(int)
    assert (np.bincount(box, minlength=32) == 1).all()
    assert not np.array_equal(u, doe.unit_sample("sobol", 32, 2, seed=8))


def test_lhs_one_point_per_stratum_and_seeded():
    u = doe.unit_sample("lhs", 50, 3, seed=3)
    assert u.shape == (50, 3)
    assert all((c == 1).all() for c in _strata_counts(u, 50))
    assert np.array_equal(u, doe.unit_sample("lhs", 50, 3, seed=3))


def test_grid_full_factorial_last_parameter_fastest():
    u = doe.unit_sample("grid", 12 ** 2, 2, seed=0)
    assert u.shape == (144, 2)
    assert np.allclose(u[:12, 0], 0.0) and np.allclose(u[:12, 1], np.linspace(0, 1, 12))
    with pytest.raises(InputError, match="needs k\\^3 designs \\(e.g. 27 or 64\\)"):
        doe.unit_sample("grid", 30, 3, seed=0)


def test_design_values_scales():
    ps = doe.parse_vary(CASE, ["mu=0.1:0.5,kt_flat=1e6:1e8:log"])
    u = np.array([[0.0, 0.0], [0.5, 0.5], [1.0, 1.0]])
    vals = doe.design_values(ps, u)
    assert vals[0] == (0.1, 1e6)
    assert vals[1][0] == pytest.approx(0.3, rel=1e-15)
    assert vals[1][1] == pytest.approx(1e7, rel=1e-13)
    assert vals[2] == (0.5, pytest.approx(1e8, rel=1e-13))


# ------------------------------------------------------------------------------ F_adm

# the search itself is checked on known stresses in tests/fortran/test_admissible.f90; the
# Python side keeps the grid (for the messages) equal to the kernel's


def test_admissible_grid_is_geometric_and_ends_at_the_half_limit():
    g = doe.admissible_grid(7.5)
    assert len(g) == doe.ADM_GRID and g[-1] == 7.5
    assert g[0] == pytest.approx(7.5 * 10 ** -doe.ADM_DECADES, rel=1e-14)
    assert np.allclose(g[1:] / g[:-1], 10 ** (doe.ADM_DECADES / (doe.ADM_GRID - 1)), rtol=1e-14)


# ------------------------------------------------------------------------------ output

def _spec(labels=("1", "2.5")):
    params = doe.parse_vary(CASE, ["mu=0.1:0.6,neck_elements=2:9"])
    return doe.make_spec(CASE, params, [float(x) for x in labels], list(labels), 40, "sobol", 0)


def test_columns_follow_the_interface():
    assert doe_layout.columns(_spec()) == [
        "design", "mu", "neck_elements", "F_lim", "F_lim_backbone", "gamma_b", "M_max",
        "M_min", "lift_off", "gamma_P@1", "f_res@1", "sigma_a@1", "hcf_ok@1", "jump@1",
        "gamma_P@2.5", "f_res@2.5", "sigma_a@2.5", "hcf_ok@2.5", "jump@2.5", "F_adm",
        "status", "message"]
    assert doe.parse_forces("2, 5.50,10") == ([2.0, 5.5, 10.0], ["2", "5.50", "10"])
    with pytest.raises(InputError, match="--forces: 2 is given twice"):
        doe.parse_forces("2,2")
    with pytest.raises(InputError, match="positive finite"):
        doe.parse_forces("1,-2")


def test_cells_round_trip_exactly():
    x = 0.1 + 0.2
    assert float(doe_layout.cell(x)) == x and doe_layout.cell(x) == "0.30000000000000004"
    assert doe_layout.cell(True) == "true" and doe_layout.cell(np.bool_(False)) == "false"
    assert doe_layout.cell(float("nan")) == "" and doe_layout.cell(None) == ""
    assert doe_layout.cell(np.float64(2.5)) == "2.5" and doe_layout.cell(7) == "7"
    assert doe_layout.cell("two\nlines") == "two lines"


def _fake_rows(spec, values, start):
    rows = []
    for i, (mu, n) in enumerate(values):
        d = start + i
        if d % 7 == 3:
            rows.append({"status": "physics", "message": f"jammed, design {d}, \"quoted\""})
            continue
        forces = (1.0, 2.5)
        rows.append({"status": "ok", "message": "", "F_lim": 10 * mu, "gamma_b": 1e-4 * mu,
                     "M_max": mu, "M_min": -mu, "lift_off": d % 2 == 0, "F_adm": 4 * mu,
                     "gamma_P": [1e-5 * F for F in forces], "f_res": [180.0 + F for F in forces],
                     "sigma_a": [1e7 * F for F in forces], "hcf_ok": [F < 2 for F in forces]})
    return rows


def _spec_and_values():
    """The run of _spec, the values of its 40 Sobol designs over mu and neck_elements, and
    those parameters."""
    ps = doe.parse_vary(CASE, ["mu=0.1:0.6,neck_elements=2:9"])
    return _spec(), doe.design_values(ps, doe.unit_sample("sobol", 40, 2, 0)), ps


def _write(out, spec, values, chunk, resume=False, order=None, force=False):
    o = doe_io.Output(out, spec, values)
    first = o.open(resume=resume, overwrite=force)
    chunks = [(s, values[s:s + chunk]) for s in range(first, len(values), chunk)]
    for s, v in (chunks if order is None else [chunks[i] for i in order(len(chunks))]):
        text, _ = doe_io.format_rows(spec, s, v, _fake_rows(spec, v, s))
        o.put(s, len(v), text)
    o.close()
    return first, o


def test_chunks_written_in_design_order_whatever_the_completion_order(tmp_path):
    spec = _spec()
    values = doe.design_values([doe.parse_vary(CASE, ["mu=0.1:0.6"])[0],
                                doe.parse_vary(CASE, ["neck_elements=2:9"])[0]],
                               doe.unit_sample("sobol", 40, 2, 0))
    _write(tmp_path / "a.csv", spec, values, 6)
    _write(tmp_path / "b.csv", spec, values, 6, order=lambda n: list(range(n))[::-1])
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()
    header, rows = doe_io.read_csv(tmp_path / "a.csv")
    assert header == doe_layout.columns(spec) and len(rows) == 40
    assert [int(r[0]) for r in rows] == list(range(40))
    assert rows[3][-2:] == ["physics", 'jammed, design 3, "quoted"']
    assert float(rows[0][1]) == values[0][0] and int(rows[0][2]) == values[0][1]


def test_resume_after_a_cut_at_any_byte_gives_the_same_file(tmp_path):
    spec, values, _ = _spec_and_values()
    full = tmp_path / "full.csv"
    _write(full, spec, values, 5)
    data = full.read_bytes()
    header_len = data.index(b"\n") + 1
    line_ends = [i + 1 for i, b in enumerate(data) if b == ord("\n")]
    cut_file = tmp_path / "cut.csv"
    meta = (tmp_path / "full.csv.meta.json").read_text()
    for cut in sorted(set(range(header_len, len(data), 97)) | {header_len, len(data) - 1,
                                                                len(data)}):
        cut_file.write_bytes(data[:cut])
        (tmp_path / "cut.csv.meta.json").write_text(meta)
        first, out = _write(cut_file, spec, values, 5, resume=True)
        complete = sum(1 for e in line_ends if e <= cut) - 1  # lines after the header
        assert first == complete, cut
        assert cut_file.read_bytes() == data, cut
        assert out.written == 40
    # the counts of a resumed file include the rows found in it
    cut_file.write_bytes(data[:line_ends[10]])  # the header and 10 rows
    first, out = _write(cut_file, spec, values, 5, resume=True)
    assert first == 10 and out.counts["physics"] == sum(1 for d in range(10) if d % 7 == 3)


def test_chunks_finished_out_of_order_survive_an_interruption_in_the_journal(tmp_path):
    # chunks 0..7 of 5 designs; 3, 5, 6 finish early (held in memory and in the journal),
    # then the run dies: a resumed run recovers them, computes only 0..2, 4, 7 and writes the
    # file an uninterrupted run writes
    from udmap.doe.executors import chunk_ranges
    spec, values, _ = _spec_and_values()
    _write(tmp_path / "full.csv", spec, values, 5)
    out = tmp_path / "cut.csv"
    o = doe_io.Output(out, spec, values)
    o.open()
    for k in (3, 5, 6, 0):
        s = 5 * k
        text, _ = doe_io.format_rows(spec, s, values[s:s + 5], _fake_rows(spec, values[s:s + 5], s))
        o.put(s, 5, text)
    assert o.written == 5 and sorted(o._pending) == [15, 25, 30]
    o.close()  # the interruption: nothing else reaches the disk
    journal = tmp_path / "cut.csv.pending"
    assert journal.exists()
    # a record cut by the interruption at the end of the journal is ignored
    with open(journal, "ab") as f:
        f.write(b"#chunk 35 5 999\n35,0.1")
    r = doe_io.Output(out, spec, values)
    first = r.open(resume=True)
    assert first == 5 and r.held == [(15, 5), (25, 10)]
    todo = chunk_ranges(first, 40, r.held, 5)
    assert todo == [(5, 10), (10, 15), (20, 25), (35, 40)]
    assert r.counts["physics"] == sum(1 for d in list(range(5)) + list(range(15, 20)) +
                                      list(range(25, 35)) if d % 7 == 3)
    for s, e in todo[::-1]:
        text, _ = doe_io.format_rows(spec, s, values[s:e], _fake_rows(spec, values[s:e], s))
        r.put(s, e - s, text)
    r.close()
    assert out.read_bytes() == (tmp_path / "full.csv").read_bytes()
    assert not journal.exists()


def test_chunk_ranges_skip_held_designs():
    from udmap.doe.executors import chunk_ranges
    assert chunk_ranges(0, 10, [], 4) == [(0, 4), (4, 8), (8, 10)]
    assert chunk_ranges(3, 20, [(5, 2), (12, 8)], 4) == [(3, 5), (7, 11), (11, 12)]
    assert chunk_ranges(10, 10, [], 4) == []


def test_resume_refuses_another_run_and_overwrite_needs_force(tmp_path):
    spec, values, ps = _spec_and_values()
    out = tmp_path / "r.csv"
    _write(out, spec, values, 8)
    with pytest.raises(InputError, match="exists: pass --resume"):
        doe_io.Output(out, spec, values).open()
    other = doe.make_spec(CASE, ps, [1.0, 2.5], ["1", "2.5"], 40, "sobol", 1)
    with pytest.raises(InputError, match="different run \\(differs in: seed\\)"):
        doe_io.Output(out, other, values).open(resume=True)
    # a line that does not belong to the run (values of another seed) is detected
    text = out.read_text().splitlines(keepends=True)
    text[5] = text[5].replace(doe_layout.cell(values[4][0]), "0.25", 1)
    out.write_text("".join(text))
    with pytest.raises(InputError, match="line 6 of .* does not belong to this run"):
        doe_io.Output(out, spec, values).open(resume=True)
    first, _ = _write(out, spec, values, 8, force=True)
    assert first == 0 and len(doe_io.read_csv(out)[1]) == 40


def test_parquet_copy_matches_the_csv(tmp_path):
    spec, values, _ = _spec_and_values()
    _, out = _write(tmp_path / "q.csv", spec, values, 8)
    written = out.finish()
    import pyarrow.parquet as pq  # installed by make deps (PY_PACKAGES)
    table = pq.read_table(written).to_pydict()
    header, rows = doe_io.read_csv(tmp_path / "q.csv")
    assert list(table) == header
    assert table["mu"] == [float(r[1]) for r in rows]
    assert table["hcf_ok@1"][0] is (rows[0][header.index("hcf_ok@1")] == "true")
    assert table["status"] == [r[-2] for r in rows]


def test_pareto_front():
    from udmap.doe.plot import pareto_front
    cf = [500, 600, 550, 700, 800, 650, 900]
    fa = [3.0, 2.0, 4.0, 4.0, 6.0, 5.0, 5.5]
    assert pareto_front(cf, fa) == [0, 2, 5, 4]


# ------------------------------------------------------------------------------ command line

def _cli(*args):
    return subprocess.run([sys.executable, "-m", "udmap", *args], capture_output=True,
                          text=True, cwd=ROOT, timeout=60)


@pytest.mark.parametrize("args,needle", [
    (("--vary", "mux=0.1:0.5"), "--vary mux: not a parameter"),
    (("--vary", "mu=0.1:0.5,CF=-1:900"), "--vary CF=-1:900: damper.CF must be in [0.001, 1e6] N, got -1"),
    (("--vary", "airfoil.elements=1:40"), "must be an even integer in [2, 1000], got 0"),
    (("--vary", "mu=0.1:0.5,CF=800:900", "--method", "grid"), "a grid over 2 parameters"),
    (("--vary", "mu=0.1:0.5", "--forces", "1,x"), "--forces: expected comma-separated numbers"),
    (("--vary", "mu=0.1:0.5", "--dask", "somewhere"), "--dask somewhere: expected local:K"),
    (("--vary", "mu=0.1:0.5", "--workers", "0"), "--workers must be at least 1"),
])
def test_cli_bad_input_exit_2_and_nothing_written(tmp_path, args, needle):
    out = tmp_path / "o.csv"
    r = _cli("doe", "cases/blade_a.json", "--samples", "7", "--out", str(out), *args)
    assert r.returncode == 2, r.stderr
    assert needle in r.stderr
    assert list(tmp_path.iterdir()) == []
