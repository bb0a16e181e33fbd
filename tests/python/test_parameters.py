"""The parameter table (kernel/parameters.toml) and its generator (cmake/generate_parameters.py):
the currency check that ctest runs as parameters/generated passes on the checked-in tree, and
fails, naming the stale files and how to regenerate them, after a change of the table or a hand
edit of a generated file; regenerating makes the tree current again."""
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GENERATOR = ROOT / "cmake" / "generate_parameters.py"
TABLE = "kernel/parameters.toml"
GENERATED = ("wrappers/python/udmap/parameters.py", "wrappers/c/udmap.h", "fmu/parameters.h",
             "kernel/src/api/legacy/parameters.f90", "kernel/src/api/c/parameters.f90")
MU_RANGE = 'name = "mu"\ntype = "real"\nmin = 1e-4\nmax = 10.0\n'


def _tree(root: Path) -> Path:
    """A copy of the table, the reference case and the generated files under root."""
    for path in (TABLE, "cases/blade_a.json") + GENERATED:
        (root / path).parent.mkdir(parents=True, exist_ok=True)
        (root / path).write_bytes((ROOT / path).read_bytes())
    return root


def _generate(root: Path, *args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(GENERATOR), "--root", str(root), *args],
                          capture_output=True, text=True, timeout=60)


def test_the_checked_in_files_are_current(tmp_path):
    r = _generate(_tree(tmp_path), "--check")
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"{len(GENERATED)} generated files are current" in r.stdout


def test_a_changed_range_makes_the_schema_and_the_fmu_table_stale(tmp_path):
    root = _tree(tmp_path)
    table = root / TABLE
    assert table.read_text().count(MU_RANGE) == 1
    table.write_text(table.read_text().replace(MU_RANGE, MU_RANGE.replace("10.0", "20.0")))
    r = _generate(root, "--check")
    assert r.returncode == 1
    assert ("not current with kernel/parameters.toml: wrappers/python/udmap/parameters.py, "
            "fmu/parameters.h\n") in r.stdout
    assert "regenerate with: python3 cmake/generate_parameters.py" in r.stdout
    # the diff shows the new bound in both
    assert "+    ('damper', 'asymmetric', 'mu', dict(type='real', lo=0.0001, hi=20.0," in r.stdout
    assert '+  X(mu, REAL, INPUT, DAMPER, "", 0.3, 0.0001, 20.0, 0, \\' in r.stdout
    # regenerating makes the tree current, with the new bound
    assert _generate(root).returncode == 0
    assert _generate(root, "--check").returncode == 0
    assert "lo=0.0001, hi=20.0," in (root / GENERATED[0]).read_text()


def test_a_hand_edit_of_a_generated_struct_is_found(tmp_path):
    root = _tree(tmp_path)
    header = root / "wrappers/c/udmap.h"
    text = header.read_text()
    members = "  double E, rho, zeta;\n"
    assert text.count(members) == 1
    header.write_text(text.replace(members, "  double rho, E, zeta;\n"))
    r = _generate(root, "--check")
    assert r.returncode == 1
    assert "not current with kernel/parameters.toml: wrappers/c/udmap.h\n" in r.stdout


def test_the_generated_header_block_is_bounded_by_its_markers(tmp_path):
    root = _tree(tmp_path)
    header = root / "wrappers/c/udmap.h"
    header.write_text(header.read_text().replace("/* generated:end udmap_beam_params */\n", ""))
    r = _generate(root, "--check")
    assert r.returncode != 0
    assert "generated:end udmap_beam_params" in r.stdout + r.stderr
