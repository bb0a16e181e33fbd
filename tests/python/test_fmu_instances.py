"""Instances of the FMU: only what changed is recomputed and only what is read is computed;
state get/set and serialization reproduce outputs bit for bit; reset; independent instances
in one process; variable step sizes; the FMI state machine."""
from __future__ import annotations

import ctypes
import math
import struct

import pytest

from fmu_harness import ERROR, OK, Instance

VERSIONS = [2, 3]
ctypes_uint = ctypes.c_uint32
ctypes_double = ctypes.c_double
FORCES = [0.5, 2.0, 5.0, 9.0, 20.0]


def bits(outputs: dict) -> dict:
    """Outputs with floats as their exact bit patterns (for bit-for-bit comparisons)."""
    return {k: struct.pack("<d", v) if isinstance(v, float) else v for k, v in outputs.items()}


def events(inst: Instance, since: int) -> list[str]:
    """Kinds of the kernel work logged (logEvents) since log index `since`."""
    kinds = []
    for _, category, message in inst.logs[since:]:
        if category != "logEvents":
            continue
        for key in ("blade built", "damper traced", "damper coupled", "rescaled",
                    "model built", "limit force computed", "response point computed"):
            if key in message:
                kinds.append(key)
    return kinds


def work(inst: Instance, action) -> list[str]:
    """The kernel work an action caused, sorted (the order depends on what is read first)."""
    n = len(inst.logs)
    action()
    return sorted(events(inst, n))


def read_all(inst: Instance) -> dict:
    st, out = inst.outputs()
    assert st == OK, inst.messages()
    return out


@pytest.mark.parametrize("version", VERSIONS)
def test_only_what_changed_is_recomputed(version):
    inst = Instance(version, logging_on=True)
    # ExitInitializationMode builds the blade, damper and model (and prepares the force range
    # [F_E_min, F_E_max], test_fmu_force_range.py); the outputs are computed when read
    assert work(inst, lambda: inst.setup()) == sorted(["blade built", "damper traced",
                                                        "model built"])
    assert work(inst, lambda: read_all(inst)) == sorted([
        "limit force computed", "response point computed"])
    # nothing changed: nothing recomputed, whatever is read
    assert work(inst, lambda: (inst.step(0.1), read_all(inst))) == []
    # the master sets every input each step: equal values change nothing
    assert work(inst, lambda: (inst.set(F_E=5.0, mu=0.3, CF=900.0), read_all(inst))) == []
    # a new force: only the response point
    assert work(inst, lambda: (inst.set(F_E=7.0), inst.step(0.1), read_all(inst))) == sorted([
        "response point computed"])
    assert work(inst, lambda: (inst.set(f_exc=185.0), read_all(inst))) == sorted([
        "response point computed"])
    inst.set(f_exc=0.0)
    # a new CF: the damper table is rescaled, not traced; the model is kept
    assert work(inst, lambda: (inst.set(CF=1100.0), read_all(inst))) == sorted([
        "rescaled", "limit force computed", "response point computed"])
    # a new mu, contact stiffness or damper geometry: the damper is traced again (at the
    # reference CF, then rescaled to the current one) and coupled to the model, which keeps the
    # bare-blade data; the blade is kept
    for change in ({"mu": 0.25}, {"kt_flat": 45e6}, {"flat1_y": -1.8e-3}):
        assert work(inst, lambda: (inst.set(**change), read_all(inst))) == sorted([
            "damper traced", "damper coupled", "rescaled", "limit force computed",
            "response point computed"]), change
    # a new blade parameter: the blade is rebuilt, the damper kept
    assert work(inst, lambda: (inst.set(neck_h=0.0085), read_all(inst))) == sorted([
        "blade built", "model built", "limit force computed", "response point computed"])
    # a new band: the model only
    assert work(inst, lambda: (inst.set(f_max=235.0), read_all(inst))) == sorted([
        "model built", "limit force computed", "response point computed"])
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_outputs_nobody_reads_are_not_computed(version):
    inst = Instance(version, logging_on=True)
    assert inst.setup() == OK   # builds blade, damper and model (ExitInitializationMode)
    # stepping without reading computes nothing
    assert work(inst, lambda: [inst.step(0.25) for _ in range(4)]) == []
    # the limit force needs no response point
    assert work(inst, lambda: inst.get("F_lim", "lift_off")) == ["limit force computed"]
    assert work(inst, lambda: inst.set(F_E=3.0)) == []
    st, (ratio, F_lim) = inst.get("F_ratio", "F_lim")
    assert st == OK and ratio == 3.0 / F_lim
    assert events(inst, 0).count("response point computed") == 0
    assert work(inst, lambda: inst.get("gamma_P")) == ["response point computed"]
    assert work(inst, lambda: inst.get("sigma_a", "regime", "hcf_ok")) == []
    inst.free()


