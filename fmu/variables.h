/*
 * The FMU's variable table: the single source of truth for value references, types,
 * causalities, units, start values, ranges and descriptions. model.c reads and writes
 * values through it, and describe.c generates both modelDescription.xml files and
 * documentation/index.html from it at build time. Start values are those of
 * cases/blade_a.json (tests/python/test_fmu_description.py checks them against the file).
 *
 * X(name, type, causality, group, unit, start, min, max, flags, description)
 *   type       REAL, INTEGER or BOOLEAN
 *   causality  INDEPENDENT, INPUT, PARAMETER (tunable) or OUTPUT
 *   group      what a change invalidates (inputs, parameters) or what computes it (outputs)
 *   unit       a unit of UDMAP_UNITS, or "" for dimensionless
 *   min, max   inclusive bounds (NOLIMIT for none); POSITIVE additionally excludes zero,
 *              OPEN excludes both bounds, EVEN asks for an even integer; the bounds are the
 *              physical ranges of the case-file schema of the Python package
 *              (udmap.case.SCHEMA; tests/python/test_fmu_ranges.py checks that they agree)
 * The value reference of a variable is its position in the table.
 */
#ifndef UDMAP_FMU_VARIABLES_H
#define UDMAP_FMU_VARIABLES_H

#define UDMAP_VARIABLE_TABLE(X) \
  X(time, REAL, INDEPENDENT, NONE, "s", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Simulation time; the outputs are quasi-steady and do not depend on it") \
  /* ---------------------------------------------------------------- inputs */ \
  X(F_E, REAL, INPUT, FORCE, "N", 5.0, 0.0, NOLIMIT, 0, \
    "Proof excitation force amplitude at E (transverse, airfoil mid-length)") \
  X(f_exc, REAL, INPUT, FORCE, "Hz", 0.0, 0.0, NOLIMIT, 0, \
    "Excitation frequency; 0 means at resonance (the peak of the response), otherwise it " \
    "must lie in [f_min, f_max]") \
  X(mu, REAL, INPUT, DAMPER, "", 0.3, 1e-4, 10.0, 0, \
    "Friction coefficient of the damper contacts") \
  X(CF, REAL, INPUT, CF, "N", 900.0, 1e-3, 1e6, 0, \
    "Centrifugal load on the damper") \
  X(kn_flat, REAL, INPUT, DAMPER, "N/m", 60e6, 1e2, 1e12, 0, \
    "Normal contact stiffness of each flat-side contact point") \
  X(kt_flat, REAL, INPUT, DAMPER, "N/m", 40e6, 1e2, 1e12, 0, \
    "Tangential contact stiffness of each flat-side contact point") \
  X(kn_curved, REAL, INPUT, DAMPER, "N/m", 80e6, 1e2, 1e12, 0, \
    "Normal contact stiffness of the curved-side contact point") \
  X(kt_curved, REAL, INPUT, DAMPER, "N/m", 50e6, 1e2, 1e12, 0, \
    "Tangential contact stiffness of the curved-side contact point") \
  /* ---------------------------------------------------------------- blade parameters */ \
  X(neck_L, REAL, PARAMETER, BLADE, "m", 0.020, 1e-4, 3.0, 0, \
    "Neck length (radial), clamped at its root") \
  X(neck_h, REAL, PARAMETER, BLADE, "m", 0.008, 1e-5, 1.0, 0, \
    "Neck section height in the bending direction") \
  X(neck_b, REAL, PARAMETER, BLADE, "m", 0.020, 1e-5, 1.0, 0, \
    "Neck section width") \
  X(platform_L, REAL, PARAMETER, BLADE, "m", 0.010, 1e-5, 1.0, 0, \
    "Platform length (radial); the master point P is at its mid-height") \
  X(platform_m, REAL, PARAMETER, BLADE, "kg", 0.021, 1e-6, 1e3, 0, \
    "Platform mass, lumped at P") \
  X(platform_J, REAL, PARAMETER, BLADE, "kg.m2", 1.4e-6, 1e-15, 1e2, 0, \
    "Platform rotary inertia about P") \
  X(airfoil_L, REAL, PARAMETER, BLADE, "m", 0.120, 1e-4, 3.0, 0, \
    "Airfoil length (radial)") \
  X(airfoil_h, REAL, PARAMETER, BLADE, "m", 0.004, 1e-5, 1.0, 0, \
    "Airfoil section height in the bending direction") \
  X(airfoil_b, REAL, PARAMETER, BLADE, "m", 0.030, 1e-5, 1.0, 0, \
    "Airfoil section width") \
  X(neck_elements, INTEGER, PARAMETER, BLADE, "", 8, 1.0, 1000.0, 0, \
    "Number of equal beam elements of the neck") \
  X(airfoil_elements, INTEGER, PARAMETER, BLADE, "", 24, 2.0, 1000.0, EVEN, \
    "Number of equal beam elements of the airfoil (even, so that E is a node)") \
  X(E, REAL, PARAMETER, BLADE, "Pa", 170e9, 1e6, 1e13, 0, \
    "Young's modulus of the blade") \
  X(rho, REAL, PARAMETER, BLADE, "kg/m3", 8200.0, 1e2, 3e4, 0, \
    "Density of the blade") \
  X(zeta, REAL, PARAMETER, BLADE, "", 0.002, 0.0, 0.5, 0, \
    "Damping ratio of the first bare-blade mode (stiffness-proportional damping C = beta K)") \
  /* ---------------------------------------------------------------- damper parameters */ \
  X(pitch, REAL, PARAMETER, DAMPER, "m", 0.026, 1e-6, 1.0, 0, \
    "Circumferential distance between the platform centres P_L and P_R") \
  X(y_P, REAL, PARAMETER, DAMPER, "m", 0.006, -1.0, 1.0, 0, \
    "Radial coordinate of the platform centres, from the damper centre of gravity G") \
  X(beta_L_deg, REAL, PARAMETER, DAMPER, "deg", 45.0, 0.0, 90.0, OPEN, \
    "Inclination of the left (flat-side) platform face") \
  X(beta_R_deg, REAL, PARAMETER, DAMPER, "deg", 45.0, 0.0, 90.0, OPEN, \
    "Inclination of the right (curved-side) platform face") \
  X(flat1_x, REAL, PARAMETER, DAMPER, "m", -6.724e-3, -1.0, 1.0, 0, \
    "First flat-side contact point, x (circumferential, from G towards the curved side)") \
  X(flat1_y, REAL, PARAMETER, DAMPER, "m", -1.724e-3, -1.0, 1.0, 0, \
    "First flat-side contact point, y (radially outward from G)") \
  X(flat2_x, REAL, PARAMETER, DAMPER, "m", -1.068e-3, -1.0, 1.0, 0, \
    "Second flat-side contact point, x") \
  X(flat2_y, REAL, PARAMETER, DAMPER, "m", 3.932e-3, -1.0, 1.0, 0, \
    "Second flat-side contact point, y") \
  X(curved_x, REAL, PARAMETER, DAMPER, "m", 3.268e-3, -1.0, 1.0, 0, \
    "Curved-side contact point, x") \
  X(curved_y, REAL, PARAMETER, DAMPER, "m", 1.768e-3, -1.0, 1.0, 0, \
    "Curved-side contact point, y") \
  /* ---------------------------------------------------------------- analysis parameters */ \
  X(f_min, REAL, PARAMETER, ANALYSIS, "Hz", 150.0, 1e-3, 1e6, 0, \
    "Lower end of the frequency band searched for the resonance") \
  X(f_max, REAL, PARAMETER, ANALYSIS, "Hz", 230.0, 1e-3, 1e6, 0, \
    "Upper end of the frequency band searched for the resonance") \
  X(sigma_all, REAL, PARAMETER, ANALYSIS, "Pa", 80e6, 1e3, 1e10, 0, \
    "Allowable alternating stress of the HCF criterion") \
  X(harmonics, INTEGER, PARAMETER, HARMONICS, "", 1, 0.0, 64.0, 0, \
    "Harmonics of the platform rotation (PHYSICS.md 4.1): 1 the single-harmonic method, " \
    "2..64 multi-harmonic layers with harmonics 0..H, 0 automatic (raised until the outputs " \
    "change by less than the case's harmonic_tol, 1e-3 by default)") \
  /* ---------------------------------------------------------------- outputs */ \
  X(gamma_P, REAL, OUTPUT, POINT, "rad", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Platform rotation amplitude (at resonance, or at f_exc); +inf when unbounded " \
    "(zeta = 0 and F_E >= F_lim)") \
  X(sigma_a, REAL, OUTPUT, POINT, "Pa", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Alternating stress amplitude at the airfoil-platform junction; +inf when unbounded") \
  X(F_lim, REAL, OUTPUT, LIMIT, "N", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Limit excitation force: above it friction alone cannot bound the response") \
  X(f_res, REAL, OUTPUT, POINT, "Hz", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Frequency of the response peak (or f_exc); the bare-blade natural frequency when " \
    "unbounded") \
  X(u_E, REAL, OUTPUT, POINT, "m", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Displacement amplitude at E; +inf when unbounded") \
  X(k_re, REAL, OUTPUT, POINT, "N.m/rad", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Damper stiffness at gamma_P, real part (0 in the unbounded limit)") \
  X(k_im, REAL, OUTPUT, POINT, "N.m/rad", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Damper stiffness at gamma_P, imaginary part (damping; 0 in the unbounded limit)") \
  X(F_ratio, REAL, OUTPUT, RATIO, "", 0.0, NOLIMIT, NOLIMIT, 0, \
    "F_E / F_lim") \
  X(hcf_ok, BOOLEAN, OUTPUT, POINT, "", 0.0, NOLIMIT, NOLIMIT, 0, \
    "HCF criterion: F_E <= 0.5 min(F_lim, F_lim_backbone) and sigma_a <= sigma_all " \
    "(sigma_max instead of sigma_a when harmonics is not 1)") \
  X(regime, INTEGER, OUTPUT, POINT, "", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Contact regime at gamma_P: 0 stuck, 1 partial slip, 2 full slip, 3 at or above F_lim") \
  X(lift_off, BOOLEAN, OUTPUT, LIMIT, "", 0.0, NOLIMIT, NOLIMIT, 0, \
    "A damper contact opens during the cycle (the damper left its design envelope)") \
  X(gamma_max, REAL, OUTPUT, POINT, "rad", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Largest excursion of the platform rotation from its mean, from all harmonics (gamma_P " \
    "when harmonics = 1); +inf when unbounded") \
  X(sigma_max, REAL, OUTPUT, POINT, "Pa", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Largest excursion of the junction stress from its mean, from all harmonics (sigma_a " \
    "when harmonics = 1); +inf when unbounded") \
  X(harmonics_used, INTEGER, OUTPUT, POINT, "", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Harmonics H of the point (the one chosen when harmonics = 0, automatic)") \
  X(F_lim_backbone, REAL, OUTPUT, LIMIT, "N", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Limit force from the backbone: the supremum of the force that peaks at an amplitude " \
    "(PHYSICS.md 5); below F_lim when a contact lifts off") \
  X(jump, BOOLEAN, OUTPUT, POINT, "", 0.0, NOLIMIT, NOLIMIT, 0, \
    "The peak sits at a jump gamma_c of the damper stiffness k(gamma) (PHYSICS.md 2.5): " \
    "gamma_P = gamma_c, k interpolated between its one-sided values")

/* X(name, kg, m, s, rad, factor, description) over the units used above. */
#define UDMAP_UNITS(X) \
  X("s", 0, 0, 1, 0, 1.0, "second") \
  X("N", 1, 1, -2, 0, 1.0, "newton") \
  X("Hz", 0, 0, -1, 0, 1.0, "hertz") \
  X("m", 0, 1, 0, 0, 1.0, "metre") \
  X("kg", 1, 0, 0, 0, 1.0, "kilogram") \
  X("kg.m2", 1, 2, 0, 0, 1.0, "kilogram square metre") \
  X("kg/m3", 1, -3, 0, 0, 1.0, "kilogram per cubic metre") \
  X("Pa", 1, -1, -2, 0, 1.0, "pascal") \
  X("N/m", 1, 0, -2, 0, 1.0, "newton per metre") \
  X("N.m/rad", 1, 2, -2, -1, 1.0, "newton metre per radian") \
  X("rad", 0, 0, 0, 1, 1.0, "radian") \
  X("deg", 0, 0, 0, 1, 0.017453292519943295, "degree")

#endif /* UDMAP_FMU_VARIABLES_H */
