"""Plausibility checks of a case (issue: "unit mistakes caught"), separate from the range
checks of the schema: a case inside every range can still be physically implausible, most often
because a value was typed in another unit. Each check gives a warning that names the quantity,
says why it looks wrong and suggests the likely unit error; nothing is refused.

The checks (docs/case-files.md, "Plausibility"):
- the platform heavier than the rest of the beam blade (grams for kg);
- the platform's rotary inertia far above that of a rigid bar of its mass and length
  (kg mm^2 for kg m^2);
- a base-cycle amplitude gamma_b above 1e-2 rad (contact stiffnesses in N/mm for N/m);
- the stuck damper shifting the first frequency by less than 0.1 % or more than 100 %;
- the band [f_min, f_max] missing the bare or the stuck first mode.
"""
from __future__ import annotations

from ..errors import UdmapError

#: Largest plausible gamma_b [rad] and range of the stuck frequency shift.
GAMMA_B_MAX = 1e-2
SHIFT_MIN, SHIFT_MAX = 1e-3, 1.0
#: Rotary inertia above this times m L^2 / 12 of the platform looks like kg mm^2.
INERTIA_FACTOR = 1e3


def _g(x: float) -> str:
    return f"{x:.4g}"


def plausibility_warnings(case, blade, damper, model=None) -> list[str]:
    """The warnings of a built case: its blade, damper and (when built) model, udmap objects;
    without the model the checks that need the stuck peak are left out."""
    out = []
    b = case.blade
    if b["kind"] == "beam":
        rest = b["rho"] * sum(b[p]["b"] * b[p]["h"] * b[p]["L"] for p in ("neck", "airfoil"))
        m, J, L = b["platform"]["m"], b["platform"]["J"], b["platform"]["L"]
        if m > rest:
            out.append(f"blade.platform.m = {_g(m)} kg is heavier than the rest of the blade "
                       f"({_g(rest)} kg of neck and airfoil): was it given in grams? "
                       f"({_g(m)} g would be {_g(m / 1000)} kg)")
        if J > INERTIA_FACTOR * m * L ** 2 / 12:
            out.append(f"blade.platform.J = {_g(J)} kg m^2 is over {INERTIA_FACTOR:g} times that "
                       f"of a rigid bar of the platform's mass and length ({_g(m * L**2 / 12)} "
                       "kg m^2): was it given in kg mm^2? (1 kg mm^2 = 1e-6 kg m^2)")
    if damper.kind == "asymmetric" and damper.gamma_b > GAMMA_B_MAX:
        d = case.damper
        out.append(f"the base-cycle amplitude gamma_b = {_g(damper.gamma_b)} rad is above "
                   f"{GAMMA_B_MAX:g} rad (the contacts deflect by degrees before they slip): "
                   f"were the contact stiffnesses given in N/mm? (kn_flat = {_g(d['kn_flat'])} "
                   "N/m; 1 N/mm = 1e3 N/m)")
    a = case.analysis
    f1 = float(blade.natural_frequencies(1)[0])
    in_band = a["f_min"] <= f1 <= a["f_max"]
    f_stuck = None
    if model is not None:
        try:
            g_small = 1e-3 * (damper.gamma_s if damper.gamma_s > 0 else damper.gamma_b)
            f_stuck = float(model.backbone_curve([g_small])[1][0]) if g_small > 0 else None
        except UdmapError:
            pass  # no stuck peak inside the band
    if not in_band or (model is not None and f_stuck is None):
        found = f"bare first mode at {_g(f1)} Hz" + (
            "" if model is None else f", stuck at {_g(f_stuck)} Hz" if f_stuck is not None
            else ", no stuck peak inside the band")
        out.append(f"the band [analysis.f_min, analysis.f_max] = [{_g(a['f_min'])}, "
                   f"{_g(a['f_max'])}] Hz misses the first mode ({found}): are the band or "
                   "the blade in other units (Hz for rad/s, mm-t-s for SI)?")
    elif damper.kind == "asymmetric" and f_stuck is not None:
        shift = f_stuck / f1 - 1
        if not SHIFT_MIN <= shift <= SHIFT_MAX:
            out.append(f"the stuck damper shifts the first frequency by {100 * shift:.3g} % "
                       f"({_g(f1)} Hz bare, {_g(f_stuck)} Hz stuck), outside "
                       f"{100 * SHIFT_MIN:g} % to {100 * SHIFT_MAX:g} %: are the contact "
                       "stiffnesses or the blade in another unit?")
    return out


def with_hints(error: UdmapError, hints: list[str]) -> UdmapError:
    """The error with the plausibility warnings of its case appended: a failure that a unit
    mistake explains says so (the band holding a second mode, no resonance in the band)."""
    if hints and error.args:
        error.args = (f"{error.args[0]} (plausibility: {'; '.join(hints)})",) + error.args[1:]
    return error
