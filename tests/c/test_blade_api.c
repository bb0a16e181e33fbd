/* The blade section of the C API (wrappers/c/udmap.h): blade A's size and first natural
 * frequency, receptances against the layer response (Sherman-Morrison evaluated here in C
 * complex arithmetic), export and re-import through Matrix Market, and a status 2 with a
 * message naming the field or file for every kind of bad input. */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "udmap.h"

static void write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  fputs(text, f);
  fclose(f);
}

/* Blade A's M with a K file of the text (written to k_path) is refused with needle; *bad
 * stays as it was, so that the caller can check that no refused call made a handle. */
static void check_bad_k_file(udmap_error err, const char *m_path, const char *k_path,
                             const char *text, const char *needle, const char *name,
                             udmap_blade *bad) {
  write_file(k_path, text);
  int status =
      udmap_new_blade_matrices(err, m_path, k_path, NULL, 16, 39, NULL, NULL, 0.002, bad);
  check_error(err, status, needle, name);
}

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL, copy = NULL, bad = NULL;
  udmap_beam_params p = blade_a_beam_params();
  int status, ndof = 0, has_stress = 0;

  status = udmap_new_blade_beam(err, &p, &blade);
  check(status == UDMAP_OK && blade != NULL, "blade A builds");
  status = udmap_blade_get_size(err, blade, &ndof, &has_stress);
  check(status == UDMAP_OK && ndof == 64 && has_stress == 1, "blade A: 64 DOFs with stress");

  double f[3];
  status = udmap_blade_natural_frequencies(err, blade, 3, f);
  check(status == UDMAP_OK, "natural frequencies");
  check_close(f[0], 187.119057, 1e-7, "f1 = 187.119057 Hz");
  check(f[0] < f[1] && f[1] < f[2], "frequencies ascending");

  /* Receptances and the layer response with k = 1.3e4 + 2e3 i across the band. */
  enum { N = 9 };
  double fq[N], rec[10 * N], lay[6 * N];
  for (int i = 0; i < N; i++) fq[i] = 150.0 + 10.0 * i;
  status = udmap_blade_receptances(err, blade, N, fq, rec);
  check(status == UDMAP_OK, "receptances");
  status = udmap_blade_layer_response(err, blade, N, fq, 1.3e4, 2e3, lay);
  check(status == UDMAP_OK, "layer response");
  double worst = 0;
  for (int i = 0; i < N; i++) {
    const double *r = rec + 10 * i;
    double complex gE = r[0] + I * r[1], gg = r[2] + I * r[3], EE = r[4] + I * r[5];
    double complex sE = r[6] + I * r[7], sg = r[8] + I * r[9], k = 1.3e4 + 2e3 * I;
    double complex g = gE / (1 + k * gg), s = sE - k * sg * g, u = EE - k * gE * g;
    const double *l = lay + 6 * i;
    worst = fmax(worst, cabs(l[0] + I * l[1] - g) / cabs(g));
    worst = fmax(worst, cabs(l[2] + I * l[3] - s) / cabs(s));
    worst = fmax(worst, cabs(l[4] + I * l[5] - u) / cabs(u));
  }
  check(worst < 1e-13, "layer response = Sherman-Morrison of the receptances");
  /* |H_gE| near the resonance (190 Hz) exceeds that at 150 Hz. */
  check(cabs(rec[40] + I * rec[41]) > 10 * cabs(rec[0] + I * rec[1]), "|H_gE| grows towards the resonance");

  /* Export and import: the same receptances to 1e-12. */
  char dir[] = "/tmp/udmap_test_blade_api_XXXXXX";
  check(mkdtemp(dir) != NULL, "temporary directory");
  status = udmap_blade_export(err, blade, dir);
  check(status == UDMAP_OK, "export");
  char mpath[512], kpath[512], skpath[512], smpath[512];
  snprintf(mpath, sizeof mpath, "%s/M.mtx", dir);
  snprintf(kpath, sizeof kpath, "%s/K.mtx", dir);
  snprintf(skpath, sizeof skpath, "%s/stress_K.mtx", dir);
  snprintf(smpath, sizeof smpath, "%s/stress_M.mtx", dir);
  status = udmap_new_blade_matrices(err, mpath, kpath, NULL, 16, 39, skpath, smpath, 0.002, &copy);
  check(status == UDMAP_OK && copy != NULL, "import the export");
  double rec2[10 * N];
  status = udmap_blade_receptances(err, copy, N, fq, rec2);
  worst = 0;
  for (int i = 0; i < 10 * N; i += 2) {
    double complex a = rec[i] + I * rec[i + 1], b = rec2[i] + I * rec2[i + 1];
    worst = fmax(worst, cabs(a - b) / cabs(a));
  }
  check(status == UDMAP_OK && worst < 1e-12, "export/import: same receptances to 1e-12");
  /* Without stress rows: stress receptances are 0. */
  udmap_delete_blade(&copy);
  check(copy == NULL, "delete sets the handle to NULL");
  status = udmap_new_blade_matrices(err, mpath, kpath, NULL, 16, 39, NULL, NULL, 0.002, &copy);
  check(status == UDMAP_OK, "import without stress rows");
  udmap_blade_get_size(err, copy, &ndof, &has_stress);
  check(has_stress == 0, "no stress rows");
  udmap_blade_receptances(err, copy, 1, fq, rec2);
  check(rec2[6] == 0 && rec2[7] == 0 && rec2[8] == 0 && rec2[9] == 0, "stress receptances 0");
  udmap_delete_blade(&copy);

  /* Bad beam parameters: status 2, the field named, no handle. */
  p = blade_a_beam_params();
  p.neck_L = -0.02;
  status = udmap_new_blade_beam(err, &p, &bad);
  check_error(err, status, "blade.neck.L must be a positive finite number", "negative neck length");
  check(bad == NULL, "no handle after an error");
  p = blade_a_beam_params();
  p.E = NAN;
  status = udmap_new_blade_beam(err, &p, &bad);
  check_error(err, status, "blade.E", "NaN Young's modulus");
  p = blade_a_beam_params();
  p.airfoil_elements = 25;
  status = udmap_new_blade_beam(err, &p, &bad);
  check_error(err, status, "blade.airfoil.elements must be an even integer", "odd airfoil elements");
  p = blade_a_beam_params();
  p.zeta = -1;
  status = udmap_new_blade_beam(err, &p, &bad);
  check_error(err, status, "blade.zeta", "negative zeta");
  status = udmap_new_blade_beam(err, NULL, &bad);
  check_error(err, status, "'params' is a NULL handle", "NULL params");

  /* Bad files and indices. */
  status = udmap_new_blade_matrices(err, "/nonexistent/M.mtx", kpath, NULL, 16, 39, NULL, NULL,
                                    0.002, &bad);
  check_error(err, status, "'/nonexistent/M.mtx' not found", "missing M file");
  char badpath[512];
  snprintf(badpath, sizeof badpath, "%s/bad.mtx", dir);
  check_bad_k_file(err, mpath, badpath,
                   "%%MatrixMarket matrix coordinate real symmetric\n64 64 3\n1 1 1.0\n",
                   "line 3: file ends after 1 of 3 entries", "short K file", &bad);
  check_bad_k_file(err, mpath, badpath,
                   "%%MatrixMarket matrix coordinate real symmetric\n64 64 1\n65 1 1.0\n",
                   "index (65, 1) out of range", "index out of range", &bad);
  check_bad_k_file(err, mpath, badpath,
                   "%%MatrixMarket tensor coordinate real symmetric\n64 64 1\n1 1 1.0\n",
                   "bad banner", "bad banner", &bad);
  write_file(badpath, "%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 1\n2 1 1\n2 2 1\n");
  status = udmap_new_blade_matrices(err, badpath, badpath, NULL, 1, 2, NULL, NULL, 0.0, &bad);
  check_error(err, status, "is not symmetric", "non-symmetric matrix");
  status = udmap_new_blade_matrices(err, mpath, kpath, NULL, 65, 39, NULL, NULL, 0.002, &bad);
  check_error(err, status, "gamma_dof must be a DOF number from 1 to 64", "gamma_dof out of range");
  status = udmap_new_blade_matrices(err, mpath, NULL, NULL, 16, 39, NULL, NULL, 0.002, &bad);
  check_error(err, status, "'K_path' is a NULL handle", "NULL K path");
  check(bad == NULL, "still no handle");

  /* Bad arguments of the evaluations. */
  status = udmap_blade_natural_frequencies(err, blade, 0, f);
  check_error(err, status, "nmodes", "nmodes 0");
  double many[100];
  status = udmap_blade_natural_frequencies(err, blade, 100, many);
  check_error(err, status, "nmodes: the number of natural frequencies must be from 1 to 64",
              "nmodes 100");
  double neg[2] = {150.0, -1.0};
  status = udmap_blade_receptances(err, blade, 2, neg, rec);
  check_error(err, status, "f_hz[1] must be a non-negative finite frequency", "negative frequency");
  status = udmap_blade_layer_response(err, blade, 1, fq, NAN, 0.0, lay);
  check_error(err, status, "k_re + i k_im must be finite", "NaN damper stiffness");
  status = udmap_blade_receptances(err, NULL, 1, fq, rec);
  check_error(err, status, "'blade' is a NULL handle", "NULL blade");
  status = udmap_blade_export(err, blade, "/nonexistent/dir");
  check_error(err, status, "export directory '/nonexistent/dir' does not exist", "bad export dir");
  status = udmap_blade_get_size(err, blade, &ndof, &has_stress);
  check(status == UDMAP_OK && udmap_check_error(err) == UDMAP_OK, "a good call clears the error");

  /* Platform rows (PHYSICS.md 2.6): the beam's u_P = -w_P (w_P is DOF 15), v_P held; a set
   * replaces them, v_row NULL holds v_P; bad rows are refused and the old ones kept. */
  double u_row[64], v_row[64], row[64];
  int known = -1;
  status = udmap_blade_get_platform_rows(err, blade, 64, u_row, v_row, &known);
  int beam_ok = status == UDMAP_OK && known == 1 && u_row[14] == -1.0;
  for (int i = 0; i < 64; i++) beam_ok = beam_ok && v_row[i] == 0.0 && (i == 14 || u_row[i] == 0.0);
  check(beam_ok, "beam platform rows: u_P = -w_P, v_P held");
  for (int i = 0; i < 64; i++) row[i] = 0.5 * i;
  status = udmap_blade_set_platform_rows(err, blade, 64, row, NULL);
  udmap_blade_get_platform_rows(err, blade, 64, u_row, v_row, &known);
  check(status == UDMAP_OK && u_row[63] == 31.5 && v_row[63] == 0.0 && known == 1,
        "set platform rows, v_row NULL");
  status = udmap_blade_set_platform_rows(err, blade, 63, row, row);
  check_error(err, status, "ndof must be the blade's number of DOFs, 64, got 63", "rows: ndof");
  status = udmap_blade_set_platform_rows(err, blade, 64, NULL, row);
  check_error(err, status, "'u_row' is a NULL handle", "rows: NULL u_row");
  row[3] = NAN;
  status = udmap_blade_set_platform_rows(err, blade, 64, u_row, row);
  check_error(err, status, "v_row has a non-finite entry", "rows: NaN in v_row");
  for (int i = 0; i < 64; i++) row[i] = 0.0;
  status = udmap_blade_set_platform_rows(err, blade, 64, row, NULL);
  check_error(err, status, "u_row is zero", "rows: zero u_row");
  udmap_blade_get_platform_rows(err, blade, 64, u_row, v_row, &known);
  check(u_row[63] == 31.5, "rows kept after a refused set");

  udmap_delete_blade(&blade);
  udmap_delete_blade(&blade); /* NULL handle: nothing */
  udmap_delete_blade(NULL);
  udmap_delete_error(&err);

  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  if (system(cmd) != 0) printf("note: could not remove %s\n", dir);
  return check_finish();
}
