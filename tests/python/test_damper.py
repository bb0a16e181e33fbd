"""Python Damper class over the C API (PHYSICS.md section 2)."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest
from scipy.interpolate import PchipInterpolator

from udmap import Damper, InputError, PhysicsError

BLADE_A = dict(CF=900.0, mu=0.3, pitch=0.026, y_P=0.006, beta_L_deg=45.0, beta_R_deg=45.0,
               flat_points=[[-6.724e-3, -1.724e-3], [-1.068e-3, 3.932e-3]],
               curved_point=[3.268e-3, 1.768e-3],
               kn_flat=60e6, kt_flat=40e6, kn_curved=80e6, kt_curved=50e6)
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


@pytest.fixture(scope="module")
def blade_a():
    return Damper.asymmetric(**BLADE_A)


def test_blade_a_reference_numbers(blade_a):
    assert blade_a.M_max == pytest.approx(6.44037, abs=1e-5)
    assert blade_a.M_min == pytest.approx(-6.44037, abs=1e-5)
    assert blade_a.gamma_b == pytest.approx(5.4829e-4, rel=1e-4)
    assert blade_a.k_stuck == pytest.approx(12811.12, rel=1e-6)
    assert 0 < blade_a.gamma_s < blade_a.gamma_b
    assert blade_a.lift_off is False


def test_stiffness_shapes_and_limits(blade_a):
    g = np.geomspace(1e-12, 1.0, 50).reshape(5, 10)
    k = blade_a.stiffness(g)
    assert k.shape == (5, 10) and k.dtype == complex
    assert np.all(k.real > 0) and np.all(k.imag >= 0)
    k0 = blade_a.stiffness(1e-12)
    assert isinstance(k0, complex)
    assert k0 == complex(blade_a.k_stuck, 0.0)
    # Below gamma_s no slip at all.
    assert np.all(blade_a.stiffness(np.linspace(1e-6, 0.99, 20) * blade_a.gamma_s).imag == 0)


def test_elongation_energy(blade_a):
    """E(gamma) = E_b + 2 Delta_M (gamma - gamma_b) above gamma_b."""
    gb, dM = blade_a.gamma_b, blade_a.M_max - blade_a.M_min
    g = np.array([1.0, 1.5, 3.0, 10.0]) * gb
    E = math.pi * g**2 * blade_a.stiffness(g).imag
    np.testing.assert_allclose(E, E[0] + 2 * dM * (g - gb), rtol=1e-9)


def test_loop_plateaus_and_describing_function(blade_a):
    for a in (0.8 * blade_a.gamma_b, 3 * blade_a.gamma_b):
        tau, M = blade_a.loop(a, n=20000)
        assert tau[0] == 0 and tau[1] == pytest.approx(2 * math.pi / 20000)
        k_re = np.sum(M * np.cos(tau)) * (2 / len(tau)) / a
        k_im = -np.sum(M * np.sin(tau)) * (2 / len(tau)) / a
        k = blade_a.stiffness(a)
        assert k_re == pytest.approx(k.real, rel=1e-6)
        assert k_im == pytest.approx(k.imag, rel=1e-6)
    tau, M = blade_a.loop(3 * blade_a.gamma_b)
    assert M.max() == pytest.approx(blade_a.M_max, rel=1e-12)
    assert M.min() == pytest.approx(blade_a.M_min, rel=1e-12)


def test_derivative(blade_a):
    g = np.array([0.7, 0.95, 2.0, 20.0]) * blade_a.gamma_b
    h = 1e-6 * g
    fd = (blade_a.stiffness(g + h) - blade_a.stiffness(g - h)) / (2 * h)
    np.testing.assert_allclose(blade_a.stiffness_derivative(g), fd, rtol=1e-5,
                               atol=1e-7 * blade_a.k_stuck / blade_a.gamma_b)


def test_set_CF_scaling_law():
    d = Damper.asymmetric(**BLADE_A)
    g = np.array([0.5, 0.8, 0.95, 1.5, 4.0]) * d.gamma_b
    k = d.stiffness(g)
    d.set_CF(1.5 * BLADE_A["CF"])
    np.testing.assert_allclose(d.stiffness(1.5 * g), k, rtol=1e-12)
    assert d.M_max == pytest.approx(1.5 * 6.440366972477, rel=1e-9)
    traced = Damper.asymmetric(**dict(BLADE_A, CF=1.5 * BLADE_A["CF"]))
    np.testing.assert_allclose(traced.stiffness(1.5 * g), k, rtol=1e-9)
    with pytest.raises(InputError, match="CF"):
        d.set_CF(float("nan"))


def test_lift_off_flag():
    f = np.array(BLADE_A["flat_points"])
    mid, half = f.mean(axis=0), (f[1] - f[0]) / 2
    d = Damper.asymmetric(**dict(BLADE_A, flat_points=[mid - half / 2, mid + half / 2]))
    assert d.lift_off is True


@pytest.mark.parametrize("field, value", [("CF", float("nan")), ("mu", -0.3), ("pitch", 0.0),
                                          ("kn_flat", -1.0), ("kt_curved", float("inf")),
                                          ("beta_R_deg", 90.0), ("y_P", "high")])
def test_bad_parameters_named(field, value):
    with pytest.raises(InputError, match=field):
        Damper.asymmetric(**dict(BLADE_A, **{field: value}))


def test_bad_points_and_amplitudes(blade_a):
    with pytest.raises(InputError, match="curved_point"):
        Damper.asymmetric(**dict(BLADE_A, curved_point=[1.0]))
    with pytest.raises(InputError, match="flat"):
        Damper.asymmetric(**dict(BLADE_A, flat_points=[[0, 0], [0, 0]]))
    with pytest.raises(InputError, match=r"gamma\[1\]"):
        blade_a.stiffness([1e-4, -1e-4])
    with pytest.raises(InputError, match="gamma_a"):
        blade_a.loop(float("nan"))


def test_jammed_damper_is_a_physics_error():
    with pytest.raises(PhysicsError, match="jams"):
        Damper.asymmetric(**dict(BLADE_A, mu=5.0))


def test_jenkins_values():
    d = Damper.jenkins(2.0, 3.0)
    k = d.stiffness([1.6, 2.0, 5.0])
    np.testing.assert_allclose(k.real, [1.947954, 1.608998, 0.504632], atol=1e-6)
    np.testing.assert_allclose(k.imag, [0.149208, 0.477465, 0.534761], atol=1e-6)
    assert (d.gamma_b, d.M_max, d.M_min, d.k_stuck) == (1.5, 3.0, -3.0, 2.0)
    tau, M = d.loop(5.0, 8)
    assert M[0] == 3.0 and M[4] == -3.0


def test_table_against_scipy_pchip():
    jen = Damper.jenkins(2.0, 3.0)
    g = np.geomspace(0.1, 10.0, 25)
    k = jen.stiffness(g)
    t = Damper.table(g, k.real, k.imag, delta_M=6.0)
    x = np.geomspace(0.1, 10.0, 301)
    kt = t.stiffness(x)
    np.testing.assert_allclose(kt.real, PchipInterpolator(np.log(g), k.real)(np.log(x)),
                               rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(kt.imag, PchipInterpolator(np.log(g), k.imag)(np.log(x)),
                               rtol=1e-12, atol=1e-12)
    # Constant below, extrapolated above (exact for a Jenkins element with delta_M = 2 M_slip).
    assert t.stiffness(1e-3) == k[0]
    assert t.stiffness(40.0).imag == pytest.approx(jen.stiffness(40.0).imag, rel=1e-12)
    assert t.stiffness(40.0).real == pytest.approx(k[-1].real * (10 / 40) ** 1.5, rel=1e-12)
    bare = Damper.table(g, k.real, k.imag)
    with pytest.raises(InputError, match="last row"):
        bare.stiffness(20.0)
    with pytest.raises(InputError, match="k_im"):
        Damper.table(g, k.real, -k.imag - 1)
    with pytest.raises(InputError, match="gamma"):
        Damper.table(g[::-1], k.real, k.imag)
    with pytest.raises(InputError, match="table"):
        bare.loop(1.0)


def test_cli_table_json():
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "wrappers", "python"))
    out = subprocess.run([sys.executable, "-m", "udmap", "table",
                          os.path.join(ROOT, "cases", "blade_a.json"), "--gammas",
                          "1e-5,5e-4,3e-3", "--json"], capture_output=True, text=True, env=env,
                         cwd=ROOT, check=True)
    data = json.loads(out.stdout)
    for key in ("gamma_b", "M_max", "M_min", "lift_off", "points"):
        assert key in data
    assert data["M_max"] == pytest.approx(6.44037, abs=1e-5)
    assert data["lift_off"] is False
    assert [p["gamma"] for p in data["points"]] == [1e-5, 5e-4, 3e-3]
    assert data["points"][0]["k_re"] == pytest.approx(12811.12, rel=1e-6)
