/*
 * udmap: convergence-free mapping of underplatform damper-blade performance.
 * C API over the Fortran kernel (kernel/src/api*.f90).
 *
 * Conventions (dftd4 style):
 *  - opaque handles, created by udmap_new_* and released by udmap_delete_* (which accept NULL
 *    and set the handle to NULL);
 *  - the error handle comes first; every function returns a status (UDMAP_OK on success),
 *    and on failure the error handle carries the status and a message naming the argument;
 *  - arrays are passed as pointers with their length; complex numbers as (re, im) pairs;
 *  - frequencies in Hz, everything else SI.
 * No function keeps global state: handles are independent and may be used from several
 * threads as long as one handle is not used by two threads at once.
 */
#ifndef UDMAP_H
#define UDMAP_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define UDMAP_OK 0
#define UDMAP_EINPUT 2   /* bad input: a parameter, file or argument is invalid */
#define UDMAP_EPHYSICS 3 /* physics failure: jammed damper, no resonance in the band */
#define UDMAP_ENUMERIC 4 /* numerical failure: a LAPACK/ARPACK routine failed */

#define UDMAP_MAX_ROOTS 8

typedef struct _udmap_error *udmap_error;
typedef struct _udmap_blade *udmap_blade;
typedef struct _udmap_damper *udmap_damper;
typedef struct _udmap_model *udmap_model;

/* ---------------------------------------------------------------- version, errors */

/* Version as 10000 * major + 100 * minor + patch. */
int udmap_get_version(void);

udmap_error udmap_new_error(void);
void udmap_delete_error(udmap_error *error);
/* Status of the last failed call on this handle (UDMAP_OK if none). */
int udmap_check_error(udmap_error error);
/* Copies the message (NUL-terminated, truncated to buflen - 1 characters). */
void udmap_get_error(udmap_error error, char *buffer, int buflen);

/* ---------------------------------------------------------------- blade */

/* Built-in beam blade (PHYSICS.md 1.1). */
/* generated:begin udmap_beam_params (from kernel/parameters.toml: do not edit) */
typedef struct {
  double E, rho, zeta;
  double neck_L, neck_h, neck_b;
  double platform_L, platform_m, platform_J;
  double airfoil_L, airfoil_h, airfoil_b;
  int neck_elements, airfoil_elements;
} udmap_beam_params;
/* generated:end udmap_beam_params */

int udmap_new_blade_beam(udmap_error error, const udmap_beam_params *params, udmap_blade *blade);

/* Imported blade (PHYSICS.md 1.2) from Matrix Market files; C_path, sK_path, sM_path may be
 * NULL. gamma_dof and exc_dof are 1-based. Without C, damping is beta K from zeta. */
int udmap_new_blade_matrices(udmap_error error, const char *M_path, const char *K_path,
                             const char *C_path, int gamma_dof, int exc_dof,
                             const char *sK_path, const char *sM_path, double zeta,
                             udmap_blade *blade);

void udmap_delete_blade(udmap_blade *blade);

/* Number of DOFs and whether stress rows are present (1) or not (0). */
int udmap_blade_get_size(udmap_error error, udmap_blade blade, int *ndof, int *has_stress);

/* The first nmodes bare natural frequencies [Hz], ascending. */
int udmap_blade_natural_frequencies(udmap_error error, udmap_blade blade, int nmodes,
                                    double *f_hz);

/* Bare receptances at n frequencies: out has 10*n doubles, per frequency the (re, im) pairs
 * of H_gE, H_gg, H_EE, H_sE, H_sg (stress ones 0 without stress rows). */
int udmap_blade_receptances(udmap_error error, udmap_blade blade, int n, const double *f_hz,
                            double *out);

/* Sherman-Morrison layer response to a unit force at E with damper stiffness k on gamma:
 * out has 6*n doubles, per frequency the (re, im) pairs of g~ (rotation), s~ (stress), u~_E. */
int udmap_blade_layer_response(udmap_error error, udmap_blade blade, int n, const double *f_hz,
                               double k_re, double k_im, double *out);

/* The platform translations of a traveling wave (PHYSICS.md 2.6) as rows of the blade's DOFs:
 * u_P = u_row . q (circumferential, not zero) and v_P = v_row . q (radial; v_row NULL: held).
 * ndof must be the blade's; entries finite. The beam sets them itself (u_P = -w_P); a matrices
 * blade needs them before a model at a nonzero interblade phase is made from it. */
int udmap_blade_set_platform_rows(udmap_error error, udmap_blade blade, int ndof,
                                  const double *u_row, const double *v_row);

/* The rows set above (ndof doubles each); *known = 0 and zero rows when the blade has none. */
int udmap_blade_get_platform_rows(udmap_error error, udmap_blade blade, int ndof, double *u_row,
                                  double *v_row, int *known);

/* Writes M.mtx, K.mtx (and stress_K.mtx, stress_M.mtx with stress rows, C.mtx with explicit
 * damping) into the existing directory dir (Matrix Market, full precision). */
int udmap_blade_export(udmap_error error, udmap_blade blade, const char *dir);

/* ---------------------------------------------------------------- damper */

