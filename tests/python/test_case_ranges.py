"""The case-file schema (udmap.case.SCHEMA): physical ranges with messages naming the field
and the range, the same ranges in docs/case-files.md and in `doe --vary`, and the multi-harmonic
settings accepted (the FMU's ranges: test_fmu_ranges.py)."""
import copy
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from udmap import doe
from udmap import InputError
from udmap.case import (ANALYSIS_DEFAULTS, SCHEMA, Case, fmt_number, load_case,
                        schema_markdown, validate)

ROOT = Path(__file__).resolve().parents[2]
BLADE_A = json.loads((ROOT / "cases" / "blade_a.json").read_text())


def _edited(path, value):
    data = copy.deepcopy(BLADE_A)
    node = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return data


def _cli(case_path, *args):
    return subprocess.run([sys.executable, "-m", "udmap", "backbone", str(case_path),
                           "--forces", "1,4", "--json", *args], capture_output=True, text=True,
                          cwd=ROOT, timeout=120)


# The three absurd but well-typed values of the issue: input errors naming the field and the
# allowed range (they used to reach the kernel and fail as "M is not positive definite").
@pytest.mark.parametrize("path,value,message", [
    (("blade", "E"), 1e300, "blade.E must be in [1e6, 1e13] Pa, got 1e300"),
    (("blade", "rho"), 1e-12, "blade.rho must be in [100, 30000] kg/m3, got 1e-12"),
    (("blade", "neck", "L"), 1e5, "blade.neck.L must be in [0.0001, 3] m, got 1e5"),
])
def test_absurd_values_are_input_errors_naming_field_and_range(tmp_path, path, value, message):
    p = tmp_path / "absurd.json"
    p.write_text(json.dumps(_edited(path, value)))
    r = _cli(p)
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert r.stderr.strip() == f"udmap: error: {message}"
    assert r.stdout == ""


@pytest.mark.parametrize("section", ["blade", "damper"])
@pytest.mark.parametrize("kind", [["beam"], {"kind": "beam"}, None, True, 0, "fe2"])
def test_kind_of_any_type_is_named(section, kind):
    with pytest.raises(InputError) as info:
        validate(_edited((section, "kind"), kind))
    assert str(info.value).startswith(f"{section}.kind must be one of ")
    assert str(info.value).endswith(json.dumps(kind))


@pytest.mark.parametrize("path,value,message", [
    (("blade", "E"), [170e9], "blade.E must be a number in [1e6, 1e13] Pa, got [170000000000.0]"),
    (("blade", "E"), {"v": 1}, 'blade.E must be a number in [1e6, 1e13] Pa, got {"v": 1}'),
    (("blade", "E"), None, "blade.E must be a number in [1e6, 1e13] Pa, got null"),
    (("blade", "E"), True, "blade.E must be a number in [1e6, 1e13] Pa, got true"),
    (("blade", "E"), "170e9", 'blade.E must be a number in [1e6, 1e13] Pa, got "170e9"'),
    (("blade", "E"), 10**400, "blade.E must be in [1e6, 1e13] Pa, got 1.000e400"),
    (("blade", "neck", "elements"), True, "blade.neck.elements must be an integer in [1, 1000], "
     "got true"),
    (("blade", "neck", "elements"), 8.5, "blade.neck.elements must be an integer in [1, 1000], "
     "got 8.5"),
    (("blade", "neck"), [1, 2], "blade.neck must be an object, got [1, 2]"),
    (("damper", "flat_points"), {"x": 1}, "damper.flat_points must be 2 points"),
    (("damper", "flat_points"), [[0.0, 0.0], "p"], "damper.flat_points[1] must be a point"),
    (("damper", "curved_point"), [0.0, 2.0], "damper.curved_point[1] must be in [-1, 1] m, got 2"),
    (("damper", "beta_R_deg"), 0.0, "damper.beta_R_deg must be in (0, 90) deg, got 0"),
    (("damper", "mu"), 11.0, "damper.mu must be in [0.0001, 10], got 11"),
    (("analysis", "eigen_method"), ["auto"], 'analysis.eigen_method must be one of auto, direct, '
     'modal, got ["auto"]'),
    (("analysis", "rtol"), 1e-2, "analysis.rtol must be in [1e-15, 0.001], got 0.01"),
    (("analysis", "harmonics"), 1.5, 'analysis.harmonics must be 1, an integer in [2, 64] or '
     '"auto", got 1.5'),
    (("analysis", "harmonics"), 0, "analysis.harmonics must be 1"),
    (("analysis", "harmonics"), 101, "analysis.harmonics must be 1"),
    (("analysis", "harmonics"), "Auto", "analysis.harmonics must be 1"),
    (("analysis", "harmonic_tol"), 0.0, "analysis.harmonic_tol must be in [1e-10, 0.1], got 0"),
    (("name",), ["x"], 'name must be a string, got ["x"]'),
    (("description",), 3, "description must be a string, got 3"),
    (("name",), "\ud800", 'name must be valid Unicode text, got "\\ud800"'),
])
def test_wrong_types_and_ranges_are_named(path, value, message):
    with pytest.raises(InputError) as info:
        validate(_edited(path, value))
    assert str(info.value).startswith(message), str(info.value)


