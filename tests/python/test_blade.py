"""udmap.Blade (wrappers/python/udmap/blade.py) against independent computations: the exported
Matrix Market files read back with scipy, direct solves in numpy (refined with long-double
residuals, since a plain double solve of blade A is only good to ~1e-9 at resonance), a 40-digit
decimal band solve for the 2048-element beam, and the errors raised for bad input."""
from decimal import Decimal, getcontext

import numpy as np
import pytest
import scipy.io

import udmap
from udmap import Blade, InputError

GAMMA, EXC = 16, 39  # 1-based DOFs of blade A
BAND = np.array([150.0, 170.0, 185.0, 187.0, 187.119057676, 187.3, 190.0, 200.0, 215.0, 230.0])


@pytest.fixture(scope="module")
def blade(blade_a_beam):
    return blade_a_beam


@pytest.fixture(scope="module")
def exported(blade, tmp_path_factory):
    d = tmp_path_factory.mktemp("blade_a")
    blade.export(d)
    mats = {name: scipy.io.mmread(str(d / f"{name}.mtx"))
            for name in ("M", "K", "stress_K", "stress_M")}
    dense = {name: (m.toarray() if hasattr(m, "toarray") else np.asarray(m))
             for name, m in mats.items()}
    return d, dense


def refined_solve(K, M, om, beta, k, rhs, iterations=4):
    """Solves (K (1 + i om beta) - om^2 M + k e_g e_g^T) x = rhs by iterative refinement with
    the residual formed in long double from K and M themselves (forming D in double would
    round its entries, a perturbation this stiffness amplifies to ~1e-10)."""
    D = K * (1 + 1j * om * beta) - om ** 2 * M
    D[GAMMA - 1, GAMMA - 1] += k
    Kl, Ml = K.astype(np.longdouble), M.astype(np.longdouble)
    fk = np.clongdouble(1) + 1j * np.longdouble(om) * np.longdouble(beta)
    x = np.linalg.solve(D, rhs).astype(np.clongdouble)
    for _ in range(iterations):
        r = rhs.astype(np.clongdouble) - (fk * (Kl @ x) - np.longdouble(om) ** 2 * (Ml @ x))
        r[GAMMA - 1] -= np.clongdouble(k) * x[GAMMA - 1]
        x = x + np.linalg.solve(D, r.astype(np.complex128))
    return x


def direct(dense, f_hz, beta, k=0.0):
    """Receptances (k = 0) or layer response by direct solves of (D + k e_g e_g^T) q = e."""
    K, M = dense["K"], dense["M"]
    s_k, s_m = dense["stress_K"].ravel(), dense["stress_M"].ravel()
    om = 2 * np.pi * f_hz
    rhs = np.zeros((K.shape[0], 2), complex)
    rhs[EXC - 1, 0] = 1
    rhs[GAMMA - 1, 1] = 1
    q = refined_solve(K, M, om, beta, k, rhs)
    s = s_k.astype(np.longdouble) - np.longdouble(om) ** 2 * s_m.astype(np.longdouble)
    return dict(gE=complex(q[GAMMA - 1, 0]), gg=complex(q[GAMMA - 1, 1]), EE=complex(q[EXC - 1, 0]),
                sE=complex(s @ q[:, 0]), sg=complex(s @ q[:, 1]))


def test_blade_a_size_and_frequencies(blade):
    assert blade.ndof == 64
    assert blade.has_stress
    f = blade.natural_frequencies(3)
    assert f[0] == pytest.approx(187.119057, rel=1e-7)
    assert np.all(np.diff(f) > 0)
    assert "ndof=64" in repr(blade)


def test_exported_matrices_are_symmetric_and_banded(exported):
    _, dense = exported
    K, M = dense["K"], dense["M"]
    assert K.shape == M.shape == (64, 64)
    assert np.array_equal(K, K.T) and np.array_equal(M, M.T)
    i, j = np.nonzero(K)
    assert np.max(np.abs(i - j)) == 3
    # The bare frequencies from scipy's own eigensolver on the exported matrices.
    from scipy.linalg import eigh
    mu = eigh(M, K, eigvals_only=True)  # inverted pencil: accurate lowest modes
    assert np.sqrt(1 / mu[-1]) / (2 * np.pi) == pytest.approx(187.119057676, rel=1e-9)


def test_receptances_against_direct_solves(blade, exported):
    _, dense = exported
    f1 = blade.natural_frequencies(1)[0]
    beta = 2 * 0.002 / (2 * np.pi * f1)
    freqs = np.concatenate([BAND, [50.0, 1079.375, 5000.0, 20000.0]])
    rec = blade.receptances(freqs)
    for i, f in enumerate(freqs):
        ref = direct(dense, f, beta)
        for name in ("gE", "gg", "EE", "sE", "sg"):
            assert abs(rec[name][i] - ref[name]) <= 1e-10 * abs(ref[name]), (name, f)


def test_receptances_shape_follows_input(blade):
    rec = blade.receptances(np.full((2, 3), 200.0))
    assert rec["gE"].shape == (2, 3)
    assert np.all(rec["gE"] == rec["gE"][0, 0])
    assert blade.receptances(200.0)["EE"].shape == ()


