"""The subcommands of the command line (INTERFACES.md "Command line"), each on a case file."""
from __future__ import annotations

import json
import math
import os
import shutil
from pathlib import Path

import numpy as np

from .. import hbm
from ..case import build_blade, build_contact, build_damper, build_model, load_case
from ..case.plausibility import plausibility_warnings, with_hints
from ..case.traveling import apply_options, wave_of, wave_warnings
from ..errors import InputError, UdmapError
from ..progress import Progress
from .output import (add_verdicts, add_warning, emit, finite, point_json, print_head,
                     print_points, print_rows)
from .files import (CURVE_COLUMNS, POINT_COLUMNS, check_out, curve_rows, point_rows,
                    write_outputs)
from .units import header, rounded, units_of


def _with_harmonics(case, args):
    """The case with --harmonics (if given) overriding analysis.harmonics."""
    if getattr(args, "harmonics", None) is not None:
        case.analysis["harmonics"] = args.harmonics
    return case


def _load(args, harmonics: bool = True):
    """The command's case with --harmonics (the mapping's, when `harmonics`) and the traveling
    wave's options applied."""
    case = load_case(args.case)
    if harmonics:
        _with_harmonics(case, args)
    apply_options(case, args.blades, args.engine_order, args.ibpa)
    return case


def _wave(data: dict, case) -> dict:
    """Adds the traveling wave's fields (engine_order, blades, ibpa_deg) to `data` and its
    warnings (a phase given with a damper that does not depend on it)."""
    data.update(wave_of(case.analysis).output())
    for text in wave_warnings(case):
        add_warning(data, text)
    return data


#: Largest platform rotation of the valid range (docs/case-files.md, "Valid range") [rad].
GAMMA_VALID_MAX = 1.0


def cmd_table(args) -> None:
    case = load_case(args.case)
    damper = build_damper(case)
    gammas = np.asarray(args.gammas)
    k = damper.stiffness(gammas)
    data = {"gamma_b": damper.gamma_b, "gamma_s": damper.gamma_s, "M_max": damper.M_max,
            "M_min": damper.M_min, "k_stuck": damper.k_stuck, "lift_off": bool(damper.lift_off),
            "points": [{"gamma": float(g), "k_re": float(kk.real), "k_im": float(kk.imag)}
                       for g, kk in zip(gammas, k)],
            # PHYSICS.md 2.5: k jumps at gamma_c; at gamma_c itself k is k(gamma_c-)
            "jumps": [{"gamma_c": j["gamma_c"], "k_re_minus": j["k_minus"].real,
                       "k_im_minus": j["k_minus"].imag, "k_re_plus": j["k_plus"].real,
                       "k_im_plus": j["k_plus"].imag} for j in damper.jumps]}
    if np.any(gammas > GAMMA_VALID_MAX):
        # k(gamma) is defined at any amplitude, but the damper's kinematics (PHYSICS.md 2.1)
        # take small rotations: docs/case-files.md, "Valid range"
        add_warning(data, f"gamma above {GAMMA_VALID_MAX:g} rad ({rounded(float(gammas.max()))} "
                          "rad) is outside the valid range 1e-12 to 1 rad: the damper's "
                          "small-rotation kinematics do not hold there (was it given in "
                          "degrees?)")

    def table(d):
        print_head(d, skip=("jumps",))
        print_rows([header("gamma"), header("k_re"), header("k_im")],
                   [[p["gamma"], p["k_re"], p["k_im"]] for p in d["points"]],
                   ["gamma", "k_re", "k_im"])
        if d["jumps"]:
            print(f"k(gamma) jumps at {len(d['jumps'])} amplitude(s) gamma_c (PHYSICS.md 2.5):")
            print_rows([header("gamma_c", "gamma_c"), header("k_re", "k_re(gamma_c-)"),
                        header("k_im", "k_im(gamma_c-)"), header("k_re", "k_re(gamma_c+)"),
                        header("k_im", "k_im(gamma_c+)")],
                       [[j["gamma_c"], j["k_re_minus"], j["k_im_minus"], j["k_re_plus"],
                         j["k_im_plus"]] for j in d["jumps"]],
                       ["gamma_c", "k_re", "k_im", "k_re", "k_im"])
    emit(args, data, table)


def _model(case, blade, damper):
    """The model of the case; a failure to build it carries the case's plausibility hints."""
    try:
        return build_model(case, blade, damper)
    except UdmapError as exc:
        raise with_hints(exc, plausibility_warnings(case, blade, damper)) from None


