"""What the FE codes write, read the same in every format: every file gzipped, CRLF line ends,
tabs, comments and lowercase keywords give the same model as the plain files; CalculiX decks
with nested *INCLUDE files; ANSYS HBMAT .mapping files and NWRITE/NLIST node tables; Abaqus
internal nodes (negative ids, no coordinates); CalculiX shell exports refused with the reason."""
from __future__ import annotations

import gzip
import shutil
import subprocess

import numpy as np
import pytest

from udmap import InputError
from udmap.fe import read_fe

from fe_compare import ccx_section, rel, same_model
from fe_deck import make_deck, write_inp
from fe_writers import with_internal_node, write_labelled, write_nastran
from test_fe_readers import BLOCK_ABAQUS, DATA, ROTOR_ABAQUS, ROTOR_ANSYS

CCX_FILES = ("sti", "mas", "dof", "inp")


@pytest.fixture(scope="module")
def ccx(tmp_path_factory):
    """A fresh CalculiX export of the clamped test blade."""
    d = tmp_path_factory.mktemp("ccx_text")
    write_inp(make_deck(), d / "b.inp", "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP")
    subprocess.run(["ccx", "-i", "b"], cwd=d, check=True, capture_output=True, timeout=100)
    return d


def _copy_section(section, src, dst, transform=None, gz=False):
    """The section's files copied to ``dst`` (text transformed, then gzipped as NAME.gz)."""
    files = {}
    for key, name in section["files"].items():
        text = (src / name).read_bytes()
        if transform:
            text = transform(key, text)
        target = dst / (name.split("/")[-1] + (".gz" if gz else ""))
        target.write_bytes(gzip.compress(text) if gz else text)
        files[key] = target.name
    return {**section, "files": files}


def _crlf_tabs(key, data: bytes) -> bytes:
    """CRLF line ends, and tabs where blanks separate numbers (not in fixed NASTRAN fields)."""
    text = data.decode()
    lines = text.splitlines()
    if key in ("sti", "mas"):
        lines = ["\t".join(x.split()) for x in lines]
    return ("\r\n".join(lines) + "\r\n").encode()


SECTIONS = {"ansys": (ROTOR_ANSYS, DATA), "abaqus": (BLOCK_ABAQUS, DATA),
            "abaqus_rotor": (ROTOR_ABAQUS, DATA)}


@pytest.mark.parametrize("name", ["ansys", "abaqus", "abaqus_rotor", "calculix", "nastran",
                                  "matrix_market"])
@pytest.mark.parametrize("variant", ["gz", "crlf_tabs", "crlf_tabs_gz"])
def test_every_format_gzipped_crlf_tabs(name, variant, ccx, written, tmp_path):
    if name == "calculix":
        section, src = ccx_section("b"), ccx
    elif name in ("nastran", "matrix_market"):
        section, src = written[name]
    else:
        section, src = SECTIONS[name]
    plain = read_fe(section, src)
    (tmp_path / "v").mkdir()
    sec = _copy_section(section, src, tmp_path / "v", _crlf_tabs if "crlf" in variant else None,
                        gz="gz" in variant)
    same_model(read_fe(sec, tmp_path / "v"), plain)
    assert all(f.endswith(".gz") == ("gz" in variant) for f in sec["files"].values())


@pytest.fixture(scope="module")
def written(ccx):
    """The CalculiX export written as a NASTRAN punch and bulk data and as Matrix Market."""
    fe = read_fe(ccx_section("b"), ccx)
    return {fmt: _written(fmt, fe, ccx / fmt) for fmt in ("nastran", "matrix_market")}


def _written(fmt, fe, d):
    """The model written as a NASTRAN punch + bulk data or as plain Matrix Market files."""
    from udmap.fe import matrix_market
    d.mkdir(exist_ok=True)
    if fmt == "matrix_market":
        names = matrix_market.write(fe, d, "mm")
        return {"format": "matrix_market", "files": names}, d
    write_nastran(d / "m.pch", d / "m.bdf", fe.K, fe.M, fe.dof_node, fe.dof_comp,
                  fe.node_ids, fe.node_xyz)
    return {"format": "nastran", "files": {"pch": "m.pch", "bdf": "m.bdf"}}, d


def test_gz_name_on_a_plain_file_and_broken_gzip(ccx, tmp_path):
    sec = _copy_section(ccx_section("b"), ccx, tmp_path)
    shutil.copy(tmp_path / "b.dof", tmp_path / "b.dof.gz")
    with pytest.raises(InputError, match=r"blade\.files\.dof: .*b\.dof\.gz: named \.gz but not "
                                         "gzip-compressed"):
        read_fe({**sec, "files": {**sec["files"], "dof": "b.dof.gz"}}, tmp_path)
    (tmp_path / "cut.mas.gz").write_bytes(gzip.compress((tmp_path / "b.mas").read_bytes())[:200])
    with pytest.raises(InputError, match=r"blade\.files\.mas: .*cut\.mas\.gz"):
        read_fe({**sec, "files": {**sec["files"], "mas": "cut.mas.gz"}}, tmp_path)


