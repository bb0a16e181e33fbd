"""The FMUs at an engine order (PHYSICS.md 2.6, INTERFACES.md "FMU"): integer parameters
blades and engine_order select the traveling wave; the outputs are the kernel's traveling-wave
peak (the Python model at the same phase), EO = 0 and EO = N are the in-phase answer."""
from __future__ import annotations

import pytest

from fmu_harness import CASE, OK, Instance
from udmap.case import build_blade, build_damper, load_case
from udmap.model import Model


@pytest.fixture(scope="module")
def models():
    case = load_case(str(CASE))
    blade, damper = build_blade(case), build_damper(case)
    return {ibpa: Model(blade, damper, 150.0, 230.0, ibpa_deg=ibpa).backbone([5.0])[0]
            for ibpa in (0.0, 90.0, -90.0)}


@pytest.mark.parametrize("version", [2, 3])
def test_engine_orders(version, models):
    inst = Instance(version)
    assert inst.setup() == OK
    for eo, ibpa in ((1, 90.0), (3, -90.0), (4, 0.0), (0, 0.0)):
        assert inst.set(F_E=5.0, blades=4, engine_order=eo) == OK
        st, out = inst.outputs()
        assert st == OK, inst.messages()
        ref = models[ibpa]
        for key in ("gamma_P", "f_res", "sigma_a"):
            assert out[key] == pytest.approx(ref[key], rel=1e-12), (eo, key)
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_case_fmu_of_a_matrices_blade_at_an_engine_order(version, tmp_path):
    """`udmap fmu` of a matrices case with u_dof and an engine order: the FMU starts at the
    case's engine order, takes the platform rows from u_dof, and answers as the case does."""
    import json
    import zipfile

    from fmu_harness import write_matrices_table_case
    from fmpy import simulate_fmu
    from udmap.case import build_model
    from udmap.fmu_case import write_case_fmu

    path = write_matrices_table_case(tmp_path)
    data = json.loads(path.read_text())
    blade_a = json.loads(CASE.read_text())
    data["damper"] = blade_a["damper"]
    data["blade"]["u_dof"] = data["blade"]["gamma_dof"] - 1   # the platform's w_P
    data["analysis"].update(blades=4, engine_order=1)
    path.write_text(json.dumps(data))
    case = load_case(str(path))
    ref = build_model(case).backbone([5.0])[0]
    fmu = tmp_path / f"wave{version}.fmu"
    write_case_fmu(case, fmu, fmi=version)
    with zipfile.ZipFile(fmu) as z:
        text = z.read("resources/udmap-case.txt").decode()
    assert "u_dof 15" in text
    res = simulate_fmu(str(fmu), start_time=0, stop_time=0.002, step_size=0.001,
                       start_values={"F_E": 5.0}, output=["gamma_P", "f_res", "sigma_a"])
    for key in ("gamma_P", "f_res", "sigma_a"):
        assert res[key][-1] == pytest.approx(ref[key], rel=1e-12), key


def test_force_table_at_an_engine_order():
    """At EO != 0 the force table is built as the forces visit it (no range prepared at the
    initialization): the first force of a panel is the exact point; once its panels are
    built the others come from the table, within harmonic_tol/1000 of the exact points."""
    import numpy as np
    case = load_case(str(CASE))
    model = Model(build_blade(case), build_damper(case), 150.0, 230.0, ibpa_deg=15.0)
    inst = Instance(2, logging_on=True)
    assert inst.set(blades=24, engine_order=1) == OK
    assert inst.setup() == OK
    assert any("built as the forces visit it" in m for _, _, m in inst.logs)
    forces = [5.0] + list(np.linspace(4.6, 5.4, 17))
    exact = {F: p for F, p in zip(forces, model.backbone(forces))}
    got = []
    for F in forces:
        assert inst.set(F_E=F) == OK and inst.step(1e-3) == OK
        st, out = inst.outputs()
        assert st == OK, inst.messages()
        got.append(out)
    for key in ("gamma_P", "f_res", "sigma_a"):
        # (the FMU starts the peak search from the secular equation alone: the same roots to
        # the solver's tolerance)
        assert got[0][key] == pytest.approx(exact[5.0][key], rel=1e-9), key
        for F, out in zip(forces, got):
            assert out[key] == pytest.approx(exact[F][key], rel=1e-6), (F, key)
    built = [m for _, _, m in inst.logs if m.startswith("force table:")]
    assert built, "no panel was built"
    inst.free()
