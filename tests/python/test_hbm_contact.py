"""The damper's contact law in time through the Python API: one AFT evaluation with the loading
history against the closed-form Jenkins describing function (PHYSICS.md 2.4)."""
import math

import numpy as np
import pytest

from udmap import InputError
from udmap.case import contact_from_section
from udmap.hbm import Contact, hbm_settings, dti_settings


def jenkins_k(kt, M_slip, a):
    a_s = M_slip / kt
    if a <= a_s:
        return complex(kt, 0.0)
    b = math.acos(1 - 2 * a_s / a)
    return complex(kt / math.pi * (b - math.sin(2 * b) / 2),
                   4 * M_slip / (math.pi * a) * (1 - a_s / a))


@pytest.mark.parametrize("a,expected", [(1.6, (1.947954, 0.149208)), (2.0, (1.608998, 0.477465)),
                                        (5.0, (0.504632, 0.534761))])
def test_jenkins_describing_function(a, expected):
    c = Contact.jenkins(2.0, 3.0)
    G = a * np.exp(0.3j)
    M0, M, gmax = c.aft([G])
    k = M[0] / G
    assert abs(k.real - expected[0]) < 6e-7 and abs(k.imag - expected[1]) < 6e-7
    assert abs(k - jenkins_k(2.0, 3.0, a)) < 1e-12
    assert gmax == pytest.approx(a, rel=1e-14)
    assert abs(M0) < 1e-12


def test_sampled_aft_converges():
    c = Contact.jenkins(2.0, 3.0)
    exact = jenkins_k(2.0, 3.0, 2.0)
    errs = [abs(c.aft([2.0], samples=n)[1][0] / 2.0 - exact) for n in (128, 256)]
    assert 3.0 < errs[0] / errs[1] < 5.5


def test_contact_errors():
    with pytest.raises(InputError, match="kt"):
        Contact.jenkins(-1.0, 1.0)
    with pytest.raises(InputError, match="table"):
        contact_from_section({"kind": "table", "file": "x.csv"})
    c = Contact.jenkins(2.0, 3.0)
    with pytest.raises(InputError, match="samples"):
        c.aft([1.0, 0.5], samples=3)
    with pytest.raises(InputError, match="unknown setting"):
        hbm_settings(nonsense=1)
    with pytest.raises(InputError, match="variant"):
        hbm_settings(variant="other")
    assert dti_settings().steps_per_period == 1024
    assert hbm_settings(harmonics=5, variant="full").harmonics == 5
