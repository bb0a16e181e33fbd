"""The FMU's force range (parameters F_E_min, F_E_max): ExitInitializationMode prepares the
kernel's tables over the range (udmap_model_cover_forces), so that (a) no later step with F_E
in the range builds force-table points, (b) the outputs are those of an FMU whose table is
built on demand (bit for bit at harmonics = 1; within the table's harmonic_tol/1000 at H > 1,
both being within it of the exact point), (c) a force outside the range is still answered
exactly and said once in the log, and (d) a bad range is an FMI error naming the variables.
Blade A, FMI 2.0 and 3.0, co-simulation and model exchange."""
from __future__ import annotations

import math

import numpy as np
import pytest

from fmu_harness import CASE, ERROR, OK, Instance

from udmap.case import build_model, load_case

REAL = ["gamma_P", "sigma_a", "f_res", "u_E", "k_re", "k_im", "gamma_max", "sigma_max"]
DISCRETE = ["regime", "hcf_ok", "harmonics_used", "jump"]
RANGE = (2.0, 6.0)
FORCES = list(np.random.default_rng(23).uniform(*RANGE, 25))
TOL = 1e-3 * 1e-3   # harmonic_tol / 1000, the force table's accuracy


def built(inst: Instance, since: int) -> list[str]:
    """The log lines of force-table points built since log index `since`."""
    return [m for _, c, m in inst.logs[since:] if c == "logEvents" and "exact points built" in m]


def outside(inst: Instance) -> list[str]:
    return [m for _, c, m in inst.logs if "outside the prepared force range" in m]


def instance(version, harmonics, F_E_min, F_E_max, model_exchange=False, name="range"):
    inst = Instance(version, name, logging_on=True, model_exchange=model_exchange)
    assert inst.set(harmonics=harmonics, F_E_min=F_E_min, F_E_max=F_E_max) == OK
    assert inst.setup() == OK, inst.messages()
    return inst


def point(inst: Instance, F_E: float) -> dict:
    assert inst.set(F_E=F_E) == OK
    if not inst.model_exchange:
        assert inst.step(1e-3) == OK
    st, values = inst.get(*REAL, *DISCRETE)
    assert st == OK, inst.messages()
    return dict(zip(REAL + DISCRETE, values))


def exact(F_E: float, harmonics) -> dict:
    """The Python package's exact point (the FMU's eigenvalue start)."""
    case = load_case(CASE)
    case.analysis["harmonics"] = harmonics
    case.analysis["eigen_method"] = "modal"
    return build_model(case).backbone([F_E])[0]


def rel(a: float, b: float) -> float:
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


@pytest.mark.parametrize("version,model_exchange", [(2, False), (3, False), (2, True)])
@pytest.mark.parametrize("harmonics", [1, 3])
def test_steps_in_the_range_build_nothing_and_equal_the_table_built_on_demand(
        version, model_exchange, harmonics):
    prepared = instance(version, harmonics, *RANGE, model_exchange)
    # the initialization said what it did and what it took, in one line
    init = [m for _, c, m in prepared.logs if "initialization took" in m]
    assert len(init) == 1 and " ms " in init[0] and "[2, 6] N" in init[0], prepared.logs[-5:]
    # the same FMU with its range elsewhere: the table of these forces is built on demand
    on_demand = instance(version, harmonics, 20.0, 30.0, model_exchange, "on_demand")
    n = len(prepared.logs)
    worst = 0.0
    for F in FORCES + FORCES[:5]:   # also forces seen before
        p, q = point(prepared, F), point(on_demand, F)
        assert [p[k] for k in DISCRETE] == [q[k] for k in DISCRETE], F
        for k in REAL:
            if harmonics == 1:
                assert p[k] == q[k], (F, k)   # the same single-harmonic table, bit for bit
            else:
                assert rel(p[k], q[k]) <= 2 * TOL, (F, k, p[k], q[k])
                worst = max(worst, rel(p[k], q[k]))
    assert built(prepared, n) == [], built(prepared, n)[:3]
    assert outside(prepared) == []
    if harmonics != 1:
        # the reference really built its table on the way (so (a) can fail), and answered
        # from it (so the comparison is of two tables, not of two exact solves)
        assert built(on_demand, 0) and worst > 0.0
    prepared.free()
    on_demand.free()


@pytest.mark.parametrize("version", [2, 3])
def test_a_force_outside_the_range_is_exact_and_said_once(version):
    inst = instance(version, 3, *RANGE)
    point(inst, 4.0)
    assert outside(inst) == []
    # as without a range: the first force of a level-0 panel (ln(10)/8 wide in ln F_E) is
    # solved exactly; a second one there builds the panel on demand and is answered from it
    n = len(inst.logs)
    for F, first in ((8.0, True), (8.5, False), (1.5, True), (8.0, False)):
        got = point(inst, F)
        ref = exact(F, 3)
        for k in ("gamma_P", "sigma_a", "f_res", "u_E", "gamma_max", "sigma_max"):
            assert rel(got[k], ref[k]) <= (1e-9 if first else TOL), (F, k, got[k], ref[k])
        assert got["harmonics_used"] == 3 and got["regime"] == ref["regime"]
    assert len(built(inst, n)) == 1 and "F_E = 8.5 N" in built(inst, n)[0]
    assert len(outside(inst)) == 1 and "F_E = 8 N" in outside(inst)[0], outside(inst)
    # the range moved: said again for a force outside the new one
    assert inst.set(F_E_min=1.0, F_E_max=3.0) == OK
    point(inst, 2.5)
    assert len(outside(inst)) == 1
    point(inst, 4.0)
    assert len(outside(inst)) == 2
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_a_change_of_mu_prepares_the_range_again_in_that_step(version):
    inst = instance(version, 3, *RANGE)
    point(inst, 3.0)
    assert inst.set(mu=0.25) == OK
    n = len(inst.logs)
    point(inst, 3.0)
    again = [m for _, c, m in inst.logs[n:] if "prepared again" in m]
    assert len(again) == 1 and "harmonics 3" in again[0], inst.logs[n:]
    n = len(inst.logs)
    for F in FORCES[:8]:
        point(inst, F)
    assert built(inst, n) == []
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_a_bad_range_is_an_error_naming_the_variable(version):
    inst = Instance(version, "bad")
    # each value on its own: below its minimum, not finite
    assert inst.set(F_E_min=-1.0) == ERROR
    assert any("F_E_min must be in [0, inf) N, got -1" in m for m in inst.messages())
    assert inst.set(F_E_max=math.nan) == ERROR
    assert any("F_E_max" in m and "NaN" in m for m in inst.messages())
    assert inst.set(F_E_max=math.inf) == ERROR
    # the two together: F_E_min must be below F_E_max, at ExitInitializationMode
    assert inst.set(F_E_min=6.0, F_E_max=2.0) == OK
    assert inst.setup() == ERROR
    assert any("F_E_min = 6 N must be below F_E_max = 2 N" in m for m in inst.messages()), \
        inst.messages()
    inst.free()
    # and in step mode, at the next output
    inst = Instance(version, "bad_later")
    assert inst.setup() == OK
    assert inst.set(F_E_min=5.0, F_E_max=5.0) == OK
    st, _ = inst.get("gamma_P")
    assert st == ERROR
    assert any("F_E_min = 5 N must be below F_E_max = 5 N" in m for m in inst.messages())
    # a good range again: usable
    assert inst.set(F_E_max=7.0) == OK
    st, _ = inst.get("gamma_P")
    assert st == OK
    inst.free()