/* Asymmetric flat/curved rigid damper (PHYSICS.md 2.1). */
/* generated:begin udmap_asymmetric_params (from kernel/parameters.toml: do not edit) */
typedef struct {
  double CF, mu, pitch, y_P, beta_L_deg, beta_R_deg;
  double flat1_x, flat1_y, flat2_x, flat2_y, curved_x, curved_y;
  double kn_flat, kt_flat, kn_curved, kt_curved;
} udmap_asymmetric_params;
/* generated:end udmap_asymmetric_params */

int udmap_new_damper_asymmetric(udmap_error error, const udmap_asymmetric_params *params,
                                udmap_damper *damper);
/* Rotational Jenkins element (PHYSICS.md 2.4): kt [N m/rad], M_slip [N m]. */
int udmap_new_damper_jenkins(udmap_error error, double kt, double M_slip, udmap_damper *damper);
/* Measured table (PHYSICS.md 2.4): n rows of gamma (ascending, > 0), k_re, k_im;
 * has_delta_M = 1 enables extrapolation beyond the last row with delta_M. */
int udmap_new_damper_table(udmap_error error, int n, const double *gamma, const double *k_re,
                           const double *k_im, int has_delta_M, double delta_M,
                           udmap_damper *damper);
void udmap_delete_damper(udmap_damper *damper);

typedef struct {
  double gamma_b;  /* base-cycle amplitude [rad] */
  double gamma_s;  /* largest amplitude without slip [rad] */
  double M_max;    /* upward plateau moment [N m] */
  double M_min;    /* downward plateau moment [N m] */
  double k_stuck;  /* stuck stiffness k_Re at small amplitude [N m/rad] */
  int lift_off;    /* 1 if a contact opens during the cycle */
} udmap_damper_info;

int udmap_damper_get_info(udmap_error error, udmap_damper damper, udmap_damper_info *info);

/* k(gamma) = k_re + i k_im for n amplitudes [rad] (each > 0; a table without delta_M only up to
 * its last row). */
int udmap_damper_stiffness(udmap_error error, udmap_damper damper, int n, const double *gamma,
                           double *k_re, double *k_im);

/* dk/dgamma for n amplitudes [N m/rad^2] (closed forms of the base cycle and the traced loops;
 * the PCHIP derivative for a table). */
int udmap_damper_stiffness_derivative(udmap_error error, udmap_damper damper, int n,
                                      const double *gamma, double *dk_re, double *dk_im);

/* Jumps of k(gamma) (PHYSICS.md 2.5; with lift-off the steady loop can change its shape
 * abruptly at gamma_c): their number (0 without), and jump i (0-based, ascending) at the current
 * CF: gamma_c [rad] and the one-sided stiffnesses k(gamma_c-), k(gamma_c+) as {re, im}
 * [N m/rad]. At gamma_c itself udmap_damper_stiffness returns k(gamma_c-). */
int udmap_damper_jump_count(udmap_error error, udmap_damper damper, int *n);
int udmap_damper_jump_get(udmap_error error, udmap_damper damper, int i, double *gamma_c,
                          double k_minus[2], double k_plus[2]);

/* The steady loop M_r(tau) at amplitude gamma_a, gamma = gamma_a cos(tau), at n equally spaced
 * tau in [0, 2 pi) (asymmetric and jenkins kinds). */
int udmap_damper_loop(udmap_error error, udmap_damper damper, double gamma_a, int n,
                      double *tau, double *M_r);

/* New centrifugal load: rescales the table (PHYSICS.md 2.3) without tracing again. */
int udmap_damper_set_CF(udmap_error error, udmap_damper damper, double CF);

/* ---------------------------------------------------------------- mapping, backbone */

/* Analysis settings; fill with udmap_analysis_defaults, then change what is needed. */
/* generated:begin udmap_analysis (from kernel/parameters.toml: do not edit) */
typedef struct {
  double f_min, f_max;  /* band [Hz] */
  double sigma_all;     /* allowable alternating stress [Pa], default 80e6 */
  double rtol;          /* relative tolerance of peak and root refinement, default 1e-12 */
  int grid_per_decade;  /* backbone amplitude grid density for root bracketing, default 24 */
  int eigen_method;     /* eigenvalue start: 0 auto (a direct solve once per model, then the
                           secular equation), 1 direct for every layer, 2 secular only */
  int dense_max;        /* largest ndof for the dense eigen-solver (zggev); larger banded models
                           use ARPACK shift-invert, default 200 */
  int sweep_points;     /* bare-blade samples over the band for the response curves, default 400 */
  int harmonics;        /* harmonics of the platform rotation (PHYSICS.md 4.1): 1 (default) the
                           single-harmonic method; H = 2..64 harmonics 0..H in multi-harmonic
                           layers; 0 automatic (raised until the outputs change by less than
                           harmonic_tol) */
  double harmonic_tol;  /* relative change that stops the automatic choice, default 1e-3 */
  double ibpa_deg;      /* interblade phase angle [deg] of the traveling wave (PHYSICS.md 2.6),
                           default 0 (in phase) */
} udmap_analysis;
/* generated:end udmap_analysis */

void udmap_analysis_defaults(udmap_analysis *analysis);

/* A model couples a blade and a damper over a band. It borrows both handles (they must outlive
 * it) and caches what it derived from them; changes of the damper (udmap_damper_set_CF) are
 * noticed and only the affected caches are rebuilt. */