@pytest.mark.parametrize("k", [1.3e4, 5e3 + 3e3j, 1e7 + 1e6j])
def test_layer_response_is_the_direct_solve_with_the_damper(blade, exported, k):
    _, dense = exported
    f1 = blade.natural_frequencies(1)[0]
    beta = 2 * 0.002 / (2 * np.pi * f1)
    # Peak of |g~| on a grid: the resonance of the blade with this damper.
    grid = np.linspace(150.0, 400.0, 25001)
    g, _, _ = blade.layer_response(grid, k)
    fpk = grid[np.argmax(np.abs(g))]
    freqs = np.array([150.0, 187.119057676, fpk, fpk + 0.3, 230.0])
    g, s, u = blade.layer_response(freqs, k)
    for i, f in enumerate(freqs):
        ref = direct(dense, f, beta, k)
        assert abs(g[i] - ref["gE"]) <= 1e-10 * abs(ref["gE"])
        assert abs(s[i] - ref["sE"]) <= 1e-10 * abs(ref["sE"])
        assert abs(u[i] - ref["EE"]) <= 1e-10 * abs(ref["EE"])


def test_export_import_round_trip(blade, exported):
    d, _ = exported
    copy = Blade.matrices(d / "M.mtx", d / "K.mtx", GAMMA, EXC, zeta=0.002,
                          stress_K=d / "stress_K.mtx", stress_M=d / "stress_M.mtx")
    assert copy.ndof == 64 and copy.has_stress
    a, b = blade.receptances(BAND), copy.receptances(BAND)
    for name in a:
        np.testing.assert_allclose(b[name], a[name], rtol=1e-12, atol=0)
    plain = Blade.matrices(str(d / "M.mtx"), str(d / "K.mtx"), GAMMA, EXC, zeta=0.002)
    assert not plain.has_stress
    assert np.all(plain.receptances(BAND)["sE"] == 0)
    assert (d / "blade.json").is_file()


def decimal_band_solve(K, M, beta, f_hz, exc, gamma, digits=40):
    """H_gE = q[gamma] for (K (1 + i omega beta) - omega^2 M) q = e_exc by band elimination
    without pivoting in decimal arithmetic (below the first resonance the real part of D is
    positive definite). Complex numbers as (re, im) pairs of Decimals."""
    getcontext().prec = digits
    n = K.shape[0]
    om = Decimal(2) * Decimal("3.14159265358979323846264338327950288419716939937510") * Decimal(f_hz)
    fb = om * Decimal(beta)
    kb = 3
    K, M = K.tocsr(), M.tocsr()
    A = [dict() for _ in range(n)]
    for i in range(n):
        for mat, sign in ((K, 1), (M, -1)):
            row = mat.getrow(i)
            for j, v in zip(row.indices, row.data):
                v = Decimal(float(v))
                re, im = A[i].get(j, (Decimal(0), Decimal(0)))
                if sign > 0:
                    A[i][j] = (re + v, im + v * fb)
                else:
                    A[i][j] = (re - om * om * v, im)
    b = [(Decimal(0), Decimal(0)) for _ in range(n)]
    b[exc] = (Decimal(1), Decimal(0))

    def mul(x, y):
        return (x[0] * y[0] - x[1] * y[1], x[0] * y[1] + x[1] * y[0])

    def div(x, y):
        d = y[0] * y[0] + y[1] * y[1]
        return ((x[0] * y[0] + x[1] * y[1]) / d, (x[1] * y[0] - x[0] * y[1]) / d)

    for k in range(n):
        piv = A[k][k]
        for i in range(k + 1, min(n, k + kb + 1)):
            if k not in A[i]:
                continue
            t = div(A[i][k], piv)
            for j in range(k, min(n, k + kb + 1)):
                if j in A[k]:
                    p = mul(t, A[k][j])
                    re, im = A[i].get(j, (Decimal(0), Decimal(0)))
                    A[i][j] = (re - p[0], im - p[1])
            p = mul(t, b[k])
            b[i] = (b[i][0] - p[0], b[i][1] - p[1])
    x = [None] * n
    for k in range(n - 1, -1, -1):
        s = b[k]
        for j in range(k + 1, min(n, k + kb + 1)):
            if j in A[k]:
                p = mul(A[k][j], x[j])
                s = (s[0] - p[0], s[1] - p[1])
        x[k] = div(s, A[k][k])
    return complex(float(x[gamma][0]), float(x[gamma][1]))


