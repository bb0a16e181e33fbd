"""The FMU's inputs and parameters have the ranges of the case-file schema (udmap.case.SCHEMA)
in its variable table (fmu/parameters.h, generated from kernel/parameters.toml as the schema is,
hence the min/max of modelDescription.xml), and a value outside is refused with the case
loader's message under the FMU's name."""
import math
import re
from pathlib import Path

import pytest

from fmu_harness import CASE, ERROR, OK, Instance, description
from udmap import doe
from udmap import InputError
from udmap.case import SCHEMA, fmt_number, load_case, validate

ROOT = Path(__file__).resolve().parents[2]


def _fmu_table() -> dict:
    """name -> (min, max, flags) of the FMU's variable table (fmu/parameters.h)."""
    text = (ROOT / "fmu" / "parameters.h").read_text()
    rows = re.findall(r"X\((\w+), (REAL|INTEGER|BOOLEAN), (\w+), \w+, \"[^\"]*\", [^,]+, "
                      r"([^,]+), ([^,]+), ([^,]+),", text)

    def number(t):
        return math.inf if t.strip() == "NOLIMIT" else float(t)
    return {name: (number(lo), number(hi), flags.strip()) for name, _, caus, lo, hi, flags
            in rows if caus in ("INPUT", "PARAMETER")}


def test_fmu_ranges_are_the_schema():
    # every FMU input and parameter that is a case-file field has the schema's range
    table = _fmu_table()
    case = load_case(CASE)
    names = doe.parameter_names(case)
    compared = 0
    for name, (lo, hi, flags) in table.items():
        if name in ("F_E", "f_exc", "F_E_min", "F_E_max"):  # the FMU's only, not case-file fields
            assert (lo, hi) == (0.0, math.inf), name
            continue
        if name in ("blades", "engine_order"):  # optional analysis fields of the case file
            f = SCHEMA[("analysis", None)][name]
            assert (lo, hi) == (f.lo, f.hi) and flags == "0", (name, lo, hi, flags)
            compared += 1
            continue
        if name == "harmonics":  # 0 stands for "auto", 1 and 2..64 as in the case file
            f = SCHEMA[("analysis", None)]["harmonics"]
            assert (lo, hi) == (0.0, f.hi) and flags == "0", (lo, hi, flags)
            compared += 1
            continue
        path = names[name]
        kind = case.blade["kind"] if path[0] == "blade" else \
            case.damper["kind"] if path[0] == "damper" else None
        dotted = ".".join(k for k in path[1:] if isinstance(k, str))
        f = SCHEMA[(path[0], kind)][dotted]
        assert (lo, hi) == (f.lo, f.hi), (name, (lo, hi), (f.lo, f.hi))
        assert ("OPEN" in flags) == f.open and ("EVEN" in flags) == f.even, name
        compared += 1
    assert compared == 36


@pytest.mark.parametrize("version", [2, 3])
def test_out_of_range_message_is_the_case_file_message(version):
    # the FMU's message is the case loader's for the same value, with the FMU's name for the
    # case file's dotted path
    case = load_case(CASE)
    names = doe.parameter_names(case)
    inst = Instance(version)
    assert inst.setup() == OK
    for name, value in [("E", 1e300), ("rho", 1e-12), ("neck_L", 1e5), ("mu", 0.0),
                        ("kt_flat", 3e12), ("airfoil_elements", 23), ("flat2_y", -1.5),
                        ("beta_R_deg", 90.0), ("zeta", 0.75), ("sigma_all", 2.5e-3)]:
        path = names[name]
        dotted = doe.Parameter("", path, 0, 0).dotted
        with pytest.raises(InputError) as info:
            validate(doe.validation_dict(doe.with_values(case, [path], [value])))
        expected = str(info.value).replace(dotted, name, 1)
        assert inst.set(**{name: value}) == ERROR
        kept = fmt_number(inst.get(name)[1][0])
        assert inst.messages()[-1].split(": ", 1)[1] == f"{expected}; {name} keeps {kept}"
    st, out = inst.outputs()
    assert st == OK and math.isfinite(out["sigma_a"]), inst.messages()
    inst.free()


@pytest.mark.parametrize("version", [2, 3])
def test_model_description_carries_the_ranges(version):
    table = _fmu_table()
    seen = 0
    for v in description(version).modelVariables:
        if v.name not in table:
            continue
        lo, hi, _ = table[v.name]
        assert float(v.min) == lo, v.name
        assert (v.max is None and hi == math.inf) or float(v.max) == hi, v.name
        seen += 1
    assert seen == len(table) == 40
