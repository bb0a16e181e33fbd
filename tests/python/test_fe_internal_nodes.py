"""Internal nodes that the FE code numbers itself (Abaqus: negative ids, no coordinates): fine
anywhere in the model, refused (exit 2 naming the field and the node) on the platform, at the
excitation or in a gauge."""
from __future__ import annotations

import json
import re
import shutil

import numpy as np
import pytest

from udmap.fe import read_fe

from fe_case_fixtures import case_dict, export, run  # noqa: F401  (fixture)
from fe_compare import ccx_section
from fe_writers import with_internal_node, write_labelled


@pytest.fixture
def abaqus_case(export, tmp_path, monkeypatch):
    """The test blade as an Abaqus labelled export with an internal node -1 tied to the tip."""
    d, deck = export
    fe = read_fe(ccx_section("blade"), d)
    K, M, dn, dc = with_internal_node(fe, anchor=int(fe.node_ids[-1]), k=1e7, m=1e-3)
    write_labelled(tmp_path / "K.mtx", K, dn, dc)
    write_labelled(tmp_path / "M.mtx", M, dn, dc)
    shutil.copy(d / "blade.inp", tmp_path / "blade.inp")
    monkeypatch.setenv("UDMAP_CACHE_DIR", str(tmp_path / "cache"))
    case = case_dict(deck)
    case["blade"].update(format="abaqus", files={"stiffness": "K.mtx", "mass": "M.mtx",
                                                 "inp": "blade.inp"})
    return tmp_path, case


BAD = {
    "platform": (lambda b: b["platform"]["nodes"].append(-1),
                 r"blade\.platform\.nodes\[\d+\]: node -1 is an internal node of the FE code, "
                 r"without coordinates \(nodes of .*blade\.inp\)"),
    "excitation": (lambda b: b["excitation"].update(node=-1),
                   r"blade\.excitation\.node: node -1 is an internal node .*blade\.inp"),
    "gauge": (lambda b: b["stress"].update(gauge=[b["stress"]["gauge"][0], -1]),
              r"blade\.stress\.gauge\[1\]: node -1 is an internal node .*blade\.inp"),
}


@pytest.mark.parametrize("where", list(BAD))
def test_internal_node_refused_on_platform_excitation_gauge(abaqus_case, capsys, where):
    d, case = abaqus_case
    edit, pattern = BAD[where]
    edit(case["blade"])
    (d / "case.json").write_text(json.dumps(case))
    (d / "red").mkdir()
    status, _, err = run(["reduce", d / "case.json", "--out", d / "red" / "r.json"], capsys)
    assert status == 2 and re.search(pattern, err), err
    assert list((d / "red").iterdir()) == []


def test_internal_node_elsewhere_reduces(abaqus_case, capsys):
    d, case = abaqus_case
    (d / "case.json").write_text(json.dumps(case))
    status, out, err = run(["reduce", d / "case.json", "--out", d / "red" / "r.json",
                            "--json"], capsys)
    assert status == 0, err
    data = json.loads(out)
    full, red = np.array(data["freqs_full"]), np.array(data["freqs_reduced"])
    assert len(full) and np.max(np.abs(red[:len(full)] / full - 1)) < 1e-6
