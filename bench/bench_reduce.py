#!/usr/bin/env python3
"""Platform Centred Reduction benchmark (issue 12): a generated 3D solid blade
(udmap.fe.generator) of about 10^4, 10^5 and 10^6 DOFs, reduced with blade A's band
(f_max = 230 Hz, modes up to 3 f_max, the default residual blocks).

10^6 DOFs takes 6 to 9 minutes and 16 GB: it runs when the machine has at least
MEM_1E6_GB of available memory (else the bench says why it is left out);
UDMAP_BENCH_1E6=0 leaves it out, UDMAP_BENCH_1E6=1 runs it regardless.

Generation is excluded: the parent generates and saves the model, a child process loads it,
reduces it (timed: the whole platform_centred_reduction call, input checks included; wall
and CPU seconds of all threads: MUMPS is sequential, only the BLAS runs on several threads,
so on a machine shared with other jobs the CPU time bounds what the wall time would be on an
idle one) and reports its peak resident memory (ru_maxrss, which includes the loaded K and M).
Method `reduce`: the reduction alone; `reduce_full_check`: with the full model's
eigenfrequencies in [0, 3 f_max] (a second sparse eigen-solve, for the check), whose largest
relative difference to the reduced ones is error_f_res; run up to UDMAP_BENCH_REDUCE_CHECK_MAX
DOFs (default 2e4, as it costs three more factorisations). Targets: 10^5 DOFs under 60 s and
4 GB, 10^6 under 15 min and 20 GB. UDMAP_BENCH_REDUCE_SIZES (e.g. "1e4,1e5:C3D20R,1e6")
overrides the sizes, each with its element (default C3D8).

Elements: C3D8, the generator's own assembly, at 10^4, 10^5 and 10^6 DOFs; and C3D20R at about
10^5 (123 294 DOFs), the usual CalculiX element for blades, whose consistent mass is only
positive semi-definite: the quadratic mesh of the same blade, assembled by ccx (SOLVER =
MATRIXSTORAGE, in the generation time) and read by the calculix reader.

BLAS: MUMPS spends nearly all its time in BLAS dgemm/dtrsm, which Debian's reference BLAS runs
at about 1.7 Gflop/s. The reduction child runs on Debian's OpenBLAS (libopenblas0-pthread,
fetched once with `apt-get download` and unpacked, not installed, into BUILD/openblas; the
child's LD_LIBRARY_PATH points at its libblas.so.3/liblapack.so.3, so the system's BLAS
alternative, which every test uses, is left as it is), with OPENBLAS_NUM_THREADS = the cores.
UDMAP_BENCH_REDUCE_BLAS=reference keeps the reference BLAS; if OpenBLAS cannot be fetched the
bench says so and uses the reference BLAS. Each record names the libblas.so.3 the child loaded.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import scipy.sparse as sp

ROOT = Path(__file__).resolve().parents[1]
OPENBLAS_DEB = "libopenblas0-pthread"
#: Available memory [GB] below which 10^6 DOFs is left out (its measured peak is 15.8 GB).
MEM_1E6_GB = 18.0
F_MAX = 230.0
TARGETS = {100_000: (60.0, 4.0), 1_000_000: (900.0, 20.0)}
#: The quadratic mesh has about 3.7 times the DOFs of the linear one it is made from (the
#: midside nodes): 10^5 gives a C3D20R blade of 123 294 DOFs.
HEX20_DOFS_PER_CORNER_DOF = 3.3


def build_dir() -> Path:
    return Path(os.environ.get("UDMAP_BUILD_DIR") or ROOT / "build")


def openblas_dir() -> "Path | None":
    """The directory holding Debian's OpenBLAS libblas.so.3 and liblapack.so.3, unpacked into
    BUILD/openblas on first use (apt-get download + dpkg -x: nothing is installed); None (with
    a message) when that fails."""
    dest = build_dir() / "openblas"
    found = sorted(dest.glob("usr/lib/*/openblas-pthread/libblas.so.3"))
    if not found:
        try:
            with tempfile.TemporaryDirectory() as tmp:
                subprocess.run(["apt-get", "download", OPENBLAS_DEB], cwd=tmp, check=True,
                               capture_output=True, text=True)
                deb = next(Path(tmp).glob(f"{OPENBLAS_DEB}_*.deb"))
                dest.mkdir(parents=True, exist_ok=True)
                subprocess.run(["dpkg", "-x", str(deb), str(dest)], check=True,
                               capture_output=True, text=True)
        except (OSError, StopIteration, subprocess.CalledProcessError) as e:
            msg = getattr(e, "stderr", "") or str(e)
            print(f"  bench_reduce: could not fetch {OPENBLAS_DEB} ({msg.strip()[:200]}); "
                  "the reduction runs on the system BLAS", flush=True)
            return None
        found = sorted(dest.glob("usr/lib/*/openblas-pthread/libblas.so.3"))
    return found[0].parent if found else None


def child_env() -> dict:
    """The reduction child's environment: the tree's Python package, and OpenBLAS unless
    UDMAP_BENCH_REDUCE_BLAS=reference."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "wrappers" / "python"))
    if os.environ.get("UDMAP_BENCH_REDUCE_BLAS", "openblas") != "reference":
        lib = openblas_dir()
        if lib is not None:
            env["LD_LIBRARY_PATH"] = os.pathsep.join(
                [str(lib)] + [p for p in [os.environ.get("LD_LIBRARY_PATH")] if p])
            env.setdefault("OPENBLAS_NUM_THREADS", str(os.cpu_count() or 1))
    return env


