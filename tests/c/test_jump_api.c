/* C API of the jumps of k(gamma) (PHYSICS.md 2.5) and of F_lim_backbone (PHYSICS.md 5), the
 * functions an FMU or another C caller uses: blade A with mu = 0.3639798354357481,
 * CF = 1178.4721311181784, whose k jumps at gamma_c = 1.0335e-3 rad. The one-sided values
 * against udmap_damper_stiffness at and just above gamma_c, the jump flags of the backbone at
 * 3.5 (inside the jump) and 4.5 N (above it), gamma_P = gamma_c there, F_lim_backbone below
 * F_lim with lift-off and equal to it for blade A, and the statuses of bad calls. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "udmap.h"

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_damper d = NULL, a = NULL;
  udmap_blade blade = NULL;
  udmap_model model = NULL;
  udmap_analysis an;
  udmap_point pts[2];
  int n = -1, jump[2] = {-1, -1};
  double gamma_c = 0, km[2], kp[2], kr[2], ki[2], g[2], F_lim = 0, F_bb = 0;
  const udmap_asymmetric_params pa = blade_a_damper_params();
  udmap_asymmetric_params p = pa;
  const udmap_beam_params bp = blade_a_beam_params();
  const double F[2] = {3.5, 4.5};

  p.mu = 0.3639798354357481;
  p.CF = 1178.4721311181784;
  check(udmap_new_damper_asymmetric(err, &p, &d) == UDMAP_OK, "create lift-off damper");
  check(udmap_damper_jump_count(err, d, &n) == UDMAP_OK && n == 1, "one jump");
  check(udmap_damper_jump_get(err, d, 0, &gamma_c, km, kp) == UDMAP_OK, "get jump 0");
  check(fabs(gamma_c / 1.0335e-3 - 1) < 1e-4, "gamma_c");
  g[0] = gamma_c;
  g[1] = gamma_c * (1 + 1e-12);
  udmap_damper_stiffness(err, d, 2, g, kr, ki);
  check(fabs(kr[0] - km[0]) < 1e-9 * fabs(km[0]) && fabs(ki[0] - km[1]) < 1e-9 * fabs(km[1]),
        "k(gamma_c) is the value below");
  check(fabs(kr[1] - kp[0]) < 1e-6 * fabs(kp[0]) && fabs(ki[1] - kp[1]) < 1e-6 * fabs(kp[1]),
        "k just above gamma_c is the value above");
  check(fabs(kp[1] - km[1]) > 0.3 * km[1], "k_im jumps");
  check(udmap_damper_jump_get(err, d, 1, &g[0], kr, ki) == UDMAP_EINPUT, "index 1 refused");
  check(udmap_damper_jump_get(err, d, -1, &g[0], kr, ki) == UDMAP_EINPUT, "index -1 refused");

  check(udmap_new_blade_beam(err, &bp, &blade) == UDMAP_OK, "blade A");
  udmap_analysis_defaults(&an);
  an.f_min = 150.0;
  an.f_max = 230.0;
  check(udmap_new_model(err, blade, d, &an, &model) == UDMAP_OK, "model");
  check(udmap_model_backbone_jumps(err, model, 2, jump) == UDMAP_EINPUT, "jumps before backbone");
  check(udmap_model_backbone(err, model, 2, F, pts) == UDMAP_OK, "backbone");
  check(udmap_model_backbone_jumps(err, model, 2, jump) == UDMAP_OK, "jumps");
  check(jump[0] == 1 && jump[1] == 0, "3.5 N in the jump, 4.5 N above");
  check(pts[0].gamma_P == gamma_c && pts[1].gamma_P > gamma_c, "gamma_P at and above gamma_c");
  check(udmap_model_backbone_jumps(err, model, 3, jump) == UDMAP_EINPUT, "wrong count refused");
  check(udmap_model_limit_force(err, model, &F_lim) == UDMAP_OK, "F_lim");
  check(udmap_model_limit_force_backbone(err, model, &F_bb) == UDMAP_OK, "F_lim_backbone");
  check(F_bb > 0.5 * F_lim && F_bb < F_lim, "F_lim_backbone below F_lim with lift-off");

  /* blade A's own damper: no jump, F_lim_backbone = F_lim */
  check(udmap_new_damper_asymmetric(err, &pa, &a) == UDMAP_OK, "blade A damper");
  check(udmap_damper_jump_count(err, a, &n) == UDMAP_OK && n == 0, "no jump");
  check(udmap_model_set_damper(err, model, a) == UDMAP_OK, "set damper");
  udmap_model_limit_force(err, model, &F_lim);
  udmap_model_limit_force_backbone(err, model, &F_bb);
  check(F_bb == F_lim, "F_lim_backbone = F_lim without lift-off");
  check(udmap_damper_jump_count(err, NULL, &n) == UDMAP_EINPUT, "NULL damper");

  udmap_delete_model(&model);
  udmap_delete_damper(&d);
  udmap_delete_damper(&a);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  return check_finish();
}
