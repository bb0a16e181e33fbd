/* C API of the damper section: blade_a numbers, k(gamma), dk, loop, set_CF, errors. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "udmap.h"

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_damper d = NULL, j = NULL, t = NULL;
  udmap_damper_info info;
  char msg[512];
  const udmap_asymmetric_params p = blade_a_damper_params();

  check(udmap_new_damper_asymmetric(err, &p, &d) == UDMAP_OK && d != NULL, "create blade_a");
  check(udmap_damper_get_info(err, d, &info) == UDMAP_OK, "get info");
  check(fabs(info.M_max - 6.44037) <= 1e-5 && fabs(info.M_min + 6.44037) <= 1e-5, "plateaus");
  check(close_to(info.gamma_b, 5.4829e-4, 1e-4), "gamma_b");
  check(close_to(info.k_stuck, 12811.12, 1e-6), "k_stuck");
  check(info.lift_off == 0, "no lift-off");

  double g[4] = {1e-12, 0.5 * info.gamma_b, 3 * info.gamma_b, 1.0}, kr[4], ki[4], dr[4], di[4];
  check(udmap_damper_stiffness(err, d, 4, g, kr, ki) == UDMAP_OK, "stiffness");
  check(close_to(kr[0], info.k_stuck, 1e-14) && ki[0] == 0, "stuck limit");
  check(ki[2] > 0 && kr[2] > 0 && kr[2] < info.k_stuck, "slipping");
  check(udmap_damper_stiffness_derivative(err, d, 4, g, dr, di) == UDMAP_OK, "derivative");
  check(dr[2] < 0, "k_re decreases above gamma_b");

  enum { N = 256 };
  double tau[N], M[N];
  check(udmap_damper_loop(err, d, 3 * info.gamma_b, N, tau, M) == UDMAP_OK, "loop");
  double mx = -1e300, mn = 1e300;
  for (int i = 0; i < N; i++) {
    mx = M[i] > mx ? M[i] : mx;
    mn = M[i] < mn ? M[i] : mn;
  }
  check(close_to(mx, info.M_max, 1e-12) && close_to(mn, info.M_min, 1e-12), "loop plateaus");
  check(tau[0] == 0.0 && close_to(tau[1], 2 * M_PI / N, 1e-14), "tau spacing");

  /* CF scaling law: k(gamma; 2 CF) = k(gamma/2; CF). */
  double g2 = 1.2 * info.gamma_b, k1r, k1i, k2r, k2i;
  udmap_damper_stiffness(err, d, 1, &g2, &k1r, &k1i);
  check(udmap_damper_set_CF(err, d, 1800.0) == UDMAP_OK, "set_CF");
  double g3 = 2 * g2;
  udmap_damper_stiffness(err, d, 1, &g3, &k2r, &k2i);
  check(close_to(k2r, k1r, 1e-12) && close_to(k2i, k1i, 1e-12), "CF scaling");
  udmap_damper_get_info(err, d, &info);
  check(close_to(info.M_max, 2 * 6.44036697, 1e-8), "M_max scales with CF");

  /* Errors: status and a message naming the argument. */
  double bad = -1.0;
  check(udmap_damper_stiffness(err, d, 1, &bad, kr, ki) == UDMAP_EINPUT, "negative gamma");
  udmap_get_error(err, msg, sizeof msg);
  check(strstr(msg, "gamma[0]") != NULL, "message names gamma[0]");
  check(udmap_damper_set_CF(err, d, NAN) == UDMAP_EINPUT, "NaN CF");
  udmap_asymmetric_params q = p;
  q.kt_curved = NAN;
  udmap_damper e = NULL;
  check(udmap_new_damper_asymmetric(err, &q, &e) == UDMAP_EINPUT && e == NULL, "NaN kt_curved");
  udmap_get_error(err, msg, sizeof msg);
  check(strstr(msg, "kt_curved") != NULL, "message names kt_curved");
  q = p;
  q.mu = 5.0;
  check(udmap_new_damper_asymmetric(err, &q, &e) == UDMAP_EPHYSICS && e == NULL, "jammed damper");
  check(udmap_damper_get_info(err, NULL, &info) == UDMAP_EINPUT, "NULL handle");

  /* Jenkins: the values of PHYSICS.md 2.4. */
  check(udmap_new_damper_jenkins(err, 2.0, 3.0, &j) == UDMAP_OK, "jenkins");
  double a[3] = {1.6, 2.0, 5.0}, er[3] = {1.947954, 1.608998, 0.504632}, ei[3] = {0.149208, 0.477465, 0.534761};
  udmap_damper_stiffness(err, j, 3, a, kr, ki);
  for (int i = 0; i < 3; i++) check(fabs(kr[i] - er[i]) <= 1e-6 && fabs(ki[i] - ei[i]) <= 1e-6, "jenkins values");
  check(udmap_damper_set_CF(err, j, 100.0) == UDMAP_EINPUT, "jenkins has no CF");

  /* Table without delta_M: amplitudes beyond the last row are refused. */
  double tg[3] = {1e-4, 1e-3, 1e-2}, tr[3] = {100, 80, 30}, ti[3] = {0, 10, 20};
  check(udmap_new_damper_table(err, 3, tg, tr, ti, 0, 0.0, &t) == UDMAP_OK, "table");
  double in = 5e-3, out = 2e-2;
  check(udmap_damper_stiffness(err, t, 1, &in, kr, ki) == UDMAP_OK, "table inside");
  check(udmap_damper_stiffness(err, t, 1, &out, kr, ki) == UDMAP_EINPUT, "table beyond last row");
  check(udmap_damper_loop(err, t, 1e-3, N, tau, M) == UDMAP_EINPUT, "table has no loop");

  udmap_delete_damper(&d);
  udmap_delete_damper(&j);
  udmap_delete_damper(&t);
  udmap_delete_damper(&t); /* NULL is fine */
  check(d == NULL && t == NULL, "delete sets NULL");
  udmap_delete_error(&err);
  return check_finish();
}
