"""Shared timing helper for the benchmark scripts: medians of repeated runs."""
from __future__ import annotations

import statistics
import time


def measure(fn, repeats: int = 21, inner: int = 1, warmup: int = 2) -> dict:
    """Times `fn` (called `inner` times per sample) `repeats` times after `warmup` calls;
    returns seconds per call as median, min and max, and the repeat count."""
    for _ in range(warmup):
        fn()
    samples = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(inner):
            fn()
        samples.append((time.perf_counter() - t0) / inner)
    return {"seconds_median": statistics.median(samples), "seconds_min": min(samples),
            "seconds_max": max(samples), "repeats": repeats}


def record(case: str, method: str, setting: str, timing: dict, error_gamma_P=None,
           error_sigma_a=None, error_f_res=None, **extra) -> dict:
    """A benchmark record with the fields of INTERFACES.md (errors None when not applicable)."""
    rec = {"case": case, "method": method, "setting": setting, **timing,
           "error_gamma_P": error_gamma_P, "error_sigma_a": error_sigma_a,
           "error_f_res": error_f_res}
    rec.update(extra)
    return rec
