"""Real exports, written by the FE codes themselves (tests/data/fe/real, README.md there): each is
read with its elastic frequencies equal to what the FE code printed, or refused with the reason.

- CalculiX test-suite decks (GPL-2, LICENSE-CalculiX.txt), run here by ccx with
  ``*FREQUENCY, SOLVER=MATRIXSTORAGE`` in place of their ``*FREQUENCY`` step: against the
  eigenfrequencies of the suite's reference output (``.dat.ref``, 7 digits);
- an MSC Nastran 2016 ``PARAM,EXTOUT,DMIGPCH`` punch with the four DMIGs Nastran writes (FENIAX,
  GPL-3, LICENSE-FENIAX.md), against the eigenvalue table of the same model's ``.f06``."""
from __future__ import annotations

import gzip
import json
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse.linalg as sla

from udmap import InputError
from udmap.cli import main
from udmap.fe import read_fe
from udmap.fe._text import read_text
from udmap.fe.nastran import cards, read_grids

from fe_compare import ccx_section

REAL = Path(__file__).resolve().parents[1] / "data" / "fe" / "real"


def matrixstorage(src: Path, d: Path, job: str) -> dict:
    """The deck with its first ``*FREQUENCY`` step made a ``SOLVER=MATRIXSTORAGE`` one (the
    steps after it left out), run by ccx in ``d``; returns the ``fe`` blade section."""
    out = []
    for line in src.read_text().split("\n"):
        if re.match(r"\s*\*frequency", line, re.I):
            out.append("*FREQUENCY, SOLVER=MATRIXSTORAGE")
            continue
        out.append(line)
        if re.match(r"\s*\*end\s*step", line, re.I) and any("MATRIXSTORAGE" in x for x in out):
            break
    (d / f"{job}.inp").write_text("\n".join(out) + "\n")
    subprocess.run(["ccx", "-i", job], cwd=d, check=True, capture_output=True, timeout=100)
    return ccx_section(job)


def printed_ccx(path: Path) -> np.ndarray:
    """Frequencies (cycles/time) of the first eigenvalue table of a CalculiX .dat file."""
    text = path.read_text()
    rows = []
    for line in text[text.index("E I G E N V A L U E   O U T P U T"):].split("\n")[6:]:
        parts = line.split()
        if len(parts) != 5:
            if rows:
                break
            continue
        rows.append(float(parts[3]))
    return np.array(rows)


def printed_f06(path: Path) -> np.ndarray:
    """The CYCLES column of the REAL EIGENVALUES table of a NASTRAN .f06."""
    lines = path.read_text().split("\n")
    k = next(i for i, x in enumerate(lines) if "R E A L   E I G E N V A L U E S" in x)
    rows = []
    for line in lines[k + 3:]:
        parts = line.split()
        if len(parts) != 7:
            break
        rows.append(float(parts[4]))
    return np.array(rows)


def frequencies(fe, k):
    """The k lowest eigenfrequencies of a clamped model, M possibly semi-definite (shift-invert
    about 0 sees only the finite eigenvalues)."""
    w = sla.eigsh(fe.K.tocsc(), k=k, M=fe.M.tocsc(), sigma=0, which="LM",
                  return_eigenvectors=False)
    return np.sort(np.sqrt(w)) / (2 * np.pi)


@pytest.mark.parametrize("deck,dofs,semidefinite", [("beamf", 720, True),
                                                     ("beam8f", 1200, False)])
