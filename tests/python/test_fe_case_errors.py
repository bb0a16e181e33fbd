"""Bad ``fe`` input: exit status 2, a message naming the field and the file, nothing
half-written (no reduced case, no partial cache entry)."""
from __future__ import annotations

import json
import re

import pytest

from fe_case_fixtures import FORCES, export, run, work  # noqa: F401  (fixtures)


def _edit_file(name, edit):
    def apply(d, case):
        path = d / name
        path.write_text(edit(path.read_text()))
    return apply


def _edit_case(edit):
    def apply(d, case):
        edit(case)
    return apply


def _mass_offdiag(text):
    lines = text.splitlines()
    r, c, v = lines[0].split()          # 1 1 m11; (1, 2) made 10 sqrt(m11 m22): indefinite
    return "\n".join([lines[0], f"1 2 {10 * float(v):.6e}"] +
                     [x for x in lines[1:] if x.split()[:2] != ["1", "2"]]) + "\n"


BAD = {
    "node not in the model": (
        _edit_case(lambda c: c["blade"]["platform"]["nodes"].append(999999)),
        r"blade\.platform\.nodes\[\d+\]: node 999999 is not in the model \(nodes of .*blade\.inp\)"),
    "excitation node not in the model": (
        _edit_case(lambda c: c["blade"]["excitation"].update(node=888888)),
        r"blade\.excitation\.node: node 888888 is not in the model .*blade\.inp"),
    "gauge node not in the model": (
        _edit_case(lambda c: c["blade"]["stress"].update(gauge=[1, 777777])),
        r"blade\.stress\.gauge\[1\]: node 777777 is not in the model .*blade\.inp"),
    "empty platform set": (
        _edit_case(lambda c: c["blade"]["platform"].update(nodes=[])),
        r"blade\.platform\.nodes is empty.*\[case file .*case\.json\]"),
    "empty platform box": (
        _edit_case(lambda c: (c["blade"]["platform"].pop("nodes"),
                              c["blade"]["platform"].update(box=[[1, 1, 1], [2, 2, 2]]))),
        r"blade\.platform\.box selects no node of the model \(nodes of .*blade\.inp\)"),
    "zero-length axis": (
        _edit_case(lambda c: c["blade"]["platform"].update(axis=[0, 0, 0])),
        r"blade\.platform\.axis has zero length.*\[case file .*case\.json\]"),
    "zero-length direction": (
        _edit_case(lambda c: c["blade"]["excitation"].update(direction=[0, 0, 0])),
        r"blade\.excitation\.direction has zero length"),
    "DOF map not matching the matrices": (
        _edit_file("blade.dof", lambda t: "\n".join(t.splitlines()[:-1]) + "\n"),
        r"blade\.files\.sti: .*blade\.sti refers to row \d+ but the DOF map .*blade\.dof has "
        r"\d+ rows"),
    "unsymmetric M": (
        _edit_file("blade.mas", lambda t: t + "4 1 1.0e-3\n"),
        r"blade\.files\.mas: the mass matrix is not symmetric \(.*blade\.mas\)"),
    "indefinite M (negative diagonal)": (
        _edit_file("blade.mas", lambda t: "\n".join(
            [(" ".join(x.split()[:2]) + " -1.0") if x.split()[:2] == ["5", "5"] else x
             for x in t.splitlines()]) + "\n"),
        r"blade\.files\.mas: the mass matrix is not positive definite \(.*blade\.mas\)"),
    "indefinite M (off-diagonal)": (
        _edit_file("blade.mas", _mass_offdiag),
        r"blade\.files\.mas: the mass matrix is not positive definite \(.*blade\.mas\)"),
    "gamma_P does not move in the band's mode": (
        _edit_case(lambda c: c["blade"]["platform"].update(axis=[0, 0, 1])),
        r"blade\.platform\.axis: the platform rotation gamma_P about this axis does not move in "
        r"the band's mode\(s\) at 2613\.5\d* Hz .*blade\.inp"),
    "excitation on the platform": (
        _edit_case(lambda c: c["blade"]["excitation"].update(
            node=c["blade"]["platform"]["nodes"][0])),
        r"blade\.excitation\.node: node \d+ must be a free node off the platform"),
    "missing file": (
        _edit_case(lambda c: c["blade"]["files"].update(mas="nope.mas")),
        r"blade\.files\.mas: file not found: .*nope\.mas"),
    "unknown field": (
        _edit_case(lambda c: c["blade"].update(colour="red")),
        r"blade\.colour: unknown field"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_exits_2_and_writes_nothing(work, capsys, name):
    d, _, case, calls = work
    apply, pattern = BAD[name]
    apply(d, case)
    (d / "case.json").write_text(json.dumps(case))
    (d / "red").mkdir()
    status, out, err = run(["reduce", d / "case.json", "--out", d / "red" / "r.json"], capsys)
    assert status == 2, err
    assert re.search(pattern, err), err
    assert list((d / "red").iterdir()) == []
    cache = d / "cache" / "fe"
    if cache.exists():     # only a complete entry may be there (inputs checked after it)
        assert not any(p.name.startswith(".tmp") for p in cache.iterdir())
    status, _, err2 = run(["backbone", d / "case.json", "--forces", FORCES], capsys)
    assert status == 2
