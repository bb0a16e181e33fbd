"""Bad inputs and physics failures: the right FMI status with a formatted message through the
logger (a value outside its range: an FMI error with the message of the case-file validation),
and the instance computes normally again once valid values arrive. zeta = 0 at or
above F_lim: a warning, regime 3 and no NaN. Random input vectors: no crash, and every output
read with status OK is finite."""
from __future__ import annotations

import math
import random

import pytest

from fmu_harness import ERROR, OK, WARNING, Instance

VERSIONS = [2, 3]
REAL_OUTPUTS = ["gamma_P", "sigma_a", "F_lim", "f_res", "u_E", "k_re", "k_im", "F_ratio"]


def ready(version, **values) -> Instance:
    inst = Instance(version)
    if values:
        assert inst.set(**values) == OK
    assert inst.setup() == OK
    return inst


def usable(version) -> tuple[Instance, dict]:
    """A ready instance whose outputs are usable, and those outputs."""
    inst = ready(version)
    return inst, assert_usable(inst)


def fails_at_evaluation(inst: Instance, **values) -> list[str]:
    """Sets values the FMU accepts alone and asserts that the outputs then fail: the error
    messages."""
    assert inst.set(**values) == OK
    st, _ = inst.outputs()
    assert st == ERROR
    return inst.messages(ERROR)


