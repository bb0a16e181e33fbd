"""Writes the FMI cross-check files of the FMUs (run by the build, fmu/CMakeLists.txt).

    python3 fmu/cross_check.py BUILD_DIR VERSION

For each FMU and interface, BUILD_DIR/cross-check/fmus/<FMI version>/<cs|me>/<platform>/udmap/
VERSION/udmap/ receives, in the layout of the FMI cross-check rules (modelica/fmi-cross-check):
udmap.fmu, udmap_in.csv (the inputs F_E, mu, CF over time), udmap_ref.csv (every output at
every step), udmap_ref.opt (start, stop, step, tolerance) and ReadMe.md. The reference is not
produced by the FMU: it is computed by the Python package over the kernel library (the command
line's `backbone` for the case with that mu and CF), one output row per input row.
"""
from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
START, STOP, STEP = 0.0, 4.0, 0.1
INPUTS = ["F_E", "mu", "CF"]
OUTPUTS = ["gamma_P", "sigma_a", "F_lim", "f_res", "u_E", "k_re", "k_im", "F_ratio", "hcf_ok",
           "regime", "lift_off"]
TIMING = {
    "cs": "Co-simulation: the outputs at the end of a\n  step answer the inputs set at its start "
          "(the row before; the first row answers its own inputs).",
    "me": "Model exchange: the outputs at a time answer the\n  inputs at that same time."}
FMUS = [("2.0", "linux64", "udmap.fmu"), ("3.0", "x86_64-linux", "udmap-fmi3.fmu")]


def inputs(t: float) -> tuple[float, float, float]:
    """F_E through the stuck, partial- and gross-slip ranges and beyond the limit force, then
    back; mu and CF ramps (piecewise linear, given at every step, so no interpolation)."""
    F = 0.2 + 19.8 * (t / 2.5) ** 2 if t <= 2.5 else 20.0 - 12.0 * (t - 2.5) / 1.5
    mu = 0.3 if t <= 1.0 else 0.3 - 0.08 * min(t - 1.0, 2.0) / 2.0
    CF = 900.0 if t <= 2.0 else 900.0 + 300.0 * (t - 2.0) / 2.0
    return round(F, 12), round(mu, 12), round(CF, 9)


def reference(times):
    sys.path.insert(0, str(ROOT / "wrappers" / "python"))
    from udmap.case import build_blade, build_damper, build_model, load_case, validate

    base = json.loads((ROOT / "cases" / "blade_a.json").read_text())
    case = load_case(ROOT / "cases" / "blade_a.json")
    blade = build_blade(case)
    rows = []
    for t in times:
        F, mu, CF = inputs(t)
        data = json.loads(json.dumps(base))
        data["damper"].update(mu=mu, CF=CF)
        c = validate(data, ROOT / "cases")
        damper = build_damper(c)
        model = build_model(c, blade, damper)
        F_lim = model.limit_force()
        p = model.backbone([F])[0]
        values = {"gamma_P": p["gamma_P"], "sigma_a": p["sigma_a"], "F_lim": F_lim,
                  "f_res": p["f_res"], "u_E": p["u_E"], "k_re": p["k_re"], "k_im": p["k_im"],
                  "F_ratio": F / F_lim, "hcf_ok": int(bool(p["hcf_ok"])),
                  "regime": int(p["regime"]), "lift_off": int(bool(damper.lift_off))}
        rows.append((t, (F, mu, CF), values))
        del model, damper
    return rows


def fmt(x) -> str:
    return repr(x) if isinstance(x, float) else str(x)


README = """# udmap {version}: FMI {fmi} {interface_name}

Exported by udmap {version} (`make build`, {platform}). The FMU is algebraic: the outputs are
the steady forced response of blade A (`cases/blade_a.json`) at resonance for the current
inputs, with no states and no events.

- `udmap_in.csv`: the inputs `F_E` [N] (through the stuck, partial-slip and gross-slip ranges
  and past the limit force), `mu` and `CF` [N], given at every output step.
- `udmap_ref.csv`: every output at every step, computed not by the FMU but by the udmap Python
  package over the kernel library (the command line's `backbone` for the case with that `mu`
  and `CF`). The FMU reproduces it to about 1e-12 relative. {timing}
- `udmap_ref.opt`: start and stop time, output step and relative tolerance.

Simulated with FMPy: `fmpy.simulate_fmu('udmap.fmu', fmi_type='{fmi_type}', input=...,
output_interval={step})` reproduces `udmap_ref.csv`.
"""


def main(argv) -> int:
    build, version = Path(argv[1]), argv[2]
    n = round((STOP - START) / STEP)
    times = [round(START + i * STEP, 12) for i in range(n + 1)]
    rows = reference(times)
    in_csv = "time," + ",".join(INPUTS) + "\n" + "".join(
        f"{fmt(t)}," + ",".join(fmt(x) for x in u) + "\n" for t, u, _ in rows)

    def ref_csv(lag: int) -> str:
        """Outputs per time; with lag 1 those of the previous step's inputs (co-simulation:
        a step ends with the answer to the inputs set at its start)."""
        return "time," + ",".join(OUTPUTS) + "\n" + "".join(
            f"{fmt(t)}," + ",".join(fmt(rows[max(i - lag, 0)][2][k]) for k in OUTPUTS) + "\n"
            for i, (t, _, _) in enumerate(rows))
    opt = f"StartTime, {START}\nStopTime, {STOP}\nStepSize, {STEP}\nRelTol, 1e-06\n"
    root = build / "cross-check"
    shutil.rmtree(root, ignore_errors=True)
    for fmi, platform, archive in FMUS:
        for interface, fmi_type, name in (("cs", "CoSimulation", "co-simulation"),
                                          ("me", "ModelExchange", "model exchange")):
            d = root / "fmus" / fmi / interface / platform / "udmap" / version / "udmap"
            d.mkdir(parents=True)
            shutil.copyfile(build / archive, d / "udmap.fmu")
            (d / "udmap_in.csv").write_text(in_csv)
            (d / "udmap_ref.csv").write_text(ref_csv(1 if interface == "cs" else 0))
            (d / "udmap_ref.opt").write_text(opt)
            (d / "ReadMe.md").write_text(README.format(
                version=version, fmi=fmi, interface_name=name, platform=platform,
                fmi_type=fmi_type, step=STEP, timing=TIMING[interface]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
