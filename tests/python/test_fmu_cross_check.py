"""The FMI cross-check files written by the build (build/cross-check/, fmu/cross_check.py):
the layout and files the cross-check rules ask for, checked by fmpy's own validator, and fmpy
reproducing every _ref.csv from its _in.csv with the FMU beside it, for both FMUs and both
interfaces."""
from __future__ import annotations

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.cross_check.validate_vendor_repo import validate_test_fmu
from fmpy.util import read_csv, read_ref_opt_file

from fmu_harness import BUILD

DIRS = [(fmi, interface, platform) for fmi, platform in (("2.0", "linux64"),
                                                         ("3.0", "x86_64-linux"))
        for interface in ("cs", "me")]


def model_dir(fmi, interface, platform):
    base = BUILD / "cross-check" / "fmus" / fmi / interface / platform / "udmap"
    versions = sorted(p for p in base.iterdir() if p.is_dir())
    assert len(versions) == 1, versions
    return versions[0] / "udmap"


@pytest.mark.parametrize("fmi,interface,platform", DIRS)
def test_layout_and_files(fmi, interface, platform):
    d = model_dir(fmi, interface, platform)
    for name in ("udmap.fmu", "udmap_in.csv", "udmap_ref.csv", "udmap_ref.opt", "ReadMe.md"):
        assert (d / name).is_file(), name
    assert validate_test_fmu(str(d)) == []


@pytest.mark.parametrize("fmi,interface,platform", DIRS)
def test_fmpy_reproduces_the_reference(fmi, interface, platform):
    d = model_dir(fmi, interface, platform)
    opt = read_ref_opt_file(str(d / "udmap_ref.opt"))
    inputs = read_csv(str(d / "udmap_in.csv"))
    ref = read_csv(str(d / "udmap_ref.csv"))
    names = list(ref.dtype.names[1:])
    r = simulate_fmu(str(d / "udmap.fmu"),
                     fmi_type="CoSimulation" if interface == "cs" else "ModelExchange",
                     start_time=opt["StartTime"], stop_time=opt["StopTime"],
                     output_interval=opt["StepSize"], relative_tolerance=opt["RelTol"],
                     input=inputs, output=names, validate=True)
    assert np.allclose(r["time"], ref["time"], rtol=0.0, atol=1e-12)
    assert len(r) == len(ref) == round((opt["StopTime"] - opt["StartTime"]) / opt["StepSize"]) + 1
    worst = 0.0
    for name in names:
        a, b = r[name].astype(float), ref[name].astype(float)
        if name in ("hcf_ok", "regime", "lift_off"):
            assert np.array_equal(a, b), name
            continue
        scale = np.where(b != 0.0, np.abs(b), 1.0)
        err = np.abs(a - b) / scale
        worst = max(worst, float(err.max()))
        assert err.max() <= 1e-12, (name, float(err.max()))
    # the inputs go through every regime and past the limit force
    assert set(ref["regime"].astype(int)) == {0, 1, 2, 3}
    print(f"FMI {fmi} {interface}: {len(r)} rows, worst relative difference {worst:.1e}")
