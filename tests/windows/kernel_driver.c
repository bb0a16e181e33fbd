/* The kernel library loaded by path, as the Python package loads it: udmap.dll from the
 * unpacked Windows wheel under Wine, or libudmap.so natively (tests/package/test_wheels.py).
 *
 *   udmap-kernel-driver LIBRARY
 *
 * Prints blade A's F_lim and its backbone at H = 1, 3 and 9 (the C API over udmap.h's types,
 * each function looked up by name) as IEEE-754 bit patterns, one number per line, so that the
 * two sides can be compared to the last bit or to a relative tolerance. */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
#include "udmap.h"
#ifdef _WIN32
#include <windows.h>
#define OPEN(path) ((void *)LoadLibraryA(path))
#define SYMBOL(h, name) ((void *)GetProcAddress((HMODULE)(h), name))
#else
#include <dlfcn.h>
#define OPEN(path) dlopen(path, RTLD_NOW | RTLD_LOCAL)
#define SYMBOL(h, name) dlsym(h, name)
#endif

/* p_<name>: the library's <name>, with the type that udmap.h declares for it */
#define LOAD(name)                                                                          \
  __typeof__(&name) p_##name = (__typeof__(&name))SYMBOL(lib, #name);                       \
  if (!p_##name) { fprintf(stderr, "kernel_driver: %s not exported\n", #name); return 2; }

static void print_bits(const char *what, double x)
{
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  printf("%s %016" PRIx64 " %.17g\n", what, u, x);
}

int main(int argc, char **argv)
{
  if (argc != 2) { fprintf(stderr, "usage: kernel_driver LIBRARY\n"); return 2; }
  void *lib = OPEN(argv[1]);
  if (!lib) { fprintf(stderr, "kernel_driver: cannot load %s\n", argv[1]); return 2; }
  LOAD(udmap_new_error) LOAD(udmap_get_error) LOAD(udmap_delete_error)
  LOAD(udmap_new_blade_beam) LOAD(udmap_delete_blade)
  LOAD(udmap_new_damper_asymmetric) LOAD(udmap_delete_damper)
  LOAD(udmap_analysis_defaults) LOAD(udmap_new_model) LOAD(udmap_delete_model)
  LOAD(udmap_model_limit_force) LOAD(udmap_model_set_harmonics) LOAD(udmap_model_backbone)

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
  const double forces[] = {0.5, 1.0, 2.0, 5.0, 10.0, 15.0, 20.0};
  enum { NFORCE = sizeof forces / sizeof forces[0] };
  const int harmonics[] = {1, 3, 9};

  udmap_error error = p_udmap_new_error();
  udmap_blade blade = NULL;
  udmap_damper damper = NULL;
  udmap_model model = NULL;
  udmap_analysis analysis;
  udmap_point points[NFORCE];
  double F_lim = 0.0;
  int status;
  p_udmap_analysis_defaults(&analysis);
  analysis.f_min = 150.0;
  analysis.f_max = 230.0;
  if ((status = p_udmap_new_blade_beam(error, &beam, &blade))) goto done;
  if ((status = p_udmap_new_damper_asymmetric(error, &damper_params, &damper))) goto done;
  if ((status = p_udmap_new_model(error, blade, damper, &analysis, &model))) goto done;
  if ((status = p_udmap_model_limit_force(error, model, &F_lim))) goto done;
  print_bits("F_lim", F_lim);
  for (int k = 0; k < 3; ++k) {
    if ((status = p_udmap_model_set_harmonics(error, model, harmonics[k], analysis.harmonic_tol))) goto done;
    if ((status = p_udmap_model_backbone(error, model, NFORCE, forces, points))) goto done;
    for (int i = 0; i < NFORCE; ++i) {
      char what[64];
      snprintf(what, sizeof what, "H%d_F%g_gamma_P", harmonics[k], forces[i]);
      print_bits(what, points[i].gamma_P);
      snprintf(what, sizeof what, "H%d_F%g_f_res", harmonics[k], forces[i]);
      print_bits(what, points[i].f_res);
      snprintf(what, sizeof what, "H%d_F%g_sigma_a", harmonics[k], forces[i]);
      print_bits(what, points[i].sigma_a);
    }
  }
done:
  if (status) {
    char message[512];
    p_udmap_get_error(error, message, (int)sizeof message);
    fprintf(stderr, "kernel_driver: status %d: %s\n", status, message);
  }
  p_udmap_delete_model(&model);
  p_udmap_delete_damper(&damper);
  p_udmap_delete_blade(&blade);
  p_udmap_delete_error(&error);
  return status;
}
