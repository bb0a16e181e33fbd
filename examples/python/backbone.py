#!/usr/bin/env python3
"""Backbone of blade A with its asymmetric damper through the Python package (numpy).

Run with the package importable (pip install ./wrappers/python, or PYTHONPATH=wrappers/python)
and the kernel library found (UDMAP_PREFIX=<install prefix>, UDMAP_LIBRARY=<path>/libudmap.so,
or a build tree next to the package). Prints F_lim and, per excitation force F_E, the resonance
peak: gamma_P [rad], f_res [Hz], sigma_a [Pa].
"""
import numpy as np

import udmap
from udmap.case import build_model, load_case

case = load_case()                  # the embedded blade A; load_case("my_case.json") for others
model = build_model(case)           # blade + damper + band, from the case's sections
forces = np.array([1.0, 2.0, 5.0])  # F_E [N]
points = model.backbone(forces)     # one dict per force: gamma_P, f_res, sigma_a, u_E, ...

gamma_P = np.array([p["gamma_P"] for p in points])
f_res = np.array([p["f_res"] for p in points])
sigma_a = np.array([p["sigma_a"] for p in points])
print(f"udmap {udmap.version()}, blade A")
print(f"F_lim = {model.limit_force():.8e} N")
print("# F_E [N]  gamma_P [rad]  f_res [Hz]  sigma_a [Pa]")
for row in np.column_stack([forces, gamma_P, f_res, sigma_a]):
    print(" ".join(f"{x:.8e}" for x in row))
