"""Report plots of the mapping results (PNG, matplotlib without a display).

Every function takes plain numbers and arrays (no kernel objects) and writes one figure:
labelled axes with units, logarithmic where the quantity spans decades, the design limits
marked. Frequencies in Hz, amplitudes in rad, stresses in MPa on the axes.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

REGIME_COLORS = {0: "tab:blue", 1: "tab:orange", 2: "tab:green", 3: "tab:red"}
REGIME_LABELS = {0: "stuck", 1: "partial slip", 2: "full slip", 3: r"$F_E \geq F_{lim}$"}


def _finish(fig, ax, path: Path, title: str) -> Path:
    ax.set_title(title, fontsize=11)
    ax.grid(True, which="major", alpha=0.35)
    ax.grid(True, which="minor", alpha=0.12)
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def _force_limits(ax, F_lim: float) -> None:
    ax.axvline(F_lim, color="k", lw=1.2, ls="-")
    ax.axvline(0.5 * F_lim, color="k", lw=1.0, ls="--")
    ymax = ax.get_ylim()[1]
    ax.text(F_lim, ymax, r" $F_{lim}$", va="top", ha="left", fontsize=9)
    ax.text(0.5 * F_lim, ymax, r"$0.5\,F_{lim}$ ", va="top", ha="right", fontsize=9)


def _regime_dots(ax, x, y, regime) -> None:
    regime = np.asarray(regime)
    for r, color in REGIME_COLORS.items():
        sel = regime == r
        if np.any(sel):
            ax.plot(np.asarray(x)[sel], np.asarray(y)[sel], "o", ms=3.5, color=color,
                    label=REGIME_LABELS[r], zorder=3)


def gg_diagram(F_E, sigma_a, F_lim: float, sigma_all: float, path, *, regime=None,
               F_E_undamped=None, sigma_a_undamped=None, zeta: float | None = None,
               F_marked=None, sigma_marked=None, G1=None, G2=None) -> Path:
    """The GG design diagram (paper Fig. 12b): peak alternating stress at the witness section
    against the proof excitation force, with F_lim, 0.5 F_lim and sigma_all marked, and the
    points G1 (the base cycle reached, gamma_P = gamma_b) and G2 (F_E = 0.5 F_lim) as
    (F_E, sigma_a) pairs when given."""
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    F_E = np.asarray(F_E, float)
    s = np.asarray(sigma_a, float) / 1e6
    label = r"$\zeta$ = " + (f"{100 * zeta:.2g} %" if zeta is not None else "case")
    ax.plot(F_E, s, "-", color="tab:blue", lw=1.8, label=label)
    if F_E_undamped is not None:
        ax.plot(F_E_undamped, np.asarray(sigma_a_undamped, float) / 1e6, "--", color="0.35",
                lw=1.3, label=r"$\zeta$ = 0")
    if F_marked is not None:
        ax.plot(F_marked, np.asarray(sigma_marked, float) / 1e6, "o", color="tab:blue", ms=4)
    for point, name in ((G1, "$G_1$"), (G2, "$G_2$")):
        if point is not None:
            ax.plot(point[0], point[1] / 1e6, "s", color="k", ms=6, zorder=4)
            ax.annotate(name, (point[0], point[1] / 1e6), textcoords="offset points",
                        xytext=(-4, 8), ha="right", fontsize=10)
    ax.set_xlim(0, 1.2 * F_lim)
    finite = s[np.isfinite(s) & (F_E <= 1.2 * F_lim)]
    ytop = max(1.3 * sigma_all / 1e6, 1.05 * finite.max() if finite.size else 0)
    ax.set_ylim(0, ytop)
    ax.axhline(sigma_all / 1e6, color="tab:red", lw=1.2)
    ax.text(1.19 * F_lim, sigma_all / 1e6, r"$\sigma_{a,all}$ = " + f"{sigma_all / 1e6:g} MPa",
            color="tab:red", va="bottom", ha="right", fontsize=9)
    ax.axvspan(0, 0.5 * F_lim, ymax=min(sigma_all / 1e6 / ytop, 1), color="tab:green",
               alpha=0.07, lw=0)
    _force_limits(ax, F_lim)
    ax.set_xlabel(r"proof excitation force $F_E$ [N]")
    ax.set_ylabel(r"peak alternating stress $\sigma_a$ at the airfoil-platform junction [MPa]")
    ax.legend(loc="upper left", fontsize=9)
    return _finish(fig, ax, path, "GG design diagram (damper performance, witness stress)")


def gamma_vs_force(F_E, gamma_P, F_lim: float, gamma_s: float, gamma_b: float, path, *,
                   regime=None, F_E_undamped=None, gamma_undamped=None) -> Path:
    """Peak platform rotation against the proof force (paper Fig. 11b), log-log: the stuck
    range is a straight line of slope 1."""
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    ax.loglog(F_E, gamma_P, "-", color="0.15", lw=0.8, label=r"$\zeta$ of the case")
    if F_E_undamped is not None:
        ax.loglog(F_E_undamped, gamma_undamped, "--", color="0.35", lw=1.3, label=r"$\zeta$ = 0")
    if regime is not None:
        _regime_dots(ax, F_E, gamma_P, regime)
    for value, name, ls, va in ((gamma_b, r"$\gamma_b$ (base cycle)", "-.", "bottom"),
                                (gamma_s, r"$\gamma_s$ (end of stick)", ":", "top")):
        if value and value > 0:
            ax.axhline(value, color="tab:purple", lw=1.0, ls=ls)
            ax.text(ax.get_xlim()[1], value, name + " ", color="tab:purple", va=va, ha="right",
                    fontsize=9)
    _force_limits(ax, F_lim)
    ax.set_xlabel(r"proof excitation force $F_E$ [N]")
    ax.set_ylabel(r"peak platform rotation $\gamma_P$ [rad]")
    ax.legend(loc="upper left", fontsize=8)
    return _finish(fig, ax, path, r"Damper performance curve: $\gamma_P$ at resonance")


def fres_vs_force(F_E, f_res, F_lim: float, path, *, f_stuck=None, f_bare=None,
                  F_E_undamped=None, f_undamped=None) -> Path:
    """Resonance frequency against the proof force (paper Fig. 11c): from the stuck-damper
    frequency down towards the bare blade's as the damper slips."""
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    ax.semilogx(F_E, f_res, "-", color="tab:blue", lw=1.6, label=r"$\zeta$ of the case")
    if F_E_undamped is not None:
        ax.semilogx(F_E_undamped, f_undamped, "--", color="0.35", lw=1.3, label=r"$\zeta$ = 0")
    for value, name, va in ((f_stuck, "stuck damper", "bottom"), (f_bare, "bare blade", "top")):
        if value:
            ax.axhline(value, color="tab:purple", lw=0.9, ls=":")
            ax.text(ax.get_xlim()[0], value, " " + name + f" {value:.2f} Hz", color="tab:purple",
                    va=va, fontsize=9)
    _force_limits(ax, F_lim)
    ax.set_xlabel(r"proof excitation force $F_E$ [N]")
    ax.set_ylabel(r"resonance frequency $f_{res}$ [Hz]")
    ax.legend(loc="center left", fontsize=8)
    return _finish(fig, ax, path, "Resonance frequency of the damped blade")


