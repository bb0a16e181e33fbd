"""Stress test of udmap.hbm (standard method and time integration) through the Python API over
extreme but legal inputs: friction 1e-4..2, centrifugal load 1e-3..1e5 N, contact stiffnesses
scaled 1e-3..1e3, amplitudes 1e-12..1 rad, blade damping 0 and 1e-5, forces just below, at and
above F_lim, a band without resonance, near-singular imported matrices. Every call returns
finite numbers or raises a udmap error with a message; nothing crashes, hangs or gives NaN."""
import math

import numpy as np
import pytest
import scipy.io

from udmap import Blade, UdmapError
from udmap import hbm
from udmap.case import contact_from_section, damper_from_section, load_case

DAMPER = load_case().damper


def finite_or_error(fn):
    """Runs fn; returns its result if every number in it is finite, None on a udmap error."""
    try:
        out = fn()
    except UdmapError as exc:
        assert str(exc) and exc.status in (2, 3, 4)
        return None
    for p in out:
        for k, v in p.items():
            if isinstance(v, float):
                assert math.isfinite(v), (k, p)
            elif isinstance(v, list):
                assert all(math.isfinite(x) for x in v), (k, p)
    return out


@pytest.mark.parametrize("mu", [1e-4, 0.3, 2.0])
@pytest.mark.parametrize("CF", [1e-3, 900.0, 1e5])
@pytest.mark.parametrize("kscale", [1e-3, 1e3])
def test_damper_parameters(blade_a_beam, mu, CF, kscale):
    d = dict(DAMPER, mu=mu, CF=CF)
    for k in ("kn_flat", "kt_flat", "kn_curved", "kt_curved"):
        d[k] = DAMPER[k] * kscale
    try:
        c = contact_from_section(d)
    except UdmapError:
        return
    for a in (1e-12, 1e-6, 1e-3, 1.0):
        try:
            M0, M, gmax = c.aft([a, 0.0, 0.2j * a])
        except UdmapError as exc:
            assert str(exc)
            continue
        assert np.all(np.isfinite(M)) and math.isfinite(M0) and gmax > 0
    # a force of the order of the slip moments over the lever arms
    finite_or_error(lambda: hbm.hbm(blade_a_beam, c, 150, 230, [0.01 * mu * CF]))


@pytest.mark.parametrize("zeta", [0.0, 1e-5])
def test_limit_force(zeta, blade_a_params):
    blade = Blade.beam(**dict(blade_a_params, zeta=zeta))
    F_lim = 21.677454956969921  # blade A's damper (backbone)
    for frac in (0.99, 1.0, 1.01):
        pts = finite_or_error(lambda: hbm.hbm(blade, contact_from_section(DAMPER), 150, 230,
                                                  [frac * F_lim],
                                                  damper=damper_from_section(DAMPER)))
        if pts is not None and frac >= 1.0:
            assert pts[0]["regime"] == 3 or pts[0].get("unbounded")
        finite_or_error(lambda: hbm.dti(blade, contact_from_section(DAMPER), [frac * F_lim],
                                        freq=190.0, steps_per_period=64, max_periods=200))


def test_band_without_resonance(blade_a_beam):
    with pytest.raises(UdmapError, match="no resonance"):
        hbm.hbm(blade_a_beam, contact_from_section(DAMPER), 400, 600, [1.0],
                damper=damper_from_section(DAMPER))


def test_near_singular_matrices(tmp_path):
    """Two DOFs joined by a very stiff spring and a nearly massless second mass."""
    M = np.array([[1.0, 0.0], [0.0, 1e-9]])
    K = np.array([[1e8 + 1.0, -1e8], [-1e8, 1e8]])
    for name, A in (("M", M), ("K", K)):
        scipy.io.mmwrite(str(tmp_path / f"{name}.mtx"), A, symmetry="symmetric")
    try:
        blade = Blade.matrices(tmp_path / "M.mtx", tmp_path / "K.mtx", 1, 2, zeta=0.01)
    except UdmapError:
        return
    jen = {"kind": "jenkins", "kt": 0.25, "M_slip": 0.2}
    contact = contact_from_section
    f0 = 1 / (2 * math.pi)
    finite_or_error(lambda: hbm.hbm(blade, contact(jen), 0.5 * f0, 2 * f0, [0.05, 0.3]))
    finite_or_error(lambda: hbm.hbm(blade, contact(jen), 0.5 * f0, 2 * f0, [0.05], variant="full"))
    finite_or_error(lambda: hbm.dti(blade, contact(jen), [0.05], freq=f0, steps_per_period=64,
                                    max_periods=300))
