"""The generated blade as CalculiX solids (udmap.fe.generator.quadratic_mesh), shared by the FE
tests: K and M exported by ``ccx`` (*FREQUENCY, SOLVER=MATRIXSTORAGE) and read back, and
CalculiX's own first frequencies with a *RIGID BODY platform, bare and with a rotational spring
on gamma_P (the rotation about z: ROT NODE DOF 3)."""
from __future__ import annotations

import subprocess

from test_fe_calculix import ccx_frequencies
from udmap.fe import read_fe
from udmap.fe.generator import generate_blade, quadratic_mesh, write_solid_deck

K_SPRING = 1.0e5         # N m/rad on gamma_P


def solid_blade(d, n_dofs: int, shape: str = "brick", brick: str = "C3D20R") -> dict:
    """In directory d: the blade of about n_dofs linear DOFs meshed as ``shape``, its model,
    and CalculiX's frequencies "bare" and "stuck"."""
    b = generate_blade(n_dofs)
    mesh = quadratic_mesh(b, shape)
    ref_node, rot_node = mesh.xyz.shape[0] + 1, mesh.xyz.shape[0] + 2
    extra = [(ref_node, b.ref_point), (rot_node, b.ref_point)]
    rigid = f"*RIGID BODY, NSET=PLATFORM, REF NODE={ref_node}, ROT NODE={rot_node}"
    spring = (f"*ELEMENT, TYPE=SPRING1, ELSET=ESPRING\n900001, {rot_node}\n"
              f"*SPRING, ELSET=ESPRING\n3\n{K_SPRING!r}")
    freq = "*STEP\n*FREQUENCY\n2\n*END STEP"
    write_solid_deck(b, mesh, d / "export.inp", brick=brick)
    write_solid_deck(b, mesh, d / "bare.inp", brick=brick, step=freq, extra_nodes=extra,
                     extra=rigid)
    write_solid_deck(b, mesh, d / "stuck.inp", brick=brick, step=freq, extra_nodes=extra,
                     extra=rigid + "\n" + spring)
    subprocess.run(["ccx", "-i", "export"], cwd=d, check=True, capture_output=True, timeout=300)
    fe = read_fe({"format": "calculix", "files": {k: f"export.{k}" for k in
                                                  ("sti", "mas", "dof", "inp")}}, d)
    return {"blade": b, "mesh": mesh, "fe": fe, "dir": d, "bare": ccx_frequencies(d, "bare"),
            "stuck": ccx_frequencies(d, "stuck")}
