"""``udmap nodal CASE --blades N --forces ...``: the nodal-diameter sweep of udmap.nodal
(PHYSICS.md 2.6, INTERFACES.md "Command line"), as a table, JSON, CSV and plot."""
from __future__ import annotations


from ..case import build_blade, build_damper, load_case
from ..errors import InputError
from ..nodal import sweep
from ..progress import Progress
from .args import float_list, harmonics_arg
from .files import add_file_options, check_out, write_outputs
from .output import add_warning, emit, finite, print_rows
from .units import UNITS, header, units_of

#: The CSV columns of a sweep point (JSON fields, SI; ibpa_deg in degrees).
NODAL_COLUMNS = ("engine_order", "ibpa_deg", "nodal_diameter", "F_E", "gamma_P", "f_res",
                 "sigma_a", "sigma_max", "F_lim", "hcf_ok", "worst")


def add_nodal_parser(sub) -> None:
    p = sub.add_parser("nodal", help="nodal-diameter sweep: the peaks of every engine order",
                       description="The peaks of every engine order 0..N-1 of a wheel of N "
                       "blades (traveling waves, PHYSICS.md 2.6), the worst engine order per "
                       "force marked.")
    p.add_argument("case", metavar="CASE", help="case file (JSON)")
    p.add_argument("--blades", type=int, required=True, help="number of blades N (2..10000)")
    p.add_argument("--forces", type=float_list, required=True,
                   help="excitation force amplitudes F_E [N], comma-separated")
    p.add_argument("--harmonics", type=harmonics_arg, default=None, metavar="H|auto",
                   help="harmonics (1, H or auto; overrides analysis.harmonics)")
    p.add_argument("--json", action="store_true", help="print JSON on stdout")
    add_file_options(p)
    p.set_defaults(func=cmd_nodal)


def cmd_nodal(args) -> None:
    if not 2 <= args.blades <= 10000:
        raise InputError(f"--blades {args.blades}: the number of blades must lie in [2, 10000]")
    paths = check_out(args, "nodal")
    case = load_case(args.case)
    if args.harmonics is not None:
        case.analysis["harmonics"] = args.harmonics
    blade, damper = build_blade(case), build_damper(case)
    with Progress(args.blades, "nodal sweep") as bar:
        data = sweep(blade, damper, case.analysis, args.blades, args.forces, bar.update)
    data["warnings"] = []
    if damper.kind != "asymmetric":
        add_warning(data, f"a {damper.kind} damper acts on gamma_P alone: the interblade phase "
                    "does not change it (PHYSICS.md 2.6), so every engine order gives the "
                    "in-phase answer")
    for p in data["points"]:
        for k in ("gamma_P", "f_res", "sigma_a", "sigma_max", "F_lim"):
            p[k] = finite(p[k])
    sigma_all = case.analysis["sigma_all"]

    def table(d):
        keys = ("engine_order", "ibpa_deg", "nodal_diameter", "F_E", "gamma_P", "f_res",
                "sigma_a", "F_lim", "hcf_ok")
        fmt = [k if k in UNITS else "" for k in keys]
        print_rows([header(k) for k in keys] + [""],
                   [[p[k] if not isinstance(p[k], bool) else str(p[k]).lower() for k in keys]
                    + ["<- worst" if p["worst"] else ""] for p in d["points"]],
                   [("d" if f == "" else f) for f in fmt] + [""], left=1)
        for w in d["worst"]:
            print(f"F_E = {w['F_E']:g} N: worst engine order {w['engine_order']} (nodal "
                  f"diameter {w['nodal_diameter']}, ibpa {w['ibpa_deg']:g} deg)")

    def plot(path):
        from .. import plots
        plots.nodal_sweep(data, sigma_all, path)

    if paths:
        data["units"] = units_of(data)
        rows = [[p.get(c) for c in NODAL_COLUMNS] for p in data["points"]]
        written = write_outputs(paths, data, NODAL_COLUMNS, rows, plot)
    else:
        written = []
    emit(args, data, table)
    if written and not args.json:
        for path in written:
            print(f"wrote {path}")



