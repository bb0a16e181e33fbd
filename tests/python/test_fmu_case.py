"""`udmap fmu CASE --out NAME.fmu [--fmi 2|3]`: the FMU of a user's case. A matrices blade (blade
A exported to Matrix Market with its stress rows) with a measured `table` damper (blade A's
damper tabulated, with delta_M), and blade A itself with other start values of mu and CF: the
FMUs validate, carry the case in resources/, leave out what does not apply, and fmpy's
simulate_fmu over a sequence of inputs equals the command line on the same case to 1e-10, in
model exchange and co-simulation, FMI 2.0 and FMI 3.0."""
from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

from fmu_harness import CASE, FMUS, ROOT, cli, token, write_matrices_table_case

REAL = ["gamma_P", "sigma_a", "f_res", "u_E", "k_re", "k_im"]


def udmap(*args):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
    return subprocess.run([sys.executable, "-m", "udmap", *map(str, args)], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def matrices_table_case(tmp_path_factory):
    return write_matrices_table_case(tmp_path_factory.mktemp("case"))


@pytest.fixture(scope="module")
def beam_case(tmp_path_factory):
    d = tmp_path_factory.mktemp("beam")
    data = json.loads(CASE.read_text())
    data["damper"].update(mu=0.25, CF=1100.0)
    path = d / "beam.json"
    path.write_text(json.dumps(data))
    return path


def make(case, version, tmp_path):
    out = tmp_path / f"{case.stem}-fmi{version}.fmu"
    r = udmap("fmu", case, "--out", out, "--fmi", version)
    assert r.returncode == 0, r.stderr
    return out


def make_valid(case, version, tmp_path):
    """The case FMU, checked by fmpy's validation: (path, model description, variables by
    name)."""
    fmu = make(case, version, tmp_path)
    assert validate_fmu(str(fmu)) == []
    md = read_model_description(str(fmu))
    return fmu, md, {v.name: v for v in md.modelVariables}


def simulate(fmu, fmi_type, rows, names):
    dtype = [("time", float)] + [(n, float) for n in names]
    table, t = [], 0.0
    for values in rows:
        table.append((t, *values))
        t += 0.5
        table.append((t, *values))
    table = np.array(table, dtype=dtype)
    return simulate_fmu(str(fmu), fmi_type=fmi_type, stop_time=t - 1e-9, output_interval=0.25,
                        input=table, output=REAL + ["F_lim", "regime"] + names, validate=True)


def compare(r, references, key_names):
    worst = 0.0
    for row in r:
        key = tuple(float(row[n]) for n in key_names[1:])
        data, points = references[key]
        p = points[float(row["F_E"])]
        for name in REAL:
            if p[name] == 0.0:
                assert row[name] == 0.0
                continue
            err = abs(row[name] - p[name]) / abs(p[name])
            worst = max(worst, err)
            assert err <= 1e-10, (name, key, float(row["F_E"]), row[name], p[name])
        assert abs(row["F_lim"] - data["F_lim"]) <= 1e-10 * data["F_lim"]
        assert int(row["regime"]) == p["regime"]
    return worst


@pytest.mark.parametrize("version", [2, 3])
def test_matrices_blade_with_table_damper(matrices_table_case, version, tmp_path):
    fmu, md, names = make_valid(matrices_table_case, version, tmp_path)
    # a table damper has no mu, CF, stiffnesses or geometry; a matrices blade no beam data
    for gone in ("mu", "CF", "kn_flat", "pitch", "neck_L", "E", "airfoil_elements"):
        assert gone not in names
    assert float(names["zeta"].start) == 0.002 and "F_E" in names and "f_exc" in names
    case_token = md.guid if version == 2 else md.instantiationToken
    assert case_token != token(version)
    with zipfile.ZipFile(fmu) as zf:
        listing = set(zf.namelist())
        doc = zf.read("documentation/index.html").decode()
        assert "matrices blade" in doc and "measured damper table" in doc
    assert {"resources/udmap-case.txt", "resources/K.mtx", "resources/M.mtx",
            "resources/stress_K.mtx"} <= listing
    forces = [0.2, 0.5, 1.5, 3.0, 6.0, 12.0]
    data = cli("backbone", matrices_table_case, "--forces", ",".join(map(repr, forces)))
    references = {(): (data, {p["F_E"]: p for p in data["points"]})}
    worst = 0.0
    for fmi_type in ("ModelExchange", "CoSimulation"):
        r = simulate(fmu, fmi_type, [(F,) for F in forces], ["F_E"])
        worst = max(worst, compare(r, references, ["F_E"]))
        assert {int(x) for x in r["regime"]} >= {0, 1}  # a table knows stuck and slip
    print(f"FMI {version} matrices + table: worst relative difference {worst:.1e}")
    # directional derivatives through fmpy: F_E analytic (the table's PCHIP slope), zeta by a
    # finite difference, against central differences of the outputs
    from fmpy import extract, instantiate_fmu
    unzipped = extract(str(fmu))
    inst = instantiate_fmu(unzipped, md, fmi_type="ModelExchange")
    vr = {n: v.valueReference for n, v in names.items()}
    outs = [vr[n] for n in ("gamma_P", "sigma_a", "f_res", "F_lim")]
    set_real = inst.setReal if version == 2 else inst.setFloat64
    get_real = inst.getReal if version == 2 else inst.getFloat64
    if version == 2:
        inst.setupExperiment(startTime=0.0)
        inst.enterInitializationMode()
    else:
        inst.enterInitializationMode(startTime=0.0)
    inst.exitInitializationMode()
    for F in (0.2, 1.5, 6.0):
        set_real([vr["F_E"]], [F])
        for known, x0 in (("F_E", F), ("zeta", 0.002)):
            d = inst.getDirectionalDerivative(outs, [vr[known]], [1.0])
            h = 1e-5 * x0
            set_real([vr[known]], [x0 + h])
            yp = get_real(outs)
            set_real([vr[known]], [x0 - h])
            ym = get_real(outs)
            set_real([vr[known]], [x0])
            y0 = get_real(outs)
            for a, p_, m_, y in zip(d, yp, ym, y0):
                fd = (p_ - m_) / (2 * h)
                assert abs(a - fd) <= max(1e-5 * abs(fd), 1e-9 * abs(y) / x0), (known, F, a, fd)
    inst.terminate()
    inst.freeInstance()


@pytest.mark.parametrize("version", [2, 3])
def test_beam_case_with_other_starts(beam_case, version, tmp_path):
    fmu, md, names = make_valid(beam_case, version, tmp_path)
    assert float(names["mu"].start) == 0.25 and float(names["CF"].start) == 1100.0
    assert len(names) == len(read_model_description(str(FMUS[version])).modelVariables)
    rows = [(F, CF, mu) for CF, mu in ((1100.0, 0.25), (900.0, 0.25), (900.0, 0.3))
            for F in (0.5, 3.0, 12.0)]
    references = {}
    base = json.loads(beam_case.read_text())
    for CF, mu in {(CF, mu) for _, CF, mu in rows}:
        base["damper"].update(CF=CF, mu=mu)
        path = tmp_path / f"c{CF}_{mu}.json"
        path.write_text(json.dumps(base))
        data = cli("backbone", path, "--forces", "0.5,3.0,12.0")
        references[(CF, mu)] = data, {p["F_E"]: p for p in data["points"]}
    worst = 0.0
    for fmi_type in ("ModelExchange", "CoSimulation"):
        r = simulate(fmu, fmi_type, rows, ["F_E", "CF", "mu"])
        worst = max(worst, compare(r, references, ["F_E", "CF", "mu"]))
    print(f"FMI {version} beam case: worst relative difference {worst:.1e}")


def test_bad_requests(matrices_table_case, tmp_path):
    r = udmap("fmu", matrices_table_case, "--out", tmp_path / "x.zip")
    assert r.returncode == 2 and "--out" in r.stderr
    r = udmap("fmu", tmp_path / "missing.json", "--out", tmp_path / "x.fmu")
    assert r.returncode == 2
    assert not (tmp_path / "x.fmu").exists()
    assert not list(tmp_path.glob(".udmap-fmu-*"))


@pytest.mark.parametrize("version", [2, 3])
def test_resources_are_checked_at_instantiation(beam_case, version, tmp_path):
    """The binary refuses the generic token for a case FMU, and a damaged case file, with a
    message that names the file and line; the unchanged FMU instantiates."""
    import ctypes
    from fmpy import extract
    fmu = make(beam_case, version, tmp_path)
    md = read_model_description(str(fmu))
    good = md.guid if version == 2 else md.instantiationToken
    d = Path(extract(str(fmu)))
    platform = "linux64" if version == 2 else "x86_64-linux"
    dll = ctypes.CDLL(str(d / "binaries" / platform / "udmap.so"))
    messages = []
    if version == 2:
        logger_t = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int,
                                    ctypes.c_char_p, ctypes.c_char_p)
        logger = logger_t(lambda e, n, s, c, m: messages.append(m.decode()))
        callbacks = (ctypes.c_void_p * 5)(ctypes.cast(logger, ctypes.c_void_p), None, None,
                                         None, None)
        f = dll.fmi2Instantiate
        f.restype = ctypes.c_void_p
        f.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p,
                      ctypes.c_void_p, ctypes.c_int, ctypes.c_int]
        location = (d / "resources").as_uri().encode()

        def instantiate(tok):
            return f(b"x", 0, tok.encode(), location, callbacks, 0, 0)
        free = dll.fmi2FreeInstance
    else:
        logger_t = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p,
                                    ctypes.c_char_p)
        logger = logger_t(lambda e, s, c, m: messages.append(m.decode()))
        f = dll.fmi3InstantiateModelExchange
        f.restype = ctypes.c_void_p
        f.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_bool,
                      ctypes.c_bool, ctypes.c_void_p, logger_t]
        location = (str(d / "resources") + "/").encode()

        def instantiate(tok):
            return f(b"x", tok.encode(), location, False, False, None, logger)
        free = dll.fmi3FreeInstance
    free.argtypes = [ctypes.c_void_p]
    c = instantiate(good)
    assert c, messages
    free(c)
    assert not instantiate(token(version))
    assert "does not match this FMU's" in messages[-1]
    case_file = d / "resources" / "udmap-case.txt"
    text = case_file.read_text()
    case_file.write_text(text.replace("damper asymmetric", "damper sponge"))
    assert not instantiate(good)
    assert "udmap-case.txt, line" in messages[-1] and "damper kind" in messages[-1]
    case_file.write_text(text)


def test_out_is_not_overwritten_without_force_and_follows_the_umask(matrices_table_case,
                                                                     tmp_path):
    out = tmp_path / "x.fmu"
    out.write_bytes(b"someone's file")
    r = udmap("fmu", matrices_table_case, "--out", out)
    assert r.returncode == 2 and "pass --force" in r.stderr and r.stdout == ""
    assert out.read_bytes() == b"someone's file"
    old = os.umask(0o022)
    try:
        r = udmap("fmu", matrices_table_case, "--out", out, "--force")
    finally:
        os.umask(old)
    assert r.returncode == 0, r.stderr
    assert zipfile.is_zipfile(out)
    assert stat.S_IMODE(out.stat().st_mode) == 0o644          # not 0600: colleagues can read it
    assert not list(tmp_path.glob(".udmap-fmu-*"))
