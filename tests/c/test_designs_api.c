/* C API of many designs in one call (udmap_model_designs): blade A with three dampers, one of
 * them with lift-off and one jammed, against the single calls (udmap_new_damper_asymmetric,
 * udmap_model_set_damper, _limit_force, _limit_force_backbone, _backbone, _backbone_jumps,
 * _admissible_force) bit for bit; the stages computed only when asked; a design rescaled from
 * a reference tracing (CF times 1.5, contact stiffnesses times 2: PHYSICS.md 2.3) against its
 * own tracing; the traces counted; the statuses of bad calls; the plausibility warnings per
 * design (udmap_model_designs_warnings) against udmap_model_warnings. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "udmap.h"

#define N 3
#define NF 2

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL;
  udmap_damper d = NULL, own = NULL;
  udmap_model model = NULL;
  udmap_analysis an;
  udmap_point pts[NF];
  const udmap_beam_params bp = blade_a_beam_params();
  const double F[NF] = {2.0, 5.0};
  udmap_asymmetric_params p[N], ref[N];
  double F_lim[N], F_bb[N], gamma_b[N], M_max[N], M_min[N], F_adm[N];
  double gamma_P[N * NF], f_res[N * NF], sigma_a[N * NF];
  int lift_off[N], unb[N * NF], ok[N * NF], jump[N * NF], status[N], stage[N], jmp[NF];
  char message[N * 256];
  udmap_design_outputs out;
  int i, j, same = 1;

  for (i = 0; i < N; i++) p[i] = blade_a_damper_params();
  p[1].mu = 0.3639798354357481; /* lift-off, a jump of k near 1e-3 rad */
  p[1].CF = 1178.4721311181784;
  p[2].mu = 3.0; /* jams */
  memset(&out, 0, sizeof out);
  out.F_lim = F_lim;
  out.F_lim_backbone = F_bb;
  out.gamma_b = gamma_b;
  out.M_max = M_max;
  out.M_min = M_min;
  out.lift_off = lift_off;
  out.gamma_P = gamma_P;
  out.f_res = f_res;
  out.sigma_a = sigma_a;
  out.unbounded = unb;
  out.hcf_ok = ok;
  out.jump = jump;
  out.F_adm = F_adm;
  out.status = status;
  out.stage = stage;
  out.message = message;
  out.message_len = 256;

  check(udmap_new_blade_beam(err, &bp, &blade) == UDMAP_OK, "blade A");
  check(udmap_new_damper_jenkins(err, 1.0, 1e-3, &d) == UDMAP_OK, "jenkins");
  udmap_analysis_defaults(&an);
  an.f_min = 150.0;
  an.f_max = 230.0;
  check(udmap_new_model(err, blade, d, &an, &model) == UDMAP_OK, "model");
  check(udmap_model_designs(err, model, N, p, NULL, NF, F, 31, &out) == UDMAP_OK, "designs");
  check(out.traces == 3, "three tracings");
  check(status[0] == UDMAP_OK && status[1] == UDMAP_OK, "two designs computed");
  check(status[2] == UDMAP_EPHYSICS && stage[2] == UDMAP_DESIGN_FAILED_DAMPER &&
            strstr(message + 2 * 256, "jams") != NULL,
        "the jammed damper's failure recorded");
  check(lift_off[0] == 0 && lift_off[1] == 1, "lift-off flags");
  check(F_bb[1] < F_lim[1] && F_bb[0] == F_lim[0],
        "F_lim_backbone below F_lim with lift-off only");

  /* the same numbers from the single calls */
  for (i = 0; i < 2; i++) {
    double Fl = 0, Fb = 0, Fa = 0;
    udmap_damper_info info;
    check(udmap_new_damper_asymmetric(err, &p[i], &own) == UDMAP_OK, "damper");
    check(udmap_model_set_damper(err, model, own) == UDMAP_OK, "set damper");
    udmap_damper_get_info(err, own, &info);
    udmap_model_limit_force(err, model, &Fl);
    udmap_model_limit_force_backbone(err, model, &Fb);
    check(udmap_model_backbone(err, model, NF, F, pts) == UDMAP_OK, "backbone");
    udmap_model_backbone_jumps(err, model, NF, jmp);
    check(udmap_model_admissible_force(err, model, Fl < Fb ? Fl : Fb, 80e6, 1e-12, &Fa) ==
              UDMAP_OK, "F_adm");
    same = same && info.gamma_b == gamma_b[i] && info.M_max == M_max[i] &&
           info.M_min == M_min[i] && Fl == F_lim[i] && Fb == F_bb[i] && Fa == F_adm[i];
    for (j = 0; j < NF; j++)
      same = same && pts[j].gamma_P == gamma_P[i * NF + j] && pts[j].f_res == f_res[i * NF + j] &&
             pts[j].sigma_a == sigma_a[i * NF + j] && pts[j].hcf_ok == ok[i * NF + j] &&
             pts[j].unbounded == unb[i * NF + j] && jmp[j] == jump[i * NF + j];
    check(udmap_model_set_damper(err, model, d) == UDMAP_OK, "back to the jenkins damper");
    udmap_delete_damper(&own);
  }
  check(same, "one call per chunk = the single calls, bit for bit");

  /* only F_lim: no peaks, no F_adm written */
  for (i = 0; i < N * NF; i++) gamma_P[i] = -1;
  F_adm[0] = -1;
  check(udmap_model_designs(err, model, 1, p, NULL, NF, F, UDMAP_DESIGN_LIMIT, &out) == UDMAP_OK,
        "F_lim only");
  check(out.traces == 0, "the tracing is kept in the model");
  check(gamma_P[0] == -1 && F_adm[0] == -1 && F_lim[0] > 0, "only the stage asked for");

  /* a design rescaled from a reference: CF x 1.5, every contact stiffness x 2 */
  ref[0] = p[0];
  ref[1] = p[0];
  p[1] = p[0];
  p[1].CF *= 1.5;
  p[1].kn_flat *= 2;
  p[1].kt_flat *= 2;
  p[1].kn_curved *= 2;
  p[1].kt_curved *= 2;
  check(udmap_model_designs(err, model, 2, p, ref, NF, F, 31, &out) == UDMAP_OK, "rescaled");
  check(out.traces == 0 && status[1] == UDMAP_OK, "no new tracing");
  {
    double g1 = gamma_b[1], P1 = gamma_P[NF + 1], A1 = F_adm[1], L1 = F_lim[1];
    check(udmap_model_designs(err, model, 2, p, NULL, NF, F, 31, &out) == UDMAP_OK, "own");
    check(out.traces == 1, "its own tracing");
    check_close(g1, gamma_b[1], 1e-13, "gamma_b: CF/kappa");
    check_close(g1, 0.75 * gamma_b[0], 1e-13, "gamma_b = (1.5/2) gamma_b of the reference");
    check_close(L1, F_lim[1], 1e-13, "F_lim");
    check_close(P1, gamma_P[NF + 1], 1e-9, "gamma_P at 5 N");
    check_close(A1, F_adm[1], 1e-9, "F_adm");
  }
  ref[1].mu = 0.2;
  check(udmap_model_designs(err, model, 2, p, ref, NF, F, 31, &out) == UDMAP_OK, "bad ref");
  check(status[1] == UDMAP_EINPUT && strstr(message + 256, "common factor") != NULL,
        "a reference that differs in mu is refused for that design");

  out.status = NULL;
  check(udmap_model_designs(err, model, 1, p, NULL, NF, F, 31, &out) == UDMAP_EINPUT,
        "status array required");
  out.status = status;
  check(udmap_model_designs(err, model, 1, p, NULL, NF, F, 64, &out) == UDMAP_EINPUT,
        "unknown stage refused");
  check(udmap_model_designs(err, model, 1, NULL, ref, NF, F, 31, &out) == UDMAP_EINPUT,
        "reference without params refused");

  /* the plausibility warnings per design (udmap_model_designs_warnings) against
   * udmap_model_warnings on the model with each design's damper: blade A's own damper, its
   * stiffnesses in N/mm (x 1e-3: gamma_b large), and a jammed damper (-1) */
  {
    int kinds[N], wk[8], nw = 0, bits, k;
    char texts[8 * UDMAP_WARNING_LEN];
    p[0] = blade_a_damper_params();
    p[1] = p[0];
    p[1].kn_flat *= 1e-3;
    p[1].kt_flat *= 1e-3;
    p[1].kn_curved *= 1e-3;
    p[1].kt_curved *= 1e-3;
    p[2] = p[0];
    p[2].mu = 3.0;
    check(udmap_model_designs_warnings(err, model, N, p, NULL, NF, F, 31, &out, kinds) ==
              UDMAP_OK, "warnings");
    check(status[0] == UDMAP_OK && status[1] == UDMAP_OK && status[2] == UDMAP_EPHYSICS,
          "the designs' stages too");
    check(kinds[0] == 0, "blade A: no warning");
    check(kinds[1] & (1 << (UDMAP_WARNING_GAMMA_B_LARGE - 1)), "N/mm: gamma_b large");
    check(kinds[2] == -1, "the jammed damper: -1");
    for (i = 0; i < 2; i++) {
      check(udmap_new_damper_asymmetric(err, &p[i], &own) == UDMAP_OK, "damper");
      check(udmap_model_set_damper(err, model, own) == UDMAP_OK, "set damper");
      check(udmap_model_warnings(err, model, 8, UDMAP_WARNING_LEN, wk, texts, &nw) == UDMAP_OK,
            "model warnings");
      bits = 0;
      for (k = 0; k < nw; k++) bits |= 1 << (wk[k] - 1);
      check(bits == kinds[i], "the same kinds as udmap_model_warnings");
      check(udmap_model_set_damper(err, model, d) == UDMAP_OK, "back to the jenkins damper");
      udmap_delete_damper(&own);
    }
    check(udmap_model_designs_warnings(err, model, 1, p, NULL, NF, F, 31, &out, NULL) ==
              UDMAP_EINPUT, "kinds required");
  }

  udmap_delete_model(&model);
  udmap_delete_damper(&d);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  return check_finish();
}
