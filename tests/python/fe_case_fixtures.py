"""Shared fixtures of the fe case tests: a fresh CalculiX export of the test blade, a case
directory with an empty reduction cache, and a counter of the reductions done."""
from __future__ import annotations

import json
import shutil
import subprocess

import pytest

from fe_deck import make_deck, write_inp
from udmap.cli import main

import udmap.reduction as REDUCTION

FORCES = "0.05,0.2,1"


@pytest.fixture(scope="module")
def export(tmp_path_factory):
    d = tmp_path_factory.mktemp("fe_export")
    deck = make_deck()
    write_inp(deck, d / "blade.inp", "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP")
    subprocess.run(["ccx", "-i", "blade"], cwd=d, check=True, capture_output=True, timeout=100)
    return d, deck


def case_dict(deck):
    return {"name": "hex8 blade",
            "blade": {"kind": "fe", "format": "calculix",
                      "files": {"sti": "blade.sti", "mas": "blade.mas", "dof": "blade.dof",
                                "inp": "blade.inp"},
                      "platform": {"nodes": list(deck.platform), "ref_point": list(deck.ref_point),
                                   "axis": [0, 1, 0]},
                      "excitation": {"node": deck.exc_node, "direction": [1, 0, 0]},
                      "stress": {"gauge": list(deck.gauge), "E": 2.0e11},
                      "zeta": 0.002},
            "damper": {"kind": "jenkins", "kt": 1.0e5, "M_slip": 0.05},
            "analysis": {"f_min": 2400, "f_max": 3000}}


@pytest.fixture
def work(export, tmp_path, monkeypatch):
    """A case directory with its own copy of the export and an empty cache; counts reductions."""
    d, deck = export
    for name in ("blade.sti", "blade.mas", "blade.dof", "blade.inp"):
        shutil.copy(d / name, tmp_path / name)
    monkeypatch.setenv("UDMAP_CACHE_DIR", str(tmp_path / "cache"))
    calls = []
    real = REDUCTION.platform_centred_reduction

    def counted(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)
    monkeypatch.setattr(REDUCTION, "platform_centred_reduction", counted)
    case = case_dict(deck)
    (tmp_path / "case.json").write_text(json.dumps(case))
    return tmp_path, deck, case, calls


def run(args, capsys):
    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err