def response_curves(curves, backbone_points, f_min: float, f_max: float, path, *,
                    backbone_curve=None) -> Path:
    """Non-linear response curves gamma_P(f) for several forces by layered force mapping
    (paper Figs. 7, 8b, 10a), with their peaks and the backbone through them."""
    fig, ax = plt.subplots(figsize=(7.6, 5.4))
    cmap = plt.get_cmap("viridis")
    n = max(len(curves), 1)
    for i, c in enumerate(curves):
        color = cmap(i / max(n - 1, 1))
        parts = np.asarray(c.get("part", np.ones(len(c["f"]), int)))
        for j, p in enumerate(np.unique(parts)):
            sel = parts == p
            ax.semilogy(np.asarray(c["f"])[sel], np.asarray(c["gamma_P"])[sel], "-", color=color,
                        lw=1.2, label=f"$F_E$ = {c['F_E']:g} N" if j == 0 else None)
    if backbone_curve is not None:
        g, f = backbone_curve
        sel = (np.asarray(f) >= f_min) & (np.asarray(f) <= f_max)
        ax.semilogy(np.asarray(f)[sel], np.asarray(g)[sel], "k--", lw=1.0, label="backbone")
    bp = [p for p in backbone_points if not p.get("unbounded")]
    if bp:
        ax.semilogy([p["f_res"] for p in bp], [p["gamma_P"] for p in bp], "ko", ms=4,
                    label="peaks (backbone)")
    ax.set_xlim(f_min, f_max)
    ax.set_xlabel("excitation frequency $f$ [Hz]")
    ax.set_ylabel(r"platform rotation amplitude $\gamma_P$ [rad]")
    ax.legend(loc="upper left", fontsize=8, ncol=2)
    return _finish(fig, ax, path, "Non-linear response curves (amplitude layered force mapping)")


