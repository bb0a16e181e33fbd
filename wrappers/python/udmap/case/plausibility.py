"""Plausibility checks of a case (issue: "unit mistakes caught"), separate from the range
checks of the schema: a case inside every range can still be physically implausible, most often
because a value was typed in another unit. Each check gives a warning that names the quantity,
says why it looks wrong and suggests the likely unit error; nothing is refused.

The checks and their texts are the kernel's (kernel/src/mapping/plausibility.f90, through
:meth:`udmap.model.Model.warnings` and :func:`udmap.model.plausibility_warnings`), the same in
every interface (docs/case-files.md, "Plausibility"):
- the platform heavier than the rest of the beam blade (grams for kg): ``platform_mass``;
- the platform's rotary inertia far above that of a rigid bar of its mass and length
  (kg mm^2 for kg m^2): ``platform_inertia``;
- a base-cycle amplitude gamma_b above 1e-2 rad (contact stiffnesses in N/mm for N/m):
  ``gamma_b_large``;
- the stuck damper shifting the first frequency by less than 0.1 % or more than 100 %:
  ``stuck_shift``;
- the band [f_min, f_max] missing the bare or the stuck first mode: ``band_misses_mode``.
"""
from __future__ import annotations

from ..errors import UdmapError
from ..model import WARNING_KINDS, plausibility_warnings as _kernel_warnings

#: Largest plausible gamma_b [rad] (the kernel's plausibility_gamma_b_max): the DOE compares
#: the gamma_b of a chunk's designs, which come as numbers from one kernel call, against it.
GAMMA_B_MAX = 1e-2
#: The kinds of warning (stable short keys).
KINDS = WARNING_KINDS
PLATFORM_MASS, PLATFORM_INERTIA, GAMMA_B_LARGE, STUCK_SHIFT, BAND_MISSES_MODE = KINDS


def blade_checks(blade, f_min: float, f_max: float) -> list[tuple]:
    """(kind, text) of the checks that need no damper: the beam's platform and the band
    [f_min, f_max] [Hz] against the bare first mode of ``blade`` (a udmap Blade)."""
    return _kernel_warnings(blade, f_min, f_max)


def plausibility_checks(case, blade, damper, model=None) -> list[tuple]:
    """(kind, text) of the warnings of a built case: its blade, damper and (when built) model,
    udmap objects; without the model the checks that need the stuck peak are left out."""
    if model is not None:
        return model.warnings()
    a = case.analysis
    return _kernel_warnings(blade, a["f_min"], a["f_max"], damper)


def plausibility_warnings(case, blade, damper, model=None) -> list[str]:
    """The texts of :func:`plausibility_checks`."""
    return [text for _, text in plausibility_checks(case, blade, damper, model)]


def with_hints(error: UdmapError, hints: list[str]) -> UdmapError:
    """The error with the plausibility warnings of its case appended: a failure that a unit
    mistake explains says so (the band holding a second mode, no resonance in the band)."""
    if hints and error.args:
        error.args = (f"{error.args[0]} (plausibility: {'; '.join(hints)})",) + error.args[1:]
    return error
