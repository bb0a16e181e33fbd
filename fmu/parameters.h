/*
 * The FMU's variable table and the items of its case file (fmu/case.h).
 * fmu/variables.h documents the columns of UDMAP_VARIABLE_TABLE.
 * Generated from kernel/parameters.toml by cmake/generate_parameters.py: do not edit; edit the
 * table and run cmake/generate_parameters.py.
 */
#ifndef UDMAP_FMU_PARAMETERS_H
#define UDMAP_FMU_PARAMETERS_H

#define UDMAP_VARIABLE_TABLE(X) \
  X(time, REAL, INDEPENDENT, NONE, "s", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Simulation time; the outputs are quasi-steady and do not depend on it") \
  X(F_E, REAL, INPUT, FORCE, "N", 5.0, 0.0, NOLIMIT, 0, \
    "Proof excitation force amplitude at E (transverse, airfoil mid-length)") \
  X(f_exc, REAL, INPUT, FORCE, "Hz", 0.0, 0.0, NOLIMIT, 0, \
    "Excitation frequency; 0 means at resonance (the peak of the response), otherwise it " \
    "must lie in [f_min, f_max]") \
  X(mu, REAL, INPUT, DAMPER, "", 0.3, 0.0001, 10.0, 0, \
    "Friction coefficient of the damper contacts") \
  X(CF, REAL, INPUT, CF, "N", 900.0, 0.001, 1e6, 0, \
    "Centrifugal load on the damper") \
  X(kn_flat, REAL, INPUT, DAMPER, "N/m", 6e7, 100.0, 1e12, 0, \
    "Normal contact stiffness of each flat-side contact point") \
  X(kt_flat, REAL, INPUT, DAMPER, "N/m", 4e7, 100.0, 1e12, 0, \
    "Tangential contact stiffness of each flat-side contact point") \
  X(kn_curved, REAL, INPUT, DAMPER, "N/m", 8e7, 100.0, 1e12, 0, \
    "Normal contact stiffness of the curved-side contact point") \
  X(kt_curved, REAL, INPUT, DAMPER, "N/m", 5e7, 100.0, 1e12, 0, \
    "Tangential contact stiffness of the curved-side contact point") \
  X(neck_L, REAL, PARAMETER, BLADE, "m", 0.02, 0.0001, 3.0, 0, \
    "Neck length (radial), clamped at its root") \
  X(neck_h, REAL, PARAMETER, BLADE, "m", 0.008, 1e-5, 1.0, 0, \
    "Neck section height in the bending direction") \
  X(neck_b, REAL, PARAMETER, BLADE, "m", 0.02, 1e-5, 1.0, 0, \
    "Neck section width") \
  X(platform_L, REAL, PARAMETER, BLADE, "m", 0.01, 1e-5, 1.0, 0, \
    "Platform length (radial); the master point P is at its mid-height") \
  X(platform_m, REAL, PARAMETER, BLADE, "kg", 0.021, 1e-6, 1000.0, 0, \
    "Platform mass, lumped at P") \
  X(platform_J, REAL, PARAMETER, BLADE, "kg.m2", 1.4e-6, 1e-15, 100.0, 0, \
    "Platform rotary inertia about P") \
  X(airfoil_L, REAL, PARAMETER, BLADE, "m", 0.12, 0.0001, 3.0, 0, \
    "Airfoil length (radial)") \
  X(airfoil_h, REAL, PARAMETER, BLADE, "m", 0.004, 1e-5, 1.0, 0, \
    "Airfoil section height in the bending direction") \
  X(airfoil_b, REAL, PARAMETER, BLADE, "m", 0.03, 1e-5, 1.0, 0, \
    "Airfoil section width") \
  X(neck_elements, INTEGER, PARAMETER, BLADE, "", 8, 1.0, 1000.0, 0, \
    "Number of equal beam elements of the neck") \
  X(airfoil_elements, INTEGER, PARAMETER, BLADE, "", 24, 2.0, 1000.0, EVEN, \
    "Number of equal beam elements of the airfoil (even, so that E is a node)") \
  X(E, REAL, PARAMETER, BLADE, "Pa", 1.7e11, 1e6, 1e13, 0, \
    "Young's modulus of the blade") \
  X(rho, REAL, PARAMETER, BLADE, "kg/m3", 8200.0, 100.0, 30000.0, 0, \
    "Density of the blade") \
  X(zeta, REAL, PARAMETER, BLADE, "", 0.002, 0.0, 0.5, 0, \
    "Damping ratio of the first bare-blade mode (stiffness-proportional damping C = beta K)") \
  X(pitch, REAL, PARAMETER, DAMPER, "m", 0.026, 1e-6, 1.0, 0, \
    "Circumferential distance between the platform centres P_L and P_R") \
  X(y_P, REAL, PARAMETER, DAMPER, "m", 0.006, -1.0, 1.0, 0, \
    "Radial coordinate of the platform centres, from the damper centre of gravity G") \
  X(beta_L_deg, REAL, PARAMETER, DAMPER, "deg", 45.0, 0.0, 90.0, OPEN, \
    "Inclination of the left (flat-side) platform face") \
  X(beta_R_deg, REAL, PARAMETER, DAMPER, "deg", 45.0, 0.0, 90.0, OPEN, \
    "Inclination of the right (curved-side) platform face") \
  X(flat1_x, REAL, PARAMETER, DAMPER, "m", -0.006724, -1.0, 1.0, 0, \
    "First flat-side contact point, x (circumferential, from G towards the curved side)") \
  X(flat1_y, REAL, PARAMETER, DAMPER, "m", -0.001724, -1.0, 1.0, 0, \
    "First flat-side contact point, y (radially outward from G)") \
  X(flat2_x, REAL, PARAMETER, DAMPER, "m", -0.001068, -1.0, 1.0, 0, \
    "Second flat-side contact point, x") \
  X(flat2_y, REAL, PARAMETER, DAMPER, "m", 0.003932, -1.0, 1.0, 0, \
    "Second flat-side contact point, y") \
  X(curved_x, REAL, PARAMETER, DAMPER, "m", 0.003268, -1.0, 1.0, 0, \
    "Curved-side contact point, x") \
  X(curved_y, REAL, PARAMETER, DAMPER, "m", 0.001768, -1.0, 1.0, 0, \
    "Curved-side contact point, y") \
  X(f_min, REAL, PARAMETER, ANALYSIS, "Hz", 150.0, 0.001, 1e6, 0, \
    "Lower end of the frequency band searched for the resonance") \
  X(f_max, REAL, PARAMETER, ANALYSIS, "Hz", 230.0, 0.001, 1e6, 0, \
    "Upper end of the frequency band searched for the resonance") \
  X(sigma_all, REAL, PARAMETER, ANALYSIS, "Pa", 8e7, 1000.0, 1e10, 0, \
    "Allowable alternating stress of the HCF criterion") \
  X(harmonics, INTEGER, PARAMETER, HARMONICS, "", 1, 0.0, 64.0, 0, \
    "Harmonics of the platform rotation (PHYSICS.md 4.1): 1 the single-harmonic method, " \
    "2..64 multi-harmonic layers with harmonics 0..H, 0 automatic (raised until the outputs " \
    "change by less than the case's harmonic_tol, 1e-3 by default)") \
  X(gamma_P, REAL, OUTPUT, POINT, "rad", 0.0, NOLIMIT, NOLIMIT, 0, \
    "Platform rotation amplitude (at resonance, or at f_exc); +inf when unbounded (zeta = 0 " \
    "and F_E >= F_lim)") \
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
    "gamma_P = gamma_c, k interpolated between its one-sided values") \
  X(blades, INTEGER, PARAMETER, ANALYSIS, "", 2.0, 2.0, 10000.0, 0, \
    "Number of blades N of the wheel; with engine_order the interblade phase 2 pi EO/N of " \
    "the traveling wave (PHYSICS.md 2.6)") \
  X(engine_order, INTEGER, PARAMETER, ANALYSIS, "", 0.0, 0.0, 1e6, 0, \
    "Engine order EO (taken modulo blades); 0 is the in-phase family. The asymmetric damper " \
    "feels the phase; jenkins and table dampers do not") \
  X(F_E_min, REAL, PARAMETER, RANGE, "N", 1.0, 0.0, NOLIMIT, 0, \
    "Lowest F_E the master will use (with F_E_max; F_E_min < F_E_max): the initialization " \
    "prepares the force range so that no later step in it builds anything (0: from " \
    "F_E_max/1000; at an engine order other than 0 the range is built as the forces visit " \
    "it)") \
  X(F_E_max, REAL, PARAMETER, RANGE, "N", 10.0, 0.0, NOLIMIT, 0, \
    "Highest F_E the master will use; a force outside [F_E_min, F_E_max] is still answered " \
    "exactly, possibly in a longer step")

/* Items of resources/udmap-case.txt (fmu/case.h) that are case-file fields:
 * X(key, member of CaseConfig, conversion of the number read). */
#define UDMAP_CASE_ITEMS(X) \
  X("gamma_dof", gamma_dof, (int)) \
  X("exc_dof", exc_dof, (int)) \
  X("u_dof", u_dof, (int)) \
  X("v_dof", v_dof, (int)) \
  X("kt", kt, (double)) \
  X("M_slip", M_slip, (double)) \
  X("rtol", analysis.rtol, (double)) \
  X("grid_per_decade", analysis.grid_per_decade, (int)) \
  X("eigen_method", analysis.eigen_method, (int)) \
  X("dense_max", analysis.dense_max, (int)) \
  X("sweep_points", analysis.sweep_points, (int)) \
  X("harmonic_tol", analysis.harmonic_tol, (double))

#endif /* UDMAP_FMU_PARAMETERS_H */
