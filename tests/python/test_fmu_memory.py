"""1000 instantiate/free cycles of each FMU, each building and using every kernel object
(blade, damper, model, response point), leave the process's resident memory where it was:
through the Python importer, and through a C importer that also saves and restores the state,
has a value rejected and resets in every cycle."""
from __future__ import annotations

import gc
import os
import re
import subprocess

import pytest

from fmu_harness import OK, Instance, binary, cycles_program, token


def rss_kib() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") // 1024


@pytest.mark.parametrize("version", [2, 3])
def test_instantiate_free_cycles_do_not_grow_memory(version):
    def cycle(i):
        inst = Instance(version, f"cycle{i}")
        assert inst.setup() == OK
        # every kernel object is built and used: blade, damper, model, response point
        assert inst.set(F_E=1.0 + i % 7) == OK
        assert inst.get("gamma_P", "F_lim")[0] == OK
        inst.free()

    for i in range(20):
        cycle(i)
    gc.collect()
    before = rss_kib()
    for i in range(1000):
        cycle(i)
    gc.collect()
    growth = rss_kib() - before
    # one leaked blade or damper per cycle would be hundreds of kB per cycle
    assert growth < 2048, f"RSS grew by {growth} kB over 1000 cycles"



@pytest.mark.parametrize("version", [2, 3])
def test_c_importer_cycles_do_not_grow_memory(version, tmp_path):
    exe = cycles_program(version, tmp_path)
    r = subprocess.run([str(exe), str(binary(version)), token(version), str(version), "1020"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, (r.returncode, r.stderr[-2000:])
    growth = int(re.search(r"rss_growth_kib (-?\d+)", r.stdout).group(1))
    # two blades, two dampers and models per cycle: a leak of any would show by far
    assert growth < 512, f"RSS grew by {growth} kB over 1000 cycles"
