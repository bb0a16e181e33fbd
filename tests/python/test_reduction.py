"""Platform Centred Reduction (PHYSICS.md 1.3) of a generated 3D solid blade of about 10^4
DOFs, checked against the full model with the same rigid platform, built here independently
(its own transformation, scipy eigsh shift-invert): eigenfrequencies in [0, 3 f_max] to 1e-6
(receptances: test_reduction_receptances.py). Bad input errors."""
import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as sla

from udmap import InputError
from udmap.fe import FEModel
from udmap.fe.generator import brick_matrices, generate_blade
from udmap.reduction import platform_centred_reduction

F_MAX = 1500.0  # [0, 3 f_max] then holds five modes of the generated blade
BAND = (150.0, F_MAX)
ZETA = 0.002


@pytest.fixture(scope="module")
def blade():
    return generate_blade(10_000)


def _args(b, **kw):
    args = dict(platform_nodes=b.platform_nodes, ref_point=b.ref_point, axis=b.axis,
                exc_node=b.exc_node, exc_direction=b.exc_direction,
                stress_rows=[b.gauge_row()], f_max=F_MAX)
    args.update(kw)
    return args


@pytest.fixture(scope="module")
def reduced(blade):
    return platform_centred_reduction(blade.fe, **_args(blade))


def full_model(b):
    """T with q = [every DOF off the platform, u_R (3), theta (3, global)] (independent of the
    kernel's numbering and of its local bases); returns T, K_t, M_t."""
    fe = b.fe
    n = fe.K.shape[0]
    xyz = dict(zip(fe.node_ids.tolist(), fe.node_xyz))
    on = np.isin(fe.dof_node, b.platform_nodes)
    free = np.nonzero(~on)[0]
    nf = free.size
    rows, cols, vals = list(free), list(range(nf)), [1.0] * nf
    for j in np.nonzero(on)[0]:
        c = fe.dof_comp[j] - 1
        r = xyz[int(fe.dof_node[j])] - b.ref_point
        rows.append(j)
        cols.append(nf + c)
        vals.append(1.0)
        for k in range(3):  # (theta x r)_c = sum_k theta_k (e_k x r)_c
            e = np.zeros(3)
            e[k] = 1
            v = np.cross(e, r)[c]
            if v != 0:
                rows.append(j)
                cols.append(nf + 3 + k)
                vals.append(v)
    T = sp.csr_matrix((vals, (rows, cols)), shape=(n, nf + 6))
    return T, (T.T @ fe.K @ T).tocsc(), (T.T @ fe.M @ T).tocsc(), nf


def test_generator_brick_is_exact():
    # A brick's mass sums to rho V per direction; its stiffness has the 6 rigid-body modes
    # as null space exactly (and no other).
    Ke, Me = brick_matrices((0.002, 0.003, 0.004), 2e11, 0.3, 7800.0)
    assert abs(Me[0::3, 0::3].sum() / (7800 * 0.002 * 0.003 * 0.004) - 1) < 1e-14
    w = np.linalg.eigvalsh(Ke)
    assert np.all(np.abs(w[:6]) < 1e-9 * w[-1]) and w[6] > 1e-3 * w[-1]


def test_frequencies_equal_full_model(blade, reduced):
    T, Kt, Mt, nf = full_model(blade)
    top = 3 * F_MAX
    w, _ = sla.eigsh(Kt, k=12, M=Mt, sigma=-1.0, which="LM")
    f_full = np.sort(np.sqrt(np.abs(w)) / (2 * np.pi))
    f_full = f_full[f_full <= top]
    assert 3 <= f_full.size < 12
    assert reduced.freqs_full.size == f_full.size
    assert reduced.freqs_reduced.size == f_full.size
    np.testing.assert_allclose(reduced.freqs_full, f_full, rtol=1e-9)
    np.testing.assert_allclose(reduced.freqs_reduced, f_full, rtol=1e-6)
    print(f"largest relative frequency error in [0, 3 f_max]: "
          f"{np.max(np.abs(reduced.freqs_reduced / f_full - 1)):.2e}")
    info = reduced.info
    assert info["inertia_ok"] and info["full_count"] == f_full.size
    assert info["n_modes"] == info["cut_count"] >= 1
    assert reduced.gamma_dof == 1 and reduced.exc_dof == 7
    assert reduced.M.shape == reduced.K.shape == (info["r"], info["r"])


