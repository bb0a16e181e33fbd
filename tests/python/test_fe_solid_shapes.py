"""Tetrahedral and mixed meshes (issue 20): the generated blade in 10-node tetrahedra (C3D10,
each brick split in six) and in 20-node bricks with the airfoil in 15-node wedges (C3D20R with
C3D15), exported by ccx and read like any CalculiX export. Each reduces; the reduced model
agrees with CalculiX's own *RIGID BODY platform, bare and with a rotational spring on gamma_P, to
1e-5 (CalculiX prints 7 digits), and with the full model to 1e-6."""
from __future__ import annotations

import numpy as np
import pytest

from ccx_solids import K_SPRING, solid_blade
from udmap.fe._deck import element_types
from udmap.reduction import platform_centred_reduction

SHAPES = {"tetra": {"C3D10"}, "mixed": {"C3D20R", "C3D15"}}


@pytest.fixture(scope="module", params=sorted(SHAPES))
def blade(request, tmp_path_factory):
    shape = request.param
    return shape, solid_blade(tmp_path_factory.mktemp(shape), 1200, shape)


def test_reduced_model_equals_calculix_rigid_body(blade):
    shape, c = blade
    b, fe = c["blade"], c["fe"]
    assert set(element_types(c["dir"] / "export.inp", "inp")) == SHAPES[shape]
    red = platform_centred_reduction(fe, platform_nodes=c["mesh"].platform_nodes,
                                     ref_point=b.ref_point, axis=b.axis, exc_node=b.exc_node,
                                     exc_direction=b.exc_direction, f_max=1.05 * c["bare"][0])
    K = np.array(red.K, dtype=float)
    g = red.gamma_dof - 1
    first = []
    for spring in (0.0, K_SPRING):
        K[g, g] += spring
        w = np.linalg.eigvals(np.linalg.solve(red.M, K)).real
        first.append(np.sqrt(np.sort(w)[0]) / (2 * np.pi))
    assert c["stuck"][0] > 1.05 * c["bare"][0]      # the platform rocks in the first mode
    assert first[0] == pytest.approx(c["bare"][0], rel=1e-5)
    assert first[1] == pytest.approx(c["stuck"][0], rel=1e-5)
    assert red.info["inertia_ok"] and len(red.freqs_full) >= 1
    np.testing.assert_allclose(red.freqs_reduced, red.freqs_full, rtol=1e-6)
    print(f"{shape} ({', '.join(sorted(SHAPES[shape]))}), {fe.n} DOFs: bare {first[0]:.7g} Hz "
          f"(CalculiX {c['bare'][0]}), stuck {first[1]:.7g} Hz (CalculiX {c['stuck'][0]})")
