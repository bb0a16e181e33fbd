"""Plots of a design of experiments (``udmap doe --plot``): the admissible force over every pair of
varied parameters, the Pareto front of admissible force against the centrifugal load CF, and the
share of designs passing the HCF criterion as a function of the excitation force."""
from __future__ import annotations

from pathlib import Path



def _read_columns(path, names) -> list[list[str]]:
    """The named columns of a doe CSV as lists of strings, read in one pass (only these
    columns are kept, so millions of designs fit)."""
    import csv
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        index = [header.index(n) for n in names]
        cols: list[list[str]] = [[] for _ in names]
        for row in reader:
            for col, j in zip(cols, index):
                col.append(row[j])
    return cols


def _floats(col):
    import numpy as np
    return np.array([float(v) if v != "" else np.nan for v in col])


def pareto_front(cf, f_adm):
    """Indices of the designs on the Pareto front (smallest CF, largest F_adm), by ascending CF:
    a design is on it when every design with a CF not larger has a smaller F_adm."""
    import numpy as np
    cf, f_adm = np.asarray(cf, float), np.asarray(f_adm, float)
    ok = np.flatnonzero(np.isfinite(cf) & np.isfinite(f_adm))
    order = ok[np.lexsort((-f_adm[ok], cf[ok]))]
    front, best = [], -np.inf
    for i in order:
        if f_adm[i] > best:
            front.append(int(i))
            best = f_adm[i]
    return front


def plot_doe(path, names, labels, paths=None, prefix=None) -> list[Path]:
    """Writes ``<prefix>_pairs.png``, ``<prefix>_pareto.png`` (when CF is varied) and
    ``<prefix>_pass.png`` for the doe CSV at ``path`` (prefix: the CSV path without suffix);
    ``names`` are the varied parameters' columns, ``labels`` the forces' labels, ``paths`` their
    case paths (to recognise CF under any spelling). Returns the files written."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    path = Path(path)
    prefix = Path(prefix) if prefix is not None else path.with_suffix("")
    wanted = ["status", "F_adm"] + list(names) + [f"hcf_ok@{label}" for label in labels]
    cols = _read_columns(path, wanted)
    status = np.array(cols[0])
    n = len(status)
    ok = status == "ok"
    f_adm = _floats(cols[1])
    values = {name: _floats(c) for name, c in zip(names, cols[2:2 + len(names)])}
    passing = {label: sum(v == "true" for v in c)
               for label, c in zip(labels, cols[2 + len(names):])}
    written = []
    size = max(1.0, 20.0 * min(1.0, 400.0 / max(n, 1)))
    vmin, vmax = (np.nanmin(f_adm[ok]), np.nanmax(f_adm[ok])) if ok.any() else (0.0, 1.0)

    # 1. Admissible force over the pairs of varied parameters.
    d = len(names)
    m = max(d - 1, 1)
    fig, axes = plt.subplots(m, m, figsize=(3.2 * m + 2.2, 3.0 * m + 0.6), squeeze=False,
                             layout="constrained")
    mappable = None
    pairs = [(i, j) for i in range(1, d) for j in range(i)] if d > 1 else [(0, None)]
    for ax in axes.ravel():
        ax.set_visible(False)
    for i, j in pairs:
        ax = axes[i - 1, j] if j is not None else axes[0, 0]
        ax.set_visible(True)
        y = values[names[i]]
        if j is None:
            ax.scatter(y[ok], f_adm[ok], s=size, c=f_adm[ok], vmin=vmin, vmax=vmax,
                       cmap="viridis", rasterized=True)
            ax.set_xlabel(names[0])
            ax.set_ylabel("F_adm [N]")
            if (~ok).any():
                ax.plot(y[~ok], np.full((~ok).sum(), vmin), "rx", ms=4, label="failed")
                ax.legend(fontsize=7)
            continue
        x = values[names[j]]
        mappable = ax.scatter(x[ok], y[ok], s=size, c=f_adm[ok], vmin=vmin, vmax=vmax,
                              cmap="viridis", rasterized=True)
        if (~ok).any():
            ax.plot(x[~ok], y[~ok], "rx", ms=3, label="failed")
        if i == d - 1:
            ax.set_xlabel(names[j])
        if j == 0:
            ax.set_ylabel(names[i])
    if mappable is not None:
        fig.colorbar(mappable, ax=axes.ravel().tolist(), label="admissible force F_adm [N]")
        if (~ok).any():
            axes[0, 0].legend(fontsize=7, loc="best")
    fig.suptitle(f"Admissible force over the design space\n({ok.sum()} of {n} designs computed)",
                 fontsize=10)
    out = prefix.with_name(prefix.name + "_pairs.png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    written.append(out)

    # 2. Pareto front of admissible force against CF.
    cf_name = None
    for k, name in enumerate(names):
        if name == "CF" or (paths is not None and tuple(paths[k]) == ("damper", "CF")):
            cf_name = name
    if cf_name is not None:
        cf = values[cf_name]
        front = pareto_front(np.where(ok, cf, np.nan), np.where(ok, f_adm, np.nan))
        fig, ax = plt.subplots(figsize=(6, 4.2))
        ax.scatter(cf[ok], f_adm[ok], s=size, color="0.6", rasterized=True,
                   label="designs")
        ax.step(cf[front], f_adm[front], where="post", color="C3", lw=1.5)
        ax.plot(cf[front], f_adm[front], "o", color="C3", ms=4, label="Pareto front")
        ax.set_xlabel(f"centrifugal load {cf_name} [N]")
        ax.set_ylabel("admissible force F_adm [N]")
        ax.set_title("Largest admissible force for a given CF")
        ax.grid(alpha=0.3)
        ax.legend()
        out = prefix.with_name(prefix.name + "_pareto.png")
        fig.tight_layout()
        fig.savefig(out, dpi=110)
        plt.close(fig)
        written.append(out)

    # 3. Share of designs passing: F_E <= F_adm, and hcf_ok at the requested forces.
    fig, ax = plt.subplots(figsize=(6, 4.2))
    fa = np.sort(f_adm[ok & np.isfinite(f_adm)])
    if fa.size:
        # share(F) = #(F_adm >= F) / n, a non-increasing staircase from F = 0
        ax.step(np.r_[0.0, fa], np.r_[fa.size, fa.size - np.arange(1, fa.size + 1)] / n,
                where="post", color="C0", label="F_E <= F_adm (continuous)")
    for k, label in enumerate(labels):
        s = passing[label] / n
        ax.plot([float(label)], [s], "s", color="C1", ms=6,
                label="hcf_ok at --forces" if k == 0 else None)
    ax.set_xlabel("excitation force F_E [N]")
    ax.set_ylabel("share of designs passing the HCF criterion")
    ax.set_ylim(0, 1.02)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    shares = ", ".join(f"{k} {100 * np.mean(status == k):.1f} %" for k in sorted(set(status)))
    ax.set_title(f"Designs passing ({shares})", fontsize=9)
    ax.legend()
    out = prefix.with_name(prefix.name + "_pass.png")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    written.append(out)
    return written
