"""The lift-off jump of PHYSICS.md 2.5 in a traveling wave: blade A's damper with mu = 0.5,
whose F_bb jumps by half at gamma_c ~ 1.42e-3 rad in phase (a contact starts to lift off).

At a phase the action is set-valued on the jump: every blend of its two one-sided values, each
a linear function of the platform's harmonics (kernel/src/mapping/traveling/point.f90,
wave_jump_point). As phi -> 0 the translations drop out and this must become 2.5's
interpolation of k, which the in-phase code computes independently (on the exact describing
function, not on the traveling wave's trace)."""
from __future__ import annotations

import numpy as np
import pytest

from udmap.case import build_blade, build_damper, load_case
from udmap.model import Model

from conftest import CASE

FORCES = [float(F) for F in np.round(np.arange(4.2, 5.85, 0.1), 6)]


@pytest.fixture(scope="module")
def liftoff():
    case = load_case(CASE)
    case.damper = dict(case.damper, mu=0.5)
    blade, damper = build_blade(case), build_damper(case)
    a = case.analysis

    def model(ibpa_deg):
        return Model(blade, damper, a["f_min"], a["f_max"], harmonics=1, ibpa_deg=ibpa_deg)
    return model


def assert_continuous(points):
    """Forces 0.1 N apart into, across and out of a jump: gamma_P does not fall (beyond the
    1e-9 to which the jump is located), sigma_a rises and f_res moves by less than 0.05 Hz."""
    gamma = np.array([p["gamma_P"] for p in points])
    sigma = np.array([p["sigma_a"] for p in points])
    f = np.array([p["f_res"] for p in points])
    assert np.all(np.diff(gamma) >= -1e-9 * gamma[1:]) and np.all(np.diff(sigma) > 0)
    assert np.max(np.abs(np.diff(f))) < 0.05


def test_a_jump_at_a_tiny_phase_is_the_in_phase_jump(liftoff):
    """Over forces below, inside and above the jump: the same points flagged, gamma_P = gamma_c
    to 1e-6, f_res to 2e-6 and sigma_a to 1e-4 (the bounds of the phi -> 0 check of the smooth
    backbone: the wave's trace against the exact describing function)."""
    ref = liftoff(0.0).backbone(FORCES)
    wave = liftoff(1e-4).backbone(FORCES)
    assert [p["jump"] for p in wave] == [p["jump"] for p in ref]
    assert sum(p["jump"] for p in ref) >= 10  # most of the forces lie in the jump
    for p, r in zip(wave, ref):
        tol = 1e-6 if r["jump"] else 1e-4
        assert abs(p["gamma_P"] / r["gamma_P"] - 1) < tol, (p["F_E"], p["gamma_P"], r["gamma_P"])
        assert abs(p["f_res"] / r["f_res"] - 1) < 2e-6, (p["F_E"], p["f_res"], r["f_res"])
        assert abs(p["sigma_a"] / r["sigma_a"] - 1) < 1e-4, (p["F_E"], p["sigma_a"], r["sigma_a"])


def test_the_backbone_crosses_the_jump_continuously(liftoff):
    """gamma_P does not fall (beyond the 1e-9 to which gamma_c is located) and sigma_a rises
    with the force; f_res moves by less than 0.05 Hz between neighbouring forces 0.1 N apart,
    into, across and out of the jump."""
    points = liftoff(1e-4).backbone(FORCES)
    assert_continuous(points)
    # every one of them at gamma_c, which the kernel locates to 1e-9
    inside = np.array([p["gamma_P"] for p in points if p["jump"]])
    assert np.ptp(inside) <= 1e-9 * inside[0]


def test_a_jump_at_15_deg_where_the_branches_overlap():
    """mu = 0.46, CF = 1300 N at -15 deg: F_bb jumps from about 5.3 to 8.7 N, and near the
    jump both branches solve (the upper one already below the lower one's end). The point
    takes the lower branch to its end, whatever the force and the start: 6, 7 and 8 N share
    one gamma_c; gamma_P never falls and sigma_a rises through it. (The nested search alone
    used to return the bracket's end with sigma_a scaled to the force: 7 N below 5 N.)"""
    case = load_case(CASE)
    case.damper = dict(case.damper, mu=0.46, CF=1300.0)
    a = case.analysis
    model = Model(build_blade(case), build_damper(case), a["f_min"], a["f_max"], harmonics=1,
                  ibpa_deg=-15.0)
    points = model.backbone([4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0])
    assert [p["F_E"] for p in points if p["jump"]] == [6.0, 7.0, 8.0]
    inside = np.array([p["gamma_P"] for p in points if p["jump"]])
    assert np.ptp(inside) <= 1e-9 * inside[0]
    gamma = np.array([p["gamma_P"] for p in points])
    sigma = np.array([p["sigma_a"] for p in points])
    assert np.all(np.diff(gamma) >= -1e-9 * gamma[1:]) and np.all(np.diff(sigma) > 0)


def test_a_jump_with_a_gap_at_1_deg(liftoff):
    """At 1 deg no layer solves over some 5e-5 of gamma above gamma_c: the translations
    widen the jump. The set-valued point goes across that gap with the blend (gamma_c + s
    (gamma_+ - gamma_c), gamma_+ the first layer above it, bisected to 1e-9 like gamma_c), so
    the backbone stays continuous: gamma_P inside the jump within [gamma_c, gamma_+] and never
    falling, sigma_a rising, f_res moving by less than 0.05 Hz between forces 0.1 N apart, and
    the forces on either side of the jump on the ordinary branches. (These forces used to fail
    with status 4.)"""
    points = liftoff(1.0).backbone(FORCES)
    jump = [p["jump"] for p in points]
    assert sum(jump) >= 10 and not jump[0] and not jump[-1]
    assert_continuous(points)
    inside = np.array([p["gamma_P"] for p in points if p["jump"]])
    # a gap, not a point: wider than the narrow jump's 1e-6, narrower than 1e-3
    assert 1e-6 * inside[0] < np.ptp(inside) < 1e-3 * inside[0]