def stiffness(gamma, k, gamma_b: float, path, *, gamma_s: float | None = None,
              k_stuck: float | None = None) -> Path:
    """The damper's complex stiffness k_Re + i k_Im against the platform rotation amplitude
    (paper Fig. 4b), log amplitude axis, gamma_b (base cycle) marked."""
    gamma = np.asarray(gamma, float)
    k = np.asarray(k, complex)
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    ax.semilogx(gamma, k.real, "-", color="tab:blue", lw=1.8, label=r"$k_{Re}$")
    ax.semilogx(gamma, k.imag, "-", color="tab:orange", lw=1.8, label=r"$k_{Im}$")
    ax.axvline(gamma_b, color="tab:purple", lw=1.1, ls="-.")
    ax.text(gamma_b, ax.get_ylim()[1], r" $\gamma_b$ (base cycle)", color="tab:purple",
            va="top", fontsize=9)
    if gamma_s and gamma_s > 0 and gamma_s < gamma_b * (1 - 1e-9):
        ax.axvline(gamma_s, color="tab:purple", lw=1.0, ls=":")
        ax.text(gamma_s, 0.9 * ax.get_ylim()[1], r" $\gamma_s$", color="tab:purple", va="top",
                fontsize=9)
    ax.set_xlabel(r"platform rotation amplitude $\gamma_P$ [rad]")
    ax.set_ylabel(r"damper stiffness $k$ [N m/rad]")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper right", fontsize=9)
    return _finish(fig, ax, path, "Damper complex stiffness (first harmonic)")


def harmonics_side_by_side(F_E, sigma_1, gamma_1, F_auto, sigma_auto, sigma_max_auto,
                           gamma_auto, F_lim: float, sigma_all: float, path, *,
                           harmonics=None) -> Path:
    """The GG diagram (left) and gamma_P against F_E (right) with the single-harmonic method
    and with multi-harmonic layers at automatic H (PHYSICS.md 4.1) side by side: what the
    single-harmonic premise costs."""
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11.5, 4.6))
    ax1.plot(F_E, np.asarray(sigma_1) / 1e6, "-", color="tab:blue", lw=1.4,
             label=r"$\sigma_a$, H = 1")
    ax1.plot(F_auto, np.asarray(sigma_auto) / 1e6, "o-", color="tab:red", ms=3.5, lw=1.0,
             label=r"$\sigma_a$, auto H")
    ax1.plot(F_auto, np.asarray(sigma_max_auto) / 1e6, "s--", color="tab:purple", ms=3.0,
             lw=1.0, label=r"$\sigma_{max}$, auto H (HCF criterion)")
    ax1.axhline(sigma_all / 1e6, color="0.3", lw=1.0, ls=":",
                label=r"$\sigma_{a,all}$ = " + f"{sigma_all / 1e6:g} MPa")
    ax1.set_xlabel(r"$F_E$ [N]")
    ax1.set_ylabel("stress amplitude at the junction [MPa]")
    _force_limits(ax1, F_lim)
    ax1.legend(fontsize=8, loc="lower right")
    ax1.set_title("GG diagram", fontsize=11)
    ax1.grid(True, alpha=0.35)
    ax2.loglog(F_E, gamma_1, "-", color="tab:blue", lw=1.4, label=r"$\gamma_P$, H = 1")
    ax2.loglog(F_auto, gamma_auto, "o-", color="tab:red", ms=3.5, lw=1.0,
               label=r"$\gamma_P$ (first harmonic), auto H")
    ax2.set_xlabel(r"$F_E$ [N]")
    ax2.set_ylabel(r"$\gamma_P$ [rad]")
    ax2.legend(fontsize=8, loc="lower right")
    ax2.grid(True, which="major", alpha=0.35)
    if harmonics is not None and len(harmonics):
        ax2.set_title(f"platform rotation (auto H = {min(harmonics)}..{max(harmonics)})",
                      fontsize=11)
    else:
        ax2.set_title("platform rotation", fontsize=11)
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def response_vs_force(F_E, gamma_P, F_lim: float, f_exc: float, path, *, regime=None,
                      gamma_s: float | None = None, gamma_b: float | None = None) -> Path:
    """Platform rotation amplitude against the excitation force at one excitation frequency
    (``udmap response --plot``), log-log, with F_lim and 0.5 F_lim marked."""
    fig, ax = plt.subplots(figsize=(7.2, 5.0))
    F = np.asarray(F_E, float)
    g = np.asarray([np.nan if x is None else x for x in gamma_P], float)
    ax.loglog(F, g, "-", color="0.15", lw=0.8, label=f"$f_{{exc}}$ = {f_exc:g} Hz")
    if regime is not None:
        _regime_dots(ax, F, g, regime)
    for value, name, ls in ((gamma_b, r"$\gamma_b$ (base cycle)", "-."),
                            (gamma_s, r"$\gamma_s$ (end of stick)", ":")):
        if value and value > 0:
            ax.axhline(value, color="tab:purple", lw=1.0, ls=ls, label=name)
    _force_limits(ax, F_lim)
    ax.set_xlabel(r"excitation force $F_E$ [N]")
    ax.set_ylabel(r"platform rotation amplitude $\gamma_P$ [rad]")
    ax.legend(loc="upper left", fontsize=8)
    return _finish(fig, ax, path, f"Response at the excitation frequency {f_exc:g} Hz")


