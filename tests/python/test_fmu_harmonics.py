"""The FMU's multi-harmonic parameter and the outputs of PHYSICS.md 2.5, 4.1 and 5: `harmonics`
(1, 2..64, 0 = auto), `gamma_max`, `sigma_max`, `harmonics_used`, `F_lim_backbone` and `jump`
equal the Python package's answers on blade A, FMI 2.0 and 3.0; going back to harmonics = 1 gives
the single-harmonic numbers again, bit for bit."""
from __future__ import annotations

import math

import pytest

from fmu_harness import CASE, ERROR, OK, Instance

from udmap.case import build_model, load_case

REAL = ["gamma_P", "sigma_a", "f_res", "u_E", "gamma_max", "sigma_max"]


def reference(F_E, harmonics=1, mu=None):
    case = load_case(CASE)
    if mu is not None:
        case.damper["mu"] = mu
    case.analysis["harmonics"] = harmonics
    case.analysis["eigen_method"] = "modal"  # the FMU's eigenvalue start (same peaks)
    model = build_model(case)
    p = model.backbone([F_E])[0]
    return p, model.limit_force(), model.limit_force_backbone()


def close(a, b, rtol):
    return abs(a - b) <= rtol * max(abs(a), abs(b))


def set_up(version, name):
    """An instance of the generic FMU, set up (its setup asserted OK)."""
    inst = Instance(version, name)
    assert inst.setup() == OK
    return inst


@pytest.mark.parametrize("version", [2, 3])
def test_harmonics_parameter_matches_the_package(version):
    inst = set_up(version, "harmonics")
    assert inst.set(F_E=5.0) == OK
    st, h1 = inst.get(*REAL, "harmonics_used")
    assert st == OK and h1[-1] == 1
    assert h1[4] == h1[0] and h1[5] == h1[1]  # gamma_max = gamma_P, sigma_max = sigma_a at H = 1
    for H in (3, 0):
        assert inst.set(harmonics=H) == OK
        st, got = inst.get(*REAL, "harmonics_used", "hcf_ok")
        assert st == OK, inst.messages()
        p, _, _ = reference(5.0, "auto" if H == 0 else H)
        assert got[6] == p["harmonics"] and (H == 0 or p["harmonics"] == H)
        # 5 N lies in the force range the FMU prepares (F_E_min, F_E_max = 1, 10 N): the point
        # comes from the force table, to harmonic_tol/1000 (test_fmu_force_range.py)
        for name, x in zip(REAL, got):
            assert close(x, p[name], 1e-6), (H, name, x, p[name])
        assert got[7] == p["hcf_ok"]
        # gross slip: the higher harmonics move the peak (PHYSICS.md 4.1)
        assert abs(got[0] / h1[0] - 1) > 1e-4
    assert inst.set(harmonics=1) == OK
    st, again = inst.get(*REAL, "harmonics_used")
    assert st == OK and again == h1, (again, h1)
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_harmonics_out_of_range_is_an_error_and_the_instance_stays_usable(version):
    inst = set_up(version, "range")
    assert inst.set(harmonics=65) == ERROR
    assert any("harmonics" in m and "65" in m for m in inst.messages()), inst.messages()
    assert inst.set(harmonics=-1) == ERROR
    st, (H, used) = inst.get("harmonics", "harmonics_used")
    assert st == OK and H == 1 and used == 1
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_limit_force_backbone(version):
    # mu = 0.6 on blade A: a contact lifts off and F_bb saturates well below F_lim (PHYSICS.md 5)
    inst = set_up(version, "limit")
    assert inst.set(mu=0.6, F_E=4.0) == OK
    st, (F_lim, F_bb, lift_off) = inst.get("F_lim", "F_lim_backbone", "lift_off")
    assert st == OK, inst.messages()
    _, F_lim_ref, F_bb_ref = reference(4.0, mu=0.6)
    assert lift_off and F_bb < 0.6 * F_lim, (lift_off, F_bb, F_lim)
    assert close(F_lim, F_lim_ref, 1e-12) and close(F_bb, F_bb_ref, 1e-12), (F_bb, F_bb_ref)
    # the default design does not lift off: F_lim_backbone = F_lim
    assert inst.set(mu=0.3) == OK
    st, (F_lim, F_bb) = inst.get("F_lim", "F_lim_backbone")
    assert st == OK and close(F_bb, F_lim, 1e-12)
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_jump(version):
    # the lift-off design of test_jump.py: k(gamma) jumps at gamma_c = 1.0335e-3 rad, and the
    # forces 3.5 and 4 N peak there (PHYSICS.md 2.5)
    mu, CF = 0.3639798354357481, 1178.4721311181784
    inst = set_up(version, "jump")
    for F_E in (3.5, 4.0):
        assert inst.set(mu=mu, CF=CF, F_E=F_E) == OK
        st, (jump, gamma_P, sigma_a) = inst.get("jump", "gamma_P", "sigma_a")
        assert st == OK, inst.messages()
        case = load_case(CASE)
        case.damper.update(mu=mu, CF=CF)
        case.analysis["eigen_method"] = "modal"
        p = build_model(case).backbone([F_E])[0]
        assert jump and p["jump"] and abs(gamma_P / 1.0335e-3 - 1) < 1e-4
        assert close(gamma_P, p["gamma_P"], 1e-9) and close(sigma_a, p["sigma_a"], 1e-9)
    assert inst.set(F_E=10.0) == OK
    assert inst.get("jump") == (OK, [False])
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_F_E_steps_use_the_force_table(version):
    # after a change of F_E alone the FMU interpolates its verified force table (PHYSICS.md 4.1):
    # every step equals the package's exact multi-harmonic point to harmonic_tol/1000 = 1e-6
    inst = set_up(version, "table")
    assert inst.set(harmonics=3) == OK
    case = load_case(CASE)
    case.analysis["harmonics"] = 3
    case.analysis["eigen_method"] = "modal"
    exact = build_model(case)
    forces = [1 + 9 * ((0.6180339887498949 * i) % 1.0) for i in range(1, 31)]
    worst = 0.0
    for F_E in forces * 2:
        assert inst.set(F_E=F_E) == OK
        st, got = inst.get(*REAL)
        assert st == OK, inst.messages()
        p = exact.backbone([F_E])[0]
        for name, x in zip(REAL, got):
            assert close(x, p[name], 1e-6), (F_E, name, x, p[name])
            worst = max(worst, abs(x - p[name]) / abs(p[name]))
    assert worst > 1e-12, "no step came from the table"
    inst.free()