def test_nan_and_infinity_literals_name_their_field(tmp_path):
    p = tmp_path / "c.json"
    for literal in ("NaN", "Infinity", "-Infinity"):
        p.write_text(json.dumps(BLADE_A).replace('"E": 170000000000.0', f'"E": {literal}'))
        with pytest.raises(InputError) as info:
            load_case(p)
        assert str(info.value) == (f"blade.E: {literal} is not a valid number in a case file "
                                   "(allowed: [1e6, 1e13] Pa)")
    p.write_text("[" * 100000 + "]" * 100000)
    with pytest.raises(InputError, match="nested too deeply"):
        load_case(p)


def test_every_bound_accepted_and_just_outside_rejected():
    # each range is closed (open for the face angles): both ends load, a step beyond fails
    checked = 0
    for (section, kind), spec in SCHEMA.items():
        if kind not in (None, "beam", "asymmetric"):
            continue
        for name, f in spec.items():
            if f.type not in ("real", "int") or name in ("f_min", "f_max"):
                continue
            path = (section, *name.split("."))
            for end, step in ((f.lo, -1), (f.hi, 1)):
                inside = end if not f.open else end - step * 1e-9 * max(abs(end), 1.0)
                if f.even and int(inside) % 2:
                    inside -= step
                data = _edited(path, inside)
                if name == "engine_order":      # an engine order needs its wheel
                    data["analysis"]["blades"] = 24
                validate(data)
                outside = end + step * max(abs(end), 1.0) * 1e-6 if f.type == "real" \
                    else end + step
                with pytest.raises(InputError, match=re.escape(f"{section}.{name} must be")):
                    validate(_edited(path, outside))
                checked += 1
    assert checked >= 2 * 25


def test_multi_harmonic_settings_load_with_defaults():
    assert ANALYSIS_DEFAULTS["harmonics"] == 1 and ANALYSIS_DEFAULTS["harmonic_tol"] == 1e-3
    case = validate(BLADE_A)
    assert case.analysis["harmonics"] == 1 and case.analysis["harmonic_tol"] == 1e-3
    for h in (1, 2, 7.0, 64, "auto"):
        data = _edited(("analysis", "harmonics"), h)
        data["analysis"]["harmonic_tol"] = 1e-6
        a = validate(data).analysis
        assert a["harmonics"] == (h if h == "auto" else int(h)) and a["harmonic_tol"] == 1e-6


def test_numbers_in_messages():
    assert [fmt_number(x) for x in (1e6, 1e13, 0.3, 1e-4, 9.9e-5, -1.0, 1e5, 99999.5, 1e300,
                                    2.5e-5, 0.0, 8, 10**20, math.nan, -math.inf)] == [
        "1e6", "1e13", "0.3", "0.0001", "9.9e-5", "-1", "1e5", "99999.5", "1e300", "2.5e-5",
        "0", "8", "1.000e20", "NaN", "-inf"]


def test_case_files_guide_table_is_the_schema():
    guide = (ROOT / "docs" / "case-files.md").read_text()
    begin = guide.index("<!-- case-schema:begin")
    block = guide[guide.index("\n", begin) + 1:guide.index("<!-- case-schema:end -->")]
    assert block == schema_markdown()


@pytest.mark.parametrize("vary,message", [
    ("E=1e6:1e300", "--vary E=1e6:1e300: blade.E must be in [1e6, 1e13] Pa, got 1e300"),
    ("rho=1e-12:8000", "--vary rho=1e-12:8000: blade.rho must be in [100, 30000] kg/m3, "
     "got 1e-12"),
    ("neck_L=0.01:1e5", "--vary neck_L=0.01:1e5: blade.neck.L must be in [0.0001, 3] m, "
     "got 1e5"),
    ("mu=0.1:20", "--vary mu=0.1:20: damper.mu must be in [0.0001, 10], got 20"),
    ("flat2_y=-2:0", "--vary flat2_y=-2:0: damper.flat_points[1][1] must be in [-1, 1] m, "
     "got -2"),
    ("neck_elements=1:5000", "--vary neck_elements=1:5000: blade.neck.elements must be an "
     "integer in [1, 1000], got 5000"),
])
def test_doe_ranges_outside_the_schema_are_named(vary, message):
    case = load_case(ROOT / "cases" / "blade_a.json")
    with pytest.raises(InputError) as info:
        doe.parse_vary(case, [vary])
    assert str(info.value) == message


def test_case_is_a_plain_record():
    case = validate(BLADE_A)
    assert isinstance(case, Case) and case.name == "blade_a"
    assert case.to_dict()["blade"] == BLADE_A["blade"]