int udmap_new_model(udmap_error error, udmap_blade blade, udmap_damper damper,
                    const udmap_analysis *analysis, udmap_model *model);
void udmap_delete_model(udmap_model *model);

/* Couples another damper to the model (borrowed like the first; the old one may then be
 * deleted). The bare-blade data are kept and the backbone table is rebuilt on next use: the
 * cheap path after a change of damper parameters. */
int udmap_model_set_damper(udmap_error error, udmap_model model, udmap_damper damper);

/* One point of the non-linear response (at resonance or at a given frequency). */
typedef struct {
  double F_E;      /* excitation force amplitude [N] */
  double gamma_P;  /* platform rotation amplitude [rad] */
  double f_res;    /* frequency of the peak (or the given frequency) [Hz] */
  double sigma_a;  /* alternating stress amplitude [Pa] (0 without stress rows) */
  double u_E;      /* displacement amplitude at E [m] */
  double k_re, k_im; /* damper stiffness at gamma_P [N m/rad] */
  int regime;      /* 0 stuck, 1 partial slip, 2 full slip, 3 at or above F_lim */
  int hcf_ok;      /* F_E <= 0.5 min(F_lim, F_lim_backbone) and sigma_a <= sigma_all */
  int unbounded;   /* zeta = 0 and F_E >= F_lim (or above the backbone's asymptote, if that is
                      lower, e.g. with lift-off): no finite response; numbers are 0, regime 3 */
  int nroots;      /* number of gamma_P roots (all in roots[], ascending; beyond
                      UDMAP_MAX_ROOTS the largest ones) */
  double roots[UDMAP_MAX_ROOTS];
  double gamma_max;  /* largest excursion of gamma(t) from its mean [rad] (gamma_P at H = 1) */
  double sigma_max;  /* largest excursion of sigma(t) from its mean [Pa] (sigma_a at H = 1);
                        with harmonics > 1 hcf_ok takes sigma_max instead of sigma_a */
  int harmonics;     /* harmonics used (1: the single-harmonic method) */
} udmap_point;

int udmap_model_limit_force(udmap_error error, udmap_model model, double *F_lim);
/* F_lim_backbone [N] (PHYSICS.md 5): the level F_bb approaches at large amplitude without
 * structural damping, lim gamma k_Im(gamma) / |phi_E/phi_g|; F_lim unless lift-off lowers it.
 * The unbounded flag (zeta = 0), hcf_ok and the regime of the points use the smaller of the
 * two. */
int udmap_model_limit_force_backbone(udmap_error error, udmap_model model, double *F_lim_backbone);

/* F_adm of a design [N]: the largest F_E <= F_lim/2 whose resonant stress (sigma_a; sigma_max
 * with harmonics != 1) is at most sigma_all [Pa], refined to rtol; F_lim [N] as the caller
 * takes it (the DOE passes the smaller of F_lim and F_lim_backbone). Stress rows needed. */
int udmap_model_admissible_force(udmap_error error, udmap_model model, double F_lim,
                                 double sigma_all, double rtol, double *F_adm);

/* The regime and hcf_ok of n points computed elsewhere (e.g. by the standard method), as
 * udmap_model_backbone gives them: regime 3 when F_E >= F_lim, else 0, 1 or 2 by gamma_P
 * [rad] against the damper's gamma_s and gamma_b (udmap_damper_info); hcf_ok when F_E <=
 * F_lim/2 and sigma <= the model's sigma_all, sigma [Pa] being the stress the criterion takes
 * (sigma_a; sigma_max with harmonics > 1). A point with unbounded[i] != 0 is regime 3 and not
 * admissible (its gamma_P and sigma are not read). F_lim [N] > 0 as the caller takes it (the
 * backbone: the smaller of F_lim and F_lim_backbone; INFINITY: no limit known). */
int udmap_model_classify(udmap_error error, udmap_model model, double F_lim, int n,
                         const double *F_E, const double *gamma_P, const double *sigma,
                         const int *unbounded, int *regime, int *hcf_ok);

/* Harmonics for the next backbone, response and curves calls (as udmap_analysis.harmonics and
 * harmonic_tol), keeping every cache of the model (the bare blade, the single-harmonic backbone
 * table, the contact element of the layers). */
int udmap_model_set_harmonics(udmap_error error, udmap_model model, int harmonics,
                              double harmonic_tol);

/* The interblade phase angle [deg] for the next calls (as udmap_analysis.ibpa_deg: 0 in
 * phase, else a traveling wave, PHYSICS.md 2.6), keeping every cache of the model (a sweep
 * over engine orders builds the bare blade and the single-harmonic backbone table once). */
int udmap_model_set_ibpa(udmap_error error, udmap_model model, double ibpa_deg);

/* With on != 0, backbone points at harmonics != 1 come from the force table (what the FMU
 * uses after a change of F_E alone, PHYSICS.md 4.1): interpolated in ln F_E to
 * harmonic_tol/1000 where a verified panel of exact points holds F_E, solved exactly
 * elsewhere (the first force in a panel, and where the points jump). Off by default. */
int udmap_model_set_force_table(udmap_error error, udmap_model model, int on);