def _split_deck(text: str):
    """The deck with its *NODE block moved into nested include files, lowercase keywords,
    comments, tabs and CRLF: main -> mesh/nodes.inp (relative to the main deck) ->
    more.inp (relative to the including file)."""
    lines = text.splitlines()
    k0 = next(k for k, x in enumerate(lines) if x.upper().startswith("*NODE"))
    k1 = next(k for k in range(k0 + 1, len(lines)) if lines[k].startswith("*"))
    nodes = lines[k0 + 1:k1]
    half = len(nodes) // 2
    main = lines[:k0] + ["** the mesh", "*include, input=mesh/nodes.inp"] + lines[k1:]
    first = ["**  nodes, first half", "*node, nset=nall"] + \
        [x.replace(", ", ",\t") for x in nodes[:half]] + ["*Include,Input=more.inp"]
    second = ["*NODE"] + nodes[half:]
    return main, first, second


def test_calculix_nested_includes(ccx, tmp_path):
    main, first, second = _split_deck((ccx / "b.inp").read_text())
    (tmp_path / "mesh").mkdir()
    (tmp_path / "deck.inp").write_text("\r\n".join(main) + "\r\n")
    (tmp_path / "mesh" / "nodes.inp").write_text("\n".join(first) + "\n")
    with gzip.open(tmp_path / "mesh" / "more.inp", "wt") as f:   # gzipped, not named so
        f.write("\n".join(second) + "\n")
    sec = _copy_section(ccx_section("b"), ccx, tmp_path)
    sec["files"]["inp"] = "deck.inp"
    same_model(read_fe(sec, tmp_path), read_fe(ccx_section("b"), ccx))
    # A missing include and a loop name the file and line of the *INCLUDE.
    (tmp_path / "mesh" / "more.inp").write_text("*INCLUDE, INPUT=mesh/nodes.inp\n")
    with pytest.raises(InputError, match=r"blade\.files\.inp: .*more\.inp:1: \*INCLUDE "
                                         r"mesh/nodes\.inp includes itself"):
        read_fe(sec, tmp_path)
    (tmp_path / "mesh" / "more.inp").unlink()
    with pytest.raises(InputError, match=r"blade\.files\.inp: .*nodes\.inp:\d+: \*INCLUDE file "
                                         r"more\.inp not found"):
        read_fe(sec, tmp_path)


def _fortran_e(x, digits=13):
    """Fortran ``G20.13`` in its exponent form: ``-0.1234567890123E-01`` fills all 20 columns,
    so a negative number touches the field before it."""
    if x == 0:
        return f"{0:.{digits}f}".rjust(digits + 7)
    e = int(np.floor(np.log10(abs(x)))) + 1
    m = abs(x) / 10.0 ** e
    if round(m, digits) >= 1:
        m, e = m / 10, e + 1
    return (("-" if x < 0 else "") + f"{m:.{digits}f}E{e:+03d}").rjust(digits + 7)


