"""Shared helpers of the gg10 benchmarks: compiles bench/gg10_timing.c against the built library,
writes its input for a case (beam or matrices blade, asymmetric damper, band) and runs jobs.

A job is one line of the harness input, e.g. "standard LABEL repeats variant tol tol_path
peak_tol ds_max max_angle aft_samples warm_start full_band" (see gg10_timing.c); each returns one
JSON object with the timing statistics and the 10 peaks (gamma_P, f_res, sigma_a).
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FORCES = [float(i) for i in range(1, 11)]

#: The standard method's knobs that the harness passes, with the kernel defaults.
STANDARD_DEFAULTS = {"tol": 1e-10, "tol_path": 1e-6, "peak_tol": 1e-10, "ds_max": 0.3,
                     "max_angle": 0.35, "aft_samples": 0, "warm_start": 0, "full_band": 1}


def build_dir() -> Path:
    env = os.environ.get("UDMAP_BUILD_DIR")
    return Path(env) if env else ROOT / "build"


def compile_harness(tmp: Path) -> Path:
    """Builds gg10_timing against the kernel library of the build directory."""
    lib = build_dir() / "kernel"
    exe = tmp / "gg10_timing"
    cc = shutil.which("cc") or shutil.which("gcc")
    subprocess.run([cc, "-O2", "-std=c99", "-D_POSIX_C_SOURCE=199309L", "-Wall", "-Wextra",
                    "-I", str(ROOT / "wrappers" / "c"), str(ROOT / "bench" / "gg10_timing.c"),
                    "-o", str(exe), "-L", str(lib), "-ludmap", f"-Wl,-rpath,{lib}", "-lm"],
                   check=True)
    return exe


def beam_line(beam: dict) -> str:
    """The harness's `beam` line from flat beam parameters (udmap.case.beam_params)."""
    keys = ("E", "rho", "zeta", "neck_L", "neck_h", "neck_b", "platform_L", "platform_m",
            "platform_J", "airfoil_L", "airfoil_h", "airfoil_b", "neck_elements",
            "airfoil_elements")
    return "beam " + " ".join(repr(beam[k]) for k in keys)


def matrices_line(blade: dict, base: Path) -> str:
    """The harness's `matrices` line from a matrices blade section (paths relative to base);
    the stress rows are required here."""
    def path(key):
        p = Path(blade[key])
        return str(p if p.is_absolute() else base / p)
    return (f"matrices {path('M')} {path('K')} {blade['gamma_dof']} {blade['exc_dof']} "
            f"{path('stress_K')} {path('stress_M')} {blade['zeta']!r}")


def damper_line(d: dict) -> str:
    (f1x, f1y), (f2x, f2y) = d["flat_points"]
    cx, cy = d["curved_point"]
    return "asymmetric " + " ".join(repr(float(v)) for v in (
        d["CF"], d["mu"], d["pitch"], d["y_P"], d["beta_L_deg"], d["beta_R_deg"], f1x, f1y, f2x,
        f2y, cx, cy, d["kn_flat"], d["kt_flat"], d["kn_curved"], d["kt_curved"]))


def band_line(analysis: dict) -> str:
    return f"band {analysis['f_min']!r} {analysis['f_max']!r} {analysis['sigma_all']!r}"


def split_repeats(line: str, rounds: int) -> list[str | None]:
    """A job line with its repeats (third word) spread over `rounds` rounds: per round the
    job line with that round's share, or None where the share is 0."""
    words = line.split()
    total = int(words[2])
    out = []
    for k in range(rounds):
        n = total // rounds + (1 if k < total % rounds else 0)
        out.append(" ".join(words[:2] + [str(n)] + words[3:]) if n > 0 else None)
    return out


def standard_job(label: str, repeats: int, variant: int, knobs: dict) -> str:
    k = dict(STANDARD_DEFAULTS, **knobs)
    return (f"standard {label} {repeats} {variant} {k['tol']!r} {k['tol_path']!r} "
            f"{k['peak_tol']!r} {k['ds_max']!r} {k['max_angle']!r} {k['aft_samples']} "
            f"{k['warm_start']} {k['full_band']}")


def run_jobs(exe: Path, head: str, jobs: list[str] | list[list[str]]) -> dict[str, dict]:
    """Runs the jobs (one harness process, in order) and returns their results by label. Given
    a list of job lists (rounds), runs the harness once per round and pools the timing samples
    of each label over the rounds, so that a burst of load from other processes spreads over
    the settings instead of hitting one."""
    rounds = jobs if jobs and isinstance(jobs[0], list) else [jobs]
    runs: dict[str, dict] = {}
    for lines_in in rounds:
        proc = subprocess.Popen([str(exe)], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        out, err = proc.communicate(head + "\n" + "\n".join(lines_in) + "\n")
        if proc.returncode != 0:
            raise SystemExit(f"gg10_timing failed (status {proc.returncode}):\n{err}")
        lines = out.splitlines()
        if len(lines) != len(lines_in):
            raise SystemExit(f"gg10_timing: {len(lines_in)} jobs but {len(lines)} results:\n"
                             f"{err}")
        for line in lines:
            r = json.loads(line)
            old = runs.get(r["name"])
            if old is not None and "failed" in old:
                continue
            if old is not None and "samples" in old and "samples" in r:
                r["samples"] = old["samples"] + r["samples"]
            runs[r["name"]] = r
    for r in runs.values():
        t = sorted(r.get("samples", []))
        if t:
            r.update(seconds_median=t[len(t) // 2], seconds_min=t[0], seconds_max=t[-1],
                     repeats=len(t))
    return runs


def rel_errors(run: dict, ref: dict) -> dict:
    """Largest relative differences over the forces: error_gamma_P, error_sigma_a,
    error_f_res."""
    def worst(key):
        return max(abs(a / b - 1.0) for a, b in zip(run[key], ref[key]))
    return {"error_gamma_P": worst("gamma_P"), "error_sigma_a": worst("sigma_a"),
            "error_f_res": worst("f_res")}


def timing(run: dict) -> dict:
    return {k: run[k] for k in ("seconds_median", "seconds_min", "seconds_max", "repeats")}
