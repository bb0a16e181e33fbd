"""A `matrices` blade whose M is only positive semi-definite (massless directions, as a reduced
beam or shell model or a C3D20R blade can have): the modes of infinite frequency enter the
receptances as their static part z z^T, so H_gE, H_gg, H_EE and the stress receptances equal a
direct dense solve of (K (1 + i omega beta) - omega^2 M) q = e (PHYSICS.md 1.2, 1.3) to 1e-10,
on the modal path and above it; the natural frequencies are the finite ones. An M with an
eigenvalue below -1e-12 max|M| is refused, rounding is not."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la

from udmap import UdmapError
from udmap.blade import Blade
from udmap.case.fe import _write_mtx_dense, _write_mtx_vector

GAMMA, ZETA = 5, 0.002
# (DOFs, 0-based rows of the diagonal mass that are zero): 11 finite modes (8 summed term by
# term, 3 in the series with the massless part), and 7 (all summed, the massless part alone)
SIZES = {"series": (14, (3, 8, 11)), "all_summed": (10, (2, 6, 8))}


def model(N, MASSLESS):
    """A fixed-free spring chain with coupling springs, its mass B^T D B with three zero
    masses in D: M is singular with a null space that is no coordinate direction."""
    rng = np.random.default_rng(7)
    k = 1e6 * (1 + rng.random(N))
    K = np.diag(k + np.r_[k[1:], 0]) - np.diag(k[1:], 1) - np.diag(k[1:], -1)
    K += 1e4 * np.eye(N)
    d = 0.1 * (1 + rng.random(N))
    d[list(MASSLESS)] = 0
    B = np.eye(N) + 0.2 * rng.standard_normal((N, N))
    M = B.T @ np.diag(d) @ B
    M = 0.5 * (M + M.T)
    sK = 1e5 * rng.standard_normal(N)
    sM = 1e-2 * rng.standard_normal(N)
    return K, M, sK, sM


def blade_from(tmp_path, K, M, sK, sM):
    EXC = K.shape[0]
    _write_mtx_dense(tmp_path / "K.mtx", K)
    _write_mtx_dense(tmp_path / "M.mtx", M)
    _write_mtx_vector(tmp_path / "sK.mtx", sK)
    _write_mtx_vector(tmp_path / "sM.mtx", sM)
    return Blade.matrices(str(tmp_path / "M.mtx"), str(tmp_path / "K.mtx"), GAMMA, EXC,
                          zeta=ZETA, stress_K=str(tmp_path / "sK.mtx"),
                          stress_M=str(tmp_path / "sM.mtx"))


@pytest.mark.parametrize("size", sorted(SIZES))
def test_massless_blade_receptances_equal_direct_solve(size, tmp_path):
    N, MASSLESS = SIZES[size]
    EXC = N
    K, M, sK, sM = model(N, MASSLESS)
    mu = la.eigh(M, K, eigvals_only=True)          # M z = mu K z, mu = 1/omega^2
    assert np.sum(mu < 1e-12 * mu.max()) == len(MASSLESS)      # M is singular
    with pytest.raises(la.LinAlgError):
        np.linalg.cholesky(M)
    finite = np.sort(1 / np.sqrt(mu[mu > 1e-12 * mu.max()])) / (2 * np.pi)
    b = blade_from(tmp_path, K, M, sK, sM)
    nf = N - len(MASSLESS)
    np.testing.assert_allclose(b.natural_frequencies(nf), finite, rtol=1e-12)
    with pytest.raises(UdmapError, match=f"natural frequencies must be from 1 to {nf} "):
        b.natural_frequencies(nf + 1)
    beta = 2 * ZETA / (2 * np.pi * finite[0])
    freqs = np.array([0.3, 0.99, 1.0, 1.01, 1.7, 2.6]) * finite[0]
    freqs = np.r_[freqs, 0.5 * (finite[2] + finite[3]), 0.45 * finite[-3], 0.6 * finite[-3],
                  1.3 * finite[-1]]
    got = b.receptances(freqs)
    worst = 0.0
    for j, f in enumerate(freqs):
        w = 2 * np.pi * f
        D = K * (1 + 1j * w * beta) - w * w * M
        q = np.linalg.solve(D, np.eye(N)[:, [GAMMA - 1, EXC - 1]].astype(complex))
        want = {"gE": q[GAMMA - 1, 1], "gg": q[GAMMA - 1, 0], "EE": q[EXC - 1, 1],
                "sE": (sK - w * w * sM) @ q[:, 1], "sg": (sK - w * w * sM) @ q[:, 0]}
        for name, ref in want.items():
            err = abs(got[name][j] - ref) / abs(ref)
            worst = max(worst, err)
            assert err <= 1e-10, (name, f, ref, got[name][j])
    print(f"massless blade ({size}): largest relative error of the receptances {worst:.1e}")


def test_indefinite_mass_refused_rounding_accepted(tmp_path):
    N, MASSLESS = SIZES["series"]
    K, M, sK, sM = model(N, MASSLESS)
    big = abs(M).max()
    blade_from(tmp_path, K, M - 1e-14 * big * np.eye(N), sK, sM)
    with pytest.raises(UdmapError, match=r"M is not positive definite \(nor semi-definite"):
        blade_from(tmp_path, K, M - 1e-9 * big * np.eye(N), sK, sM)


def test_massless_banded_blade_lowest_modes(tmp_path):
    # 200 DOFs in band storage: the lowest modes by subspace iteration with K^-1 M and the
    # series from solves with K (R_n = a^T K^-1 (M K^-1)^n b - kept modes), exact for a
    # semi-definite M too; every fifth DOF massless (a diagonal M)
    n = 200
    rng = np.random.default_rng(1)
    k = 1e6 * (1 + rng.random(n))
    K = np.diag(k + np.r_[k[1:], 0]) - np.diag(k[1:], 1) - np.diag(k[1:], -1)
    d = 0.1 * (1 + rng.random(n))
    d[::5] = 0
    M = np.diag(d)
    _write_mtx_dense(tmp_path / "K.mtx", K)
    _write_mtx_dense(tmp_path / "M.mtx", M)
    b = Blade.matrices(str(tmp_path / "M.mtx"), str(tmp_path / "K.mtx"), 100, n, zeta=ZETA)
    mu = la.eigh(M, K, eigvals_only=True)
    finite = np.sort(1 / np.sqrt(mu[mu > 1e-12 * mu.max()])) / (2 * np.pi)
    np.testing.assert_allclose(b.natural_frequencies(5), finite[:5], rtol=1e-12)
    beta = 2 * ZETA / (2 * np.pi * finite[0])
    for f in (0.5 * finite[0], finite[0], 1.5 * finite[1]):
        w = 2 * np.pi * f
        q = np.linalg.solve(K * (1 + 1j * w * beta) - w * w * M,
                            np.eye(n)[:, [99, n - 1]].astype(complex))
        r = b.receptances([f])
        for got, want in ((r["gE"][0], q[99, 1]), (r["gg"][0], q[99, 0]),
                          (r["EE"][0], q[n - 1, 1])):
            assert abs(got - want) <= 1e-9 * abs(want), (f, want, got)
