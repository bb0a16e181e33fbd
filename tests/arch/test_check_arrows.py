"""The architecture check (tests/arch/check_arrows.py) on small trees built here under the real
docs/ARCHITECTURE.md: a tree that keeps the rules passes, and each kind of defect injected into it
(a wrong `use` or `import` arrow, a module name off its path, a face with procedures, an import
circle, a private import or attribute) fails with its file:line. The same on a copy of the real
tree: an arrow injected there is reported at its line."""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
import check_arrows  # noqa: E402

# A kernel that keeps the rules of the page: one module per row, each using what it may.
KERNEL = {
    "core/kinds.f90": "module udmap_core_kinds\n  implicit none\nend module udmap_core_kinds\n",
    "core/error.f90": "module udmap_core_error\n  use udmap_core_kinds, only: wp\n"
                      "end module udmap_core_error\n",
    "blade/type.f90": "module udmap_blade_type\n  use udmap_core_error\n  use, intrinsic :: "
                      "iso_c_binding\nend module udmap_blade_type\n",
    "blade/io/mmio.f90": "module udmap_blade_io_mmio\n  use udmap_blade_type\n"
                         "end module udmap_blade_io_mmio\n",
    "damper/tracer/core.f90": "module udmap_damper_tracer_core\n  use udmap_core_kinds\n"
                              "end module udmap_damper_tracer_core\n",
    "damper/type.f90": "module udmap_damper_type\n  use udmap_core_kinds\n"
                       "  use udmap_damper_tracer_core\nend module udmap_damper_type\n",
    "contact/element.f90": "module udmap_contact_element\n  use udmap_core_kinds\n"
                           "end module udmap_contact_element\n",
    "contact/element/jenkins.f90": "module udmap_contact_element_jenkins\n"
                                   "  use udmap_contact_element\n  use udmap_damper_type\n"
                                   "end module udmap_contact_element_jenkins\n",
    "mapping/layer.f90": "module udmap_mapping_layer\n  use udmap_blade_type\n"
                         "  use udmap_damper_type\ncontains\n  subroutine s()\n  end subroutine s\n"
                         "end module udmap_mapping_layer\n",
    "mapping/harmonic/layer.f90": "module udmap_mapping_harmonic_layer\n"
                                  "  use udmap_mapping_layer\n  use udmap_contact_element_jenkins\n"
                                  "end module udmap_mapping_harmonic_layer\n",
    "mapping/model.f90": "module udmap_mapping_model\n  use udmap_mapping_harmonic_layer\n"
                         "end module udmap_mapping_model\n",
    "baseline/hbm.f90": "module udmap_baseline_hbm\n  use udmap_contact_element\n"
                        "end module udmap_baseline_hbm\n",
    "udmap.f90": "module udmap\n  use udmap_mapping_model, only: model_type\n"
                 "  use udmap_baseline_hbm\n  public\nend module udmap\n",
    "api/legacy/arrays.f90": "module udmap_api_legacy_arrays\n  use udmap_mapping_model\n"
                             "end module udmap_api_legacy_arrays\n",
    "api/c/model.f90": "module udmap_api_c_model\n  use udmap_mapping_model\n"
                       "end module udmap_api_c_model\n",
    "core/version.f90.in": "module udmap_core_version\nend module udmap_core_version\n",
}

# A Python package that keeps the rules: errors, _capi, objects, case, doe, cli.
PYTHON = {
    "__init__.py": "from ._capi import version\nfrom .errors import InputError\n"
                   "from .model import Model\n",
    "__main__.py": "from .cli import main\n",
    "errors.py": "class InputError(Exception):\n    pass\n",
    "locate.py": "from .errors import InputError\n",
    "_capi.py": "import ctypes\nfrom .errors import InputError\nfrom . import locate\n\n\n"
                "class Point(ctypes.Structure):\n    _fields_ = []\n\n\n"
                "def version():\n    return Point._fields_\n",
    "blade.py": "from . import _capi\n\n\nclass Blade:\n    def __init__(self):\n"
                "        self._ptr = _capi.Point()\n",
    "damper.py": "from . import _capi\n",
    "plots.py": "from .errors import InputError\n\n\ndef plot(x):\n    return x\n",
    "model.py": "from . import _capi\nfrom .blade import Blade\n\n\nclass Model:\n"
                "    def __init__(self, blade: Blade):\n        self._ptr = blade._ptr\n"
                "        self._err = None\n",
    "fe/__init__.py": "from ._text import read_text\n",
    "fe/_text.py": "from ..errors import InputError\n\n\ndef read_text(p):\n    return p\n",
    "case/__init__.py": "from .load import load_case\n",
    "case/load.py": "from ..fe import read_text\nfrom ..model import Model\nfrom . import schema\n"
                    "from .schema import FIELDS\n\n\ndef load_case(p):\n"
                    "    import udmap.blade as b\n    return Model(b.Blade()), schema.FIELDS\n",
    "case/schema.py": "import typing\nif typing.TYPE_CHECKING:\n    from .load import Case\n"
                      "FIELDS = {}\n_PRIVATE = {}\n",
    "doe/__init__.py": "from .run import run_doe\n",
    "doe/run.py": "from ..case import load_case\nfrom .. import version\n\n\ndef run_doe(p):\n"
                  "    return load_case(p)\n",
    "cli/__init__.py": "from ..doe import run_doe\nfrom ..case.load import load_case\n\n\n"
                       "def main():\n    return run_doe, load_case\n",
}


