"""The packaged FMUs: archive layout, modelDescription.xml (validated by fmpy, checked against
INTERFACES.md and cases/blade_a.json, FMI 2 against FMI 3), documentation and licences."""
from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
import zipfile

import pytest
from fmpy.validation import validate_fmu

from fmu_harness import CASE, FMUS, PLATFORM, description

# INTERFACES.md, section FMU: name -> unit ("" dimensionless) per causality.
INPUTS = {"F_E": "N", "f_exc": "Hz", "mu": "", "CF": "N", "kn_flat": "N/m", "kt_flat": "N/m",
          "kn_curved": "N/m", "kt_curved": "N/m"}
PARAMETERS = ["neck_L", "neck_h", "neck_b", "platform_L", "platform_m", "platform_J",
              "airfoil_L", "airfoil_h", "airfoil_b", "neck_elements", "airfoil_elements", "E",
              "rho", "zeta", "pitch", "y_P", "beta_L_deg", "beta_R_deg", "flat1_x", "flat1_y",
              "flat2_x", "flat2_y", "curved_x", "curved_y", "f_min", "f_max", "sigma_all",
              "harmonics", "blades", "engine_order", "F_E_min", "F_E_max"]
OUTPUTS = {"gamma_P": "rad", "sigma_a": "Pa", "F_lim": "N", "f_res": "Hz", "u_E": "m",
           "k_re": "N.m/rad", "k_im": "N.m/rad", "F_ratio": "", "hcf_ok": "",
           "regime": "", "lift_off": "", "gamma_max": "rad", "sigma_max": "Pa",
           "harmonics_used": "", "F_lim_backbone": "N", "jump": ""}
DISCRETE_TYPES = {"hcf_ok": "Boolean", "regime": "Integer", "lift_off": "Boolean",
                  "harmonics_used": "Integer", "jump": "Boolean"}
# Base units per unit name (kg, m, s, rad) and factor: a unit means what its name says.
BASE = {"N": (1, 1, -2, 0), "Hz": (0, 0, -1, 0), "m": (0, 1, 0, 0), "kg": (1, 0, 0, 0),
        "kg.m2": (1, 2, 0, 0), "kg/m3": (1, -3, 0, 0), "Pa": (1, -1, -2, 0),
        "N/m": (1, 0, -2, 0), "N.m/rad": (1, 2, -2, -1), "rad": (0, 0, 0, 1),
        "deg": (0, 0, 0, 1), "s": (0, 0, 1, 0)}


def case_values() -> dict:
    """The start values INTERFACES.md asks for, flattened from blade_a.json."""
    c = json.loads(CASE.read_text())
    b, d, a = c["blade"], c["damper"], c["analysis"]
    v = {"E": b["E"], "rho": b["rho"], "zeta": b["zeta"]}
    for part, keys in (("neck", ("L", "h", "b", "elements")), ("platform", ("L", "m", "J")),
                       ("airfoil", ("L", "h", "b", "elements"))):
        for k in keys:
            v[f"{part}_{k}"] = b[part][k]
    for k in ("CF", "mu", "pitch", "y_P", "beta_L_deg", "beta_R_deg", "kn_flat", "kt_flat",
              "kn_curved", "kt_curved"):
        v[k] = d[k]
    (v["flat1_x"], v["flat1_y"]), (v["flat2_x"], v["flat2_y"]) = d["flat_points"]
    v["curved_x"], v["curved_y"] = d["curved_point"]
    v["f_min"], v["f_max"] = a["f_min"], a["f_max"]
    v["sigma_all"] = a.get("sigma_all", 80e6)
    v["harmonics"] = a.get("harmonics", 1)
    v["F_E"], v["f_exc"] = 5.0, 0.0
    return v


@pytest.mark.parametrize("version", [2, 3])
def test_validate_fmu_reports_no_problems(version):
    assert validate_fmu(str(FMUS[version])) == []


@pytest.mark.parametrize("version", [2, 3])
def test_archive_layout(version):
    with zipfile.ZipFile(FMUS[version]) as zf:
        names = set(zf.namelist())
    bindir = f"binaries/{PLATFORM[version]}/"
    for required in ("modelDescription.xml", "documentation/index.html",
                     bindir + "udmap.so", "documentation/licenses/license.txt",
                     "documentation/licenses/gcc-runtime-copyright.txt",
                     "documentation/licenses/GPL-3.txt", "documentation/licenses/LGPL-2.1.txt",
                     "documentation/licenses/lapack-copyright.txt"):
        assert required in names, required
    assert not any("\\" in n for n in names)
    # nothing for another platform or FMI version, except this version's Windows DLL (built
    # with UDMAP_WINDOWS_FMU, tests/windows)
    windll = "binaries/" + {2: "win64", 3: "x86_64-windows"}[version] + "/udmap.dll"
    assert not [n for n in names if n.startswith("binaries/") and not n.startswith(bindir)
                and n not in ("binaries/", windll, windll[:-len("udmap.dll")])]