/* Prepares the model so that udmap_model_backbone for forces in [F_min, F_max] [N]
 * (0 < F_min <= F_max, finite) at the current harmonics builds nothing: the single-harmonic
 * backbone table is grown to F_max and, at harmonics != 1 with the force table on, the force
 * table gets every panel of the range (as visits on demand would build them; their answers
 * agree to the layer tolerance, far inside harmonic_tol/1000). Nothing for a traveling-wave
 * model. Holds until the damper, the harmonics or harmonic_tol change. */
int udmap_model_cover_forces(udmap_error error, udmap_model model, double F_min, double F_max);

/* What the model's force table holds: *points exact points (a count that grows only when
 * panels are built), *leaves leaves, *exact_leaves of them answered by exact solves. */
int udmap_model_force_table_info(udmap_error error, udmap_model model, int *points,
                                 int *leaves, int *exact_leaves);

/* Harmonic content of point i (0-based) of the last udmap_model_backbone or
 * udmap_model_response call: gamma_h[h] = |Gamma_h| [rad], sigma_h[h] = |sigma_h| [Pa] for
 * h = 0..*nh - 1 (at most nmax entries written; *nh = harmonics + 1, or 2 at H = 1). */
int udmap_model_point_harmonics(udmap_error error, udmap_model model, int i, int nmax,
                                double *gamma_h, double *sigma_h, int *nh);

/* Backbone F_bb(gamma) and the peak frequency for n amplitudes. */
int udmap_model_backbone_curve(udmap_error error, udmap_model model, int n, const double *gamma,
                               double *F_bb, double *f_res);

/* Peaks of the non-linear response for n forces (PHYSICS.md 4). */
int udmap_model_backbone(udmap_error error, udmap_model model, int n, const double *F_E,
                         udmap_point *points);

/* Per point of the last udmap_model_backbone call (n must equal its count): 1 if gamma_P is the
 * amplitude gamma_c of a jump of k(gamma) and k (k_re, k_im of the point) is interpolated
 * between the one-sided values so that the layer peaks at F_E (PHYSICS.md 2.5), else 0. */
int udmap_model_backbone_jumps(udmap_error error, udmap_model model, int n, int *jump);

/* Response at the excitation frequency f_exc [Hz] for n forces (PHYSICS.md 4, last paragraph).
 * f_exc must lie in (0, 3 f_max]: beyond the band [f_min, f_max], where the resonance is
 * sought, up to the reach of a reduced FE blade (PHYSICS.md 1.3). The response at a fixed
 * frequency is finite even above F_lim, so unbounded is never set here (regime is still 3). */
int udmap_model_response(udmap_error error, udmap_model model, double f_exc, int n,
                         const double *F_E, udmap_point *points);

/* Response curves by amplitude layered force mapping (PHYSICS.md 3) for n forces, starting
 * from `layers` log-spaced amplitude layers (more are added where the curves bend). The curves
 * are kept in the model until the next call; read curve i (0-based, in the order of F_E) with
 * udmap_model_curve_size and udmap_model_curve_get. Points come in path order: per connected
 * part, the lower-frequency branch by rising gamma_P, the peak, the upper-frequency branch by
 * falling gamma_P (a detached part starts and ends at its bottom turning point). branch: 0
 * below the peak frequency of the point's layer, 1 above, 2 a turning point on the backbone;
 * part: 1 the main curve, 2, 3, ... detached parts. */
#define UDMAP_BRANCH_LOWER 0
#define UDMAP_BRANCH_UPPER 1
#define UDMAP_BRANCH_TURNING 2
int udmap_model_curves(udmap_error error, udmap_model model, int n, const double *F_E,
                       int layers);
int udmap_model_curve_size(udmap_error error, udmap_model model, int i, int *npoints);
/* Copies curve i into arrays of at least npoints entries (f in Hz, gamma_P in rad, sigma_a in
 * Pa). */
int udmap_model_curve_get(udmap_error error, udmap_model model, int i, int npoints, double *f_hz,
                          double *gamma_P, double *sigma_a, int *branch, int *part);

/* ---------------------------------------------------------------- plausibility warnings */

/* A blade, damper and band inside every range can still be physically implausible, most often
 * because a value was typed in another unit (docs/case-files.md, "Plausibility"). Each warning
 * has a kind and a text that names the quantity, says why it looks wrong and suggests the
 * likely unit error; nothing is refused and the results stay what they are. Kinds: */
#define UDMAP_WARNING_PLATFORM_MASS 1    /* beam platform heavier than neck and airfoil */
#define UDMAP_WARNING_PLATFORM_INERTIA 2 /* beam platform J over 1000 m L^2/12 */
#define UDMAP_WARNING_GAMMA_B_LARGE 3    /* asymmetric damper's gamma_b above 1e-2 rad */
#define UDMAP_WARNING_STUCK_SHIFT 4      /* stuck damper shifts f1 by < 0.1 % or > 100 % */
#define UDMAP_WARNING_BAND_MISSES_MODE 5 /* the band misses the bare or the stuck first mode */
/* A text length that holds every warning's text. */
#define UDMAP_WARNING_LEN 512

