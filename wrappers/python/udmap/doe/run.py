"""A whole design of experiments: the run description, the executor, the ordered output and
the summary (``python3 -m udmap doe``)."""
from __future__ import annotations

import hashlib
import json
import math
import time
from typing import Sequence

from ..case import Case, load_case
from ..errors import InputError
from ..progress import Progress
from . import executors, io
from .layout import parse_outputs
from .parameters import Parameter, parse_vary
from .plot import plot_doe
from .sampling import METHODS, design_values, unit_sample
from .worker import design_references

def parse_forces(text) -> tuple[list[float], list[str]]:
    """``'1,2.5'`` (or a list of numbers) into forces and their column labels as written."""
    if text is None:
        return [], []
    items = [s.strip() for s in text.split(",")] if isinstance(text, str) else list(text)
    forces, labels = [], []
    for item in items:
        if item == "":
            continue
        try:
            f = float(item)
        except (TypeError, ValueError):
            raise InputError(f"--forces: expected comma-separated numbers, got {item!r}") from None
        if not (math.isfinite(f) and f > 0):
            raise InputError(f"--forces: forces must be positive finite numbers, got {item}")
        label = item if isinstance(item, str) else repr(float(item)).removesuffix(".0")
        if label in labels:
            raise InputError(f"--forces: {label} is given twice")
        forces.append(f)
        labels.append(label)
    if not forces:
        raise InputError("--forces: expected at least one number")
    return forces, labels


def make_spec(case: Case, params: Sequence[Parameter], forces: Sequence[float],
              labels: Sequence[str], samples: int, method: str, seed: int,
              outputs=None) -> dict:
    """The run description: everything a worker needs (plain data, picklable) plus what a
    resumed run must match; ``token`` identifies it."""
    spec = {
        "name": case.name, "base_dir": str(case.base_dir),
        "blade": case.blade, "damper": case.damper, "analysis": case.analysis,
        "params": [{"name": p.name, "path": p.dotted, "lo": p.lo, "hi": p.hi, "scale": p.scale,
                    "integer": p.integer} for p in params],
        "paths": [list(p.path) for p in params],
        "forces": list(forces), "labels": list(labels),
        "samples": int(samples), "method": method, "seed": int(seed),
        "outputs": list(outputs) if outputs else None,
    }
    text = json.dumps(spec, sort_keys=True, default=str)
    spec["token"] = hashlib.sha256(text.encode()).hexdigest()[:16]
    return spec


def run_doe(case, vary, samples: int, out, *, method: str = "sobol", forces=None,
            seed: int = 0, workers: int | None = None, threads: bool = False,
            dask: str | None = None, chunk: int | None = None, resume: bool = False,
            overwrite: bool = False, progress: bool = True, plot: bool = False,
            stream=None, outputs=None, format: str = "csv") -> dict:
    """Runs a design of experiments and returns a summary dict.

    ``case``: a :class:`~udmap.case.Case`, a path or None (the embedded blade A); ``vary``:
    ``NAME=LO:HI[:log]`` strings or (name, lo, hi) tuples; ``forces``: '1,2' or numbers (the
    per-force columns); ``workers``: processes (default all cores; 1 runs in this process),
    ``threads=True`` for threads instead; ``dask``: 'local:K' or 'tcp://HOST:PORT';
    ``chunk``: designs per task and per write; ``resume``: continue ``out``; ``outputs``:
    'F_adm,sigma_a' or a list of names of :data:`udmap.doe.layout.OUTPUTS` (default all; the
    kernel computes only what they need); ``format``: 'csv' (default, with a Parquet copy
    when pyarrow is installed) or 'parquet' (Parquet alone).
    """
    if not isinstance(case, Case):
        case = load_case(case)
    if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
        raise InputError(f"--samples must be a positive integer, got {samples!r}")
    if method not in METHODS:
        raise InputError(f"--method must be one of {', '.join(METHODS)}, got {method!r}")
    chosen = parse_outputs(outputs)
    if plot and format == "parquet":
        raise InputError("--plot reads the CSV: use it with --format csv")
    if plot and chosen and not {"F_adm", "hcf_ok"} <= set(chosen):
        raise InputError("--plot needs the outputs F_adm and hcf_ok (add them to --outputs)")
    params = parse_vary(case, vary)
    force_values, labels = parse_forces(forces) if forces not in (None, "", []) else ([], [])
    values = design_values(params, unit_sample(method, samples, len(params), seed))
    spec = make_spec(case, params, force_values, labels, samples, method, seed, chosen)
    if format == "parquet":
        spec["rows"] = "arrow"  # the workers return Arrow batches, not row text (not in token)
    executor = executors.make_executor(workers=workers, threads=threads, dask=dask)
    if chunk is None:
        chunk = executors.default_chunk(samples, executor.workers)
    if chunk < 1:
        raise InputError(f"--chunk must be at least 1, got {chunk}")
    output = io.Output(out, spec, values, format=format)
    first = output.open(resume=resume, overwrite=overwrite)  # InputError before any work
    t0 = time.perf_counter()
    counts = dict(output.counts)
    bounds = executors.chunk_ranges(first, samples, output.held, chunk)
    todo = sum(e - s for s, e in bounds)
    refs = design_references(spec, values)  # designs sharing a tracing (PHYSICS.md 2.3)

    def chunk_refs(s, e):
        if refs is None or not (refs[s:e] >= 0).any():
            return None
        return [values[int(r)] if r >= 0 else None for r in refs[s:e]]

    # the values of a chunk when it is sent
    ranges = ((s, values[s:e], chunk_refs(s, e)) for s, e in bounds)
    computed = 0
    traces = 0
    # plausibility warnings per kind, over the designs counted (a resumed run continues the
    # counts its meta file recorded)
    warnings = dict(output.recorded("warnings", {}) if resume else {})
    warned = int(output.recorded("warnings_designs", 0)) if resume else 0
    interrupted = False
    try:
        if todo > 0:
            label = "doe" if first == 0 else f"doe (resumed at {first})"
            with Progress(todo, label, stream=stream) as bar:
                bar.enabled = bar.enabled and progress
                with executor:
                    for start, n, text, chunk_counts in executor.run(spec, ranges):
                        output.put(start, n, text)
                        computed += n
                        traces += chunk_counts.pop("traces", 0)
                        for k, v in chunk_counts.pop("warnings", {}).items():
                            warnings[k] = warnings.get(k, 0) + v
                        warned += n
                        for k, v in chunk_counts.items():
                            counts[k] = counts.get(k, 0) + v
                        bar.update(n)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        output.close()
    seconds = time.perf_counter() - t0
    summary = {"out": str(output.result_path), "designs": samples,
               "written": output.written, "computed": computed, "resumed_at": first,
               "traces": traces,
               "recovered": sum(n for _, n in output.held),
               "status": io.split_counts(counts)[0], "seconds": seconds,
               "designs_per_second": computed / seconds if seconds > 0 and computed else None,
               "workers": executor.workers, "executor": executor.kind,
               "startup_seconds": executor.startup_seconds, "interrupted": interrupted,
               "warnings": dict(sorted(warnings.items())), "warnings_designs": warned}
    output.record(warnings=summary["warnings"], warnings_designs=warned)
    if interrupted:
        return summary
    output.record(traces=traces)
    summary["parquet"] = output.finish()
    summary.update(io.pass_shares(counts, samples, labels))
    if plot:
        summary["plots"] = [str(p) for p in plot_doe(output.path, [p.name for p in params],
                                                     labels, [p.path for p in params])]
    return summary
