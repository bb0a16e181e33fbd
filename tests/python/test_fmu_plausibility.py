"""Plausibility warnings in the FMU log (docs/fmu.md, "Plausibility warnings"): a case inside
every range but typed in another unit gets the kernel's warning through the FMI logger (status
Warning, category logStatusWarning) once the model is built at ExitInitializationMode, again only
when a change of the values brings a kind of warning the previous check did not give, and the
outputs stay what the kernel computes (the check runs on a model of its own). Blade A has
none."""
from __future__ import annotations

import pytest

from fmu_harness import CASE, OK, WARNING, Instance
from udmap.case import build_model, load_case

VERSIONS = [2, 3]
MASS = ("plausibility: blade.platform.m = 21 kg is heavier than the rest of the blade (0.1443 "
        "kg of neck and airfoil): was it given in grams? (21 g would be 0.021 kg)")
GAMMA_B = ("plausibility: the base-cycle amplitude gamma_b = 0.5483 rad is above 0.01 rad (the "
           "contacts deflect by degrees before they slip): were the contact stiffnesses given "
           "in N/mm? (kn_flat = 6e+04 N/m; 1 N/mm = 1e3 N/m)")
SHIFT = ("plausibility: the stuck damper shifts the first frequency by 0.0137 % (187.1 Hz bare, "
         "187.1 Hz stuck), outside 0.1 % to 100 %: are the contact stiffnesses or the blade in "
         "another unit?")
#: blade A's contact stiffnesses [N/m] and the same numbers read as N/mm
STIFF = dict(kn_flat=60e6, kt_flat=40e6, kn_curved=80e6, kt_curved=50e6)
SOFT = {k: v / 1000 for k, v in STIFF.items()}


def warnings(inst: Instance) -> list[str]:
    """The plausibility warnings logged so far (checking their status and category); FMI 2's
    logger takes a printf format, so its messages come with '%' doubled."""
    out = []
    for status, category, message in inst.logs:
        if message.startswith("plausibility: "):
            assert status == WARNING and category == "logStatusWarning", (status, category)
            if inst.version == 2:
                assert "%" not in message.replace("%%", ""), message
                message = message.replace("%%", "%")
            out.append(message)
    return out


def reference(F_E: float, platform_m: float) -> dict:
    """The package's backbone point for blade A with this platform mass, with the FMU's
    eigenvalue start."""
    case = load_case(CASE)
    case.blade["platform"]["m"] = platform_m
    case.analysis["eigen_method"] = "modal"
    return build_model(case).backbone([F_E])[0]


@pytest.mark.parametrize("version", VERSIONS)
def test_blade_a_logs_no_warning(version):
    inst = Instance(version, "plain")
    assert inst.setup() == OK
    st, _ = inst.outputs()
    assert st == OK and warnings(inst) == []


@pytest.mark.parametrize("version", VERSIONS)
def test_platform_in_grams_warns_once_and_keeps_the_outputs(version):
    inst = Instance(version, "grams")
    assert inst.set(platform_m=21.0, F_E=2.0) == OK
    assert inst.setup() == OK  # nothing refused: the initialization succeeds
    assert warnings(inst) == [MASS]  # logged at ExitInitializationMode
    st, got = inst.get("gamma_P", "f_res", "sigma_a")
    assert st == OK
    p = reference(2.0, 21.0)
    assert got == [p["gamma_P"], p["f_res"], p["sigma_a"]]
    # more steps and forces: the same warning is not logged again
    for F in (1.0, 3.0, 5.0):
        assert inst.set(F_E=F) == OK
        assert inst.step(1e-3) == OK
        assert inst.get("gamma_P")[0] == OK
    assert warnings(inst) == [MASS]


@pytest.mark.parametrize("version", VERSIONS)
def test_a_change_that_brings_a_new_warning_logs_it(version):
    inst = Instance(version, "changes")
    assert inst.setup() == OK and warnings(inst) == []
    # the stiffnesses typed in N/mm: gamma_b and the stuck shift, each once
    assert inst.set(**SOFT) == OK
    assert inst.step(1e-3) == OK and inst.get("gamma_P")[0] == OK
    assert warnings(inst) == [GAMMA_B, SHIFT]
    assert inst.set(mu=0.35) == OK  # another damper, the same kinds: nothing new
    assert inst.step(1e-3) == OK and inst.get("gamma_P")[0] == OK
    assert warnings(inst) == [GAMMA_B, SHIFT]
    # plausible again, then implausible again: logged again
    assert inst.set(mu=0.3, **STIFF) == OK
    assert inst.step(1e-3) == OK and inst.get("gamma_P")[0] == OK
    assert warnings(inst) == [GAMMA_B, SHIFT]
    assert inst.set(**SOFT) == OK
    assert inst.step(1e-3) == OK and inst.get("gamma_P")[0] == OK
    assert warnings(inst) == [GAMMA_B, SHIFT, GAMMA_B, SHIFT]


@pytest.mark.parametrize("version", VERSIONS)
def test_fmpy_shows_the_warning_of_a_platform_in_grams(version):
    # an importer of its own: fmpy's simulation with the platform mass typed as 21 (grams)
    from fmpy import simulate_fmu

    from fmu_harness import FMUS
    logged = []

    def logger2(component, name, status, category, message):
        logged.append((status, category.decode(), message.decode()))

    def logger3(environment, status, category, message):
        logged.append((status, category.decode(), message.decode()))

    r = simulate_fmu(str(FMUS[version]), start_values={"platform_m": 21.0, "F_E": 2.0},
                     stop_time=0.01, output_interval=0.005, output=["gamma_P"],
                     logger=logger2 if version == 2 else logger3)
    found = [m for m in logged if m[2].startswith("plausibility: ")]
    assert found == [(WARNING, "logStatusWarning", MASS)], logged
    assert r["gamma_P"][-1] == reference(2.0, 21.0)["gamma_P"]