@pytest.mark.parametrize("version", [2, 3])
def test_variables_follow_interfaces(version):
    md = description(version)
    # both interfaces from one binary, both with FMU state and directional derivatives (read
    # from the XML: fmpy does not parse every capability flag)
    with zipfile.ZipFile(FMUS[version]) as zf:
        root = ET.fromstring(zf.read("modelDescription.xml"))
    suffix = "" if version == 2 else "s"
    state = "FMUstate" if version == 2 else "FMUState"
    for tag in ("ModelExchange", "CoSimulation"):
        element = root.find(tag)
        assert element is not None, tag
        assert element.get("modelIdentifier") == "udmap"
        for flag in (f"canGetAndSet{state}", f"canSerialize{state}",
                     f"providesDirectionalDerivative{suffix}"):
            assert element.get(flag) == "true", (tag, flag)
    assert md.coSimulation.canHandleVariableCommunicationStepSize
    # model exchange: algebraic, no states, no event indicators, no completed steps needed
    assert md.numberOfContinuousStates == 0 and md.numberOfEventIndicators == 0
    assert not md.derivatives and not md.eventIndicators
    me = root.find("ModelExchange")
    if version == 2:
        assert me.get("completedIntegratorStepNotNeeded") == "true"
    else:
        assert me.get("needsCompletedIntegratorStep") == "false"
    variables = {v.name: v for v in md.modelVariables}
    got_inputs = {n for n, v in variables.items() if v.causality == "input"}
    got_params = {n for n, v in variables.items() if v.causality == "parameter"}
    got_outputs = {n for n, v in variables.items() if v.causality == "output"}
    assert got_inputs == set(INPUTS)
    assert got_params == set(PARAMETERS)
    assert got_outputs == set(OUTPUTS)
    real = "Real" if version == 2 else "Float64"
    integer = "Integer" if version == 2 else "Int32"
    for name, unit in {**INPUTS, **OUTPUTS}.items():
        v = variables[name]
        assert (v.unit or "") == unit, name
        assert v.description, name
        expected = DISCRETE_TYPES.get(name, "Real").replace("Integer", integer)
        assert v.type == expected.replace("Real", real), name
        assert v.variability == ("discrete" if name in DISCRETE_TYPES else "continuous"), name
    for name in PARAMETERS:
        v = variables[name]
        assert v.variability == "tunable" and v.description, name
        assert v.type == (integer if name.endswith("_elements") or name in (
            "harmonics", "blades", "engine_order") else real), name
    assert variables["beta_L_deg"].unit == "deg" and variables["f_min"].unit == "Hz"
    assert variables["sigma_all"].unit == "Pa" and variables["platform_J"].unit == "kg.m2"


@pytest.mark.parametrize("version", [2, 3])
def test_units_are_defined_by_base_units(version):
    md = description(version)
    for unit in md.unitDefinitions:
        b = unit.baseUnit
        got = (b.kg, b.m, b.s, b.rad)
        assert got == BASE[unit.name], unit.name
        factor = 0.017453292519943295 if unit.name == "deg" else 1.0
        assert b.factor == pytest.approx(factor, rel=1e-15)


@pytest.mark.parametrize("version", [2, 3])
def test_start_values_are_blade_a(version):
    variables = {v.name: v for v in description(version).modelVariables}
    for name, value in case_values().items():
        start = variables[name].start
        assert float(start) == value, name
    for name in OUTPUTS:
        assert variables[name].start is None
        assert variables[name].initial in (None, "calculated")


@pytest.mark.parametrize("version", [2, 3])
def test_model_structure(version):
    md = description(version)
    outputs = {u.variable.name: u for u in md.outputs}
    assert set(outputs) == set(OUTPUTS)
    assert {u.variable.name for u in md.initialUnknowns} == set(OUTPUTS)
    deps = {n: {d.name for d in u.dependencies} for n, u in outputs.items()}
    # the response depends on every input; the limit force and lift-off not on the forcing
    assert deps["gamma_P"] == set(INPUTS) and deps["regime"] == set(INPUTS)
    assert deps["F_lim"] == set(INPUTS) - {"F_E", "f_exc"}
    assert deps["lift_off"] == set(INPUTS) - {"F_E", "f_exc"}
    assert deps["F_lim_backbone"] == set(INPUTS) - {"F_E", "f_exc"}
    assert deps["gamma_max"] == deps["jump"] == set(INPUTS)
    assert deps["F_ratio"] == set(INPUTS) - {"f_exc"}
    # every dependency is declared with its kind: non-linear, "dependent"
    for name, u in outputs.items():
        assert u.dependenciesKind == ["dependent"] * len(u.dependencies), name


def test_fmi2_and_fmi3_descriptions_agree():
    md2, md3 = description(2), description(3)
    v2 = {v.name: v for v in md2.modelVariables}
    v3 = {v.name: v for v in md3.modelVariables}
    assert list(v2) == list(v3)
    for name in v2:
        a, b = v2[name], v3[name]
        assert (a.valueReference, a.causality, a.variability, a.unit, a.start, a.min, a.max,
                a.description) == (b.valueReference, b.causality, b.variability, b.unit,
                                   b.start, b.min, b.max, b.description), name
    assert md2.guid == md3.instantiationToken
    assert re.fullmatch(r"\{[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}\}",
                        md2.guid)


@pytest.mark.parametrize("version", [2, 3])
def test_documentation_describes_every_variable(version):
    md = description(version)
    with zipfile.ZipFile(FMUS[version]) as zf:
        html = zf.read("documentation/index.html").decode()
        licence = zf.read("documentation/licenses/license.txt").decode()
        gcc = zf.read("documentation/licenses/gcc-runtime-copyright.txt").decode()
        lapack = zf.read("documentation/licenses/lapack-copyright.txt").decode()
    for v in md.modelVariables:
        row = re.search(r"<tr><td><code>%s</code></td>.*?</tr>" % re.escape(v.name), html)
        if v.causality == "independent":
            continue
        assert row, v.name
        assert v.description.replace("&", "&amp;").replace("<", "&lt;").replace(
            ">", "&gt;") in row.group(0), v.name
    token = md.guid if version == 2 else md.instantiationToken
    assert token in html
    for lib in ("libgfortran", "libquadmath", "LAPACK", "BLAS"):
        assert lib in licence and lib in html
    assert "GCC RUNTIME LIBRARY EXCEPTION" in gcc
    assert "Redistribution and use in source and binary forms" in lapack