/* The warnings of a blade, a damper (NULL: its check left out) and the band [f_min, f_max]
 * [Hz], without a model (the band against the bare first mode; no stuck-peak checks). *n: the
 * number of warnings (all of them); the first nmax are written: kinds[i] and the text at
 * texts + i * len (NUL-terminated, cut to len - 1 characters). kinds and texts may be NULL
 * with nmax = 0. */
int udmap_plausibility_warnings(udmap_error error, udmap_blade blade, udmap_damper damper,
                                double f_min, double f_max, int nmax, int len, int *kinds,
                                char *texts, int *n);
/* The same for a model's blade, damper and band, with the stuck peak: a backbone point at
 * 1e-3 gamma_s (gamma_b without a stuck range), computed as udmap_model_backbone_curve would
 * (no stuck peak in the band is a warning, not an error). */
int udmap_model_warnings(udmap_error error, udmap_model model, int nmax, int len, int *kinds,
                         char *texts, int *n);

/* ---------------------------------------------------------------- many designs at once */

/* The stages udmap_model_designs computes (bit flags; the outputs a design of experiments
 * asks for decide them): */
#define UDMAP_DESIGN_LIMIT 1           /* F_lim */
#define UDMAP_DESIGN_LIMIT_BACKBONE 2  /* F_lim_backbone */
#define UDMAP_DESIGN_PEAKS 4           /* gamma_P, f_res, sigma_a, unbounded, hcf_ok at F_E */
#define UDMAP_DESIGN_JUMPS 8           /* the jump flags at F_E (computes the peaks) */
#define UDMAP_DESIGN_ADMISSIBLE 16     /* F_adm (computes F_lim and F_lim_backbone) */
/* Where a design failed (udmap_design_outputs.stage): */
#define UDMAP_DESIGN_FAILED_DAMPER 1     /* tracing or rescaling the damper */
#define UDMAP_DESIGN_FAILED_LIMIT 2      /* coupling the damper, F_lim */
#define UDMAP_DESIGN_FAILED_PEAKS 3      /* the peaks */
#define UDMAP_DESIGN_FAILED_ADMISSIBLE 4 /* F_adm */

/* Where udmap_model_designs writes (caller's arrays; NULL: not written). Per design: F_lim,
 * F_lim_backbone [N], the damper's gamma_b [rad], M_max, M_min [N m], lift_off (0/1); per
 * design and force (design by design, nforces each): gamma_P [rad], f_res [Hz], sigma_a [Pa],
 * unbounded, hcf_ok, jump (0/1, as udmap_point and udmap_model_backbone_jumps give them);
 * per design F_adm [N] (udmap_model_admissible_force with the smaller of F_lim and
 * F_lim_backbone and the model's sigma_all and rtol; F_lim/2 without stress rows), status
 * (required: UDMAP_OK or the status of the design's failure), stage (0, or the
 * UDMAP_DESIGN_FAILED_* stage) and message (message_len characters per design, the failure's
 * message NUL-terminated). What precedes a failed stage is written; traces: dampers traced
 * by the call. */
typedef struct {
  double *F_lim, *F_lim_backbone, *gamma_b, *M_max, *M_min;
  int *lift_off;
  double *gamma_P, *f_res, *sigma_a;
  int *unbounded, *hcf_ok, *jump;
  double *F_adm;
  int *status, *stage;
  char *message;
  int message_len;
  int traces;
} udmap_design_outputs;

/* n designs on one model in one call, each as the single calls would compute it (set the
 * damper, F_lim, F_lim_backbone, the backbone at the nforces forces F_E [N] with its jump
 * flags, F_adm: bit for bit the same numbers), only the stages asked for. params: n
 * asymmetric damper blocks, or NULL for the model's own damper in every design. reference
 * (NULL: each design traced for its own block): per design a block equal to its own but for
 * CF and a common factor kappa of kn_flat, kt_flat, kn_curved, kt_curved; the design then
 * takes the damper traced for the reference, rescaled exactly (PHYSICS.md 2.3: amplitudes by
 * (CF/CF_ref)/kappa, moments by CF/CF_ref, k by kappa), so designs that share a reference
 * share one tracing. The model keeps the last few traced dampers between calls; afterwards
 * it is coupled to its own damper again. A failing design is recorded in out and the call
 * goes on; the call itself fails only on bad arguments. */
int udmap_model_designs(udmap_error error, udmap_model model, int n,
                        const udmap_asymmetric_params *params,
                        const udmap_asymmetric_params *reference, int nforces,
                        const double *F_E, int stages, udmap_design_outputs *out);

/* udmap_model_designs, and per design the plausibility warnings that udmap_model_warnings
 * gives on the model coupled to the design's damper, the stuck peak included, taken after its
 * stages (so those are udmap_model_designs' bit for bit): kinds[i] = the sum of
 * 1 << (kind - 1) over them (UDMAP_WARNING_*), or -1 where the design's damper fails. */
int udmap_model_designs_warnings(udmap_error error, udmap_model model, int n,
                                 const udmap_asymmetric_params *params,
                                 const udmap_asymmetric_params *reference, int nforces,
                                 const double *F_E, int stages, udmap_design_outputs *out,
                                 int *kinds);

/* ---------------------------------------------------------------- standard method, time integration */