def test_large_beam_against_decimal_band_solve(tmp_path, blade_a_params):
    """2048 airfoil elements (4112 DOFs): a double-precision solve of this stiffness is off by
    ~0.7 %; the kernel (refined solves, series of the dropped modes) must match a 40-digit solve
    of its exported matrices."""
    params = dict(blade_a_params, airfoil_elements=2048)
    big = Blade.beam(**params)
    assert big.ndof == 4112
    f1 = big.natural_frequencies(1)[0]
    assert f1 == pytest.approx(187.119057676, rel=1e-7)
    big.export(tmp_path)
    K = scipy.io.mmread(str(tmp_path / "K.mtx")).tocsr()
    M = scipy.io.mmread(str(tmp_path / "M.mtx")).tocsr()
    beta = 2 * 0.002 / (2 * np.pi * f1)
    gamma, exc = 2 * 8, 2 * 8 + 2048 - 1
    for f in (100.0, 150.0):
        ref = decimal_band_solve(K, M, beta, f, exc - 1, gamma - 1)
        got = big.receptances(f)["gE"]
        assert abs(got - ref) <= 1e-9 * abs(ref), f
        # A plain double-precision sparse solve of the same matrices is far off.
        from scipy.sparse.linalg import spsolve
        om = 2 * np.pi * f
        e = np.zeros(K.shape[0], complex)
        e[exc - 1] = 1
        plain = spsolve((K * (1 + 1j * om * beta) - om ** 2 * M).tocsc(), e)[gamma - 1]
        assert abs(plain - ref) > 1e3 * abs(got - ref)


def test_bad_beam_parameters(blade_a_params):
    BLADE_A = blade_a_params
    with pytest.raises(InputError, match=r"blade\.neck\.L must be a positive finite number"):
        Blade.beam(**dict(BLADE_A, neck_L=-0.02))
    with pytest.raises(InputError, match=r"blade\.E"):
        Blade.beam(**dict(BLADE_A, E=float("nan")))
    with pytest.raises(InputError, match=r"blade\.airfoil\.elements must be an even integer"):
        Blade.beam(**dict(BLADE_A, airfoil_elements=23))
    with pytest.raises(InputError, match=r"blade\.zeta"):
        Blade.beam(**dict(BLADE_A, zeta=-0.1))
    with pytest.raises(InputError, match="missing beam parameter"):
        Blade.beam(**{k: v for k, v in BLADE_A.items() if k != "rho"})
    with pytest.raises(InputError, match="unknown beam parameter"):
        Blade.beam(**BLADE_A, color="red")
    with pytest.raises(InputError, match="neck_elements must be an integer"):
        Blade.beam(**dict(BLADE_A, neck_elements=8.5))
    with pytest.raises(udmap.UdmapError) as info:
        Blade.beam(**dict(BLADE_A, platform_J=0.0))
    assert info.value.status == 2


def test_bad_matrix_files(exported, tmp_path):
    d, _ = exported
    with pytest.raises(InputError, match="not found"):
        Blade.matrices(tmp_path / "none.mtx", d / "K.mtx", GAMMA, EXC)
    bad = tmp_path / "bad.mtx"
    bad.write_text("%%MatrixMarket matrix coordinate real symmetric\n64 64 2\n1 1 1.0\n")
    with pytest.raises(InputError, match=r"bad\.mtx', line 3: file ends after 1 of 2 entries"):
        Blade.matrices(d / "M.mtx", bad, GAMMA, EXC)
    bad.write_text("%%MatrixMarket matrix coordinate real symmetric\n64 64 1\n70 1 1.0\n")
    with pytest.raises(InputError, match=r"index \(70, 1\) out of range"):
        Blade.matrices(d / "M.mtx", bad, GAMMA, EXC)
    bad.write_text("%%MatrixMarket matrix coordinat real symmetric\n64 64 1\n1 1 1.0\n")
    with pytest.raises(InputError, match="unsupported format 'coordinat'"):
        Blade.matrices(d / "M.mtx", bad, GAMMA, EXC)
    bad.write_text("%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 2\n1 2 1\n2 2 2\n")
    eye = tmp_path / "eye.mtx"
    eye.write_text("%%MatrixMarket matrix array real symmetric\n2 2\n1\n0\n1\n")
    with pytest.raises(InputError, match=r"K \('.*bad\.mtx'\) is not symmetric"):
        Blade.matrices(eye, bad, 1, 2)
    with pytest.raises(InputError, match="gamma_dof must be a DOF number from 1 to 64"):
        Blade.matrices(d / "M.mtx", d / "K.mtx", 0, EXC)
    with pytest.raises(InputError, match="exc_dof"):
        Blade.matrices(d / "M.mtx", d / "K.mtx", GAMMA, 65)
    with pytest.raises(InputError, match="stress_K"):
        Blade.matrices(d / "M.mtx", d / "K.mtx", GAMMA, EXC, stress_K=d / "M.mtx")


def test_bad_evaluation_arguments(blade, tmp_path):
    with pytest.raises(InputError, match="nmodes"):
        blade.natural_frequencies(0)
    with pytest.raises(InputError, match="from 1 to 64"):
        blade.natural_frequencies(65)
    with pytest.raises(InputError, match=r"f_hz\[1\] must be a non-negative finite frequency"):
        blade.receptances([100.0, -5.0])
    with pytest.raises(InputError, match="must be finite"):
        blade.layer_response([100.0], complex(float("inf"), 0.0))
    with pytest.raises(InputError, match="does not exist"):
        blade.export(tmp_path / "no" / "such" / "dir")