def assert_usable(inst: Instance, reference: dict | None = None):
    st, out = inst.outputs()
    assert st == OK, inst.messages()
    assert all(math.isfinite(float(out[k])) for k in REAL_OUTPUTS), out
    if reference is not None:
        assert out == reference
    return out


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("name,value,why", [
    ("F_E", math.nan, "F_E must be in [0, inf) N, got NaN"),
    ("F_E", -1.0, "F_E must be in [0, inf) N, got -1"),
    ("F_E", math.inf, "F_E must be in [0, inf) N, got inf"),
    ("mu", 0.0, "mu must be in [0.0001, 10], got 0"),
    ("mu", -math.inf, "mu must be in [0.0001, 10], got -inf"),
    ("CF", -900.0, "CF must be in [0.001, 1e6] N, got -900"),
    ("kn_flat", 0.0, "kn_flat must be in [100, 1e12] N/m, got 0"),
    ("kt_curved", math.nan, "kt_curved must be in [100, 1e12] N/m, got NaN"),
    ("f_exc", -185.0, "f_exc must be in [0, inf) Hz, got -185"),
    ("neck_L", -0.02, "neck_L must be in [0.0001, 3] m, got -0.02"),
    ("neck_L", 1e5, "neck_L must be in [0.0001, 3] m, got 1e5"),
    ("E", 1e300, "E must be in [1e6, 1e13] Pa, got 1e300"),
    ("rho", 1e-12, "rho must be in [100, 30000] kg/m3, got 1e-12"),
    ("zeta", -0.01, "zeta must be in [0, 0.5], got -0.01"),
    ("beta_L_deg", 90.0, "beta_L_deg must be in (0, 90) deg, got 90"),
    ("f_max", 0.0, "f_max must be in [0.001, 1e6] Hz, got 0"),
    ("sigma_all", math.nan, "sigma_all must be in [1000, 1e10] Pa, got NaN"),
    ("airfoil_elements", 25, "airfoil_elements must be an even integer in [2, 1000], got 25"),
    ("neck_elements", 0, "neck_elements must be an integer in [1, 1000], got 0"),
])
def test_bad_value_is_an_error_with_the_case_file_message(version, name, value, why):
    # the message of the case-file validation (FMU names for dotted paths), an FMI error, and
    # the instance keeps its value and computes as before
    inst, before = usable(version)
    old = inst.get(name)[1][0]
    assert inst.set(**{name: value}) == ERROR
    msg = inst.messages()[-1]
    assert msg.startswith(f"fmi{version}Set") and why in msg, msg
    assert f"{name} keeps" in msg
    assert inst.get(name)[1][0] == old
    assert inst.step(0.1) == OK
    assert_usable(inst, before)
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_f_exc_outside_the_band_is_an_error_until_fixed(version):
    inst, before = usable(version)
    # valid alone; the band decides at evaluation
    assert any("f_exc = 240 Hz is outside the band [f_min, f_max] = [150, 230] Hz" in m
               for m in fails_at_evaluation(inst, f_exc=240.0))
    # the limit force does not depend on f_exc: still available
    st, (F_lim,) = inst.get("F_lim")
    assert st == OK and F_lim == before["F_lim"]
    assert inst.set(f_max=250.0) == OK  # widen the band instead: now valid
    assert inst.outputs()[0] == OK
    assert inst.set(f_exc=0.0, f_max=230.0) == OK
    assert_usable(inst, before)
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_band_without_the_resonance_is_an_error_until_fixed(version):
    inst, before = usable(version)
    msgs = fails_at_evaluation(inst, f_min=300.0, f_max=400.0)
    assert msgs and all(m.startswith(f"fmi{version}Get") for m in msgs)
    assert any("resonance" in m for m in msgs), msgs
    assert inst.set(f_min=160.0, f_max=140.0) == OK
    assert inst.outputs()[0] == ERROR
    assert "f_min = 160 Hz must be below f_max = 140 Hz" in inst.messages(ERROR)[-1]
    assert inst.set(f_min=150.0, f_max=230.0) == OK
    assert_usable(inst, before)
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_unbounded_response_warns_without_nan(version):
    inst = ready(version, zeta=0.0)
    st, (F_lim,) = inst.get("F_lim")
    assert st == OK and F_lim > 0
    for F_E in (F_lim, 1.5 * F_lim, 40.0):
        assert inst.set(F_E=F_E) == OK and inst.step(0.1) == OK
        st, out = inst.outputs()
        assert st == WARNING, (F_E, out)
        assert not any(isinstance(v, float) and math.isnan(v) for v in out.values()), out
        assert out["regime"] == 3 and out["hcf_ok"] is False
        assert out["gamma_P"] == out["sigma_a"] == out["u_E"] == math.inf
        assert out["k_re"] == 0.0 and out["k_im"] == 0.0
        assert 150.0 < out["f_res"] < 230.0 and out["F_ratio"] == F_E / F_lim
        assert "unbounded" in inst.messages(WARNING)[-1]
    # below the limit force the response is finite again
    assert inst.set(F_E=0.5 * F_lim) == OK
    out = assert_usable(inst)
    assert out["regime"] != 3
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("change", [{"mu": 3.0}, {"pitch": 1e-6}])
def test_jammed_damper_is_an_error_until_fixed(version, change):
    inst, before = usable(version)
    assert inst.set(**change) == OK
    assert inst.step(0.1) == OK
    st, out = inst.outputs()
    assert st == ERROR
    assert not any(isinstance(v, float) and math.isnan(v) for v in out.values())
    msgs = inst.messages(ERROR)
    assert any("udmap_new_damper_asymmetric (physics, status 3)" in m and "jams" in m
               for m in msgs), msgs
    # every output needs the damper: the limit force fails the same way
    assert inst.get("F_lim")[0] == ERROR
    assert inst.set(mu=0.3, pitch=0.026) == OK
    assert inst.step(0.1) == OK
    assert_usable(inst, before)
    inst.free()


SPECIAL = [math.nan, math.inf, -math.inf, 0.0, -0.0, -1.0, 1e300, 1e-300, -1e-300]
NOMINAL = {"F_E": 5.0, "f_exc": 0.0, "mu": 0.3, "CF": 900.0, "kn_flat": 60e6,
           "kt_flat": 40e6, "kn_curved": 80e6, "kt_curved": 50e6}