def run_sequence(inst: Instance, steps) -> list[dict]:
    """Applies each step's inputs, advances by h and reads every output."""
    out = []
    for h, values in steps:
        assert inst.set(**values) == OK
        assert inst.step(h) == OK
        out.append(bits(read_all(inst)))
    return out


SEQUENCE = [(0.1, {"F_E": F}) for F in FORCES] + [
    (0.05, {"CF": 1000.0, "F_E": 3.0}), (0.2, {"mu": 0.25}), (0.01, {"F_E": 11.0}),
    (0.3, {"CF": 800.0, "mu": 0.35, "F_E": 4.0}), (0.1, {"f_exc": 186.0})]


@pytest.mark.parametrize("version", VERSIONS)
def test_state_round_trip_is_bit_for_bit(version):
    inst = Instance(version)
    assert inst.setup() == OK
    run_sequence(inst, SEQUENCE[:6])
    saved_out = bits(read_all(inst))
    st, saved_in = inst.get("F_E", "CF", "mu", "time")
    s = inst.get_state()
    data = inst.serialize(s)
    # go elsewhere: every kind of change, including a blade parameter
    rest = run_sequence(inst, SEQUENCE[6:] + [(0.1, {"neck_h": 0.009, "F_E": 2.0})])
    assert rest[-1] != saved_out
    assert inst.set_state(s) == OK
    assert bits(read_all(inst)) == saved_out
    assert inst.get("F_E", "CF", "mu", "time")[1] == saved_in
    # the serialized copy, deserialized into this and into a fresh instance
    run_sequence(inst, SEQUENCE[6:])
    st, s2 = inst.deserialize(data)
    assert st == OK and inst.set_state(s2) == OK
    assert bits(read_all(inst)) == saved_out
    other = Instance(version)
    assert other.setup() == OK
    st, s3 = other.deserialize(data)
    assert st == OK and other.set_state(s3) == OK
    assert bits(read_all(other)) == saved_out
    # and the run continues from there exactly as the original did
    assert run_sequence(other, SEQUENCE[6:]) == run_sequence(inst, SEQUENCE[6:])
    # a state that is not this FMU's is refused
    assert inst.deserialize(data[:-8])[0] == ERROR
    forged = bytearray(data)
    forged[20] ^= 0xFF  # inside the token
    assert inst.deserialize(bytes(forged))[0] == ERROR
    assert any("not saved by this FMU" in m for m in inst.messages())
    for state in (s, s2):
        assert inst.free_state(state) == OK
    other.free_state(s3)
    other.free()
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_reset_then_rerun_reproduces_outputs(version):
    inst = Instance(version)
    assert inst.setup() == OK
    first = run_sequence(inst, SEQUENCE)
    assert inst.reset() == OK
    # back to the start values
    assert inst.get("F_E", "mu", "CF", "f_exc")[1] == [5.0, 0.3, 900.0, 0.0]
    assert inst.setup() == OK
    assert run_sequence(inst, SEQUENCE) == first
    fresh = Instance(version)
    assert fresh.setup() == OK
    assert run_sequence(fresh, SEQUENCE) == first
    fresh.free()
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_instances_with_different_mu_are_independent(version):
    a, b = Instance(version, "a"), Instance(version, "b")
    for inst, mu in ((a, 0.3), (b, 0.2)):
        assert inst.set(mu=mu) == OK and inst.setup() == OK
    alternating = {"a": [], "b": []}
    for F in FORCES:
        for name, inst in (("a", a), ("b", b)):
            alternating[name] += run_sequence(inst, [(0.1, {"F_E": F})])
    assert alternating["a"] != alternating["b"]  # mu matters, so this could fail
    for name, mu in (("a", 0.3), ("b", 0.2)):
        alone = Instance(version, name + "-alone")
        assert alone.set(mu=mu) == OK and alone.setup() == OK
        assert run_sequence(alone, [(0.1, {"F_E": F}) for F in FORCES]) == alternating[name]
        alone.free()
    a.free()
    b.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_variable_step_sizes(version):
    inst = Instance(version)
    assert inst.setup(start_time=2.0) == OK
    reference = bits(read_all(inst))
    t = 2.0
    for h in (0.1, 1e-3, 2.5, 0.0, 1e-9, 7.25, 0.3333333333333333):
        assert inst.step(h) == OK
        t += h
        assert bits(read_all(inst)) == reference  # quasi-steady: time does not matter
    assert inst.get("time")[1][0] == pytest.approx(t, rel=1e-15)
    # a step from the wrong time or a negative one is refused, and nothing moves
    inst.time += 1.0
    assert inst.step(0.1) == ERROR
    inst.time -= 1.0
    assert inst.step(-0.1) == ERROR
    assert inst.step(math.nan) == ERROR
    assert inst.step(0.5) == OK
    assert inst.get("time")[1][0] == pytest.approx(t + 0.5, rel=1e-15)
    assert any("differs from the FMU time" in m for m in inst.messages())
    inst.free()


