"""The kernel objects of a case: blade, damper (its k(gamma) face), model, and the contact law
in time for the standard method (:mod:`udmap.hbm`). The case's plain dictionaries end here: the
object classes below take numbers and objects.
"""
from __future__ import annotations

from ..blade import Blade
from ..damper import Damper
from ..errors import InputError
from ..hbm import Contact
from ..model import Model
from .load import Case
from .schema import EIGEN_METHODS, flat_params
from .traveling import check_case, wave_of

ASYMMETRIC_KEYS = ("CF", "mu", "pitch", "y_P", "beta_L_deg", "beta_R_deg", "flat_points",
                   "curved_point", "kn_flat", "kt_flat", "kn_curved", "kt_curved")


def beam_params(blade: dict) -> dict:
    """The flat parameter names of the C API / FMU (neck_L, ...) for a beam blade section."""
    return flat_params(blade, "blade", "beam")


def build_blade(case: Case) -> Blade:
    """The kernel blade of a case."""
    b = case.blade
    if b["kind"] == "beam":
        return Blade.beam(**beam_params(b))
    blade = Blade.matrices(b["M"], b["K"], b["gamma_dof"], b["exc_dof"], zeta=b["zeta"],
                           C=b.get("C"), stress_K=b.get("stress_K"), stress_M=b.get("stress_M"))
    if b.get("u_dof") is not None:      # the platform translations (PHYSICS.md 2.6)
        blade.set_platform_dofs(b["u_dof"], b.get("v_dof"), gamma_dof=b["gamma_dof"],
                                prefix="blade.")
    return blade


def damper_from_section(d: dict) -> Damper:
    """The kernel damper (its k(gamma) face, the stiffness table) of a validated ``damper``
    section."""
    if d["kind"] == "asymmetric":
        return Damper.asymmetric(**{k: d[k] for k in ASYMMETRIC_KEYS})
    if d["kind"] == "jenkins":
        return Damper.jenkins(d["kt"], d["M_slip"])
    rows = d["rows"]
    return Damper.table([r[0] for r in rows], [r[1] for r in rows], [r[2] for r in rows],
                        delta_M=d.get("delta_M"))


def build_damper(case: Case) -> Damper:
    """The kernel damper (stiffness table) of a case."""
    return damper_from_section(case.damper)


def contact_from_section(d: dict) -> Contact:
    """The damper's contact law in time (kinds ``jenkins`` and ``asymmetric``) from a ``damper``
    section, for the standard method and the time integration (:mod:`udmap.hbm`)."""
    kind = d.get("kind")
    if kind == "jenkins":
        return Contact.jenkins(d["kt"], d["M_slip"])
    if kind == "asymmetric":
        try:
            params = {k: d[k] for k in ASYMMETRIC_KEYS}
        except KeyError as exc:
            raise InputError(f"damper: asymmetric parameters incomplete or invalid ({exc})") \
                from None
        return Contact.asymmetric(**params)
    raise InputError(f"damper.kind '{kind}': the standard method and the time integration "
                     "need a contact model ('asymmetric' or 'jenkins'), not a table")


def build_contact(case: Case) -> Contact:
    """The contact law in time of a case's damper (see :func:`contact_from_section`)."""
    return contact_from_section(case.damper)


def build_model(case: Case, blade: Blade | None = None, damper: Damper | None = None) -> Model:
    """The kernel model (blade + damper over the band) of a case, at its interblade phase
    (PHYSICS.md 2.6, :mod:`udmap.case.traveling`)."""
    a = case.analysis
    check_case(case)    # a design of a DOE is not validated as a whole: its phase is checked here
    blade = blade if blade is not None else build_blade(case)
    damper = damper if damper is not None else build_damper(case)
    return Model(blade, damper, a["f_min"], a["f_max"], sigma_all=a["sigma_all"],
                 rtol=a["rtol"], grid_per_decade=a["grid_per_decade"],
                 eigen_method=EIGEN_METHODS[a["eigen_method"]], dense_max=a["dense_max"],
                 sweep_points=a["sweep_points"], harmonics=a["harmonics"],
                 harmonic_tol=a["harmonic_tol"], ibpa_deg=wave_of(a).ibpa_deg)