def make_tree(tmp: Path) -> Path:
    root = tmp / "tree"
    (root / "docs").mkdir(parents=True)
    shutil.copyfile(ROOT / "docs" / "ARCHITECTURE.md", root / "docs" / "ARCHITECTURE.md")
    for rel, text in KERNEL.items():
        f = root / "kernel" / "src" / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(text)
    for rel, text in PYTHON.items():
        f = root / "wrappers" / "python" / "udmap" / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(text)
    return root


def messages(root: Path) -> list[str]:
    return [str(v) for v in check_arrows.check(root)]


def edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, 1))


@pytest.fixture
def tree(tmp_path):
    root = make_tree(tmp_path)
    assert messages(root) == []
    return root


def test_the_page_parses_into_acyclic_rules():
    text = (ROOT / "docs" / "ARCHITECTURE.md").read_text()
    for marker, units in (("kernel", {"core", "blade", "blade/reduce", "damper", "contact",
                                      "mapping", "mapping/harmonic", "baseline", "api/c",
                                      "api/legacy", "udmap.f90"}),
                          ("python", {"_capi", "errors", "blade", "damper", "model", "case",
                                      "doe", "cli", "__init__"})):
        rules, problems = check_arrows.parse_page(text, marker, "ARCHITECTURE.md")
        assert problems == []
        assert units <= set(rules.allowed)
    kernel, _ = check_arrows.parse_page(text, "kernel", "ARCHITECTURE.md")
    assert kernel.allowed["core"] == set() and "udmap.f90" in kernel.faces
    assert "damper" not in kernel.allowed["blade"] and "blade" not in kernel.allowed["damper"]
    assert "baseline" not in kernel.allowed["mapping"]
    # the legacy API on the Fortran types, never on the C API
    assert kernel.allowed["api/legacy"] == {"core", "blade", "damper", "mapping/model.f90"}


def test_a_circle_in_the_page_itself_fails(tree):
    edit(tree / "docs" / "ARCHITECTURE.md", "| `core` | kinds", "| `core` | kinds `blade` |")
    page = tree / "docs" / "ARCHITECTURE.md"
    text = page.read_text().replace("(Brent), version | — |", "(Brent), version | `blade` |")
    page.write_text(text)
    assert any("allowed arrows form a circle" in m for m in messages(tree))


def test_a_wrong_use_fails_naming_file_line_and_arrow(tree):
    edit(tree / "kernel/src/damper/type.f90", "  use udmap_core_kinds\n",
         "  use udmap_core_kinds\n  use udmap_blade_type, only: blade_type\n")
    assert messages(tree) == ["kernel/src/damper/type.f90:3: damper -> blade (use udmap_blade_type)"
                              ": not allowed by docs/ARCHITECTURE.md"]
    out = subprocess.run([sys.executable, str(HERE / "check_arrows.py"), "--root", str(tree)],
                         capture_output=True, text=True)
    assert out.returncode == 1 and "kernel/src/damper/type.f90:3: damper -> blade" in out.stdout


def test_a_file_outside_the_folders_of_the_page_fails(tree):
    (tree / "kernel/src/api_blade.f90").write_text("module udmap_api_blade\nend module\n")
    assert any(m.startswith("kernel/src/api_blade.f90:1: folder (kernel/src itself) has no row")
               for m in messages(tree))


