"""Design of experiments: ``python3 -m udmap doe`` (INTERFACES.md "Design of experiments output").

A design is the case with some blade, damper or analysis parameters changed. The designs are
sampled with :mod:`scipy.stats.qmc` (Sobol, Latin hypercube) or on a full grid, evaluated in
chunks by a serial, process-pool, thread-pool or Dask executor (a chunk of asymmetric dampers
is one kernel call, udmap_model_designs, computing only the stages the chosen ``--outputs``
need), and streamed in design order to a CSV file (plus Parquet when pyarrow is installed, or
Parquet alone). A worker reuses what the varied parameters leave unchanged (the blade, the
model's bare-blade data, one tracing for designs that differ only in CF and
``stiffness_scale``; see :class:`DesignContext`), and every design goes through the same kernel
calls on the same state
whichever worker computes it and whatever it computed before, so serial, pooled and Dask runs
give the same file byte for byte for the same seed.

Parameter names (``--vary NAME=LO:HI``): a dotted path into the case (``damper.mu``,
``blade.airfoil.h``, ``airfoil.h`` when the section is unambiguous, ``damper.flat_points[0][1]``)
or a flat FMU name (``mu``, ``CF``, ``kt_flat``, ``beta_L_deg``, ``neck_L``, ``platform_m``,
``airfoil_elements``, ``E``, ``flat1_x``, ``curved_y``, ``f_min``, ``sigma_all``, ...), and
``stiffness_scale``, a common factor of the asymmetric damper's kn_flat, kt_flat, kn_curved,
kt_curved (1: the case's values). Integer parameters (element counts) are rounded,
``airfoil.elements`` to an even number.
``NAME=LO:HI:log`` samples ``ln(value)`` uniformly (stiffnesses spanning decades).
"""
from .executors import chunk_ranges, default_chunk, default_workers, make_executor
from .layout import OUTPUTS, cell, columns, parse_outputs
from .io import FORMATS, Output, format_chunk, format_rows, read_csv
from .parameters import (SECTIONS, STIFFNESS_SCALE, Parameter, parameter_names, parse_vary,
                         resolve_name, validation_dict, with_values)
from .plot import pareto_front, plot_doe
from .run import make_spec, parse_forces, run_doe
from .sampling import METHODS, DesignValues, design_values, unit_sample
from .worker import (ADM_DECADES, ADM_GRID, ADM_TINY, STATUS_ERROR, STATUS_INPUT, STATUS_NUMERIC,
                     STATUS_OK, STATUS_PHYSICS, ChunkRows, DesignContext, admissible_grid,
                     context_for, design_references, run_chunk)

__all__ = ["chunk_ranges", "default_chunk", "default_workers", "make_executor", "FORMATS",
           "OUTPUTS", "Output", "cell", "columns", "format_chunk", "format_rows", "parse_outputs",
           "read_csv", "SECTIONS", "STIFFNESS_SCALE", "Parameter", "parameter_names",
           "parse_vary", "resolve_name", "validation_dict", "with_values", "pareto_front",
           "plot_doe", "make_spec", "parse_forces", "run_doe", "METHODS", "DesignValues",
           "design_values", "unit_sample", "ADM_DECADES", "ADM_GRID", "ADM_TINY", "STATUS_ERROR",
           "STATUS_INPUT", "STATUS_NUMERIC", "STATUS_OK", "STATUS_PHYSICS", "ChunkRows",
           "DesignContext", "admissible_grid", "context_for", "design_references", "run_chunk"]
