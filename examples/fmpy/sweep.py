#!/usr/bin/env python3
"""Sweeps the excitation force F_E through the udmap FMU with fmpy and plots the damper
performance curve (peak alternating stress and platform rotation against F_E, with F_lim).

    python3 examples/fmpy/sweep.py build/udmap.fmu --plot performance.png

The FMU is algebraic: at each communication point its outputs are the steady response at
resonance (f_exc = 0) for the current inputs, so a ramp of F_E over time is a sweep. Prints
F_lim and the rows F_E gamma_P f_res sigma_a at F_E = 1, 2 and 5 N.
"""
import argparse

import numpy as np
from fmpy import simulate_fmu

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("fmu", help="the FMU (build/udmap.fmu or build/udmap-fmi3.fmu)")
parser.add_argument("--plot", default="performance.png", help="where to write the plot")
args = parser.parse_args()

# F_E = 0.5, 1.0, ..., 10 N at t = 0, 1, ..., 19 s; one communication point per second.
forces = 0.5 * np.arange(1, 21)
signal = np.array(list(zip(np.arange(len(forces), dtype=float), forces)),
                  dtype=[("time", np.float64), ("F_E", np.float64)])
# One step more than forces: the outputs recorded at t + 1 belong to the input applied at t.
result = simulate_fmu(args.fmu, stop_time=float(len(forces)), output_interval=1.0,
                      input=signal, output=["F_E", "gamma_P", "f_res", "sigma_a", "F_lim"])

# Every recorded row holds the F_E its outputs were computed for; keep one row per force.
_, first = np.unique(result["F_E"], return_index=True)
rows = result[np.sort(first)]
print(f"F_lim = {rows['F_lim'][0]:.8e} N")
print("# F_E [N]  gamma_P [rad]  f_res [Hz]  sigma_a [Pa]")
for r in rows[np.isin(rows["F_E"], [1.0, 2.0, 5.0])]:
    print(" ".join(f"{r[k]:.8e}" for k in ("F_E", "gamma_P", "f_res", "sigma_a")))

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(rows["F_E"], rows["sigma_a"] / 1e6, "o-", label="sigma_a at resonance")
ax.axvline(rows["F_lim"][0], color="k", ls="--", label="F_lim")
ax.axvline(0.5 * rows["F_lim"][0], color="gray", ls=":", label="0.5 F_lim")
ax.axhline(80.0, color="tab:red", ls="-.", label="sigma_all (80 MPa)")
ax.set_xlabel("F_E [N]")
ax.set_ylabel("sigma_a [MPa]")
ax2 = ax.twinx()
ax2.plot(rows["F_E"], rows["gamma_P"], "s--", color="tab:orange", label="gamma_P (right)")
ax2.set_ylabel("gamma_P [rad]")
handles = ax.get_legend_handles_labels()[0] + ax2.get_legend_handles_labels()[0]
ax.legend(handles, [h.get_label() for h in handles], loc="lower right", fontsize="small")
ax.set_title("udmap FMU: damper performance (blade A)")
fig.tight_layout()
fig.savefig(args.plot, dpi=120)
print(f"wrote {args.plot}")