def test_an_import_circle_fails_even_inside_a_function(tree):
    edit(tree / "wrappers/python/udmap/doe/run.py", "    return load_case(p)\n",
         "    from ..cli import main\n    return load_case(p), main\n")
    found = messages(tree)
    assert any("import circle: udmap.cli -> udmap.doe -> udmap.doe.run -> udmap.cli" in m
               for m in found), found
    assert any("doe -> cli (udmap.cli.main): not allowed" in m for m in found)


def test_imports_for_type_checking_are_no_circle(tree):
    text = (tree / "wrappers/python/udmap/case/schema.py").read_text()
    assert "TYPE_CHECKING:\n    from .load import Case" in text     # load -> schema -> load
    assert messages(tree) == []


def test_a_module_without_a_row_fails(tree):
    (tree / "wrappers/python/udmap/doe_exec.py").write_text("from .errors import InputError\n")
    assert messages(tree) == ["wrappers/python/udmap/doe_exec.py:1: module doe_exec has no row in "
                              "docs/ARCHITECTURE.md"]


def test_an_arrow_injected_into_the_real_tree_is_reported(tmp_path):
    """On a copy of this checkout's kernel, package and page (whatever they hold today)."""
    root = tmp_path / "real"
    shutil.copytree(ROOT / "kernel" / "src", root / "kernel" / "src")
    shutil.copytree(ROOT / "wrappers" / "python" / "udmap", root / "wrappers" / "python" / "udmap",
                    ignore=shutil.ignore_patterns("__pycache__", "*.so", "*.fmu"))
    (root / "docs").mkdir()
    shutil.copyfile(ROOT / "docs" / "ARCHITECTURE.md", root / "docs" / "ARCHITECTURE.md")
    before = set(messages(root))
    rules, _ = check_arrows.parse_page((root / "docs" / "ARCHITECTURE.md").read_text(), "kernel",
                                       "page")
    src = root / "kernel" / "src"
    files = sorted(p for p in src.rglob("*.f90"))
    modules = {}
    for f in files:
        for line in f.read_text().splitlines():
            m = check_arrows._MODULE.match(line)
            if m:
                modules[m.group(1).lower()] = f.relative_to(src).as_posix()
    # the file with the fewest allowed arrows, and a module of a unit it may not use
    ranked = []
    for f in files:
        unit = check_arrows._kernel_unit(f.relative_to(src).as_posix(), rules)
        if unit is None or "module " not in f.read_text():
            continue
        banned = sorted(name for name, rel in modules.items()
                        if (u := check_arrows._kernel_unit(rel, rules)) is not None
                        and u != unit and u not in rules.allowed[unit])
        if banned:
            ranked.append((len(rules.allowed[unit]), f, unit, banned[0]))
    assert ranked, "no file in the real kernel that a wrong arrow could be injected into"
    _, target, unit, module = min(ranked, key=lambda r: (r[0], str(r[1])))
    lines = target.read_text().splitlines(keepends=True)
    at = next(i for i, l in enumerate(lines) if check_arrows._MODULE.match(l)) + 1
    lines.insert(at, f"  use {module}\n")
    target.write_text("".join(lines))
    rel = target.relative_to(root).as_posix()
    after = [m for m in messages(root) if m.startswith(f"{rel}:{at + 1}:")]
    assert any(f"{unit} -> " in m and f"(use {module})" in m for m in after), after
    # and a Python arrow upwards: the blade object importing the command line
    blade = root / "wrappers" / "python" / "udmap" / "blade.py"
    blade.write_text(blade.read_text() + "\nfrom .cli import main  # injected\n")
    n = len(blade.read_text().splitlines())
    new = set(messages(root)) - before
    assert any(m.startswith(f"wrappers/python/udmap/blade.py:{n}: blade -> cli") for m in new), new