def _computed(case, blade, damper, model, compute):
    """compute(), a failure of which carries the case's plausibility hints (the model's, so
    with the stuck peak: a band that holds the bare mode but not the stuck one says so)."""
    try:
        return compute()
    except UdmapError as exc:
        raise with_hints(exc, plausibility_warnings(case, blade, damper, model)) from None


def _plausible(data: dict, case, blade, damper, model) -> dict:
    """The plausibility warnings of the case (udmap.case.plausibility) into `data`."""
    for text in plausibility_warnings(case, blade, damper, model):
        add_warning(data, text)
    return data


def _summary(model, blade, damper) -> dict:
    return {"F_lim": model.limit_force(), "F_lim_backbone": model.limit_force_backbone(),
            "gamma_b": damper.gamma_b, "gamma_s": damper.gamma_s,
            "f1_bare": float(blade.natural_frequencies(1)[0]),
            "lift_off": bool(damper.lift_off)}


def _verdicts(data: dict, case) -> None:
    """hcf_reason on the points, against the F_lim the kernel judges them by (the smaller of
    F_lim and F_lim_backbone; F_lim with more than one harmonic), and the warnings above it."""
    add_verdicts(data, min(data["F_lim"], data["F_lim_backbone"]), case.analysis["sigma_all"],
                 F_lim_multi=data["F_lim"])


def _finish(args, paths, data: dict, table, columns, rows, plot=None) -> None:
    """Writes --out's files (when asked), then prints `data`."""
    written = []
    if paths:
        data.setdefault("warnings", [])
        data["units"] = units_of(data)
        written = write_outputs(paths, data, columns, rows, plot)
    emit(args, data, table)
    if written and not args.json:
        for path in written:
            print(f"wrote {path}")


def _limits(data: dict) -> float | None:
    F = min(data["F_lim"], data["F_lim_backbone"])
    return F if math.isfinite(F) and F < 1e300 else None


def cmd_backbone(args) -> None:
    paths = check_out(args, "backbone")
    case = _load(args)
    blade, damper = build_blade(case), build_damper(case)
    model = _model(case, blade, damper)
    points = _computed(case, blade, damper, model, lambda: model.backbone(args.forces))
    summary = _computed(case, blade, damper, model, lambda: _summary(model, blade, damper))
    data = _plausible(_wave(summary, case), case, blade, damper, model)
    data["points"] = [point_json(p) for p in points]
    _verdicts(data, case)

    def plot(path):
        from .. import plots
        pts = data["points"]
        plots.gg_diagram([p["F_E"] for p in pts], [p["sigma_a"] for p in pts],
                         _limits(data) or max(p["F_E"] for p in pts),
                         case.analysis["sigma_all"], path, F_marked=[p["F_E"] for p in pts],
                         sigma_marked=[p["sigma_a"] for p in pts])
    _finish(args, paths, data, print_points, POINT_COLUMNS, point_rows(data), plot)


def response_reach(case) -> float:
    """The highest excitation frequency [Hz] a response is answered at: 3 f_max, the reach of
    the blade's reduction (its cut-off, lower only when fewer modes were asked for)."""
    reach = 3.0 * case.analysis["f_max"]
    f_cut = ((case.fe or {}).get("info") or {}).get("f_cut")
    return min(reach, float(f_cut)) if f_cut else reach


def cmd_response(args) -> None:
    paths = check_out(args, "response")
    case = _load(args)
    a = case.analysis
    reach = response_reach(case)
    if not 0.0 < args.freq <= reach:
        raise InputError(f"--freq {args.freq} Hz is beyond the reach of the blade: (0, "
                         f"{rounded(reach)}] Hz, 3 analysis.f_max = 3 x {a['f_max']} Hz"
                         + ("" if reach == 3 * a["f_max"] else
                            ", and the cut-off of the blade's reduction")
                         + " (the band [f_min, f_max] is where the resonance is sought)")
    blade, damper = build_blade(case), build_damper(case)
    model = _model(case, blade, damper)
    summary = _computed(case, blade, damper, model, lambda: _summary(model, blade, damper))
    data = _plausible(_wave(summary, case), case, blade, damper, model)
    data["f_exc"] = args.freq
    points = _computed(case, blade, damper, model,
                       lambda: model.response(args.freq, args.forces))
    data["points"] = [point_json(dict(p, jump=False)) for p in points]
    _verdicts(data, case)

    def plot(path):
        from .. import plots
        pts = data["points"]
        plots.response_vs_force([p["F_E"] for p in pts], [p["gamma_P"] for p in pts],
                                _limits(data) or max(p["F_E"] for p in pts), args.freq, path,
                                regime=[p["regime"] for p in pts], gamma_s=data["gamma_s"],
                                gamma_b=data["gamma_b"])
    _finish(args, paths, data, print_points, POINT_COLUMNS, point_rows(data), plot)