# Per input: probability of a special value (scaled by the nominal one: NaN, infinities,
# zeros, negatives, absurdly small or large positives) and of a new plausible value; else the
# last plausible value is set again. Damper inputs change rarely: each change traces the
# damper again, which is what keeps the 10,000 vectors within a few seconds.
RATES = {"F_E": (0.15, 1.0), "f_exc": (0.15, 0.3), "mu": (0.03, 0.03), "CF": (0.05, 0.1),
         "kn_flat": (0.02, 0.01), "kt_flat": (0.02, 0.01), "kn_curved": (0.02, 0.01),
         "kt_curved": (0.02, 0.01)}


# The allowed ranges (the case-file schema's for the damper inputs).
LIMITS = {"F_E": (0.0, math.inf), "f_exc": (0.0, math.inf), "mu": (1e-4, 10.0),
          "CF": (1e-3, 1e6), "kn_flat": (1e2, 1e12), "kt_flat": (1e2, 1e12),
          "kn_curved": (1e2, 1e12), "kt_curved": (1e2, 1e12)}


def draw(rng: random.Random, name: str, plausible: dict) -> float:
    special, change = RATES[name]
    if rng.random() < special:
        return rng.choice(SPECIAL) * (NOMINAL[name] or 1.0)
    if rng.random() < change:
        if name == "F_E":
            plausible[name] = 10 ** rng.uniform(-2, 2)
        elif name == "f_exc":
            plausible[name] = 0.0 if rng.random() < 0.5 else rng.uniform(100.0, 280.0)
        else:
            plausible[name] = NOMINAL[name] * 10 ** rng.uniform(-0.5, 0.5)
    return plausible[name]


@pytest.mark.parametrize("version,count", [(2, 10000), (3, 10000)])
def test_random_input_vectors(version, count):
    rng = random.Random(20240 + version)
    inst = ready(version)
    plausible = dict(NOMINAL)
    current = dict(NOMINAL)
    statuses = {OK: 0, WARNING: 0, ERROR: 0}
    for _ in range(count):
        vector = {name: draw(rng, name, plausible) for name in NOMINAL}
        for name, value in vector.items():  # one call each: valid values are taken
            st = inst.set(**{name: value})
            ok = math.isfinite(value) and LIMITS[name][0] <= value <= LIMITS[name][1]
            assert st == (OK if ok else ERROR), (name, value, st)
            if st == OK:
                current[name] = value
        assert inst.step(1e-3) == OK
        st, out = inst.outputs()
        assert st in statuses, st
        statuses[st] += 1
        values = [float(out[k]) for k in REAL_OUTPUTS]
        if st == OK:
            assert all(math.isfinite(v) for v in values), (current, out)
        if st == WARNING:
            assert not any(math.isnan(v) for v in values), (current, out)
    # the loop exercised real computations, not only rejections
    assert statuses[OK] > count // 5, statuses
    assert statuses[ERROR] > 0, statuses
    # and the instance is usable afterwards
    assert inst.set(**NOMINAL) == OK
    assert_usable(inst)
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_zero_force_is_the_limit_of_small_forces(version, tmp_path):
    # an engine model may start from rest: F_E = 0 gives the exact F_E -> 0+ limit
    from fmu_harness import CASE, cli
    inst = ready(version, F_E=0.0)
    out = assert_usable(inst)
    assert out["gamma_P"] == out["sigma_a"] == out["u_E"] == out["F_ratio"] == 0.0
    assert out["regime"] == 0 and out["hcf_ok"] is True
    small = {p["F_E"]: p for p in cli("backbone", CASE, "--forces", "1e-6")["points"]}[1e-6]
    for key in ("f_res", "k_re"):
        assert math.isclose(out[key], small[key], rel_tol=1e-9), (key, out[key], small[key])
    assert abs(out["k_im"]) <= 1e-9 * out["k_re"]
    # and at a given frequency
    assert inst.set(f_exc=190.0) == OK
    out = assert_usable(inst)
    assert out["gamma_P"] == 0.0 and math.isclose(out["f_res"], 190.0, rel_tol=1e-12)
    inst.free()