def test_calculix_suite_decks_match_the_printed_frequencies(tmp_path, deck, dofs, semidefinite):
    sec = matrixstorage(REAL / "calculix" / f"{deck}.inp", tmp_path, deck)
    fe = read_fe(sec, tmp_path)
    assert fe.n == dofs
    printed = printed_ccx(REAL / "calculix" / f"{deck}.dat.ref")
    assert len(printed) == 10
    got = frequencies(fe, len(printed))
    assert np.max(np.abs(got / printed - 1)) < 1e-6, (got, printed)
    # C3D20R's consistent mass is only semi-definite (zero eigenvalues), C3D8's is definite.
    big = abs(fe.M).max()
    lo = sla.eigsh(fe.M.tocsc(), k=4, sigma=-1e-3 * big, which="LM", tol=1e-10,
                   return_eigenvectors=False).min()        # the smallest eigenvalue of M
    assert (lo < 1e-12 * big) == semidefinite and lo > -1e-12 * big


@pytest.mark.parametrize("deck,etype", [("beamfsh1", "S8R"), ("boxprofile", "B32R")])
def test_calculix_shell_and_beam_decks_are_refused_with_the_reason(tmp_path, capsys, deck,
                                                                   etype):
    sec = matrixstorage(REAL / "calculix" / f"{deck}.inp", tmp_path, deck)
    with pytest.raises(InputError, match=rf"blade\.files\.dof: .*{deck}\.dof:\d+: \(node \d+, "
                                         rf"component \d\) is listed again .*has {etype} "
                                         r"elements.*Mesh the blade with solid elements"):
        read_fe(sec, tmp_path)
    if deck == "beamfsh1":      # through the command line: exit status 2, nothing written
        case = {"blade": {"kind": "fe", **sec, "platform": {"nodes": [5], "ref_point": [0, 0, 0],
                                                           "axis": [0, 1, 0]},
                          "excitation": {"node": 6, "direction": [1, 0, 0]}},
                "damper": {"kind": "jenkins", "kt": 1.0e5, "M_slip": 0.05},
                "analysis": {"f_min": 10000, "f_max": 20000}}
        (tmp_path / "case.json").write_text(json.dumps(case))
        (tmp_path / "red").mkdir()
        status = main(["reduce", str(tmp_path / "case.json"), "--out",
                       str(tmp_path / "red" / "r.json")])
        err = capsys.readouterr().err
        assert status == 2 and re.search(r"blade\.files\.dof: .*beamfsh1\.dof:\d+: ", err), err
        assert list((tmp_path / "red").iterdir()) == []


def test_nastran_punch_with_four_dmigs(tmp_path):
    d = REAL / "nastran"
    sec = {"format": "nastran", "files": {"pch": str(d / "n1.pch"), "bdf": str(d / "n1.bdf")}}
    with pytest.raises(InputError, match=r"blade\.files\.pch: .*n1\.pch needs exactly one DMIG "
                                         r"whose name starts with M \(found: KAAX, MAAX, MQG1T, "
                                         r"MUG1T\); name it in blade\.dmig\.M"):
        read_fe(sec, tmp_path)
    fe = read_fe({**sec, "dmig": {"K": "KAAX", "M": "MAAX"}}, tmp_path)
    assert fe.n == 9 and list(fe.dof_node) == [2] * 6 + [4] * 3
    w = la.eigh(fe.K.toarray(), fe.M.toarray(), eigvals_only=True)
    got = np.sqrt(np.abs(w)) / (2 * np.pi)
    printed = printed_f06(d / "n1b.f06")
    assert len(printed) == 9
    assert np.all(got[:3] < 0.01) and np.all(printed[:3] < 0.01)      # the pendulum's rigid modes
    # The elastic mode of the band (72.64396 Hz) to 1e-6; Nastran's Lanczos printed the modes at
    # 75 to 159 kHz (rotary inertia 1e-6) less accurately than the punch it wrote gives them:
    # its torsion mode 6.410235E+11 against k / I = 6.410256410E+05 / 1E-06 exactly.
    assert abs(got[3] / printed[3] - 1) < 1e-6
    assert np.max(np.abs(got[3:] / printed[3:] - 1)) < 3e-5
    k = fe.K[fe.dof_index()[(2, 4)], fe.dof_index()[(2, 4)]]
    assert (2 * np.pi * got[6]) ** 2 == pytest.approx(k / 1e-6, rel=1e-12)


