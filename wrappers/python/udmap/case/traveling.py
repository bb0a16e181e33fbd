"""Traveling waves in a case (PHYSICS.md 2.6, INTERFACES.md "Traveling waves"): the one place
where ``analysis.blades``, ``analysis.engine_order`` and ``analysis.ibpa_deg`` (or the command
line's ``--blades``, ``--engine-order``, ``--ibpa``) become the interblade phase angle that the
kernel gets in its Analysis struct, with their checks and the outputs' fields.

Convention: ``ibpa_deg`` is the phase ``phi`` in degrees in ``(-180, 180]``; from an engine
order, ``phi = 360 EO / N`` with ``EO`` taken modulo ``N`` and then shifted by ``-N`` when it is
above ``N/2`` (``N = 24, EO = 23``: ``-15``; ``EO = 12``: ``180``; ``EO = 0`` or ``24``: exactly
``0``). A given ``ibpa_deg`` is normalised the same way (``270`` is ``-90``, ``-180`` is ``180``).

A validated case holds one of the two forms: ``blades`` with ``engine_order`` (``0`` when only
``blades`` is given) and no ``ibpa_deg``, or ``ibpa_deg`` (default ``0``, in phase) alone.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError
from .schema import SCHEMA, check_field

#: The analysis fields of a traveling wave, in the order of the outputs.
WAVE_FIELDS = ("engine_order", "blades", "ibpa_deg")
#: Damper kinds that act on gamma_P alone (grounded): the phase does not change them.
PHASE_FREE_DAMPERS = ("jenkins", "table")
#: Largest |cos| between platform.tangent and platform.axis accepted as orthogonal.
TANGENT_TOL = 1e-6


@dataclass(frozen=True)
class Wave:
    """The traveling wave of an analysis: ``blades`` and ``engine_order`` (None when the phase
    was given as ``ibpa_deg``) and the interblade phase ``ibpa_deg`` in (-180, 180]."""
    blades: int | None
    engine_order: int | None
    ibpa_deg: float

    @property
    def in_phase(self) -> bool:
        return self.ibpa_deg == 0.0

    def output(self) -> dict:
        """The fields every analysis output carries."""
        return {"engine_order": self.engine_order, "blades": self.blades,
                "ibpa_deg": self.ibpa_deg}


def normalised_deg(phi_deg: float) -> float:
    """An angle in degrees in (-180, 180] (exact: IEEE remainder)."""
    r = math.remainder(float(phi_deg), 360.0)
    return 180.0 if r == -180.0 else r + 0.0        # + 0.0: no negative zero


def ibpa_of(blades: int, engine_order: int) -> float:
    """The interblade phase angle [deg] of engine order EO on N blades, 360 EO/N in
    (-180, 180]; exactly 0 when EO is a multiple of N."""
    e = int(engine_order) % int(blades)
    if 2 * e > blades:
        e -= blades
    return 360.0 * e / blades + 0.0


def wave_of(analysis: dict) -> Wave:
    """The wave of a validated analysis section."""
    if analysis.get("blades") is not None:
        n, eo = analysis["blades"], analysis.get("engine_order") or 0
        return Wave(n, eo, ibpa_of(n, eo))
    return Wave(None, None, normalised_deg(analysis.get("ibpa_deg") or 0.0))


def settle_analysis(raw: dict, analysis: dict) -> None:
    """Checks the forms a case file gives (``raw``: the section as written) and leaves one of
    them in the validated ``analysis``: the two forms exclude each other, ``engine_order``
    needs ``blades``, ``blades`` alone is engine order 0."""
    given = [k for k in WAVE_FIELDS if raw.get(k) is not None]
    if "ibpa_deg" in given and len(given) > 1:
        other = "engine_order" if "engine_order" in given else "blades"
        raise InputError(f"analysis.ibpa_deg and analysis.{other} exclude each other: give the "
                         "interblade phase either as analysis.blades with analysis.engine_order "
                         "or as analysis.ibpa_deg")
    if "engine_order" in given and "blades" not in given:
        raise InputError("analysis.engine_order needs analysis.blades (the number of blades N: "
                         "phi = 2 pi EO/N)")
    if "blades" in given:
        analysis.pop("ibpa_deg", None)
        analysis.setdefault("engine_order", 0)


def _option_value(option: str, text, field: str):
    """A command-line value checked against the case field's schema row, named by its option."""
    if isinstance(text, str):
        try:
            value = int(text)
        except ValueError:
            try:
                value = float(text)
            except ValueError:
                raise InputError(f"{option} must be a number, got {text!r}") from None
            if not math.isfinite(value):
                raise InputError(f"{option} must be a finite number, got {text!r}")
    else:
        value = text
    return check_field(option, value, SCHEMA[("analysis", None)][field])


