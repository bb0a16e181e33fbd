"""The kernel library and every declaration of its C API (wrappers/c/udmap.h) for ctypes.

This module is the only one that touches the foreign interface: it loads libudmap.so (where:
:mod:`udmap.locate`), declares the structs and the signature of every function, and owns the
error handle whose :meth:`ErrorHandle.check` turns a failed status into an exception through
:func:`udmap.errors.error_from_status`. Its users are the object classes (blade, damper, model,
reduction, hbm); nothing above them touches a pointer.
"""
from __future__ import annotations

import ctypes

import numpy as np

from .errors import error_from_status
from .locate import FMU_NAMES, LIBRARY_NAME, fmu_path, library_candidates
# The parameter structs are generated from kernel/parameters.toml (cmake/generate_parameters.py).
from .parameters import Analysis, AsymmetricParams, BeamParams

__all__ = ["lib", "fmu_path", "FMU_NAMES", "ErrorHandle", "library_path", "version", "as_doubles",
           "declare"]

c_double_p = ctypes.POINTER(ctypes.c_double)
c_int_p = ctypes.POINTER(ctypes.c_int)
vp = ctypes.c_void_p
vp_p = ctypes.POINTER(ctypes.c_void_p)
_ci = ctypes.c_int
_cd = ctypes.c_double


def _load() -> ctypes.CDLL:
    tried = []
    for path in library_candidates():
        tried.append(str(path))
        if path.is_file():
            return ctypes.CDLL(str(path))
    try:
        return ctypes.CDLL(LIBRARY_NAME)
    except OSError:
        tried.append(f"{LIBRARY_NAME} (system loader path)")
    raise ImportError("udmap: kernel library not found; build it with 'make build' or set "
                      "UDMAP_LIBRARY. Tried: " + ", ".join(tried))


lib = _load()


def declare(name: str, argtypes, restype=ctypes.c_int):
    """Declares a C API function's signature and returns it."""
    fn = getattr(lib, name)
    fn.argtypes = argtypes
    fn.restype = restype
    return fn


# ---------------------------------------------------------------------------- structs
MAX_ROOTS = 8
MAX_HARMONICS = 64


class DamperInfo(ctypes.Structure):
    """udmap_damper_info: the base cycle of a damper."""
    _fields_ = [("gamma_b", _cd), ("gamma_s", _cd), ("M_max", _cd), ("M_min", _cd),
                ("k_stuck", _cd), ("lift_off", _ci)]


class Point(ctypes.Structure):
    """udmap_point: a backbone or response point."""
    _fields_ = [("F_E", _cd), ("gamma_P", _cd), ("f_res", _cd), ("sigma_a", _cd),
                ("u_E", _cd), ("k_re", _cd), ("k_im", _cd),
                ("regime", _ci), ("hcf_ok", _ci), ("unbounded", _ci),
                ("nroots", _ci), ("roots", _cd * MAX_ROOTS),
                ("gamma_max", _cd), ("sigma_max", _cd), ("harmonics", _ci),
                # the C struct's tail padding, named so that numpy sees the full item size
                ("_pad", _ci)]


class HbmSettings(ctypes.Structure):
    """udmap_hbm_settings (defaults from the kernel)."""
    _fields_ = [("harmonics", _ci), ("harmonic0", _ci), ("variant", _ci), ("tol", _cd),
                ("max_iter", _ci), ("ds_initial", _cd), ("ds_min", _cd), ("ds_max", _cd),
                ("target_iter", _ci), ("max_angle", _cd), ("max_steps", _ci),
                ("peak_tol", _cd), ("aft_samples", _ci), ("aft_max_periods", _ci),
                ("fd_step", _cd), ("gamma_limit", _cd), ("full_band", _ci),
                ("jacobian_reuse", _ci), ("tol_path", _cd), ("warm_start", _ci)]


class HbmPoint(ctypes.Structure):
    """udmap_hbm_point."""
    _fields_ = [("F_E", _cd), ("gamma_P", _cd), ("f_res", _cd), ("sigma_a", _cd),
                ("u_E", _cd), ("k_re", _cd), ("k_im", _cd), ("gamma_max", _cd),
                ("npeaks", _ci), ("peaks", _cd * MAX_ROOTS), ("peak_f", _cd * MAX_ROOTS),
                ("harmonics", _ci), ("gamma_h", _cd * MAX_HARMONICS),
                ("steps", _ci), ("iterations", _ci), ("aft_calls", _ci), ("seconds", _cd),
                ("lift_off", _ci)]


class DtiSettings(ctypes.Structure):
    """udmap_dti_settings (defaults from the kernel)."""
    _fields_ = [("steps_per_period", _ci), ("ss_tol", _cd), ("min_periods", _ci),
                ("max_periods", _ci), ("peak_rtol", _cd), ("peak_window", _cd),
                ("gamma_limit", _cd)]