def test_real_files_gzipped(tmp_path):
    d = REAL / "nastran"
    for name in ("n1.pch", "n1.bdf"):
        (tmp_path / f"{name}.gz").write_bytes(gzip.compress((d / name).read_bytes()))
    sec = {"format": "nastran", "dmig": {"K": "KAAX", "M": "MAAX"}}
    a = read_fe({**sec, "files": {"pch": "n1.pch.gz", "bdf": "n1.bdf.gz"}}, tmp_path)
    b = read_fe({**sec, "files": {"pch": "n1.pch", "bdf": "n1.bdf"}}, d)
    assert abs(a.K - b.K).max() == 0 and abs(a.M - b.M).max() == 0


def _f06_displacements(path: Path) -> dict:
    """Grid id -> (T1 T2 T3 R1 R2 R3) of the first DISPLACEMENT VECTOR table of an .f06."""
    lines = read_text(path, "f06").split("\n")
    k = next(i for i, x in enumerate(lines) if "D I S P L A C E M E N T   V E C T O R" in x)
    out = {}
    for line in lines[k + 3:]:
        parts = line.split()
        if len(parts) != 8 or parts[1] != "G":
            break
        out[int(parts[0])] = np.array([float(v) for v in parts[2:]])
    return out


def test_nastran_cd_frames_against_nastran_output():
    # One model solved by NX Nastran twice: displacements printed in each grid's CD frame,
    # cylindrical (CORD2C, free field with 9 values on a line; grids on its axis too) and a
    # shifted, rotated rectangular one (CORD2R 11). Rotated to basic with the frames the reader
    # builds, the two agree to the 7 digits printed. GRID cards with tabs inside fixed fields.
    d = REAL / "nastran"
    basic, raw = {}, {}
    for job in ("static_solid_shell_bar_global_radial_cd", "static_solid_shell_bar_xyz"):
        ids, xyz, frames = read_grids(d / f"{job}.bdf")
        u = _f06_displacements(d / f"{job}.f06.gz")
        assert len(frames) == len(ids) == 25
        raw[job] = np.array([u[int(g)] for g in ids])
        basic[job] = (xyz, np.array([np.concatenate([frames[k] @ u[int(g)][:3],
                                                      frames[k] @ u[int(g)][3:]])
                                      for k, g in enumerate(ids)]))
    (xa, ua), (xb, ub) = basic.values()
    assert np.array_equal(xa, xb)
    big = np.abs(ub).max()
    assert np.abs(ua - ub).max() < 5e-7 * big
    ra, rb = raw.values()
    assert np.abs(ra - rb).max() > 0.1 * big          # as printed, in their frames, they differ


def test_nastran_cp_positions_against_nastran_oload():
    # MSC Nastran's sbuckl2a (tabs, GRDSET, grids in two CORD2S spherical systems, one shifted):
    # the pressure PLOAD2 -2000 on its CTRIA3/CQUAD4 shell, integrated over the elements on
    # the basic positions the reader gives, has the resultant force and moment Nastran printed
    # (OLOAD RESULTANT of subcase 1).
    d = REAL / "nastran"
    ids, xyz, _ = read_grids(d / "sbuckl2a.bdf")
    pos = {int(g): xyz[k] for k, g in enumerate(ids)}
    force, moment = np.zeros(3), np.zeros(3)
    g = 1 / np.sqrt(3)
    nat = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)])
    for name, f, _ in cards(d / "sbuckl2a.bdf", "bdf"):
        if name not in ("CTRIA3", "CQUAD4"):
            continue
        x = np.array([pos[int(v)] for v in f[2:5 if name == "CTRIA3" else 6]])
        fn = np.zeros_like(x)
        if name == "CTRIA3":
            fn[:] = -2000.0 * np.cross(x[1] - x[0], x[2] - x[0]) / 6
        else:                 # consistent nodal loads of the bilinear quad (2x2 Gauss points)
            for xi in (-g, g):
                for eta in (-g, g):
                    N = (1 + nat[:, 0] * xi) * (1 + nat[:, 1] * eta) / 4
                    dxi = (nat[:, 0] * (1 + nat[:, 1] * eta) / 4) @ x
                    deta = (nat[:, 1] * (1 + nat[:, 0] * xi) / 4) @ x
                    fn += -2000.0 * np.outer(N, np.cross(dxi, deta))
        force += fn.sum(axis=0)
        moment += np.cross(x, fn).sum(axis=0)
    text = read_text(d / "sbuckl2a.f06.gz", "f06")
    totals = text[text.index("OLOAD    RESULTANT"):].split("TOTALS")[1].split("\n")[0].split()
    printed = np.array([float(v) for v in totals])
    assert printed[0] == -2.647650 and printed[4] == 8.367467e-02
    got = np.concatenate([force, moment])
    assert np.all(np.abs(got - printed) <= 5e-7 * np.abs(printed) + 1e-12), (got, printed)