def cmd_curves(args) -> None:
    paths = check_out(args, "curves")
    case = _load(args)
    blade, damper = build_blade(case), build_damper(case)
    model = _model(case, blade, damper)
    layers = args.layers or case.analysis["layers"]
    curves = _computed(case, blade, damper, model,
                       lambda: model.curves(args.forces, layers=layers))
    data = _plausible(_wave({}, case), case, model.blade, model.damper, model)
    data["curves"] = [{"F_E": c["F_E"], "f": [float(x) for x in c["f"]],
                        "gamma_P": [float(x) for x in c["gamma_P"]],
                        "sigma_a": [finite(float(x)) for x in c["sigma_a"]],
                        "branch": [int(x) for x in c["branch"]],
                        "part": [int(x) for x in c["part"]]} for c in curves]

    try:
        F_lim = model.limit_force()
    except UdmapError:  # no slip moment range (a table without delta_M): no limit known
        F_lim = math.inf
    for F in args.forces:
        if F >= F_lim:
            add_warning(data, f"F_E = {rounded(F)} N is at or above F_lim = {rounded(F_lim)} N: "
                              "the damper slips all the cycle and cannot limit the response any "
                              "more (not admissible)")

    def table(d):
        print_head(d)
        for c in d["curves"]:
            print(f"F_E = {rounded(c['F_E'])} N: {len(c['f'])} points")
            print_rows([header("f"), header("gamma_P"), header("sigma_a"), "branch"],
                       [[f, g, s, str(b)]
                        for f, g, s, b in zip(c["f"], c["gamma_P"], c["sigma_a"], c["branch"])],
                       ["f", "gamma_P", "sigma_a", ""])

    def plot(path):
        from .. import plots
        g = [x for c in data["curves"] for x in c["gamma_P"]]
        try:  # the peaks and the backbone line where the model gives them
            peaks = model.backbone(args.forces)
            g += [p["gamma_P"] for p in peaks if not p["unbounded"]]
            g_line = np.geomspace(min(g), 1.5 * max(g), 240)
            line = (g_line, model.backbone_curve(g_line)[1])
        except UdmapError:
            peaks, line = [], None
        plots.response_curves(data["curves"], peaks, case.analysis["f_min"],
                              case.analysis["f_max"], path, backbone_curve=line)
    _finish(args, paths, data, table, CURVE_COLUMNS, curve_rows(data), plot)


def cmd_hbm(args) -> None:
    paths = check_out(args, "hbm")
    case = _load(args, harmonics=False)
    blade = build_blade(case)
    a = case.analysis
    damper = build_damper(case)
    if _traveling(case, damper):
        points = _wave_hbm(case, blade, damper, args)
    else:
        with Progress(len(args.forces), "hbm") as bar, bar.ticking():
            points = hbm.hbm(blade, build_contact(case), a["f_min"], a["f_max"], args.forces,
                             harmonics=args.harmonics, variant=args.variant,
                             sigma_all=a["sigma_all"], progress=bar.update)
        hbm.classify(blade, damper, a["f_min"], a["f_max"], a["sigma_all"], points)
    data = _wave({"harmonics": args.harmonics, "variant": args.variant}, case)
    data["points"] = [point_json(p) for p in points]
    add_verdicts(data, None, a["sigma_all"])

    def plot(path):
        from .. import plots
        pts = data["points"]
        F_lim = pts[0].get("F_lim") if pts else None
        plots.gg_diagram([p["F_E"] for p in pts], [p["sigma_a"] for p in pts],
                         F_lim if F_lim and math.isfinite(F_lim) else max(args.forces),
                         a["sigma_all"], path, F_marked=[p["F_E"] for p in pts],
                         sigma_marked=[p["sigma_a"] for p in pts])
    _finish(args, paths, data, print_points, POINT_COLUMNS, point_rows(data), plot)


