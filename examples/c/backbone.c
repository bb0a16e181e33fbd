/* Backbone of blade A with its asymmetric damper through the C API (udmap.h).
 * Build: cc backbone.c $(pkg-config --cflags --libs udmap) -o backbone   (or: make)
 * Prints F_lim and, per excitation force F_E, the resonance peak: gamma_P, f_res, sigma_a. */
#include <stdio.h>
#include "udmap.h"

/* Prints the error handle's message and returns the status. */
static int report(udmap_error error, int status, const char *what)
{
  char message[512];
  if (status == UDMAP_OK) return 0;
  udmap_get_error(error, message, (int)sizeof message);
  fprintf(stderr, "backbone: %s failed (status %d): %s\n", what, status, message);
  return status;
}

int main(void)
{
  /* blade A and its damper (cases/blade_a.json) */
  const udmap_beam_params beam = {
    .E = 170e9, .rho = 8200.0, .zeta = 0.002,
    .neck_L = 0.020, .neck_h = 0.008, .neck_b = 0.020,
    .platform_L = 0.010, .platform_m = 0.021, .platform_J = 1.4e-6,
    .airfoil_L = 0.120, .airfoil_h = 0.004, .airfoil_b = 0.030,
    .neck_elements = 8, .airfoil_elements = 24};
  const udmap_asymmetric_params damper_params = {
    .CF = 900.0, .mu = 0.3, .pitch = 0.026, .y_P = 0.006,
    .beta_L_deg = 45.0, .beta_R_deg = 45.0,
    .flat1_x = -6.724e-3, .flat1_y = -1.724e-3, .flat2_x = -1.068e-3, .flat2_y = 3.932e-3,
    .curved_x = 3.268e-3, .curved_y = 1.768e-3,
    .kn_flat = 60e6, .kt_flat = 40e6, .kn_curved = 80e6, .kt_curved = 50e6};
  const double forces[] = {1.0, 2.0, 5.0};
  enum { NFORCE = sizeof forces / sizeof forces[0] };

  udmap_error error = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_damper damper = NULL;
  udmap_model model = NULL;
  udmap_analysis analysis;
  udmap_point points[NFORCE];
  double F_lim = 0.0;
  int status;

  udmap_analysis_defaults(&analysis);
  analysis.f_min = 150.0;
  analysis.f_max = 230.0;

  if ((status = report(error, udmap_new_blade_beam(error, &beam, &blade), "blade"))) goto done;
  if ((status = report(error, udmap_new_damper_asymmetric(error, &damper_params, &damper),
                       "damper"))) goto done;
  if ((status = report(error, udmap_new_model(error, blade, damper, &analysis, &model),
                       "model"))) goto done;
  if ((status = report(error, udmap_model_limit_force(error, model, &F_lim), "F_lim")))
    goto done;
  if ((status = report(error, udmap_model_backbone(error, model, NFORCE, forces, points),
                       "backbone"))) goto done;

  const int v = udmap_get_version();
  printf("udmap %d.%d.%d, blade A\n", v / 10000, v / 100 % 100, v % 100);
  printf("F_lim = %.8e N\n", F_lim);
  printf("# F_E [N]  gamma_P [rad]  f_res [Hz]  sigma_a [Pa]\n");
  for (int i = 0; i < NFORCE; ++i)
    printf("%.8e %.8e %.8e %.8e\n", points[i].F_E, points[i].gamma_P, points[i].f_res,
           points[i].sigma_a);

done:
  udmap_delete_model(&model);
  udmap_delete_damper(&damper);
  udmap_delete_blade(&blade);
  udmap_delete_error(&error);
  return status;
}
