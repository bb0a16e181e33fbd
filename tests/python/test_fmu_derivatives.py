"""Directional derivatives (fmi2GetDirectionalDerivative, fmi3GetDirectionalDerivative) of the
real outputs against central differences of the outputs themselves, at forces in the stuck,
partial-slip and gross-slip regimes, FMI 2.0 and FMI 3.0, model exchange and co-simulation.
F_E is analytic (the backbone's envelope-theorem slope), CF exact by the scaling law, mu and
zeta a finite difference inside the FMU (relative step 1e-4); the reference here is a central
difference of relative step 1e-5 with the outputs read back through the FMI."""
from __future__ import annotations

import math

import pytest

from fmu_harness import ERROR, OK, Instance

OUTPUTS = ["gamma_P", "sigma_a", "f_res", "F_lim", "u_E", "k_re", "k_im", "F_ratio"]
CHECKED = ["gamma_P", "sigma_a", "f_res", "F_lim"]
KNOWNS = ["F_E", "mu", "CF", "zeta"]
# force -> contact regime of blade A at the start values
FORCES = {0.2: 0, 0.5: 1, 3.0: 2}
STEP = 1e-5
TOL = 1e-5


def central(fmu, known, names):
    st, (x0,) = fmu.get(known)
    h = STEP * abs(x0)
    ys = []
    for x in (x0 + h, x0 - h):
        assert fmu.set(**{known: x}) == OK
        st, y = fmu.get(*names)
        assert st == OK
        ys.append(y)
    assert fmu.set(**{known: x0}) == OK
    return [(a - b) / (2 * h) for a, b in zip(*ys)], x0


def agree(d, fd, y, x):
    """Relative agreement to TOL; where the derivative vanishes (e.g. d gamma_P / d mu when
    stuck) a difference of elasticity |x/y (d - fd)| below 1e-9 counts as agreement."""
    return abs(d - fd) <= max(TOL * abs(fd), 1e-9 * abs(y) / abs(x))


@pytest.mark.parametrize("version,model_exchange", [(2, False), (2, True), (3, False),
                                                    (3, True)])
def test_derivatives_equal_central_differences(version, model_exchange):
    fmu = Instance(version, model_exchange=model_exchange)
    assert fmu.setup() == OK
    worst = {}
    for F, regime in FORCES.items():
        assert fmu.set(F_E=F) == OK
        st, (reg,) = fmu.get("regime")
        assert st == OK and reg == regime, (F, reg)
        st, y0 = fmu.get(*CHECKED)
        for known in KNOWNS:
            st, d = fmu.derivative(CHECKED, [known], [1.0])
            assert st == OK, fmu.messages()
            fd, x0 = central(fmu, known, CHECKED)
            for name, a, b, y in zip(CHECKED, d, fd, y0):
                assert agree(a, b, y, x0), f"d{name}/d{known} at F_E={F}: {a!r} vs {b!r}"
                if abs(b * x0) > 1e-6 * abs(y):  # a derivative that does not vanish
                    worst[known] = max(worst.get(known, 0.0), abs(a - b) / abs(b))
    print(f"FMI {version} {'ME' if model_exchange else 'CS'} worst relative difference per "
          f"known: " + ", ".join(f"{k} {v:.1e}" for k, v in worst.items()))
    fmu.free()


def test_known_slopes_and_seed_vectors():
    fmu = Instance(3, model_exchange=True)
    assert fmu.setup() == OK
    assert fmu.set(F_E=0.2) == OK  # stuck: linear in F_E, f_res and F_lim do not move
    st, (g, s, f, F_lim, u, k_re, k_im, ratio) = fmu.get(*OUTPUTS)
    st, d = fmu.derivative(OUTPUTS, ["F_E"], [1.0])
    assert st == OK
    assert d[0] == pytest.approx(g / 0.2, rel=1e-12)
    assert d[1] == pytest.approx(s / 0.2, rel=1e-12)
    assert d[4] == pytest.approx(u / 0.2, rel=1e-12)
    assert d[2] == 0.0 and d[3] == 0.0 and d[5] == 0.0 and d[6] == 0.0
    assert d[7] == pytest.approx(1.0 / F_lim, rel=1e-15)
    # F_lim is proportional to CF (PHYSICS.md 2.3): dF_lim/dCF = F_lim / CF
    st, (CF,) = fmu.get("CF")
    st, (dF_lim,) = fmu.derivative(["F_lim"], ["CF"], [1.0])
    assert dF_lim == pytest.approx(F_lim / CF, rel=1e-12)
    # one call with a seed over several knowns is the same linear combination
    assert fmu.set(F_E=3.0) == OK
    seed = [0.7, -2.0, 0.01, 0.05]
    st, combined = fmu.derivative(OUTPUTS, KNOWNS, seed)
    assert st == OK
    parts = [fmu.derivative(OUTPUTS, [k], [1.0])[1] for k in KNOWNS]
    for i, name in enumerate(OUTPUTS):
        expected = sum(w * p[i] for w, p in zip(seed, parts))
        assert combined[i] == pytest.approx(expected, rel=1e-6, abs=1e-12 * abs(parts[0][i])), name
    fmu.free()


def test_response_at_a_given_frequency():
    fmu = Instance(2)
    assert fmu.setup() == OK
    assert fmu.set(f_exc=185.0, F_E=3.0) == OK
    st, y0 = fmu.get(*CHECKED)
    for known in ("F_E", "CF", "mu", "f_exc"):
        st, d = fmu.derivative(CHECKED, [known], [1.0])
        assert st == OK
        fd, x0 = central(fmu, known, CHECKED)
        for name, a, b, y in zip(CHECKED, d, fd, y0):
            assert agree(a, b, y, x0), f"d{name}/d{known}: {a!r} vs {b!r}"
    fmu.free()


def test_bad_requests_are_errors():
    fmu = Instance(2)
    assert fmu.setup() == OK
    st, _ = fmu.derivative(["F_E"], ["mu"], [1.0])  # an input is no unknown
    assert st == ERROR and "not a real output" in fmu.messages()[-1]
    st, _ = fmu.derivative(["gamma_P"], ["regime"], [1.0])
    assert st == ERROR and "not a real input" in fmu.messages()[-1]
    st, _ = fmu.derivative(["gamma_P"], ["mu"], [math.nan])
    assert st == ERROR
    # zeta = 0 above the limit force: unbounded, no derivative (and no NaN)
    assert fmu.set(zeta=0.0, F_E=40.0) == 0
    st, d = fmu.derivative(["gamma_P", "sigma_a"], ["F_E"], [1.0])
    assert st == ERROR and "unbounded" in fmu.messages()[-1]
    assert not any(math.isnan(x) for x in d)
    # back in range, the same instance answers again
    assert fmu.set(zeta=0.002, F_E=3.0) == OK
    st, d = fmu.derivative(["gamma_P"], ["zeta"], [1.0])
    assert st == OK and d[0] < 0.0
    fmu.free()