class DtiPoint(ctypes.Structure):
    """udmap_dti_point."""
    _fields_ = [("F_E", _cd), ("f", _cd), ("gamma_1", _cd), ("sigma_1", _cd),
                ("gamma_max", _cd), ("gamma_0", _cd), ("ss_error", _cd), ("periods", _ci),
                ("runs", _ci), ("seconds", _cd), ("lift_off", _ci)]


class DtiWheelPoint(ctypes.Structure):
    """udmap_dti_wheel_point."""
    _fields_ = [("blade0", DtiPoint), ("blades", _ci), ("engine_order", _ci), ("phi", _cd),
                ("gamma_spread", _cd), ("sigma_spread", _cd), ("phase_spread", _cd)]


# ---------------------------------------------------------------------------- functions
# errors and version
get_version = declare("udmap_get_version", [], _ci)
new_error = declare("udmap_new_error", [], vp)
delete_error = declare("udmap_delete_error", [vp_p], None)
check_error = declare("udmap_check_error", [vp], _ci)
get_error = declare("udmap_get_error", [vp, ctypes.c_char_p, _ci], None)

# blade
new_blade_beam = declare("udmap_new_blade_beam", [vp, ctypes.POINTER(BeamParams), vp_p])
new_blade_matrices = declare("udmap_new_blade_matrices",
                             [vp, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, _ci, _ci,
                              ctypes.c_char_p, ctypes.c_char_p, _cd, vp_p])
delete_blade = declare("udmap_delete_blade", [vp_p], None)
blade_get_size = declare("udmap_blade_get_size", [vp, vp, c_int_p, c_int_p])
blade_natural_frequencies = declare("udmap_blade_natural_frequencies",
                                    [vp, vp, _ci, c_double_p])
blade_receptances = declare("udmap_blade_receptances", [vp, vp, _ci, c_double_p, c_double_p])
blade_layer_response = declare("udmap_blade_layer_response",
                               [vp, vp, _ci, c_double_p, _cd, _cd, c_double_p])
blade_export = declare("udmap_blade_export", [vp, vp, ctypes.c_char_p])
blade_set_platform_rows = declare("udmap_blade_set_platform_rows",
                                  [vp, vp, _ci, c_double_p, c_double_p])
blade_get_platform_rows = declare("udmap_blade_get_platform_rows",
                                  [vp, vp, _ci, c_double_p, c_double_p, c_int_p])

# damper: the k(gamma) face
new_damper_asymmetric = declare("udmap_new_damper_asymmetric",
                                [vp, ctypes.POINTER(AsymmetricParams), vp_p])
new_damper_jenkins = declare("udmap_new_damper_jenkins", [vp, _cd, _cd, vp_p])
new_damper_table = declare("udmap_new_damper_table",
                           [vp, _ci, c_double_p, c_double_p, c_double_p, _ci, _cd, vp_p])
delete_damper = declare("udmap_delete_damper", [vp_p], None)
damper_get_info = declare("udmap_damper_get_info", [vp, vp, ctypes.POINTER(DamperInfo)])
damper_stiffness = declare("udmap_damper_stiffness",
                           [vp, vp, _ci, c_double_p, c_double_p, c_double_p])
damper_stiffness_derivative = declare("udmap_damper_stiffness_derivative",
                                      [vp, vp, _ci, c_double_p, c_double_p, c_double_p])
damper_loop = declare("udmap_damper_loop", [vp, vp, _cd, _ci, c_double_p, c_double_p])
damper_set_CF = declare("udmap_damper_set_CF", [vp, vp, _cd])
damper_jump_count = declare("udmap_damper_jump_count", [vp, vp, c_int_p])
damper_jump_get = declare("udmap_damper_jump_get", [vp, vp, _ci, c_double_p, _cd * 2, _cd * 2])

# model: the mapping
analysis_defaults = declare("udmap_analysis_defaults", [ctypes.POINTER(Analysis)], None)
new_model = declare("udmap_new_model", [vp, vp, vp, ctypes.POINTER(Analysis), vp_p])
delete_model = declare("udmap_delete_model", [vp_p], None)
model_set_damper = declare("udmap_model_set_damper", [vp, vp, vp])
model_limit_force = declare("udmap_model_limit_force", [vp, vp, c_double_p])
model_limit_force_backbone = declare("udmap_model_limit_force_backbone", [vp, vp, c_double_p])
model_backbone_jumps = declare("udmap_model_backbone_jumps", [vp, vp, _ci, c_int_p])
model_backbone_curve = declare("udmap_model_backbone_curve",
                               [vp, vp, _ci, c_double_p, c_double_p, c_double_p])
