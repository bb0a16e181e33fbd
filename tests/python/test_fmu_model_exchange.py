"""Model exchange: fmpy.simulate_fmu(..., fmi_type='ModelExchange') over a table that steps
F_E, CF, mu (and the excitation frequency). The FMU has no states and no event indicators;
its outputs at every recorded time are the command line's answer for the inputs at that same
time (no communication delay as in co-simulation), to 1e-12 relative, FMI 2.0 and FMI 3.0."""
from __future__ import annotations

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.validation import validate_fmu

from fmu_harness import FMUS, OK, Instance, reference, step_table

SEGMENTS = [(900.0, 0.3, 0.0, [0.2, 0.5, 2.0, 5.0, 12.0, 20.0]),
            (1200.0, 0.3, 0.0, [0.5, 5.0]),
            (1200.0, 0.22, 0.0, [2.0, 8.0]),
            (700.0, 0.35, 0.0, [3.5, 20.0]),
            (900.0, 0.3, 185.0, [1.0, 12.0])]
REAL = ["gamma_P", "sigma_a", "f_res", "u_E", "k_re", "k_im"]
INPUTS = ["F_E", "CF", "mu", "f_exc"]
OUTPUTS = REAL + ["F_lim", "F_ratio", "regime", "hcf_ok", "lift_off"]
DURATION = 0.5


def inputs_at(tab, t):
    """The table's inputs at time t: inside a segment its values; at a step time those before
    and after the step (fmpy records both sides of an input event)."""
    rows = np.nonzero(tab["time"] == t)[0]
    if len(rows) == 0:
        rows = [np.searchsorted(tab["time"], t) - 1]
    return [{k: float(tab[k][i]) for k in INPUTS} for i in rows]


@pytest.fixture(scope="module")
def results():
    tab, stop = step_table(SEGMENTS, DURATION)
    out = {}
    for version in (2, 3):
        out[version] = simulate_fmu(str(FMUS[version]), fmi_type="ModelExchange",
                                    stop_time=stop - 1e-9, output_interval=0.2, input=tab,
                                    output=OUTPUTS + INPUTS, validate=True)
    return tab, out


@pytest.fixture(scope="module")
def references(tmp_path_factory):
    d = tmp_path_factory.mktemp("me")
    refs = {}
    for CF, mu, f_exc, forces in SEGMENTS:
        refs[(CF, mu, f_exc)] = reference(d, CF, mu, f_exc, forces,
                                          name=f"cf{CF}_mu{mu}_f{f_exc}")
    return refs


@pytest.mark.parametrize("version", [2, 3])
def test_validation_reports_nothing(version):
    assert validate_fmu(str(FMUS[version])) == []


@pytest.mark.parametrize("version", [2, 3])
def test_outputs_follow_the_inputs_of_the_same_time(results, references, version):
    tab, out = results
    r = out[version]
    assert len(r) > 50
    worst, checked = 0.0, 0
    for row in r:
        t = float(row["time"])
        u = {k: float(row[k]) for k in INPUTS}
        # model exchange: the recorded inputs are those of the table at the same time
        assert u in inputs_at(tab, t), t
        data, points = references[(u["CF"], u["mu"], u["f_exc"])]
        p = points[u["F_E"]]
        for key in REAL:
            if p[key] == 0.0:
                assert row[key] == 0.0, (key, t)
                continue
            err = abs(row[key] - p[key]) / abs(p[key])
            worst = max(worst, err)
            assert err <= 1e-12, f"{key} at t={t}: {row[key]!r} vs {p[key]!r}"
        assert abs(row["F_lim"] - data["F_lim"]) <= 1e-12 * data["F_lim"], t
        assert row["F_ratio"] == pytest.approx(u["F_E"] / data["F_lim"], rel=1e-12, abs=0.0)
        assert int(row["regime"]) == p["regime"] and bool(row["hcf_ok"]) == p["hcf_ok"], t
        assert bool(row["lift_off"]) == data["lift_off"], t
        checked += 1
    assert checked == len(r)
    print(f"FMI {version} model exchange: {checked} rows, worst relative difference {worst:.1e}")
    assert {int(x) for x in r["regime"]} == {0, 1, 2, 3}


def test_fmi2_and_fmi3_agree(results):
    _, out = results
    for name in out[2].dtype.names:
        assert np.array_equal(out[2][name], out[3][name]), name


@pytest.mark.parametrize("version", [2, 3])
def test_model_exchange_state_machine(version):
    """Instantiated -> initialization -> event mode -> continuous time mode -> event mode;
    the continuous-state functions accept only n = 0, co-simulation calls are refused."""
    import ctypes
    fmu = Instance(version, model_exchange=True)
    assert fmu.c
    assert fmu.setup() == OK
    p = f"fmi{version}"
    dll = fmu.dll
    c = ctypes.c_void_p(fmu.c)
    empty = (ctypes.c_double * 1)()
    b = [ctypes.c_int() if version == 2 else ctypes.c_bool() for _ in range(6)]
    t = ctypes.c_double()
    if version == 2:
        class EventInfo(ctypes.Structure):
            _fields_ = [(n, ctypes.c_int) for n in ("a", "b", "c", "d", "e")] + [
                ("t", ctypes.c_double)]
        info = EventInfo(1, 1, 1, 1, 1, 1.0)
        assert dll.fmi2NewDiscreteStates(c, ctypes.byref(info)) == OK
        assert (info.a, info.b, info.c, info.d, info.e) == (0, 0, 0, 0, 0)
    else:
        assert dll.fmi3UpdateDiscreteStates(c, *[ctypes.byref(x) for x in b[:5]],
                                            ctypes.byref(t)) == OK
        assert not any(x.value for x in b[:5])
    assert getattr(dll, f"{p}EnterContinuousTimeMode")(c) == OK
    getattr(dll, f"{p}SetTime").argtypes = [ctypes.c_void_p, ctypes.c_double]
    assert getattr(dll, f"{p}SetTime")(c, 0.5) == OK
    assert fmu.get("time")[1][0] == 0.5
    deriv = "fmi2GetDerivatives" if version == 2 else "fmi3GetContinuousStateDerivatives"
    for fn in (deriv, f"{p}GetEventIndicators", f"{p}GetContinuousStates",
               f"{p}GetNominalsOfContinuousStates"):
        assert getattr(dll, fn)(c, empty, ctypes.c_size_t(0)) == OK, fn
        assert getattr(dll, fn)(c, empty, ctypes.c_size_t(1)) == 3, fn
    assert getattr(dll, f"{p}SetContinuousStates")(c, empty, ctypes.c_size_t(0)) == OK
    assert getattr(dll, f"{p}CompletedIntegratorStep")(c, 1, ctypes.byref(b[0]),
                                               ctypes.byref(b[1])) == OK
    assert not b[0].value and not b[1].value
    # inputs are taken in continuous time mode and answered at once
    assert fmu.set(F_E=2.0) == OK
    st, (g2,) = fmu.get("gamma_P")
    assert st == OK and g2 > 0.0
    assert getattr(dll, f"{p}EnterEventMode")(c) == OK
    # co-simulation functions are refused in a model-exchange instance
    if version == 2:
        dll.fmi2DoStep.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int]
        assert dll.fmi2DoStep(c, 0.5, 0.1, 1) == 3
    else:
        assert fmu.f_do_step(fmu.c, 0.5, 0.1, True, *[ctypes.byref(x) for x in b[:3]],
                             ctypes.byref(t)) == 3
    assert any("not allowed" in m for m in fmu.messages())
    assert fmu.f_terminate(fmu.c) == OK
    fmu.free()
