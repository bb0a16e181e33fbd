"""CalculiX as an independent reference of the rigid platform: its own eigenfrequencies of the
test blade with a *RIGID BODY platform (bare, and with a rotational spring on the platform's
rotation) against the full model with the platform made rigid by transformation (the reference
of fe_reference.py) and against the reduced model."""
from __future__ import annotations

import re
import subprocess

import numpy as np
import pytest
import scipy.linalg as la

import fe_reference as ref
from udmap.reduction import platform_centred_reduction
from fe_deck import make_deck, write_inp
from udmap.fe import read_fe

AXIS = [0.0, 1.0, 0.0]   # the blade bends in x: the platform rocks about y (rot node DOF 2)
K_SPRING = 1.0e5         # N m/rad on gamma_P
MODES = 6


def ccx_frequencies(directory, job):
    subprocess.run(["ccx", "-i", job], cwd=directory, check=True, capture_output=True,
                   timeout=100)
    text = (directory / f"{job}.dat").read_text()
    block = text.split("E I G E N V A L U E   O U T P U T")[1].split("P A R T I C I P")[0]
    rows = [line.split() for line in block.splitlines()
            if re.match(r"\s+\d+\s+\S+\s+\S+\s+\S+\s+\S+\s*$", line)]
    return np.array([float(r[3]) for r in rows])   # cycles/time


@pytest.fixture(scope="module")
def blade(tmp_path_factory):
    d = tmp_path_factory.mktemp("ccx_rigid")
    deck = make_deck()
    ref_node, rot_node = int(deck.node_ids.max()) + 1, int(deck.node_ids.max()) + 2
    extra = [(ref_node, deck.ref_point), (rot_node, deck.ref_point)]
    rigid = f"*RIGID BODY, NSET=PLAT, REF NODE={ref_node}, ROT NODE={rot_node}"
    spring = (f"*ELEMENT, TYPE=SPRING1, ELSET=ESPRING\n900001, {rot_node}\n"
              f"*SPRING, ELSET=ESPRING\n2\n{K_SPRING!r}")
    freq = f"*STEP\n*FREQUENCY\n{MODES}\n*END STEP"
    write_inp(deck, d / "export.inp", "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP")
    write_inp(deck, d / "bare.inp", freq, extra_nodes=extra, extra=rigid)
    write_inp(deck, d / "stuck.inp", freq, extra_nodes=extra, extra=rigid + "\n" + spring)
    subprocess.run(["ccx", "-i", "export"], cwd=d, check=True, capture_output=True, timeout=100)
    fe = read_fe({"format": "calculix", "files": {k: f"export.{k}" for k in
                                                  ("sti", "mas", "dof", "inp")}}, d)
    return {"deck": deck, "fe": fe, "bare": ccx_frequencies(d, "bare"),
            "stuck": ccx_frequencies(d, "stuck")}


def test_rigid_platform_equals_calculix_rigid_body(blade):
    deck, fe = blade["deck"], blade["fe"]
    rig = ref.rigid_platform(fe, deck.platform, deck.ref_point, AXIS, deck.exc_node,
                             [1, 0, 0])
    bare = ref.frequencies(rig.K, rig.M, 1.01 * blade["bare"][-1])[:MODES]
    K = rig.K.tolil()
    K[rig.gamma, rig.gamma] += K_SPRING
    stuck = ref.frequencies(K.tocsr(), rig.M, 1.01 * blade["stuck"][-1])[:MODES]
    # The spring raises the first bending mode (the platform rocks in it) and no other much.
    assert blade["stuck"][0] > 1.05 * blade["bare"][0]
    np.testing.assert_allclose(bare, blade["bare"], rtol=1e-5)
    np.testing.assert_allclose(stuck, blade["stuck"], rtol=1e-5)


def test_reduced_model_equals_calculix_rigid_body(blade):
    deck, fe = blade["deck"], blade["fe"]
    f1 = blade["bare"][0]
    red = platform_centred_reduction(
        fe, platform_nodes=deck.platform, ref_point=deck.ref_point, axis=AXIS,
        exc_node=deck.exc_node, exc_direction=[1, 0, 0], f_max=1.05 * f1)
    g = red.gamma_dof - 1
    K = np.array(red.K, dtype=float)
    bare = np.sqrt(la.eigh(K, red.M, eigvals_only=True)[0]) / (2 * np.pi)
    K[g, g] += K_SPRING
    stuck = np.sqrt(la.eigh(K, red.M, eigvals_only=True)[0]) / (2 * np.pi)
    assert bare == pytest.approx(blade["bare"][0], rel=1e-5)
    assert stuck == pytest.approx(blade["stuck"][0], rel=1e-5)
