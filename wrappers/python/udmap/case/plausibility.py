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

#: The kinds of warning: a stable short key per check (the DOE counts them per kind).
PLATFORM_MASS, PLATFORM_INERTIA, GAMMA_B_LARGE, STUCK_SHIFT, BAND_MISSES_MODE = (
    "platform_mass", "platform_inertia", "gamma_b_large", "stuck_shift", "band_misses_mode")
KINDS = (PLATFORM_MASS, PLATFORM_INERTIA, GAMMA_B_LARGE, STUCK_SHIFT, BAND_MISSES_MODE)


def _g(x: float) -> str:
    return f"{x:.4g}"


def blade_checks(blade_data: dict, f1: float, f_min: float, f_max: float) -> list[tuple]:
    """(kind, text) of the checks that need no damper: the beam's platform (``blade_data``, the
    case's ``blade`` section) and the band [f_min, f_max] against the bare first mode f1 [Hz]."""
    out = []
    b = blade_data
    if b["kind"] == "beam":
        rest = b["rho"] * sum(b[p]["b"] * b[p]["h"] * b[p]["L"] for p in ("neck", "airfoil"))
        m, J, L = b["platform"]["m"], b["platform"]["J"], b["platform"]["L"]
        if m > rest:
            out.append((PLATFORM_MASS,
                        f"blade.platform.m = {_g(m)} kg is heavier than the rest of the blade "
                        f"({_g(rest)} kg of neck and airfoil): was it given in grams? "
                        f"({_g(m)} g would be {_g(m / 1000)} kg)"))
        if J > INERTIA_FACTOR * m * L ** 2 / 12:
            out.append((PLATFORM_INERTIA,
                        f"blade.platform.J = {_g(J)} kg m^2 is over {INERTIA_FACTOR:g} times "
                        f"that of a rigid bar of the platform's mass and length "
                        f"({_g(m * L**2 / 12)} kg m^2): was it given in kg mm^2? "
                        "(1 kg mm^2 = 1e-6 kg m^2)"))
    if not f_min <= f1 <= f_max:
        out.append((BAND_MISSES_MODE, _band_text(f_min, f_max, f"bare first mode at {_g(f1)} Hz")))
    return out


def _band_text(f_min: float, f_max: float, found: str) -> str:
    return (f"the band [analysis.f_min, analysis.f_max] = [{_g(f_min)}, {_g(f_max)}] Hz misses "
            f"the first mode ({found}): are the band or the blade in other units (Hz for "
            "rad/s, mm-t-s for SI)?")


def gamma_b_text(gamma_b: float, kn_flat: float) -> str:
    """The warning of an asymmetric damper's gamma_b above GAMMA_B_MAX."""
    return (f"the base-cycle amplitude gamma_b = {_g(gamma_b)} rad is above {GAMMA_B_MAX:g} rad "
            "(the contacts deflect by degrees before they slip): were the contact stiffnesses "
            f"given in N/mm? (kn_flat = {_g(kn_flat)} N/m; 1 N/mm = 1e3 N/m)")


def plausibility_checks(case, blade, damper, model=None) -> list[tuple]:
    """(kind, text) of the warnings of a built case: its blade, damper and (when built) model,
    udmap objects; without the model the checks that need the stuck peak are left out."""
    a = case.analysis
    f1 = float(blade.natural_frequencies(1)[0])
    out = [w for w in blade_checks(case.blade, f1, a["f_min"], a["f_max"])
           if w[0] != BAND_MISSES_MODE]
    if damper.kind == "asymmetric" and damper.gamma_b > GAMMA_B_MAX:
        out.append((GAMMA_B_LARGE, gamma_b_text(damper.gamma_b, case.damper["kn_flat"])))
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
        out.append((BAND_MISSES_MODE, _band_text(a["f_min"], a["f_max"], found)))
    elif damper.kind == "asymmetric" and f_stuck is not None:
        shift = f_stuck / f1 - 1
        if not SHIFT_MIN <= shift <= SHIFT_MAX:
            out.append((STUCK_SHIFT,
                        f"the stuck damper shifts the first frequency by {100 * shift:.3g} % "
                        f"({_g(f1)} Hz bare, {_g(f_stuck)} Hz stuck), outside "
                        f"{100 * SHIFT_MIN:g} % to {100 * SHIFT_MAX:g} %: are the contact "
                        "stiffnesses or the blade in another unit?"))
    return out


def plausibility_warnings(case, blade, damper, model=None) -> list[str]:
    """The texts of :func:`plausibility_checks`."""
    return [text for _, text in plausibility_checks(case, blade, damper, model)]


def with_hints(error: UdmapError, hints: list[str]) -> UdmapError:
    """The error with the plausibility warnings of its case appended: a failure that a unit
    mistake explains says so (the band holding a second mode, no resonance in the band)."""
    if hints and error.args:
        error.args = (f"{error.args[0]} (plausibility: {'; '.join(hints)})",) + error.args[1:]
    return error