/* The standard convergence-based method (PHYSICS.md 6) and the time-domain ground truth
 * (PHYSICS.md 7). The damper enters as its contact law in time (udmap_contact): the steady
 * moment for a periodic gamma(t) is traced with the loading history of PHYSICS.md 2.1, exactly
 * (event-driven) unless a number of AFT samples is set. */
typedef struct _udmap_contact *udmap_contact;

#define UDMAP_HBM_CONDENSED 0 /* harmonic balance on the damper DOF after condensation */
#define UDMAP_HBM_FULL 1      /* harmonic balance on all DOFs */
#define UDMAP_HBM_MAX_HARMONICS 64

/* Rotational Jenkins element (PHYSICS.md 2.4): kt [N m/rad], M_slip [N m]. */
int udmap_new_contact_jenkins(udmap_error error, double kt, double M_slip, udmap_contact *contact);
/* Asymmetric flat/curved damper (PHYSICS.md 2.1), with its CF ramp. */
int udmap_new_contact_asymmetric(udmap_error error, const udmap_asymmetric_params *params,
                                 udmap_contact *contact);
void udmap_delete_contact(udmap_contact *contact);

/* One AFT evaluation: gamma(tau) = G0 + Re(sum_h G_h e^{i h tau}), h = 1..H, G as H (re, im)
 * pairs; returns the steady M_r = M0 + Re(sum_h M_h e^{i h tau}) (M as H pairs) and the largest
 * gamma. samples = 0: exact event-driven integration; >= 2H+1: classical sampled AFT. */
int udmap_contact_aft(udmap_error error, udmap_contact contact, int H, double G0, const double *G,
                      int samples, double *M0, double *M, double *gamma_max);

/* Settings of the standard method; fill with udmap_hbm_defaults, then change what is needed. */
typedef struct {
  int harmonics;       /* H: harmonics 1..H (default 1) */
  int harmonic0;       /* 1: also balance the static harmonic 0 (default 0) */
  int variant;         /* UDMAP_HBM_CONDENSED (default) or UDMAP_HBM_FULL */
  double tol;          /* Newton: relative step tolerance at the peak (default 1e-10) */
  int max_iter;        /* Newton iterations per corrector (default 30) */
  double ds_initial;   /* arc-length steps in relative amplitude/frequency units: */
  double ds_min;       /*   first 0.05, smallest 1e-9, largest 0.3 */
  double ds_max;
  int target_iter;     /* step control: Newton iterations aimed at per step (default 4) */
  double max_angle;    /* largest turn of the tangent per step [rad] (default 0.35) */
  int max_steps;       /* continuation steps per force (default 20000) */
  double peak_tol;     /* peak refinement tolerance on the arc length (default 1e-10) */
  int aft_samples;     /* 0: exact event-driven AFT (default); N >= 2H+1: N samples per period */
  int aft_max_periods; /* periods until the damper loop repeats, at most (default 8) */
  double fd_step;      /* relative finite-difference step of the damper Jacobian (1e-7) */
  double gamma_limit;  /* amplitude [rad] beyond which the response is unbounded (10) */
  int full_band;       /* 1: continue to f_max (default); 0: stop once past the peak */
  int jacobian_reuse;  /* 1: keep the damper Jacobian while Newton contracts well (default) */
  double tol_path;     /* Newton: relative step tolerance along the path (default 1e-6) */
  int warm_start;      /* udmap_hbm_peaks: 0 sweeps the band for every force (default); 1 starts
                          each force after the first at the previous force's peak (state scaled
                          by the force ratio) and climbs the new curve to its peak instead of
                          sweeping the band; 2 also the first force, from the peak of the stuck
                          linear response. For curves with one peak per force (a climb that
                          fails falls back to the sweep) */
} udmap_hbm_settings;

void udmap_hbm_defaults(udmap_hbm_settings *settings);

/* The peak of the first harmonic of gamma_P on the continued response curve of one force. */
typedef struct {
  double F_E;        /* excitation force amplitude [N] */
  double gamma_P;    /* first-harmonic amplitude of gamma_P at the peak [rad] */
  double f_res;      /* frequency of the peak [Hz] (or the given frequency) */
  double sigma_a;    /* first-harmonic stress amplitude [Pa] (0 without stress rows) */
  double u_E;        /* first-harmonic displacement amplitude at E [m] */
  double k_re, k_im; /* M_1/Gamma_1 at the peak [N m/rad] */
  double gamma_max;  /* largest gamma_P(t) over the period [rad] */
  int npeaks;        /* local maxima of gamma_1 on the curve (peaks[], peak_f[], ascending) */
  double peaks[UDMAP_MAX_ROOTS];
  double peak_f[UDMAP_MAX_ROOTS];
  int harmonics;     /* number of entries of gamma_h */
  double gamma_h[UDMAP_HBM_MAX_HARMONICS]; /* |Gamma_h|, h = 1..harmonics [rad] */
  int steps;         /* accepted continuation steps */
  int iterations;    /* Newton iterations */
  int aft_calls;     /* AFT evaluations (Jacobians included) */
  double seconds;    /* wall time of this force [s] */
  int lift_off;      /* 1 if a damper contact opens during the cycle at the peak */
} udmap_hbm_point;