def test_nastran_include_files(tmp_path):
    # sbuckl2a with its bulk data moved into INCLUDE files, as Nastran reads them: the first
    # half in a gzipped file of a subfolder whose quoted name goes on over two lines, the rest
    # in a second file; the positions and frames are the same as from the one file.
    lines = (REAL / "nastran" / "sbuckl2a.bdf").read_text().split("\n")
    begin = next(k for k, s in enumerate(lines) if s.upper().startswith("BEGIN BULK"))
    bulk = lines[begin + 1:]
    cut = next(k for k in range(len(bulk) // 2, len(bulk)) if bulk[k][:1].isalpha())
    geo, rest = bulk[:cut], bulk[cut:]     # each file ends after a whole card
    (tmp_path / "mesh").mkdir()
    with gzip.open(tmp_path / "mesh" / "geometry.bdf", "wt") as f:
        f.write("\n".join(geo) + "\n")
    (tmp_path / "mesh" / "rest.bdf").write_text("\n".join(rest) + "\n")
    main_deck = lines[:begin + 1] + ["INCLUDE 'mesh/", "  geometry.bdf' $ the grids",
                                     "include 'mesh/rest.bdf'"]
    (tmp_path / "model.bdf").write_text("\n".join(main_deck) + "\n")
    got = read_grids(tmp_path / "model.bdf")
    ref = read_grids(REAL / "nastran" / "sbuckl2a.bdf")
    assert np.array_equal(got[0], ref[0]) and np.array_equal(got[1], ref[1])
    assert sorted(got[2]) == sorted(ref[2])
    assert all(np.array_equal(got[2][k], ref[2][k]) for k in ref[2])
    # a card's place is its own file and line
    files = {"geometry.bdf": geo, "rest.bdf": rest}
    places = [(name, at.rsplit(":", 1)) for name, _, at in cards(tmp_path / "model.bdf", "bdf")]
    assert {Path(f).name for _, (f, _) in places} == set(files)
    assert all(files[Path(f).name][int(n) - 1].upper().startswith(name) for name, (f, n) in places)
    # a missing file and a loop name the file and line of the INCLUDE
    (tmp_path / "mesh" / "rest.bdf").write_text("INCLUDE '../model.bdf'\n")
    with pytest.raises(InputError, match=r"bdf: .*rest\.bdf:1: INCLUDE \.\./model\.bdf "
                                         r"includes itself"):
        read_grids(tmp_path / "model.bdf", "bdf")
    (tmp_path / "mesh" / "rest.bdf").unlink()
    with pytest.raises(InputError, match=r"bdf: .*model\.bdf:\d+: INCLUDE file mesh/rest\.bdf "
                                         r"not found"):
        read_grids(tmp_path / "model.bdf", "bdf")