def loaded_blas() -> str:
    """The libblas.so.3 this process has mapped (after the kernel library is loaded)."""
    try:
        for line in Path("/proc/self/maps").read_text().splitlines():
            path = line.split()[-1]
            if path.endswith("/libblas.so.3") or "/libblas.so.3" in path:
                return os.path.realpath(path)
    except OSError:
        pass
    return "unknown"


def child(directory: Path, check: bool) -> None:
    from udmap.fe import FEModel
    from udmap.reduction import platform_centred_reduction
    z = np.load(directory / "model.npz")
    fe = FEModel(K=sp.load_npz(directory / "K.npz").tocsr(), M=sp.load_npz(directory / "M.npz").tocsr(),
                 dof_node=z["dof_node"], dof_comp=z["dof_comp"], node_ids=z["node_ids"],
                 node_xyz=z["node_xyz"])
    ru0 = resource.getrusage(resource.RUSAGE_SELF)
    t0 = time.perf_counter()
    red = platform_centred_reduction(
        fe, platform_nodes=z["platform"], ref_point=z["ref_point"], axis=z["axis"],
        exc_node=int(z["exc_node"]), exc_direction=z["exc_direction"],
        stress_rows=[z["gauge_row"]], f_max=F_MAX, check_full=check)
    seconds = time.perf_counter() - t0
    ru1 = resource.getrusage(resource.RUSAGE_SELF)
    cpu = (ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime)
    rss_gb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024 / 1e9
    err = None
    if check and red.freqs_full.size == red.freqs_reduced.size and red.freqs_full.size:
        err = float(np.max(np.abs(red.freqs_reduced / red.freqs_full - 1)))
    info = {k: v for k, v in red.info.items() if k != "freqs_reduced_all"}
    info["freqs_reduced_all"] = red.info["freqs_reduced_all"].tolist()
    print(json.dumps({"blas": loaded_blas(), "seconds": seconds, "cpu_seconds": cpu, "peak_rss_gb": rss_gb, "error_f_res": err,
                      "freqs_full": red.freqs_full.tolist(),
                      "freqs_reduced": red.freqs_reduced.tolist(), "info": info}))


def generate(n_dofs: int, element: str, tmp: Path):
    """The generated blade of about ``n_dofs`` DOFs and its model: C3D8 assembled by the
    generator, or C3D20R (quadratic bricks with reduced integration: a positive semi-definite
    consistent mass) assembled by CalculiX itself (*FREQUENCY, SOLVER=MATRIXSTORAGE) and read
    back with the calculix reader. Returns (blade, model, platform nodes)."""
    from udmap.fe import read_fe
    from udmap.fe.generator import generate_blade, quadratic_mesh, write_solid_deck
    if element == "C3D8":
        b = generate_blade(n_dofs)
        return b, b.fe, b.platform_nodes
    b = generate_blade(int(n_dofs / HEX20_DOFS_PER_CORNER_DOF))
    mesh = quadratic_mesh(b)
    write_solid_deck(b, mesh, tmp / "export.inp", brick=element)
    subprocess.run(["ccx", "-i", "export"], cwd=tmp, check=True, capture_output=True)
    fe = read_fe({"format": "calculix", "files": {k: f"export.{k}" for k in
                                                  ("sti", "mas", "dof", "inp")}}, tmp)
    for f in tmp.glob("export.*"):
        f.unlink()
    return b, fe, mesh.platform_nodes


