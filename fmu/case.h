/*
 * The case of an FMU made by `udmap fmu CASE` (wrappers/python/udmap/fmu_case.py): the generic
 * binary finds resources/udmap-case.txt at instantiation and takes from it the blade and
 * damper kinds, their data files (read by the kernel's own readers), the analysis settings,
 * the start values, the variables the case has, and the case's instantiation token. Without
 * that file the binary is the generic FMU of blade A.
 *
 * udmap-case.txt, one item a line ("#" starts a comment):
 *   token {xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx}
 *   blade beam | blade matrices
 *   M FILE, K FILE, C FILE, stress_K FILE, stress_M FILE   (matrices; FILE in resources/)
 *   gamma_dof N, exc_dof N                                  (matrices, 1-based)
 *   u_dof N, v_dof N                     (matrices, optional: the platform translations)
 *   damper asymmetric | damper jenkins | damper table
 *   kt X, M_slip X                                          (jenkins)
 *   table N, then N lines "gamma k_re k_im"; delta_M X      (table)
 *   rtol X, grid_per_decade N, eigen_method N, dense_max N, sweep_points N
 *   start NAME VALUE                                        (start value of a variable)
 *   absent NAME                                             (a variable the case has not)
 */
#ifndef UDMAP_FMU_CASE_H
#define UDMAP_FMU_CASE_H

#include <stdbool.h>
#include <stddef.h>

#include "config.h"
#include "udmap.h"

#define CASE_FILE "udmap-case.txt"
#define CASE_PATH_MAX 4096

typedef enum { BLADE_BEAM, BLADE_MATRICES } BladeKind;
typedef enum { DAMPER_ASYMMETRIC, DAMPER_JENKINS, DAMPER_TABLE } DamperKind;

typedef struct {
  char token[40];
  BladeKind blade;
  char M[CASE_PATH_MAX], K[CASE_PATH_MAX], C[CASE_PATH_MAX]; /* full paths, "" if none */
  char stress_K[CASE_PATH_MAX], stress_M[CASE_PATH_MAX];
  int gamma_dof, exc_dof;
  int u_dof, v_dof; /* platform translations (traveling waves), 0 if none */
  DamperKind damper;
  double kt, M_slip;
  int n; /* table rows */
  double *gamma, *k_re, *k_im;
  bool has_delta_M;
  double delta_M;
  udmap_analysis analysis; /* rtol, grid_per_decade, eigen_method, dense_max, sweep_points */
  double start[UDMAP_NVARS];
  bool present[UDMAP_NVARS];
} CaseConfig;

/* Reads the case from the resource location (FMI 2: a file URI; FMI 3: a path). Returns NULL
 * with msg[0] == 0 when there is no case file (the generic FMU), NULL with a message when the
 * file is bad. */
CaseConfig *case_read(const char *resourceLocation, char *msg, size_t n);
void case_free(CaseConfig *c);

#endif /* UDMAP_FMU_CASE_H */