def nodal_sweep(data: dict, sigma_all: float, path) -> Path:
    """The nodal-diameter sweep (PHYSICS.md 2.6) in one figure: above, sigma_a against the
    nodal diameter, forward waves (0 <= ibpa <= 180 deg) solid and backward ones dashed, one
    colour per force, the worst engine order of each force ringed; below, the GG diagrams of the
    in-phase family and of the worst nodal diameter of the largest force, side by side."""
    pts = data["points"]
    forces = sorted({p["F_E"] for p in pts})
    fig = plt.figure(figsize=(10.5, 8.2))
    top = fig.add_subplot(2, 1, 1)
    colors = plt.cm.viridis(np.linspace(0.0, 0.9, max(len(forces), 1)))
    for F, color in zip(forces, colors):
        for backward, ls in ((False, "-"), (True, "--")):
            sel = sorted((p for p in pts if p["F_E"] == F and p["sigma_a"] is not None
                          and (p["ibpa_deg"] < 0) == backward
                          and not (backward and p["nodal_diameter"] == 0)),
                         key=lambda p: p["nodal_diameter"])
            if not sel:
                continue
            top.plot([p["nodal_diameter"] for p in sel], [p["sigma_a"] / 1e6 for p in sel],
                     ls, marker="o", ms=3, color=color,
                     label=f"$F_E$ = {F:g} N" + (" (backward)" if backward else ""))
        for w in data["worst"]:
            if w["F_E"] == F and w["sigma_max"] is not None:
                top.plot(w["nodal_diameter"], w["sigma_max"] / 1e6, "o", ms=10, mfc="none",
                         mec="tab:red", mew=1.5)
    top.axhline(sigma_all / 1e6, color="tab:red", lw=1.2)
    top.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    top.set_xlabel("nodal diameter")
    top.set_ylabel(r"$\sigma_a$ at resonance [MPa]")
    top.set_title(f"Nodal-diameter sweep, {data['blades']} blades: solid forward, dashed "
                  "backward, red rings the worst engine order", fontsize=10)
    top.grid(True, alpha=0.35)
    top.legend(fontsize=7, ncol=2)
    worst_eo = data["worst"][-1]["engine_order"] if data["worst"] else 0
    for k, (eo, name) in enumerate(((0, "in phase (EO 0)"),
                                    (worst_eo, f"worst: EO {worst_eo}"))):
        ax = fig.add_subplot(2, 2, 3 + k)
        sel = [p for p in pts if p["engine_order"] == eo and p["sigma_a"] is not None]
        F_lim = sel[0]["F_lim"] if sel else None
        ax.plot([p["F_E"] for p in sel], [p["sigma_a"] / 1e6 for p in sel], "o-",
                color="tab:blue", ms=4)
        ax.axhline(sigma_all / 1e6, color="tab:red", lw=1.2)
        if F_lim:
            ax.axvline(F_lim, color="k", lw=1.2)
            ax.axvline(0.5 * F_lim, color="k", lw=1.0, ls="--")
            ax.set_xlim(0, 1.2 * max(F_lim, max(forces)))
        ax.set_ylim(0, max([1.3 * sigma_all / 1e6] + [1.05 * p["sigma_a"] / 1e6 for p in sel]))
        ax.set_xlabel(r"proof excitation force $F_E$ [N]")
        ax.set_ylabel(r"$\sigma_a$ [MPa]")
        ax.set_title(f"GG diagram, {name}" + (f", $F_{{lim}}$ = {F_lim:.4g} N" if F_lim else ""),
                     fontsize=10)
        ax.grid(True, alpha=0.35)
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path
