/* C API of the plausibility warnings: udmap_plausibility_warnings and udmap_model_warnings on
 * blade A (none) and blade A with its platform in grams and its contact stiffnesses in N/mm
 * (kinds, texts, the count beyond nmax, texts cut to len - 1), the model's results unchanged by
 * the check, and the argument errors. */
#include <string.h>

#include "check.h"
#include "udmap.h"

int main(void) {
  udmap_error err = udmap_new_error();
  udmap_blade blade = NULL, heavy = NULL;
  udmap_damper damper = NULL, soft = NULL;
  udmap_model model = NULL, soft_model = NULL;
  udmap_beam_params bp = blade_a_beam_params();
  udmap_asymmetric_params dp = blade_a_damper_params();
  udmap_analysis a;
  int kinds[4], n = -1;
  char texts[4 * UDMAP_WARNING_LEN];

  check(udmap_new_blade_beam(err, &bp, &blade) == UDMAP_OK, "blade A");
  check(udmap_new_damper_asymmetric(err, &dp, &damper) == UDMAP_OK, "damper A");
  udmap_analysis_defaults(&a);
  a.f_min = 150.0;
  a.f_max = 230.0;
  check(udmap_new_model(err, blade, damper, &a, &model) == UDMAP_OK, "model A");

  /* blade A: none, with or without the model */
  check(udmap_plausibility_warnings(err, blade, damper, 150.0, 230.0, 4, UDMAP_WARNING_LEN,
                                    kinds, texts, &n) == UDMAP_OK && n == 0, "A: none");
  check(udmap_model_warnings(err, model, 4, UDMAP_WARNING_LEN, kinds, texts, &n) == UDMAP_OK &&
        n == 0, "A with the model: none");

  /* the platform in grams, without a damper */
  bp.platform_m = 21.0;
  check(udmap_new_blade_beam(err, &bp, &heavy) == UDMAP_OK, "blade with m = 21 kg");
  check(udmap_plausibility_warnings(err, heavy, NULL, 150.0, 230.0, 4, UDMAP_WARNING_LEN,
                                    kinds, texts, &n) == UDMAP_OK && n == 1, "grams: one");
  check(kinds[0] == UDMAP_WARNING_PLATFORM_MASS, "grams: kind");
  check(strcmp(texts, "blade.platform.m = 21 kg is heavier than the rest of the blade (0.1443 "
                      "kg of neck and airfoil): was it given in grams? (21 g would be 0.021 "
                      "kg)") == 0, "grams: text");
  /* a short text buffer: cut to len - 1 characters, NUL-terminated */
  check(udmap_plausibility_warnings(err, heavy, NULL, 150.0, 230.0, 1, 18, kinds, texts, &n) ==
        UDMAP_OK && n == 1 && strcmp(texts, "blade.platform.m ") == 0, "grams: cut text");

  /* the stiffnesses in N/mm: gamma_b and the stuck shift; nmax = 1 still counts both */
  dp.kn_flat /= 1000;
  dp.kt_flat /= 1000;
  dp.kn_curved /= 1000;
  dp.kt_curved /= 1000;
  check(udmap_new_damper_asymmetric(err, &dp, &soft) == UDMAP_OK, "damper in N/mm");
  check(udmap_new_model(err, blade, soft, &a, &soft_model) == UDMAP_OK, "model in N/mm");
  double F = 2.0;
  udmap_point before, after;
  check(udmap_model_backbone(err, soft_model, 1, &F, &before) == UDMAP_OK, "backbone before");
  check(udmap_model_warnings(err, soft_model, 1, UDMAP_WARNING_LEN, kinds, texts, &n) ==
        UDMAP_OK && n == 2, "N/mm: two, one written");
  check(kinds[0] == UDMAP_WARNING_GAMMA_B_LARGE &&
        strstr(texts, "gamma_b = 0.5483 rad is above 0.01 rad") != NULL &&
        strstr(texts, "were the contact stiffnesses given in N/mm? (kn_flat = 6e+04 N/m") != NULL,
        "N/mm: gamma_b text");
  check(udmap_model_warnings(err, soft_model, 4, UDMAP_WARNING_LEN, kinds, texts, &n) ==
        UDMAP_OK && n == 2 && kinds[1] == UDMAP_WARNING_STUCK_SHIFT, "N/mm: the stuck shift");
  check(strcmp(texts + UDMAP_WARNING_LEN,
               "the stuck damper shifts the first frequency by 0.0137 % (187.1 Hz bare, 187.1 Hz "
               "stuck), outside 0.1 % to 100 %: are the contact stiffnesses or the blade in "
               "another unit?") == 0, "N/mm: shift text");
  check(udmap_model_backbone(err, soft_model, 1, &F, &after) == UDMAP_OK &&
        after.gamma_P == before.gamma_P && after.f_res == before.f_res &&
        after.sigma_a == before.sigma_a, "the backbone is the same after the check");

  /* argument errors name the argument */
  check_error(err, udmap_model_warnings(err, NULL, 4, UDMAP_WARNING_LEN, kinds, texts, &n),
              "model", "NULL model");
  check_error(err, udmap_plausibility_warnings(err, NULL, NULL, 1.0, 2.0, 0, 0, NULL, NULL, &n),
              "blade", "NULL blade");
  check_error(err, udmap_model_warnings(err, model, 4, UDMAP_WARNING_LEN, kinds, NULL, &n),
              "texts", "NULL texts");
  check_error(err, udmap_model_warnings(err, model, -1, UDMAP_WARNING_LEN, kinds, texts, &n),
              "nmax", "negative nmax");
  check_error(err, udmap_model_warnings(err, model, 0, 0, NULL, NULL, NULL), "'n'", "NULL n");
  check(udmap_model_warnings(err, model, 0, 0, NULL, NULL, &n) == UDMAP_OK && n == 0,
        "nmax = 0: only the count");

  udmap_delete_model(&soft_model);
  udmap_delete_model(&model);
  udmap_delete_damper(&soft);
  udmap_delete_damper(&damper);
  udmap_delete_blade(&heavy);
  udmap_delete_blade(&blade);
  udmap_delete_error(&err);
  return check_finish();
}
