"""The fe blade's platform.tangent (PHYSICS.md 2.6, docs/fe-blades.md "Traveling waves"): its
checks (exit 2 naming blade.platform.tangent, before any reduction), the reduced model turned
into the platform's frame (an exact orthogonal change of the translation DOFs: u_P is DOF 4,
v_P DOF 5), the rows that the blade then has, and the reduced case that ``reduce --out``
writes."""
from __future__ import annotations

import json

import numpy as np
import pytest
import scipy.linalg as la

from fe_case_fixtures import export, run, work  # noqa: F401  (fixtures)
from udmap.case import build_blade, load_case
from udmap.fe import read_mm
from udmap.reduction import TRANSLATION_DOFS, platform_frame, platform_rows

AXIS = np.array([0.0, 1.0, 0.0])                   # the test blade's platform axis
TANGENT = np.array([1.0, 0.0, 1.0]) / np.sqrt(2)  # skew: the frame is a real rotation


def _case(d, case, name, **platform):
    c = json.loads(json.dumps(case))
    c["blade"]["platform"].update(platform)
    (d / name).write_text(json.dumps(c))
    return d / name


@pytest.mark.parametrize("tangent,text", [
    ([1.0, 1e-3, 0.0], "blade.platform.tangent must be orthogonal to blade.platform.axis"),
    ([0.0, 2.0, 0.0], "blade.platform.tangent must be orthogonal to blade.platform.axis"),
    ([0.0, 0.0, 0.0], "blade.platform.tangent has zero length"),
    ([1.0, 0.0], "blade.platform.tangent must be three numbers"),
])
def test_bad_tangent_exits_2_before_reducing(work, capsys, tangent, text):  # noqa: F811
    d, deck, case, calls = work
    path = _case(d, case, "bad.json", tangent=tangent)
    status, out, err = run(["backbone", path, "--forces", "0.2", "--json"], capsys)
    assert status == 2 and out == "" and text in err and calls == []


def test_traveling_wave_needs_the_tangent(work, capsys):  # noqa: F811
    d, deck, case, calls = work
    status, out, err = run(["backbone", d / "case.json", "--forces", "0.2", "--json",
                            "--blades", "8", "--engine-order", "1"], capsys)
    assert status == 2 and out == "" and "blade.platform.tangent" in err
    c = json.loads((d / "case.json").read_text())
    c["analysis"].update(blades=8, engine_order=1)
    (d / "w.json").write_text(json.dumps(c))
    status, out, err = run(["backbone", d / "w.json", "--forces", "0.2", "--json"], capsys)
    # the case file's own wave is refused before reducing (a command line's after loading)
    assert status == 2 and "blade.platform.tangent" in err and calls == [1]
    # with the tangent: accepted, and the kernel gets the phase
    path = _case(d, c, "t.json", tangent=[0.0, 0.0, -3.0])   # any length: normalised
    status, out, err = run(["backbone", path, "--forces", "0.2", "--json"], capsys)
    assert status == 0, err
    data = json.loads(out)
    assert (data["engine_order"], data["blades"], data["ibpa_deg"]) == (1, 8, 45.0)


def test_platform_frame_rows_of_a_rigid_translation(work, capsys):  # noqa: F811
    d, deck, case, calls = work
    plain = load_case(d / "case.json")                       # no tangent: not turned
    framed = load_case(_case(d, case, "t.json", tangent=(3 * TANGENT).tolist()))
    assert calls == [1]                    # one reduction: the frame is turned from it
    assert "u_dof" not in plain.blade and build_blade(plain).platform_rows() is None
    assert (framed.blade["u_dof"], framed.blade["v_dof"]) == (4, 5)
    M0 = read_mm(plain.blade["M"], "M").toarray()
    K0 = read_mm(plain.blade["K"], "K").toarray()
    M1 = read_mm(framed.blade["M"], "M").toarray()
    K1 = read_mm(framed.blade["K"], "K").toarray()
    r = len(M0)
    Q = platform_frame(AXIS, TANGENT)
    radial = np.cross(AXIS, TANGENT)
    np.testing.assert_allclose(Q, np.column_stack([TANGENT, radial, AXIS]), atol=1e-15)
    T = np.eye(r)
    k = slice(TRANSLATION_DOFS[0] - 1, TRANSLATION_DOFS[-1])
    T[k, k] = Q
    # an exact orthogonal change of coordinates: M1 = T^T M0 T, same eigenfrequencies
    assert np.abs(M1 - T.T @ M0 @ T).max() <= 1e-14 * np.abs(M0).max()
    assert np.abs(K1 - T.T @ K0 @ T).max() <= 1e-14 * np.abs(K0).max()
    w0, w1 = la.eigh(K0, M0, eigvals_only=True), la.eigh(K1, M1, eigvals_only=True)
    np.testing.assert_allclose(w1, w0, rtol=1e-11)
    # the rows: a rigid translation of the platform along the tangent (the reduced model's
    # platform translation DOFs u_R = TANGENT) gives u_P = 1, v_P = 0; along the radial
    # direction u_P = 0, v_P = 1; along the axis, or a rotation, neither
    u1, v1 = build_blade(framed).platform_rows()
    assert np.flatnonzero(u1).tolist() == [3] and np.flatnonzero(v1).tolist() == [4]
    u0, v0 = platform_rows(r, AXIS, 3 * TANGENT)         # the same rows before turning
    for direction, (u_expected, v_expected) in ((TANGENT, (1, 0)), (radial, (0, 1)),
                                                (AXIS, (0, 0))):
        q = np.zeros(r)
        q[k] = direction
        assert abs(u0 @ q - u_expected) < 1e-15 and abs(v0 @ q - v_expected) < 1e-15
        q1 = T.T @ q                                        # the same motion, turned
        assert abs(u1 @ q1 - u_expected) < 1e-15 and abs(v1 @ q1 - v_expected) < 1e-15
    q = np.zeros(r)
    q[0] = 1.0                                              # gamma_P alone
    assert u0 @ q == 0 and v0 @ q == 0 and u1 @ q == 0 and v1 @ q == 0


def test_reduce_out_writes_u_dof_and_v_dof(work, capsys):  # noqa: F811
    d, deck, case, calls = work
    path = _case(d, case, "t.json", tangent=TANGENT.tolist())
    status, out, err = run(["reduce", path, "--out", d / "red" / "r.json", "--json"], capsys)
    assert status == 0, err
    info = json.loads(out)
    new = json.loads((d / "red" / "r.json").read_text())
    assert (new["blade"]["u_dof"], new["blade"]["v_dof"]) == (4, 5) == (info["u_dof"],
                                                                       info["v_dof"])
    # the written case runs a traveling wave as the fe case does
    args = ["backbone", None, "--forces", "0.2", "--json", "--blades", "8", "--engine-order",
            "3"]
    results = []
    for p in (d / "red" / "r.json", path):
        args[1] = p
        status, out, err = run(args, capsys)
        assert status == 0, err
        results.append(json.loads(out))
    assert results[0]["ibpa_deg"] == results[1]["ibpa_deg"] == 135.0
    assert results[0]["points"] == results[1]["points"]