def test_ansys_hbmat_mapping_nwrite_and_nlist(tmp_path):
    fe = read_fe(ROTOR_ANSYS, DATA)
    labels = ["UX", "UY", "UZ", "ROTX", "ROTY", "ROTZ"]
    mapping = ["Matrix Eqn   Node   DOF"] + [f"{k + 1:10d}{a:10d}   {labels[c - 1]}"
                                           for k, (a, c) in enumerate(zip(fe.dof_node,
                                                                          fe.dof_comp))]
    (tmp_path / "rotor.mapping").write_text("\n".join(mapping) + "\n")
    xyz = np.where(abs(fe.node_xyz) < 1e-9, 0.0, fe.node_xyz)       # zeros NWRITE leaves out
    xyz[::7] *= -1.0                 # negative numbers: the columns touch ("1-0.15E+00...")
    nwrite = []
    for i, p in zip(fe.node_ids, xyz):
        last = max([k + 1 for k in range(3) if p[k] != 0] + [0])
        nwrite.append(f"{i:8d}" + "".join(_fortran_e(v) for v in p[:last]))
    assert any(len(x.split()) < 4 for x in nwrite) and any("-" in x[8:9] for x in nwrite)
    (tmp_path / "rotor.node").write_text("\n".join(nwrite) + "\n")
    nlist = [" LIST ALL SELECTED NODES.   DSYS=      0", ""]
    for k, (i, p) in enumerate(zip(fe.node_ids, xyz)):
        if k % 20 == 0:
            nlist += ["", " *****  ANSYS POST1 NODE LISTING  *****",
                      " 00000000  VERSION=LINUX x64     15:29:11  MAR 07, 2021 CP=      0.219",
                      "", "    NODE        X             Y             Z           THXY     "
                      "THYZ     THZX"]
        nlist.append(f"{i:9d}" + "".join(f"{v:21.13G}" for v in p) + "     0.00     0.00     0.00")
    (tmp_path / "rotor.lis").write_text("\n".join(nlist) + "\n")
    for nodes in ("rotor.node", "rotor.lis"):
        files = {k: str(DATA / v) for k, v in ROTOR_ANSYS["files"].items()}
        files.update(dof_map=str(tmp_path / "rotor.mapping"), nodes=str(tmp_path / nodes))
        got = read_fe({"format": "ansys", "files": files}, tmp_path)
        assert np.array_equal(got.dof_node, fe.dof_node) and rel(got.K, fe.K) == 0
        assert np.allclose(got.node_xyz, xyz, rtol=1e-12, atol=0), nodes
    # A mapping of the wrong length, and a DOF label that is not a displacement.
    (tmp_path / "short.mapping").write_text("\n".join(mapping[:-3]) + "\n")
    files["dof_map"] = str(tmp_path / "short.mapping")
    with pytest.raises(InputError, match=r"blade\.files\.dof_map: .*short\.mapping maps 342 "
                                         r"equations but the matrices are 345 x 345"):
        read_fe({"format": "ansys", "files": files}, tmp_path)
    (tmp_path / "temp.mapping").write_text("\n".join(mapping[:5] + ["5  2  TEMP"]) + "\n")
    files["dof_map"] = str(tmp_path / "temp.mapping")
    with pytest.raises(InputError, match=r"blade\.files\.dof_map: .*temp\.mapping:6: DOF TEMP"):
        read_fe({"format": "ansys", "files": files}, tmp_path)


def test_abaqus_internal_nodes_have_no_coordinates(ccx, tmp_path):
    fe = read_fe(ccx_section("b"), ccx)
    K, M, dn, dc = with_internal_node(fe, anchor=int(fe.node_ids[-1]))
    write_labelled(tmp_path / "K.mtx", K, dn, dc)
    write_labelled(tmp_path / "M.mtx", M, dn, dc)
    shutil.copy(ccx / "b.inp", tmp_path / "b.inp")
    got = read_fe({"format": "abaqus", "files": {"stiffness": "K.mtx", "mass": "M.mtx",
                                                 "inp": "b.inp"}}, tmp_path)
    assert got.internal() == {-1} and got.n == fe.n + 3
    assert np.isnan(got.coords(-1)).all() and np.array_equal(got.coords(1), fe.coords(1))
    order = np.lexsort((dc, dn))           # the labelled reader sorts by node, then dof
    assert rel(got.K, K[order][:, order]) < 1e-15 and rel(got.M, M[order][:, order]) < 1e-15


def test_calculix_shell_export_is_refused_with_the_reason(tmp_path):
    nodes = [(1, 0, 0), (2, 1, 0), (3, 2, 0), (4, 0, .5), (5, 2, .5), (6, 0, 1), (7, 1, 1),
             (8, 2, 1)]
    deck = ["*NODE"] + [f"{i}, {x}, {y}, 0" for i, x, y in nodes] + [
        "*ELEMENT, TYPE=S8R, ELSET=E", "1, 1, 3, 8, 6, 2, 5, 7, 4", "*MATERIAL, NAME=ST",
        "*ELASTIC", "2e11, 0.3", "*DENSITY", "7800", "*SHELL SECTION, ELSET=E, MATERIAL=ST",
        "0.01", "*BOUNDARY", "1, 1, 6", "4, 1, 6", "6, 1, 6", "*STEP",
        "*FREQUENCY, SOLVER=MATRIXSTORAGE", "*END STEP"]
    (tmp_path / "s8.inp").write_text("\n".join(deck) + "\n")
    subprocess.run(["ccx", "-i", "s8"], cwd=tmp_path, check=True, capture_output=True,
                   timeout=100)
    dof = (tmp_path / "s8.dof").read_text().split()
    assert len(dof) > len(set(dof))         # CalculiX writes the parent id for the expansion
    with pytest.raises(InputError, match=r"blade\.files\.dof: .*s8\.dof:\d+: \(node 2, component "
                                         r"1\) is listed again \(rows 2, 5\): the deck .*s8\.inp "
                                         r"has S8R elements, .*Mesh the blade with solid "
                                         r"elements \(C3D20R"):
        read_fe(ccx_section("s8"), tmp_path)
