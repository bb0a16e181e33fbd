"""fmpy.simulate_fmu over an input table that steps F_E through 0.5..20 N and changes CF and mu
(and the excitation frequency): every recorded output equals the command line's `backbone`
(or `response`) result for the same case to 1e-8 relative, and the FMI 2.0 and FMI 3.0 FMUs
give identical numbers."""
from __future__ import annotations

import math

import numpy as np
import pytest
from fmpy import simulate_fmu

from fmu_harness import FMUS, reference, step_table

FORCES = [0.5, 1.0, 2.0, 3.5, 5.0, 8.0, 12.0, 20.0]
# (CF, mu, f_exc, forces): a CF change alone (rescale), then mu changes, then a frequency
SEGMENTS = ([(900.0, 0.3, 0.0, FORCES)]
            + [(1200.0, 0.3, 0.0, [0.5, 2.0, 5.0, 12.0, 20.0])]
            + [(1200.0, 0.22, 0.0, [0.5, 2.0, 5.0, 12.0, 20.0])]
            + [(700.0, 0.35, 0.0, [0.5, 3.5, 8.0, 20.0])]
            + [(900.0, 0.3, 185.0, [1.0, 5.0, 12.0])])
DURATION = 0.7  # per force level; not a multiple of the output interval: variable steps
OUTPUTS = ["gamma_P", "sigma_a", "F_lim", "f_res", "u_E", "k_re", "k_im", "F_ratio", "hcf_ok",
           "regime", "lift_off"]
INPUTS = ["F_E", "CF", "mu", "f_exc"]


@pytest.fixture(scope="module")
def results():
    table, stop = step_table(SEGMENTS, DURATION)
    out = {}
    for version in (2, 3):
        out[version] = simulate_fmu(str(FMUS[version]), stop_time=stop - 1e-9,
                                    output_interval=0.25, input=table,
                                    output=OUTPUTS + INPUTS, validate=True)
    return out


def test_fmi2_and_fmi3_outputs_are_identical(results):
    r2, r3 = results[2], results[3]
    assert r2.dtype.names == r3.dtype.names
    assert len(r2) == len(r3) and len(r2) > 60
    for name in r2.dtype.names:
        assert np.array_equal(r2[name], r3[name]), name
    # variable communication steps were taken (input events between output points)
    steps = np.diff(r2["time"])
    assert len(set(np.round(steps[steps > 0], 12))) > 2




def close(a, b, rel=1e-8):
    return math.isclose(a, b, rel_tol=rel, abs_tol=0.0) or a == b


def test_outputs_equal_the_command_line(results, tmp_path):
    r = results[2]
    # the exact values the FMU held (fmpy's interpolation of the table may round them)
    groups: dict = {}
    for row in r:
        groups.setdefault((row["CF"], row["mu"], row["f_exc"]), set()).add(float(row["F_E"]))
    assert ({(round(CF, 9), round(mu, 9), round(f, 9)) for CF, mu, f in groups}
            == {(CF, mu, f) for CF, mu, f, _ in SEGMENTS})
    checked = 0
    for (CF, mu, f_exc), forces in groups.items():
        data, points = reference(tmp_path, float(CF), float(mu), float(f_exc), sorted(forces))
        for row in r[(r["CF"] == CF) & (r["mu"] == mu) & (r["f_exc"] == f_exc)]:
            F = float(row["F_E"])
            p = points[F]
            where = f"CF={CF} mu={mu} f_exc={f_exc} F_E={F} t={row['time']}"
            assert close(row["F_lim"], data["F_lim"]), where
            assert bool(row["lift_off"]) == data["lift_off"], where
            assert close(row["F_ratio"], F / data["F_lim"], 1e-15), where
            for key in ("gamma_P", "sigma_a", "f_res", "u_E", "k_re", "k_im"):
                assert close(row[key], p[key]), f"{key}: {row[key]!r} vs {p[key]!r} at {where}"
            assert int(row["regime"]) == p["regime"], where
            assert bool(row["hcf_ok"]) == p["hcf_ok"], where
            checked += 1
    assert checked == len(r)
    # the table went through every regime (stuck to above F_lim) and past the limit force
    assert {int(x) for x in r["regime"]} == {0, 1, 2, 3}
    assert r["F_ratio"].max() > 1.0 and r["F_ratio"].min() < 0.05