model_backbone = declare("udmap_model_backbone",
                         [vp, vp, _ci, c_double_p, ctypes.POINTER(Point)])
model_response = declare("udmap_model_response",
                         [vp, vp, _cd, _ci, c_double_p, ctypes.POINTER(Point)])
model_curves = declare("udmap_model_curves", [vp, vp, _ci, c_double_p, _ci])
model_curve_size = declare("udmap_model_curve_size", [vp, vp, _ci, c_int_p])
model_curve_get = declare("udmap_model_curve_get", [vp, vp, _ci, _ci, c_double_p, c_double_p,
                                                    c_double_p, c_int_p, c_int_p])
model_set_harmonics = declare("udmap_model_set_harmonics", [vp, vp, _ci, _cd])
model_set_ibpa = declare("udmap_model_set_ibpa", [vp, vp, _cd])
# plausibility warnings (docs/case-files.md, "Plausibility"): kinds UDMAP_WARNING_* of udmap.h
WARNING_KINDS = {1: "platform_mass", 2: "platform_inertia", 3: "gamma_b_large",
                 4: "stuck_shift", 5: "band_misses_mode"}
WARNING_LEN = 512
plausibility_warnings = declare("udmap_plausibility_warnings",
                                [vp, vp, vp, _cd, _cd, _ci, _ci, c_int_p, ctypes.c_char_p,
                                 c_int_p])
model_warnings = declare("udmap_model_warnings",
                         [vp, vp, _ci, _ci, c_int_p, ctypes.c_char_p, c_int_p])


def warnings_of(call, err) -> list[tuple[str, str]]:
    """(kind, text) of the warnings a C API warnings call returns: ``call(nmax, len, kinds,
    texts, n)`` with the other arguments bound, checked on the error handle ``err``."""
    nmax = 8
    while True:
        kinds = (ctypes.c_int * nmax)()
        texts = ctypes.create_string_buffer(nmax * WARNING_LEN)
        n = ctypes.c_int()
        err.check(call(nmax, WARNING_LEN, kinds, texts, ctypes.byref(n)))
        if n.value <= nmax:
            break
        nmax = n.value
    raw = texts.raw
    return [(WARNING_KINDS[kinds[i]],
             raw[i * WARNING_LEN:(i + 1) * WARNING_LEN].split(b"\0", 1)[0].decode())
            for i in range(n.value)]


model_admissible_force = declare("udmap_model_admissible_force",
                                 [vp, vp, _cd, _cd, _cd, c_double_p])
model_classify = declare("udmap_model_classify", [vp, vp, _cd, _ci, c_double_p, c_double_p,
                                                  c_double_p, c_int_p, c_int_p, c_int_p])
model_set_force_table = declare("udmap_model_set_force_table", [vp, vp, _ci])
model_cover_forces = declare("udmap_model_cover_forces", [vp, vp, _cd, _cd])
model_force_table_info = declare("udmap_model_force_table_info",
                                 [vp, vp, c_int_p, c_int_p, c_int_p])
model_point_harmonics = declare("udmap_model_point_harmonics",
                                [vp, vp, _ci, _ci, c_double_p, c_double_p, c_int_p])


class DesignOutputs(ctypes.Structure):
    """udmap_design_outputs: where udmap_model_designs writes (NULL: not written)."""
    _fields_ = [(name, c_double_p) for name in ("F_lim", "F_lim_backbone", "gamma_b", "M_max",
                                                "M_min")] + \
        [("lift_off", c_int_p)] + [(name, c_double_p) for name in ("gamma_P", "f_res",
                                                                     "sigma_a")] + \
        [(name, c_int_p) for name in ("unbounded", "hcf_ok", "jump")] + \
        [("F_adm", c_double_p), ("status", c_int_p), ("stage", c_int_p),
         ("message", ctypes.c_char_p), ("message_len", _ci), ("traces", _ci)]


model_designs = declare("udmap_model_designs", [vp, vp, _ci, vp, vp, _ci, c_double_p, _ci,
                                                ctypes.POINTER(DesignOutputs)])
model_designs_warnings = declare("udmap_model_designs_warnings",
                                 [vp, vp, _ci, vp, vp, _ci, c_double_p, _ci,
                                  ctypes.POINTER(DesignOutputs), c_int_p])

# reduction
reduce = declare("udmap_reduce", [
    vp, _ci, ctypes.c_int64, vp, vp, vp, ctypes.c_int64, vp, vp, vp, vp, vp, _ci, vp,
    vp, _ci, vp, vp, vp, _ci, vp, _ci, vp, _ci, vp, _ci, _cd, _ci, _ci, vp_p])
