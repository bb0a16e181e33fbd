"""The fmpy example of docs/fmu.md runs as written: no fmpy warning (every input set), one row
per force after the co-simulation lag, and the numbers of the package's backbone."""
from __future__ import annotations

import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np

from udmap.case import build_model, load_case

ROOT = Path(__file__).resolve().parents[2]


def snippet() -> str:
    text = (ROOT / "docs" / "fmu.md").read_text()
    m = re.search(r"<!-- fmpy-snippet:begin[^>]*-->\n(.*?)<!-- fmpy-snippet:end -->", text, re.S)
    assert m, "docs/fmu.md has no fmpy snippet between its markers"
    return textwrap.dedent(m.group(1))


def test_the_fmpy_snippet_runs_without_warnings_and_gives_the_backbone(tmp_path, fmus):
    code = snippet().replace('"build/udmap.fmu"', repr(str(fmus[2])))
    code += "\nnp.save(%r, np.array([res['F_E'], res['gamma_P'], res['sigma_a']]))\n" % str(
        tmp_path / "res.npy")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       cwd=tmp_path, timeout=300, env=dict(os.environ))
    assert r.returncode == 0, r.stderr
    assert "arning" not in r.stdout + r.stderr, r.stdout + r.stderr
    F_E, gamma_P, sigma_a = np.load(tmp_path / "res.npy")
    forces = 0.5 * np.arange(1, 21)
    assert np.array_equal(F_E, forces)   # every force answered, the last one included
    model = build_model(load_case(ROOT / "cases" / "blade_a.json"))
    ref = model.backbone(forces[[0, 9, 19]])
    assert np.allclose(gamma_P[[0, 9, 19]], [p["gamma_P"] for p in ref], rtol=1e-12, atol=0)
    assert np.allclose(sigma_a[[0, 9, 19]], [p["sigma_a"] for p in ref], rtol=1e-12, atol=0)