# Each defect injected alone: its name, the edits (file, old text, new text), the messages.
INJECTED = [
    ('a_folder_without_a_row_follows_the_folder_above',
     [('kernel/src/damper/tracer/core.f90',
       '  use udmap_core_kinds\n',
       '  use udmap_core_kinds\n  use udmap_blade_type\n')],
     ['kernel/src/damper/tracer/core.f90:3: damper -> blade (use udmap_blade_type): not '
      'allowed by docs/ARCHITECTURE.md']),
    ('blade_under_its_readers',
     [('kernel/src/blade/type.f90',
       '  use udmap_core_error\n',
       '  use udmap_core_error\n  use udmap_blade_io_mmio\n')],
     ['kernel/src/blade/type.f90:3: blade -> blade/io (use udmap_blade_io_mmio): not allowed '
      'by docs/ARCHITECTURE.md']),
    ('a_data_module_above_its_algorithms_fails',
     [('kernel/src/mapping/layer.f90',
       '  use udmap_damper_type\n',
       '  use udmap_damper_type\n  use udmap_mapping_harmonic_layer\n')],
     ['kernel/src/mapping/layer.f90:4: mapping -> mapping/harmonic (use '
      'udmap_mapping_harmonic_layer): not allowed by docs/ARCHITECTURE.md']),
    ('the_legacy_api_on_the_c_api_fails',
     [('kernel/src/api/legacy/arrays.f90',
       '  use udmap_mapping_model\n',
       '  use udmap_mapping_model\n  USE :: udmap_api_c_model\n')],
     ['kernel/src/api/legacy/arrays.f90:3: api/legacy -> api/c (use udmap_api_c_model): not '
      'allowed by docs/ARCHITECTURE.md']),
    ('a_module_off_its_path_fails',
     [('kernel/src/mapping/layer.f90',
       'module udmap_mapping_layer\n',
       'module udmap_layer\n'),
      ('kernel/src/mapping/harmonic/layer.f90',
       'use udmap_mapping_layer',
       'use udmap_layer')],
     ['kernel/src/mapping/layer.f90:1: module udmap_layer does not follow its path (expected '
      'udmap_mapping_layer)']),
    ('a_face_with_procedures_fails',
     [('kernel/src/udmap.f90',
       '  public\n',
       '  public\ncontains\n')],
     ['kernel/src/udmap.f90:5: udmap.f90 is a face (re-exports only) but holds procedures']),
    ('a_wrong_import_fails',
     [('wrappers/python/udmap/blade.py',
       'from . import _capi\n',
       'from . import _capi\nfrom .plots import plot\n')],
     ['wrappers/python/udmap/blade.py:2: blade -> plots (udmap.plots.plot): not allowed by '
      'docs/ARCHITECTURE.md']),
    ('capi_above_the_objects_fails',
     [('wrappers/python/udmap/doe/run.py',
       'from .. import version\n',
       'from .. import version\nfrom .._capi import Point\n')],
     ['wrappers/python/udmap/doe/run.py:3: doe -> _capi (udmap._capi.Point): not allowed by '
      'docs/ARCHITECTURE.md']),
    ('a_circle_inside_one_package_fails',
     [('wrappers/python/udmap/case/schema.py',
       'FIELDS = {}\n',
       'from . import load\nFIELDS = {}\n')],
     ['wrappers/python/udmap/case/load.py:3: import circle: udmap.case.load -> '
      'udmap.case.schema -> udmap.case.load']),
    ('a_private_name_of_another_module_fails',
     [('wrappers/python/udmap/cli/__init__.py',
       'from ..case.load import load_case\n',
       'from ..case.load import load_case\nfrom ..case.schema import _PRIVATE\n')],
     ['wrappers/python/udmap/cli/__init__.py:3: udmap.cli -> udmap.case.schema._PRIVATE: '
      'private name of another module']),
    ('a_private_attribute_of_another_module_fails',
     [('wrappers/python/udmap/doe/run.py',
       '    return load_case(p)\n',
       '    import udmap.model\n    return load_case(p), udmap.model._helper\n')],
     ['wrappers/python/udmap/doe/run.py:7: udmap.doe.run -> udmap.model._helper: private name '
      'of another module']),
    ('a_private_attribute_of_an_object_fails',
     [('wrappers/python/udmap/doe/run.py',
       '    return load_case(p)\n',
       '    model, fields = load_case(p)\n    return model._err.ptr\n')],
     ['wrappers/python/udmap/doe/run.py:7: udmap.doe.run uses model._err: private attribute '
      'not defined in this module']),
    ('a_private_module_outside_its_package_fails',
     [('wrappers/python/udmap/case/load.py',
       'from ..fe import read_text\n',
       'from ..fe._text import read_text\n')],
     ['wrappers/python/udmap/case/load.py:1: udmap.case.load -> udmap.fe._text: private module '
      'of udmap.fe']),
]


@pytest.mark.parametrize("edits, expected", [c[1:] for c in INJECTED],
                         ids=[c[0] for c in INJECTED])
def test_an_injected_defect_fails_naming_file_and_line(tree, edits, expected):
    for rel, old, new in edits:
        edit(tree / rel, old, new)
    assert messages(tree) == expected
