"""Case-file validation: every defect is named by its field, exit status 2, nothing written."""
import copy
import json
import subprocess
import sys
from pathlib import Path

import pytest

from udmap import InputError
from udmap.case import DEFAULT_CASE, load_case, validate

ROOT = Path(__file__).resolve().parents[2]
BLADE_A = json.loads((ROOT / "cases" / "blade_a.json").read_text())


def test_embedded_default_is_blade_a():
    # The package carries its own copy (it must work when installed); it must not drift.
    assert json.loads(DEFAULT_CASE.read_text()) == BLADE_A


def test_blade_a_validates_with_defaults():
    case = load_case(ROOT / "cases" / "blade_a.json")
    assert case.blade["neck"]["elements"] == 8
    assert case.damper["flat_points"][1] == [-1.068e-3, 3.932e-3]
    assert case.analysis["sigma_all"] == 80e6
    assert case.analysis["f_min"] == 150.0 and case.analysis["f_max"] == 230.0


def _edited(path, value, delete=False):
    data = copy.deepcopy(BLADE_A)
    node = data
    for key in path[:-1]:
        node = node[key]
    if delete:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    return data


@pytest.mark.parametrize("path,value,delete,needle", [
    (("blade", "neck", "L"), -0.02, False, "blade.neck.L must be in [0.0001, 3] m, got -0.02"),
    (("blade", "E"), float("nan"), False, "blade.E must be in [1e6, 1e13] Pa, got NaN"),
    (("blade", "airfoil", "elements"), 23, False, "blade.airfoil.elements must be an even integer in [2, 1000], got 23"),
    (("blade", "airfoil", "elements"), 2.5, False, "blade.airfoil.elements must be an even integer in [2, 1000], got 2.5"),
    (("blade", "platform", "J"), None, True, "blade.platform.J: missing field"),
    (("blade", "platform", "Jx"), 1.0, False, "blade.platform.Jx: unknown field"),
    (("blade", "kind"), "shell", False, "blade.kind must be"),
    (("damper", "mu"), "0.3", False, "damper.mu must be a number"),
    (("damper", "kt_flat"), -1.0, False, "damper.kt_flat must be in [100, 1e12] N/m, got -1"),
    (("damper", "CF"), True, False, "damper.CF must be a number"),
    (("damper", "beta_L_deg"), 95.0, False, "damper.beta_L_deg must be in (0, 90) deg, got 95"),
    (("damper", "flat_points"), [[0.0, 0.0]], False, "damper.flat_points must be 2 points"),
    (("damper", "curved_point"), [0.0, float("inf")], False, "damper.curved_point[1] must be"),
    (("damper", "kind"), "wedge", False, "damper.kind must be"),
    (("analysis", "f_max"), 100.0, False, "analysis.f_max (100.0) must exceed"),
    (("analysis", "f_min"), None, True, "analysis.f_min: missing field"),
    (("analysis", "speed"), 1, False, "analysis.speed: unknown field"),
])
def test_bad_fields_are_named(path, value, delete, needle):
    with pytest.raises(InputError, match=None) as info:
        validate(_edited(path, value, delete))
    assert needle in str(info.value)


def test_missing_section_and_unknown_top_level():
    data = copy.deepcopy(BLADE_A)
    del data["damper"]
    with pytest.raises(InputError, match="damper: missing section"):
        validate(data)
    with pytest.raises(InputError, match="bladez: unknown top-level field"):
        validate(dict(BLADE_A, bladez={}))


def test_nan_literal_and_bad_json_rejected(tmp_path):
    p = tmp_path / "c.json"
    p.write_text(json.dumps(BLADE_A).replace('"mu": 0.3', '"mu": NaN'))
    with pytest.raises(InputError, match="damper.mu: NaN is not a valid number in a case file"):
        load_case(p)
    p.write_text("{ not json")
    with pytest.raises(InputError, match="invalid JSON"):
        load_case(p)
    with pytest.raises(InputError, match="case file"):
        load_case(tmp_path / "missing.json")


def test_matrices_paths_resolved_and_checked(tmp_path):
    data = {"blade": {"kind": "matrices", "M": "M.mtx", "K": "K.mtx", "gamma_dof": 1,
                      "exc_dof": 1, "zeta": 0.0},
            "damper": {"kind": "jenkins", "kt": 0.25, "M_slip": 0.2},
            "analysis": {"f_min": 0.1, "f_max": 0.3}}
    with pytest.raises(InputError, match="blade.M: file not found"):
        validate(data, tmp_path)
    (tmp_path / "M.mtx").write_text("x")
    (tmp_path / "K.mtx").write_text("x")
    case = validate(data, tmp_path)
    assert Path(case.blade["M"]) == tmp_path / "M.mtx"


def test_table_csv_checked(tmp_path):
    data = {"blade": BLADE_A["blade"], "damper": {"kind": "table", "file": "k.csv"},
            "analysis": BLADE_A["analysis"]}
    (tmp_path / "k.csv").write_text("gamma,k_re,k_im\n1e-5,1e4,0\n1e-4,9e3,5e2\n")
    case = validate(data, tmp_path)
    assert case.damper["rows"] == [(1e-5, 1e4, 0.0), (1e-4, 9e3, 5e2)]
    (tmp_path / "k.csv").write_text("gamma,k_re,k_im\n1e-4,1e4,0\n1e-5,9e3,5e2\n")
    with pytest.raises(InputError, match="strictly ascending"):
        validate(data, tmp_path)
    (tmp_path / "k.csv").write_text("1e-5,1e4,0\n1e-4,abc,5e2\n")
    with pytest.raises(InputError, match="k.csv:2"):
        validate(data, tmp_path)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "udmap", *args], capture_output=True,
                          text=True, cwd=ROOT, timeout=60)


def test_cli_bad_case_exit_2_names_field(tmp_path):
    p = tmp_path / "bad.json"
    p.write_text(json.dumps(_edited(("damper", "kn_curved"), -5.0)))
    r = _cli("backbone", str(p), "--forces", "1,2", "--json")
    assert r.returncode == 2
    assert "damper.kn_curved must be in [100, 1e12] N/m, got -5" in r.stderr
    assert r.stdout == ""


@pytest.mark.parametrize("args", [
    ("backbone", "cases/blade_a.json"),                       # missing --forces
    ("backbone", "cases/blade_a.json", "--forces", "1,x"),
    ("backbone", "cases/blade_a.json", "--forces", "0"),
    ("response", "cases/blade_a.json", "--forces", "1"),      # missing --freq
    ("curves", "cases/blade_a.json", "--forces", "1", "--layers", "0"),
    ("table", "cases/blade_a.json", "--gammas", "nan"),
    ("dti", "cases/blade_a.json", "--forces", "1"),           # needs --freq or --peak
    ("nosuchcommand",),
])
def test_cli_bad_arguments_exit_2(args):
    r = _cli(*args)
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert r.stdout == ""


def test_numerical_settings_validated_and_passed():
    data = copy.deepcopy(BLADE_A)
    data["analysis"]["eigen_method"] = "secant"
    with pytest.raises(InputError, match="analysis.eigen_method must be one of"):
        validate(data)
    data["analysis"]["eigen_method"] = "modal"
    data["analysis"]["sweep_points"] = 1000
    case = validate(data)
    assert case.analysis["eigen_method"] == "modal" and case.analysis["dense_max"] == 200