/* Peaks for n forces over [f_min, f_max] [Hz]: continuation from f_min upwards from the stuck
 * linear response, the peak located on the curve. No peak inside the band: UDMAP_EPHYSICS. */
int udmap_hbm_peaks(udmap_error error, udmap_blade blade, udmap_contact contact, double f_min,
                    double f_max, const udmap_hbm_settings *settings, int n, const double *F_E,
                    udmap_hbm_point *points);
/* Response at f_exc [Hz] for n forces, reached by continuation from f_min. */
int udmap_hbm_response(udmap_error error, udmap_blade blade, udmap_contact contact, double f_min,
                       double f_exc, const udmap_hbm_settings *settings, int n, const double *F_E,
                       udmap_hbm_point *points);
/* The continued curve of one force: *npoints points (only the first `capacity` written) of f
 * [Hz], |Gamma_1| [rad], first-harmonic stress [Pa] and the largest gamma(t) [rad]. */
int udmap_hbm_curve(udmap_error error, udmap_blade blade, udmap_contact contact, double f_min,
                    double f_max, const udmap_hbm_settings *settings, double F_E, int capacity,
                    int *npoints, double *f, double *gamma_1, double *sigma_1, double *gamma_max);

/* Settings of the time integration; fill with udmap_dti_defaults. */
typedef struct {
  int steps_per_period; /* Newmark steps per excitation period (default 1024, >= 8) */
  double ss_tol;        /* steady state: estimated remaining relative error of gamma_1 (1e-8) */
  int min_periods;      /* least periods (default 20) */
  int max_periods;      /* most periods before giving up (default 200000) */
  double peak_rtol;     /* peak search: relative frequency tolerance (default 1e-6) */
  double peak_window;   /* peak search: first bracket half-width, relative (default 0.01) */
  double gamma_limit;   /* |gamma_P| [rad] beyond which the response is unbounded (10) */
} udmap_dti_settings;

void udmap_dti_defaults(udmap_dti_settings *settings);

/* Steady state reached from rest under F_E sin(2 pi f t) at E. */
typedef struct {
  double F_E;       /* excitation force amplitude [N] */
  double f;         /* excitation frequency [Hz] */
  double gamma_1;   /* first-harmonic amplitude of gamma_P [rad] */
  double sigma_1;   /* first-harmonic amplitude of the stress [Pa] */
  double gamma_max; /* largest gamma_P(t) over the last period [rad] */
  double gamma_0;   /* mean of gamma_P(t) over the last period [rad] */
  double ss_error;  /* estimated remaining relative error of gamma_1 */
  int periods;      /* periods integrated (last run) */
  int runs;         /* time integrations (several for the peak search) */
  double seconds;   /* wall time [s] */
  int lift_off;     /* 1 if a damper contact opened during the last period */
} udmap_dti_point;

/* Newmark (average acceleration) on the whole blade to steady state at f_exc [Hz]. */
int udmap_dti_response(udmap_error error, udmap_blade blade, udmap_contact contact,
                       const udmap_dti_settings *settings, double f_exc, int n,
                       const double *F_E, udmap_dti_point *points);
/* The frequency of the largest gamma_1 near the single-harmonic peak in [f_min, f_max]. */
int udmap_dti_peak(udmap_error error, udmap_blade blade, udmap_contact contact,
                   const udmap_dti_settings *settings, double f_min, double f_max, int n,
                   const double *F_E, udmap_dti_point *points);

/* ---------------------------------------------------------------- traveling waves */
/* A wheel excited in engine order EO vibrates in a traveling wave with the interblade phase
   phi = 2 pi EO / N (PHYSICS.md 2.6); udmap_analysis.ibpa_deg selects it for the model's
   backbone and limit force (the asymmetric damper; jenkins and table dampers do not depend on
   phi). The blade must know its platform translations. */

/* The standard method at ibpa_deg [deg] (harmonics 1, or 2..64 for 0..H): for each of the n
   forces F_E [N], continuation down from f_start[i] [Hz] (above the peak, inside the band) and
   the maximum of |Gamma_1| over frequency: gamma_P [rad], f_res [Hz], sigma_a [Pa], u_E [m] and the
   Newton iterations. */
int udmap_wave_hbm_peaks(udmap_error error, udmap_blade blade, udmap_damper damper, double f_min,
                         double f_max, double ibpa_deg, int harmonics, int n, const double* F_E,
                         const double* f_start, double* gamma_P, double* f_res, double* sigma_a,
                         double* u_E, int* iterations);

/* The whole wheel in time (PHYSICS.md 2.6, 7): `blades` blades and as many asymmetric dampers
 * (damper j between blade j's flat side and blade j + 1's curved side), blade j under
 * F_E sin(2 pi f t + j phi), phi = 2 pi engine_order / blades, from rest to steady state.
 * Blade 0's point and the spread between the blades (a wave that stays traveling has them 0). */
typedef struct {
  udmap_dti_point blade0; /* blade 0's steady state (ss_error: the largest over the blades) */
  int blades;             /* N */
  int engine_order;       /* EO */
  double phi;             /* interblade phase angle 2 pi (EO mod N) / N [rad] */
  double gamma_spread;    /* (max - min)/max of the blades' first-harmonic |gamma_P| */
  double sigma_spread;    /* the same for the first-harmonic stress */
  double phase_spread;    /* largest |arg(Gamma_{j+1}/Gamma_j) - phi| [rad] */
} udmap_dti_wheel_point;