def apply_options(case, blades=None, engine_order=None, ibpa=None) -> None:
    """``--blades N --engine-order EO`` or ``--ibpa DEG`` (text or numbers; None: not given)
    override the case's wave; then :func:`check_case`. ``--blades`` alone keeps the case's
    engine order (0 if none), ``--engine-order`` alone the case's blades."""
    a = case.analysis
    if ibpa is not None:
        if engine_order is not None or blades is not None:
            other = "--engine-order" if engine_order is not None else "--blades"
            raise InputError(f"--ibpa and {other} exclude each other: give the interblade phase "
                             "either as --blades N --engine-order EO or as --ibpa DEG")
        value = _option_value("--ibpa", ibpa, "ibpa_deg")
        a.pop("blades", None)
        a.pop("engine_order", None)
        a["ibpa_deg"] = value
    elif blades is not None or engine_order is not None:
        n = _option_value("--blades", blades, "blades") if blades is not None else a.get("blades")
        if n is None:
            raise InputError("--engine-order needs --blades N (or analysis.blades in the case)")
        eo = _option_value("--engine-order", engine_order, "engine_order") \
            if engine_order is not None else a.get("engine_order", 0)
        a.pop("ibpa_deg", None)
        a["blades"], a["engine_order"] = n, eo
    check_case(case)


def check_case(case) -> None:
    """A traveling wave (phi != 0) needs the platform translations: ``blade.u_dof`` on a
    ``matrices`` blade, ``blade.platform.tangent`` on an ``fe`` blade (the beam has them)."""
    wave = wave_of(case.analysis)
    if wave.in_phase:
        return
    b = case.blade
    # an fe blade: validated (kind fe) or reduced (a matrices blade with case.fe, whose
    # u_dof comes from the tangent)
    if (b.get("kind") == "fe" and b["platform"].get("tangent") is None) or \
            (b.get("kind") == "matrices" and b.get("u_dof") is None and case.fe is not None):
        raise InputError(f"blade.platform.tangent: a traveling wave ({_phase_text(wave)}) "
                         "needs the platform's circumferential direction (a unit vector "
                         "orthogonal to blade.platform.axis)")
    if b.get("kind") == "matrices" and b.get("u_dof") is None:
        raise InputError(f"blade.u_dof: a traveling wave ({_phase_text(wave)}) needs the DOF of "
                         "the platform's circumferential translation u_P (and blade.v_dof for "
                         "the radial one, if the model has it)")


def check_tangent(axis, tangent) -> list[float]:
    """``blade.platform.tangent`` normalised; it must be orthogonal to the axis (to
    :data:`TANGENT_TOL` after normalising both)."""
    na = math.sqrt(sum(x * x for x in axis))
    nt = math.sqrt(sum(x * x for x in tangent))
    t = [x / nt for x in tangent]
    cos = sum(x * y / na for x, y in zip(axis, t))
    if abs(cos) > TANGENT_TOL:
        raise InputError(f"blade.platform.tangent must be orthogonal to blade.platform.axis "
                         f"(the circumferential direction lies in the frontal plane), but the "
                         f"cosine of their angle is {cos:.3g}")
    return t


def wave_warnings(case) -> list[str]:
    """Warnings for the outputs: a phase given with a damper that does not depend on it."""
    wave = wave_of(case.analysis)
    kind = case.damper.get("kind")
    if wave.in_phase or kind not in PHASE_FREE_DAMPERS:
        return []
    return [f"the interblade phase ({_phase_text(wave)}) does not change a {kind} damper: it "
            "acts on gamma_P alone, grounded (PHYSICS.md 2.6); the result is the in-phase one"]


def _phase_text(wave: Wave) -> str:
    phase = f"ibpa_deg = {wave.ibpa_deg:g} deg"
    if wave.blades is not None:
        return f"engine_order {wave.engine_order} on {wave.blades} blades, {phase}"
    return phase


def require_in_phase(case, what: str) -> None:
    """Refuses a nonzero phase where the computation does not take it yet (the time
    integration of an asymmetric damper); a phase-free damper is answered in phase (with the
    warning of :func:`wave_warnings`)."""
    wave = wave_of(case.analysis)
    if wave.in_phase or case.damper.get("kind") in PHASE_FREE_DAMPERS:
        return
    raise InputError(f"{what} at a nonzero interblade phase ({_phase_text(wave)}) is not "
                     "available in this version: the layered mapping (backbone, response, "
                     "doe), hbm and nodal take it")