def measure(n_dofs: int, tmp: Path, element: str = "C3D8") -> list[dict]:
    t0 = time.perf_counter()
    b, fe, platform = generate(n_dofs, element, tmp)
    t_gen = time.perf_counter() - t0
    sp.save_npz(tmp / "K.npz", fe.K, compressed=False)
    sp.save_npz(tmp / "M.npz", fe.M, compressed=False)
    np.savez(tmp / "model.npz", dof_node=fe.dof_node, dof_comp=fe.dof_comp, node_ids=fe.node_ids,
             node_xyz=fe.node_xyz, platform=platform, ref_point=b.ref_point,
             axis=b.axis, exc_node=b.exc_node, exc_direction=b.exc_direction,
             gauge_row=b.gauge_row(fe))
    ndof = fe.K.shape[0]
    nnz = fe.K.nnz
    del b, fe
    label = f"1e{int(round(np.log10(n_dofs)))}" + ("" if element == "C3D8" else f"_{element}")
    records = []
    # the full check (a second sparse eigen-solve) up to UDMAP_BENCH_REDUCE_CHECK_MAX DOFs
    check_max = float(os.environ.get("UDMAP_BENCH_REDUCE_CHECK_MAX", "2e4"))
    checks = [False, True] if n_dofs <= check_max else [False]
    for check in checks:
        env = child_env()
        r = subprocess.run([sys.executable, __file__, "--child", str(tmp)] +
                           (["--check"] if check else []), env=env, capture_output=True,
                           text=True)
        if r.returncode != 0:
            raise SystemExit(f"bench_reduce: {ndof} DOFs failed:\n{r.stderr}")
        out = json.loads(r.stdout.strip().splitlines()[-1])
        method = "reduce_full_check" if check else "reduce"
        target = TARGETS.get(n_dofs)
        rec = {"case": f"generated_blade_{label}", "method": method,
               "setting": f"{ndof} DOFs, {element}, f_max {F_MAX:g} Hz", "element": element,
               "seconds_median": out["seconds"], "seconds_min": out["seconds"],
               "seconds_max": out["seconds"], "repeats": 1, "error_gamma_P": None,
               "error_sigma_a": None, "error_f_res": out["error_f_res"], "dofs": ndof,
               "nnz_K": nnz, "cpu_seconds": out["cpu_seconds"],
               "peak_rss_gb": out["peak_rss_gb"], "generation_seconds": t_gen,
               "r": out["info"]["r"], "n_modes": out["info"]["n_modes"],
               "factor_entries": out["info"]["factor_entries"],
               "timings": out["info"]["timings"], "blas": out["blas"],
               "blas_threads": int(env.get("OPENBLAS_NUM_THREADS", "1"))
               if "openblas" in out["blas"] else 1,
               "f_cut": out["info"]["f_cut"], "cut_count": out["info"]["cut_count"],
               "freqs_reduced_all": out["info"]["freqs_reduced_all"],
               "freqs_full": out["freqs_full"],
               "freqs_reduced": out["freqs_reduced"], "cpu_count": os.cpu_count(),
               "load_average": os.getloadavg()[0]}
        if target:
            rec["target_seconds"], rec["target_gb"] = target
            rec["meets_target"] = (out["seconds"] < target[0] and out["peak_rss_gb"] < target[1])
        print(f"  reduce {ndof:>8d} DOFs {element:6s}{' + full check' if check else '':>13}: "
              f"{out['seconds']:8.2f} s (cpu {out['cpu_seconds']:.2f} s), peak {out['peak_rss_gb']:6.2f} GB, r = {rec['r']}, "
              f"freq error {out['error_f_res']}, BLAS {out['blas']}", flush=True)
        records.append(rec)
    return records


def available_gb() -> float:
    """MemAvailable of /proc/meminfo [GB] (0 when unknown)."""
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemAvailable:"):
                return int(line.split()[1])*1024/1e9
    except (OSError, ValueError, IndexError):
        pass
    return 0.0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--json", help="output file for the records")
    ap.add_argument("--child", help=argparse.SUPPRESS)
    ap.add_argument("--check", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(Path(args.child), args.check)
        return 0
    sizes = os.environ.get("UDMAP_BENCH_REDUCE_SIZES")
    if sizes:   # "1e4,1e5:C3D20R": sizes, each with its element (default C3D8)
        runs = [(int(float(s.split(":")[0])), (s.split(":") + ["C3D8"])[1].upper())
                for s in sizes.split(",")]
    else:
        ns = [10_000, 100_000]
        switch = os.environ.get("UDMAP_BENCH_1E6")
        avail = available_gb()
        if switch == "1" or (switch != "0" and avail >= MEM_1E6_GB):
            ns.append(1_000_000)
        elif switch != "0":
            print(f"  bench_reduce: 10^6 DOFs left out: {avail:.1f} GB of memory available, it "
                  f"needs {MEM_1E6_GB:g} GB (UDMAP_BENCH_1E6=1 runs it regardless)", flush=True)
        runs = [(n, "C3D8") for n in ns]
        runs.insert(2, (100_000, "C3D20R"))
    records = []
    for n, element in runs:
        with tempfile.TemporaryDirectory() as tmp:
            records += measure(n, Path(tmp), element)
    if args.json:
        Path(args.json).write_text(json.dumps(records, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
