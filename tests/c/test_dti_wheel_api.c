/* The whole wheel in time through the C API (wrappers/c/udmap.h, udmap_dti_wheel_*): blade A
 * with its asymmetric damper; in phase (EO = 0) the wheel is the single blade, a traveling
 * wave (N = 4, EO = 1: phi = pi/2) stays one (equal blades, phase step phi), and bad arguments
 * (one blade, a Jenkins contact, a NULL blade) return status 2 naming them. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "udmap.h"

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_contact asym = NULL, jen = NULL;
  udmap_beam_params p = blade_a_beam_params();
  udmap_asymmetric_params d = blade_a_damper_params();
  udmap_dti_settings ds;
  udmap_dti_point dp;
  udmap_dti_wheel_point wp;
  double F = 5.0;
  int status;

  status = udmap_new_blade_beam(err, &p, &blade);
  check(status == UDMAP_OK, "blade A");
  status = udmap_new_contact_asymmetric(err, &d, &asym);
  check(status == UDMAP_OK && asym != NULL, "asymmetric contact");
  status = udmap_new_contact_jenkins(err, 3000.0, 1.35, &jen);
  check(status == UDMAP_OK, "jenkins contact");
  udmap_dti_defaults(&ds);
  ds.steps_per_period = 64;
  ds.ss_tol = 1e-8;

  status = udmap_dti_response(err, blade, asym, &ds, 196.0, 1, &F, &dp);
  check(status == UDMAP_OK, "single blade");
  status = udmap_dti_wheel_response(err, blade, asym, &ds, 196.0, 2, 0, 1, &F, &wp);
  check(status == UDMAP_OK, "wheel EO = 0");
  check_close(wp.blade0.gamma_1, dp.gamma_1, 1e-9, "EO = 0: gamma_1 = single blade");
  check_close(wp.blade0.sigma_1, dp.sigma_1, 1e-9, "EO = 0: sigma_1 = single blade");
  check(wp.blades == 2 && wp.engine_order == 0 && wp.phi == 0.0, "EO = 0: N, EO, phi");
  check(wp.gamma_spread < 1e-10 && wp.phase_spread < 1e-10, "EO = 0: blades equal");

  F = 2.0;
  ds.ss_tol = 1e-7;
  status = udmap_dti_wheel_response(err, blade, asym, &ds, 197.5, 4, 1, 1, &F, &wp);
  check(status == UDMAP_OK, "wheel N = 4, EO = 1");
  check_close(wp.phi, M_PI / 2, 1e-15, "EO = 1: phi = pi/2");
  check(wp.gamma_spread < 1e-6 && wp.sigma_spread < 1e-6, "EO = 1: equal amplitudes");
  check(wp.phase_spread < 1e-6, "EO = 1: phase step pi/2");
  check(wp.blade0.runs == 1 && wp.blade0.periods > 20 && wp.blade0.gamma_1 > 0.0,
        "EO = 1: one run to a steady state");

  status = udmap_dti_wheel_response(err, blade, asym, &ds, 197.0, 1, 0, 1, &F, &wp);
  check_error(err, status, "blades", "one blade");
  status = udmap_dti_wheel_response(err, blade, jen, &ds, 197.0, 4, 1, 1, &F, &wp);
  check_error(err, status, "asymmetric", "jenkins contact");
  status = udmap_dti_wheel_peak(err, NULL, asym, &ds, 150.0, 230.0, 0.0, 4, 1, 1, &F, &wp);
  check_error(err, status, "blade", "NULL blade");

  udmap_delete_contact(&asym);
  udmap_delete_contact(&jen);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  return check_finish();
}
