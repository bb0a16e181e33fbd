/* The standard-method section of the C API (wrappers/c/udmap.h): blade A with a rotational
 * Jenkins damper; the condensed and full variants give the same peak, the continued curve
 * peaks there, one AFT call reproduces the closed-form Jenkins describing function, the time
 * integration at the peak frequency agrees with the standard method converged in H, and NULL
 * handles or bad settings return status 2 with a message. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "udmap.h"

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_contact jen = NULL, bad = NULL;
  udmap_beam_params p = blade_a_beam_params();
  udmap_hbm_settings s, full;
  udmap_hbm_point pc, pf, p9;
  udmap_dti_settings ds;
  udmap_dti_point dp;
  double F = 5.0, f[4096], g1[4096], s1[4096], gm[4096], gmax_curve = 0.0;
  int status, n = 0, i;

  status = udmap_new_blade_beam(err, &p, &blade);
  check(status == UDMAP_OK, "blade A");
  status = udmap_new_contact_jenkins(err, 3000.0, 1.35, &jen);
  check(status == UDMAP_OK && jen != NULL, "jenkins contact");

  /* one AFT call: k = M_1/Gamma_1 of a Jenkins element (kt = 3000, a_s = 4.5e-4) */
  {
    double G[2] = {1e-3, 0.0}, M0, M[2], gmax, a_s = 1.35 / 3000.0, a = 1e-3;
    double b = acos(1.0 - 2.0 * a_s / a);
    status = udmap_contact_aft(err, jen, 1, 0.0, G, 0, &M0, M, &gmax);
    check(status == UDMAP_OK, "aft");
    check_close(M[0] / a, 3000.0 / M_PI * (b - sin(2.0 * b) / 2.0), 1e-12, "aft k_re");
    check_close(M[1] / a, 4.0 * 1.35 / (M_PI * a) * (1.0 - a_s / a), 1e-12, "aft k_im");
    check_close(gmax, a, 1e-14, "aft gamma_max");
  }

  udmap_hbm_defaults(&s);
  check(s.harmonics == 1 && s.variant == UDMAP_HBM_CONDENSED && s.aft_samples == 0, "defaults");
  full = s;
  full.variant = UDMAP_HBM_FULL;
  status = udmap_hbm_peaks(err, blade, jen, 150.0, 230.0, &s, 1, &F, &pc);
  check(status == UDMAP_OK, "condensed peak");
  status = udmap_hbm_peaks(err, blade, jen, 150.0, 230.0, &full, 1, &F, &pf);
  check(status == UDMAP_OK, "full peak");
  check_close(pf.gamma_P, pc.gamma_P, 1e-8, "full = condensed gamma_P");
  check_close(pf.f_res, pc.f_res, 1e-9, "full = condensed f_res");
  check_close(pf.sigma_a, pc.sigma_a, 1e-8, "full = condensed sigma_a");
  check(pc.npeaks == 1 && pc.harmonics == 1 && pc.gamma_h[0] == pc.gamma_P, "point fields");
  check(pc.steps > 0 && pc.iterations > 0 && pc.aft_calls > 0 && pc.seconds >= 0.0, "statistics");

  status = udmap_hbm_curve(err, blade, jen, 150.0, 230.0, &s, F, 4096, &n, f, g1, s1, gm);
  check(status == UDMAP_OK && n > 10 && n <= 4096, "curve");
  for (i = 0; i < n && i < 4096; i++)
    if (g1[i] > gmax_curve) gmax_curve = g1[i];
  check(fabs(f[0] - 150.0) < 1e-9 && fabs(f[n - 1] - 230.0) < 1e-9, "curve spans the band");
  check(gmax_curve <= pc.gamma_P * (1.0 + 1e-12) && gmax_curve > 0.99 * pc.gamma_P,
        "curve peaks at the refined peak");

  /* ground truth at the H = 1 peak frequency against H = 21 there (the 15th harmonic
   * excites the third mode, so lower H are not converged) */
  s.harmonics = 21;
  status = udmap_hbm_response(err, blade, jen, 150.0, pc.f_res, &s, 1, &F, &p9);
  check(status == UDMAP_OK, "H = 21 response");
  udmap_dti_defaults(&ds);
  ds.steps_per_period = 128;
  status = udmap_dti_response(err, blade, jen, &ds, pc.f_res, 1, &F, &dp);
  check(status == UDMAP_OK, "dti");
  /* N = 128 steps per period: Newmark error about 0.3 % */
  check_close(dp.gamma_1, p9.gamma_P, 5e-3, "dti gamma_1 vs H = 21");
  check_close(dp.sigma_1, p9.sigma_a, 5e-3, "dti sigma_1 vs H = 21");
  check(dp.ss_error < 1e-7 && dp.periods > 20 && dp.runs == 1, "dti steady state");

  /* errors */
  status = udmap_hbm_peaks(err, NULL, jen, 150.0, 230.0, &s, 1, &F, &pc);
  check_error(err, status, "blade", "NULL blade");
  status = udmap_hbm_peaks(err, blade, NULL, 150.0, 230.0, &s, 1, &F, &pc);
  check_error(err, status, "contact", "NULL contact");
  s.harmonics = 0;
  status = udmap_hbm_peaks(err, blade, jen, 150.0, 230.0, &s, 1, &F, &pc);
  check_error(err, status, "harmonics", "harmonics 0");
  status = udmap_new_contact_jenkins(err, 1.0, NAN, &bad);
  check_error(err, status, "M_slip", "NaN slip moment");
  check(bad == NULL, "no handle on error");
  ds.steps_per_period = 4;
  status = udmap_dti_response(err, blade, jen, &ds, 190.0, 1, &F, &dp);
  check_error(err, status, "steps_per_period", "too few steps");

  udmap_delete_contact(&jen);
  udmap_delete_contact(&jen);
  check(jen == NULL, "delete twice");
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  return check_finish();
}