@pytest.mark.parametrize("version", VERSIONS)
def test_state_machine_and_bad_calls(version):
    inst = Instance(version)
    # doStep before initialization
    assert inst.step(0.1) == ERROR
    assert any("not allowed in state Instantiated" in m for m in inst.messages())
    assert inst.setup() == OK
    # outputs and the independent variable cannot be set
    assert inst.set(gamma_P=1.0) == ERROR
    assert inst.set(time=3.0) == ERROR
    assert any("gamma_P is an output and cannot be set" in m for m in inst.messages())
    # a value reference that does not exist, a type that does not match
    st = inst._get["Real" if version == 2 else "Float64"](
        inst.c, (ctypes_uint * 1)(9999), 1, (ctypes_double * 1)(),
        *([1] if version == 3 else []))
    assert st == ERROR and any("unknown value reference 9999" in m for m in inst.messages())
    vr = inst.vars["regime"].valueReference
    st = inst._get["Real" if version == 2 else "Float64"](
        inst.c, (ctypes_uint * 1)(vr), 1, (ctypes_double * 1)(),
        *([1] if version == 3 else []))
    assert st == ERROR and any("regime" in m and "not Real/Float64" in m
                               for m in inst.messages())
    assert inst.f_terminate(inst.c) == OK
    assert inst.step(0.1) == ERROR
    assert inst.get("gamma_P")[0] == OK  # outputs stay readable after terminate
    assert inst.reset() == OK and inst.setup() == OK and inst.step(0.1) == OK
    inst.free()
    # a description of another build is refused at instantiation, with a message
    bad = Instance(version, token="{00000000-0000-0000-0000-000000000000}")
    assert not bad.c
    assert any("does not match" in m for m in bad.messages(ERROR))


@pytest.mark.parametrize("version", VERSIONS)
def test_rejected_set_changes_nothing(version):
    inst = Instance(version, logging_on=True)
    assert inst.setup() == OK
    before = bits(read_all(inst))
    n = len(inst.logs)
    # one bad value in a call: none of the call's values is taken
    assert inst.set(F_E=3.0, mu=-0.1) == ERROR
    assert inst.get("F_E", "mu")[1] == [5.0, 0.3]
    assert events(inst, n) == []
    assert bits(read_all(inst)) == before
    inst.free()