def _traveling(case, damper) -> bool:
    """A traveling wave (PHYSICS.md 2.6): an interblade phase other than 0 with the one damper
    kind that feels it."""
    return not wave_of(case.analysis).in_phase and damper.kind == "asymmetric"


def _wave_hbm(case, blade, damper, args) -> list[dict]:
    """The standard method at the case's interblade phase: each force continued down to its
    own peak from 1 % above the layered peak (a starting point only: the friction damper
    softens the blade, so coming from above follows the upper branch); F_lim(phi) and the HCF
    verdict from the model at that phase. The regime is left out: at phi /= 0 it is not the
    in-phase rule's."""
    a = case.analysis
    harmonics = args.harmonics if args.harmonics not in (None, "auto", 0) else 1
    model = build_model(case, blade=blade, damper=damper)
    starts = [min(1.01 * p["f_res"], a["f_max"] * (1 - 1e-9)) if not p.get("unbounded")
              else a["f_max"] * (1 - 1e-9) for p in model.backbone(args.forces)]
    points = hbm.wave_hbm(blade, damper, a["f_min"], a["f_max"], wave_of(a).ibpa_deg,
                          args.forces,
                          starts, harmonics=int(harmonics))
    F_lim = model.limit_force()
    for p in points:
        p["F_lim"] = F_lim
        p["hcf_ok"] = p["F_E"] <= 0.5 * F_lim and p["sigma_a"] <= a["sigma_all"]
        p["harmonics"] = int(harmonics)
    return points


def cmd_dti(args) -> None:
    case = _load(args, harmonics=False)
    blade = build_blade(case)
    a = case.analysis
    if args.freq is not None and not a["f_min"] <= args.freq <= a["f_max"]:
        raise InputError(f"--freq {args.freq} Hz is outside the band [analysis.f_min, "
                         f"analysis.f_max] = [{a['f_min']}, {a['f_max']}] Hz of the case")
    wheel = _wheel_of(args, case)
    keys = ("F_E", "f", "gamma_1", "sigma_1", "gamma_max")
    warnings = []
    if wheel is not None and case.damper.get("kind") != "asymmetric":
        warnings.append(f"damper.kind '{case.damper.get('kind')}' acts on gamma_P alone: the "
                        "interblade phase does not change it, the blades are uncoupled and "
                        "equal (blade_spread 0)")
    if wheel is not None and not warnings:
        N, EO = wheel
        f_center = None
        if args.peak and EO % N:
            # the traveling-wave single-harmonic backbone at this phase gives the centre
            a["ibpa_deg"], a["harmonics"] = 360.0 * (EO % N) / N, 1
            model = build_model(case, blade, build_damper(case))
            f_center = [p["f_res"] for p in model.backbone(args.forces)]
        points = []
        with Progress(len(args.forces), "dti (wheel)") as bar, bar.ticking():
            for i, F in enumerate(args.forces):
                points += hbm.dti_wheel(blade, build_contact(case), [F], N, EO, freq=args.freq,
                                        peak=args.peak, f_min=a["f_min"], f_max=a["f_max"],
                                        f_center=f_center[i] if f_center else None)
                bar.update(1)
        keys += ("blade_spread", "phase_spread")
    else:
        with Progress(len(args.forces), "dti") as bar, bar.ticking():
            points = hbm.dti(blade, build_contact(case), args.forces, freq=args.freq,
                             peak=args.peak, f_min=a["f_min"], f_max=a["f_max"],
                             progress=bar.update)
        if wheel is not None:
            points = [dict(p, blade_spread=0.0, phase_spread=0.0) for p in points]
            keys += ("blade_spread", "phase_spread")
    data = _wave({}, case)
    data["points"] = [{k: finite(p[k]) for k in keys} for p in points]
    if wheel is not None:
        data.update(blades=wheel[0], engine_order=wheel[1])
    for text in warnings:
        add_warning(data, text)

    def table(d):
        print_head(d)
        print_rows([header(k) for k in keys], [[p[k] for k in keys] for p in d["points"]],
                   list(keys))
    emit(args, data, table)


def _wheel_of(args, case):
    """(N, EO) of the whole wheel from the case's wave (--blades/--engine-order applied to it by
    udmap.case.traveling), or None for the single blade in phase; a phase given as ibpa_deg
    alone has no wheel to integrate."""
    wave = wave_of(case.analysis)
    if wave.blades is None:
        if not wave.in_phase:
            raise InputError("analysis.ibpa_deg: dti integrates the whole wheel; give its "
                             "blades and engine order (--blades N --engine-order EO)")
        return None
    return int(wave.blades), int(wave.engine_order)