def test_given_number_of_modes(blade, reduced):
    # n_modes = 2: the inertia check at the midpoint to the third fixed-interface mode
    red = platform_centred_reduction(blade.fe, **_args(blade, n_modes=2, check_full=False))
    assert red.info["n_modes"] == 2 and red.info["cut_count"] == 2 and red.info["cut_found"] == 2
    assert red.freqs_full.size == 0
    np.testing.assert_allclose(red.info["freqs_reduced_all"][:3], reduced.freqs_full[:3],
                               rtol=1e-6)



@pytest.mark.parametrize("change, match", [
    (dict(platform_nodes=[]), "platform_nodes: the platform set is empty"),
    (dict(axis=[0, 0, 0]), "axis: the axis of gamma_P has zero length"),
    (dict(exc_direction=[0, 0, 0]), "exc_direction"),
    (dict(platform_nodes=[99999999]), "platform_nodes: node 99999999 is not in the model"),
    (dict(exc_node=99999999), "exc_node: node 99999999 is not in the model"),
    (dict(clamp_nodes=[99999999]), "clamp_nodes: node 99999999 is not in the model"),
    (dict(f_max=None), "n_modes/f_max"),
    (dict(stress_rows=[np.ones(5)]), "stress_rows: row 0 has 5 entries"),
])
def test_bad_arguments(blade, change, match):
    with pytest.raises(InputError, match=match):
        platform_centred_reduction(blade.fe, **_args(blade, **change))


def test_exc_on_platform(blade):
    with pytest.raises(InputError, match="exc_node: node .* is on the platform"):
        platform_centred_reduction(blade.fe, **_args(blade, exc_node=int(blade.platform_nodes[0])))


def test_collinear_platform(blade):
    # two nodes (no rotational DOFs) cannot carry the rotation about their line
    nodes = blade.platform_nodes[:2]
    with pytest.raises(InputError, match="platform_nodes: the platform nodes do not fix"):
        platform_centred_reduction(blade.fe, **_args(blade, platform_nodes=nodes))


def _with(fe, **kw):
    d = dict(K=fe.K, M=fe.M, dof_node=fe.dof_node, dof_comp=fe.dof_comp, node_ids=fe.node_ids,
             node_xyz=fe.node_xyz)
    d.update(kw)
    return FEModel(**d)


def test_bad_model(blade):
    fe = blade.fe
    n = fe.K.shape[0]
    with pytest.raises(InputError, match="dof_node: 9 entries"):
        platform_centred_reduction(_with(fe, dof_node=fe.dof_node[:9]), **_args(blade))
    with pytest.raises(InputError, match="M: shape"):
        platform_centred_reduction(_with(fe, M=fe.M[:-1, :-1]), **_args(blade))
    bump = sp.csr_matrix(([1.0], ([0], [1])), shape=(n, n))
    with pytest.raises(InputError, match="M: the matrix is not symmetric"):
        platform_centred_reduction(_with(fe, M=fe.M + bump * fe.M.max()), **_args(blade))
    with pytest.raises(InputError, match="K: the matrix is not symmetric"):
        platform_centred_reduction(_with(fe, K=fe.K + bump * fe.K.max()), **_args(blade))
    # indefinite with a positive diagonal: a 2 x 2 block [[m, 3m], [3m, m]] at two free DOFs
    i, j = np.nonzero(fe.dof_node == blade.gauge[0])[0][:2]
    m = fe.M[i, i]
    blk = sp.csr_matrix(([3 * m, 3 * m], ([i, j], [j, i])), shape=(n, n))
    with pytest.raises(InputError, match="M: the mass matrix is not positive definite"):
        platform_centred_reduction(_with(fe, M=fe.M + blk), **_args(blade))
    neg = sp.csr_matrix(([-3 * m], ([i], [i])), shape=(n, n))
    with pytest.raises(InputError, match="M: .*not positive"):
        platform_centred_reduction(_with(fe, M=fe.M + neg), **_args(blade))
    with pytest.raises(InputError, match="dof_comp: components must be 1 to 6"):
        platform_centred_reduction(_with(fe, dof_comp=fe.dof_comp + 6), **_args(blade))