reduction_sizes = declare("udmap_reduction_sizes", [vp, vp] + [ctypes.POINTER(_ci)] * 6)
reduction_get = declare("udmap_reduction_get", [vp, vp, vp, vp, vp, vp, vp])
reduction_info = declare("udmap_reduction_info", [vp, vp, vp])
delete_reduction = declare("udmap_delete_reduction", [vp_p], None)

# contact: the time-domain face, and the standard method over it
new_contact_jenkins = declare("udmap_new_contact_jenkins", [vp, _cd, _cd, vp_p])
new_contact_asymmetric = declare("udmap_new_contact_asymmetric",
                                 [vp, ctypes.POINTER(AsymmetricParams), vp_p])
delete_contact = declare("udmap_delete_contact", [vp_p], None)
contact_aft = declare("udmap_contact_aft",
                      [vp, vp, _ci, _cd, c_double_p, _ci, c_double_p, c_double_p, c_double_p])
hbm_defaults = declare("udmap_hbm_defaults", [ctypes.POINTER(HbmSettings)], None)
hbm_peaks = declare("udmap_hbm_peaks", [vp, vp, vp, _cd, _cd, ctypes.POINTER(HbmSettings), _ci,
                                        c_double_p, ctypes.POINTER(HbmPoint)])
hbm_response = declare("udmap_hbm_response",
                       [vp, vp, vp, _cd, _cd, ctypes.POINTER(HbmSettings), _ci, c_double_p,
                        ctypes.POINTER(HbmPoint)])
hbm_curve = declare("udmap_hbm_curve",
                    [vp, vp, vp, _cd, _cd, ctypes.POINTER(HbmSettings), _cd, _ci, c_int_p,
                     c_double_p, c_double_p, c_double_p, c_double_p])
dti_defaults = declare("udmap_dti_defaults", [ctypes.POINTER(DtiSettings)], None)
dti_response = declare("udmap_dti_response", [vp, vp, vp, ctypes.POINTER(DtiSettings), _cd, _ci,
                                              c_double_p, ctypes.POINTER(DtiPoint)])
dti_peak = declare("udmap_dti_peak", [vp, vp, vp, ctypes.POINTER(DtiSettings), _cd, _cd, _ci,
                                      c_double_p, ctypes.POINTER(DtiPoint)])
dti_wheel_response = declare("udmap_dti_wheel_response",
                             [vp, vp, vp, ctypes.POINTER(DtiSettings), _cd, _ci, _ci, _ci,
                              c_double_p, ctypes.POINTER(DtiWheelPoint)])
dti_wheel_peak = declare("udmap_dti_wheel_peak",
                         [vp, vp, vp, ctypes.POINTER(DtiSettings), _cd, _cd, _cd, _ci, _ci, _ci,
                          c_double_p, ctypes.POINTER(DtiWheelPoint)])

wave_hbm_peaks = declare("udmap_wave_hbm_peaks",
                         [vp, vp, vp, _cd, _cd, _cd, _ci, _ci, c_double_p, c_double_p,
                          c_double_p, c_double_p, c_double_p, c_double_p, c_int_p])

# ---------------------------------------------------------------------------- helpers
class ErrorHandle:
    """Owns one udmap_error; ``check(status)`` raises the kernel's message on failure."""

    def __init__(self):
        self.ptr = ctypes.c_void_p(new_error())

    def __del__(self):
        if getattr(self, "ptr", None) is not None and lib is not None:
            delete_error(ctypes.byref(self.ptr))

    def check(self, status: int) -> None:
        if status == 0:
            return
        buf = ctypes.create_string_buffer(4096)
        get_error(self.ptr, buf, len(buf))
        message = buf.value.decode("utf-8", "replace") or f"udmap error {status}"
        raise error_from_status(status, message)


def library_path() -> str:
    """The path of the kernel library this package loaded."""
    return lib._name


def version() -> str:
    """The kernel version string 'major.minor.patch'."""
    v = get_version()
    return f"{v // 10000}.{(v // 100) % 100}.{v % 100}"


def as_doubles(values) -> "tuple[np.ndarray, ctypes._Pointer]":
    """A contiguous float64 numpy array and a ctypes pointer to it (keep the array alive)."""
    arr = np.ascontiguousarray(values, dtype=np.float64)
    return arr, arr.ctypes.data_as(c_double_p)


def doubles_ptr(arr: np.ndarray):
    """The ctypes double pointer of a float64 numpy array."""
    return arr.ctypes.data_as(c_double_p)


def ints_ptr(arr: np.ndarray):
    """The ctypes int pointer of an intc numpy array."""
    return arr.ctypes.data_as(c_int_p)