def cmd_reduce(args) -> None:
    """Writes the reduced ``matrices`` case of an ``fe`` case (files beside ``--out``)."""
    out = Path(args.out)
    if out.suffix.lower() != ".json":
        raise InputError(f"--out must name a .json case file, got {args.out}")
    if out.parent.exists() and not out.parent.is_dir():
        raise InputError(f"--out: {out.parent} is a file, not a directory")
    case = load_case(args.case)
    if case.fe is None:
        raise InputError(f"blade.kind: reduce needs an 'fe' blade ({args.case})")
    raw = json.loads(Path(args.case).read_text())
    src = Path(case.fe["cache_dir"])
    blade = {"kind": "matrices"}
    moves = []
    out.parent.mkdir(parents=True, exist_ok=True)   # a missing directory is made, like --out DIR
    for key, name in case.fe["files"].items():
        target = out.parent / f"{out.stem}_{name}"
        tmp = target.with_name(f".{target.name}.tmp")
        shutil.copyfile(src / name, tmp)
        moves.append((tmp, target))
        blade[key] = target.name
    blade.update(gamma_dof=case.blade["gamma_dof"], exc_dof=case.blade["exc_dof"],
                 zeta=case.blade["zeta"])
    for key in ("u_dof", "v_dof"):      # platform.tangent: the platform's frame (fe-blades.md)
        if key in case.blade:
            blade[key] = case.blade[key]
    damper = dict(raw["damper"])
    if damper.get("kind") == "table":
        damper["file"] = os.path.relpath(case.damper["file"], out.parent.resolve())
    new = {"name": raw.get("name", case.name),
           "description": f"Platform Centred Reduction of {Path(args.case).name} "
                          f"({case.fe['n_full']} DOFs -> {case.fe['n_reduced']})",
           "blade": blade, "damper": damper, "analysis": raw["analysis"]}
    tmp = out.with_name(f".{out.name}.tmp")
    tmp.write_text(json.dumps(new, indent=2) + "\n")
    moves.append((tmp, out))
    for a, b in moves:          # the case file last: it is complete only with its matrices
        os.replace(a, b)
    data = {"out": str(out), "n_full": case.fe["n_full"], "n_reduced": case.fe["n_reduced"],
            "gamma_dof": case.blade["gamma_dof"], "exc_dof": case.blade["exc_dof"],
            "cached": case.fe["cached"], "freqs_full": case.fe["freqs_full"],
            "freqs_reduced": case.fe["freqs_reduced"]}
    data.update({k: case.blade[k] for k in ("u_dof", "v_dof") if k in case.blade})
    a = case.analysis
    in_band = [f for f in case.fe["freqs_reduced"] if a["f_min"] <= f <= a["f_max"]]
    if len(in_band) > 1:
        # the mapping follows one resonance: backbone refuses such a band (model: "narrow it")
        listed = ", ".join(rounded(f) for f in in_band)
        add_warning(data, f"the band [analysis.f_min, analysis.f_max] = [{rounded(a['f_min'])}, "
                          f"{rounded(a['f_max'])}] Hz holds {len(in_band)} modes of the reduced "
                          f"blade ({listed} Hz): backbone and the other analyses follow one "
                          "resonance and will refuse it; narrow the band around the mode the "
                          "damper is for")

    def table(d):
        print(f"wrote {d['out']}: {d['n_full']} DOFs reduced to {d['n_reduced']} "
              f"(gamma_dof {d['gamma_dof']}, exc_dof {d['exc_dof']}"
              f"{', from the cache' if d['cached'] else ''})")
        ff, fr = d["freqs_full"], d["freqs_reduced"]
        rows = [[i + 1, ff[i] if i < len(ff) else None, fr[i] if i < len(fr) else None,
                 (fr[i] - ff[i]) / ff[i] if i < min(len(ff), len(fr)) and ff[i] > 0 else None]
                for i in range(max(len(ff), len(fr)))]
        print_rows(["mode", "full [Hz]", "reduced [Hz]", "rel. diff [1]"], rows,
                   ["d", "f", "f", ".2e"])
    emit(args, data, table)


def cmd_demo(args) -> None:
    # imported here, not above: the demo's plots load matplotlib, which no other command needs
    from ..demo import run_demo
    run_demo(load_case(args.case), Path(args.out))