/* The wheel at f_exc [Hz] for n forces (blades 2..100, engine_order >= 0; the asymmetric
 * damper only: jenkins and table dampers do not depend on phi). */
int udmap_dti_wheel_response(udmap_error error, udmap_blade blade, udmap_contact contact,
                             const udmap_dti_settings *settings, double f_exc, int blades,
                             int engine_order, int n, const double *F_E,
                             udmap_dti_wheel_point *points);
/* The wheel at the frequency of blade 0's largest gamma_1, searched around f_center [Hz]
 * (f_center <= 0: the in-phase single-harmonic peak in [f_min, f_max]). */
int udmap_dti_wheel_peak(udmap_error error, udmap_blade blade, udmap_contact contact,
                         const udmap_dti_settings *settings, double f_min, double f_max,
                         double f_center, int blades, int engine_order, int n,
                         const double *F_E, udmap_dti_wheel_point *points);

/* ---------------------------------------------------------------- FE reduction */

/* Platform Centred Reduction of a sparse FE blade (PHYSICS.md 1.3, paper section 2.1).
 * K, M: n x n symmetric, by the entries of their LOWER triangle (row >= col), 1-based COO
 * indices, duplicates add up. dof_node[n], dof_comp[n] (1..6): the node id and component of
 * each row; node_ids[n_nodes], node_xyz[3 * n_nodes] (x, y, z of each node in turn).
 * The platform nodes follow one rigid body u_i = u_R + theta x (x_i - x_R) (by transformation),
 * gamma_P = theta . axis (unit axis, right-hand sense); clamp_nodes (may be NULL with
 * n_clamp = 0) are fixed. The force acts at exc_node along exc_direction (u_E = u . d).
 * Craig-Bampton onto the seven boundary DOFs: gamma_P (reduced DOF 1), the two other rotations,
 * the three translations of the platform, u_E (reduced DOF 7); then the fixed-interface modes
 * (n_modes >= 0, or n_modes < 0: all below 3 f_max) and n_residual blocks of residual vectors
 * (0-20; the Python default 3 brings the band to about 1e-8 and below). stress_rows: n_stress rows of n (row k at
 * stress_rows[k * n]), reduced as s_r = V^T T^T s. check_full != 0 adds the checks that cost
 * a sparse factorisation each: M positive semi-definite (MUMPS finds no negative pivot of
 * M + 1e-12 max|M| I: massless DOFs are fine) and the full
 * model with the rigid platform solved in [0, 3 f_max] (or up to the highest kept mode when
 * f_max <= 0) with its inertia count. The fixed-interface modes' inertia check is always made.
 * Errors name the argument (UDMAP_EINPUT), e.g. an empty platform set, a zero axis, a node not
 * in the model, entries above the diagonal, an M that is not positive definite (nor
 * semi-definite); on error
 * *reduction is NULL. Uses ARPACK, whose dsaupd keeps internal save state: do not run two
 * reductions at once in two threads of one process. */
typedef struct _udmap_reduction *udmap_reduction;
int udmap_reduce(udmap_error error, int n, int64_t nnz_K, const int *K_row, const int *K_col,
                 const double *K_val, int64_t nnz_M, const int *M_row, const int *M_col,
                 const double *M_val, const int *dof_node, const int *dof_comp, int n_nodes,
                 const int *node_ids, const double *node_xyz, int n_platform,
                 const int *platform_nodes, const double ref_point[3], const double axis[3],
                 int exc_node, const double exc_direction[3], int n_clamp,
                 const int *clamp_nodes, int n_stress, const double *stress_rows, int n_modes,
                 double f_max, int n_residual, int check_full, udmap_reduction *reduction);
void udmap_delete_reduction(udmap_reduction *reduction);
/* Sizes: r (reduced DOFs), fixed-interface modes kept, stress rows, full-model frequencies
 * found in the check band, gamma_dof, exc_dof (1-based). Any pointer may be NULL. */
int udmap_reduction_sizes(udmap_error error, udmap_reduction reduction, int *r, int *n_modes,
                          int *n_stress, int *n_freqs_full, int *gamma_dof, int *exc_dof);
/* Copies M[r * r], K[r * r] (symmetric), stress[n_stress * r] (row k at stress[k * r]),
 * freqs_reduced[r] (all, ascending, Hz), freqs_full[n_freqs_full] (Hz). Any may be NULL. */
int udmap_reduction_get(udmap_error error, udmap_reduction reduction, double *M, double *K,
                        double *stress, double *freqs_reduced, double *freqs_full);
/* info[15]: fixed-interface cut-off [Hz], top of the check band [Hz], MUMPS's count of
 * fixed-interface modes below the cut-off and those found, the same for the full model in the
 * check band (-1 if not checked), transformed DOFs, interior DOFs, entries of the largest
 * factor, residual vectors, then wall times [s]: transformation, factorisations and static
 * modes, fixed-interface modes and residual vectors, projection, full-model check. */
int udmap_reduction_info(udmap_error error, udmap_reduction reduction, double *info);

#ifdef __cplusplus
}
#endif
#endif /* UDMAP_H */
