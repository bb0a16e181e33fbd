"""Finite element blades (PHYSICS.md 1.3, INTERFACES.md "Finite element blade"): the readers of
the FE codes' matrix exports, one module per format, all returning an :class:`FEModel`."""
from __future__ import annotations

from pathlib import Path

from ..errors import InputError
from ._text import read_mm
from .model import COMPONENTS, FEModel, convert_units, make_model

#: The files each format needs (INTERFACES.md).
FORMAT_FILES = {
    "calculix": ("sti", "mas", "dof", "inp"),
    "abaqus": ("stiffness", "mass", "inp"),
    "ansys": ("stiffness", "mass", "dof_map", "nodes"),
    "nastran": ("pch", "bdf"),
    "matrix_market": ("K", "M", "dof_map", "nodes"),
}
UNITS = ("SI", "mm-t-s")

__all__ = ["FEModel", "COMPONENTS", "FORMAT_FILES", "UNITS", "read_fe", "resolve_files",
           "make_model", "convert_units", "read_mm"]


def resolve_files(blade: dict, case_dir) -> dict:
    """The ``files`` of a blade section as absolute paths, checking that each exists."""
    fmt = blade.get("format")
    if fmt not in FORMAT_FILES:
        raise InputError(f"blade.format must be one of {', '.join(FORMAT_FILES)}, got {fmt!r}")
    files = blade.get("files")
    if not isinstance(files, dict):
        raise InputError("blade.files must be an object naming the files "
                         f"({', '.join(FORMAT_FILES[fmt])})")
    need = FORMAT_FILES[fmt]
    for key in files:
        if key not in need:
            raise InputError(f"blade.files.{key}: unknown file for format {fmt} (allowed: "
                             f"{', '.join(need)})")
    out = {}
    for key in need:
        if key not in files:
            raise InputError(f"blade.files.{key}: missing (format {fmt} needs "
                             f"{', '.join(need)})")
        if not isinstance(files[key], str) or not files[key]:
            raise InputError(f"blade.files.{key} must be a file path (string)")
        p = Path(files[key])
        p = p if p.is_absolute() else Path(case_dir) / p
        if not p.is_file():
            raise InputError(f"blade.files.{key}: file not found: {p}")
        out[key] = p
    return out


def read_fe(blade: dict, case_dir=".") -> FEModel:
    """Reads the model of an ``fe`` blade section (paths relative to ``case_dir``) and converts
    it to SI from the section's ``units``."""
    files = resolve_files(blade, case_dir)
    fmt = blade["format"]
    units = blade.get("units", "SI")
    if units not in UNITS:
        raise InputError(f"blade.units must be one of {', '.join(UNITS)}, got {units!r}")
    if fmt == "calculix":
        from . import calculix as mod
    elif fmt == "abaqus":
        from . import abaqus as mod
    elif fmt == "ansys":
        from . import ansys as mod
    elif fmt == "matrix_market":
        from . import matrix_market as mod
    else:
        from . import nastran
        return convert_units(nastran.read(files, blade.get("dmig")), units)
    return convert_units(mod.read(files), units)
