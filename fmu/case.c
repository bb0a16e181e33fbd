/* The case of an FMU made by `udmap fmu CASE`: resources/udmap-case.txt (case.h). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"

/* The directory of a resource location: a file URI (file:///p, file:/p, file://localhost/p,
 * percent-encoded) or a plain path; with a trailing '/'. */
static bool resource_dir(const char *location, char *out, size_t n) {
  const char *p = location;
  const bool uri = strncmp(location, "file:", 5) == 0;
  if (strncmp(p, "file://localhost/", 17) == 0) p += 16;
  else if (strncmp(p, "file:///", 8) == 0) p += 7;
  else if (strncmp(p, "file:/", 6) == 0) p += 5;
  size_t j = 0;
  for (; *p && j + 2 < n; p++) {
    if (uri && p[0] == '%' && isxdigit((unsigned char)p[1]) && isxdigit((unsigned char)p[2])) {
      char hex[3] = {p[1], p[2], 0};
      out[j++] = (char)strtol(hex, NULL, 16);
      p += 2;
    } else {
      out[j++] = *p;
    }
  }
  if (*p) return false;
  /* file:///C:/dir on Windows: the drive letter starts the path */
  if (uri && j >= 3 && out[0] == '/' && isalpha((unsigned char)out[1]) &&
      out[2] == ':') {
    memmove(out, out + 1, j - 1);
    j--;
  }
  if (j > 0 && out[j - 1] != '/' && out[j - 1] != '\\') out[j++] = '/';
  out[j] = '\0';
  return true;
}

static int variable_index(const char *name) {
  for (int i = 0; i < UDMAP_NVARS; i++)
    if (strcmp(udmap_variables[i].name, name) == 0) return i;
  return -1;
}

void case_free(CaseConfig *c) {
  if (!c) return;
  free(c->gamma);
  free(c->k_re);
  free(c->k_im);
  free(c);
}

static CaseConfig *fail(CaseConfig *c, FILE *f, char *msg, size_t n, const char *path, int line,
                        const char *why) {
  snprintf(msg, n, "%s, line %d: %s", path, line, why);
  if (f) fclose(f);
  case_free(c);
  return NULL;
}

CaseConfig *case_read(const char *resourceLocation, char *msg, size_t n) {
  msg[0] = '\0';
  char dir[CASE_PATH_MAX], path[CASE_PATH_MAX + 32];
  if (!resourceLocation || !resource_dir(resourceLocation, dir, sizeof dir)) return NULL;
  snprintf(path, sizeof path, "%s%s", dir, CASE_FILE);
  FILE *f = fopen(path, "r");
  if (!f) return NULL; /* the generic FMU */
  CaseConfig *c = calloc(1, sizeof *c);
  if (!c) return fail(c, f, msg, n, path, 0, "out of memory");
  udmap_analysis_defaults(&c->analysis);
  for (int i = 0; i < UDMAP_NVARS; i++) {
    c->start[i] = udmap_variables[i].start;
    c->present[i] = true;
  }
  char buf[CASE_PATH_MAX + 64], key[64], rest[CASE_PATH_MAX];
  int line = 0, rows = 0;
  while (fgets(buf, sizeof buf, f)) {
    line++;
    if (!strchr(buf, '\n') && !feof(f)) return fail(c, f, msg, n, path, line, "line too long");
    buf[strcspn(buf, "\r\n")] = '\0';
    if (rows < c->n) { /* a table row */
      if (sscanf(buf, "%lf %lf %lf", &c->gamma[rows], &c->k_re[rows], &c->k_im[rows]) != 3)
        return fail(c, f, msg, n, path, line, "a table row needs 'gamma k_re k_im'");
      rows++;
      continue;
    }
    rest[0] = '\0';
    if (buf[0] == '#' || sscanf(buf, "%63s %4095[^\n]", key, rest) < 1) continue;
    double x = strtod(rest, NULL);
    char *file = NULL;
    if (strcmp(key, "token") == 0) {
      if (strlen(rest) != 38) return fail(c, f, msg, n, path, line, "bad token");
      memcpy(c->token, rest, 39);
    } else if (strcmp(key, "blade") == 0) {
      if (strcmp(rest, "beam") == 0) c->blade = BLADE_BEAM;
      else if (strcmp(rest, "matrices") == 0) c->blade = BLADE_MATRICES;
      else return fail(c, f, msg, n, path, line, "blade must be 'beam' or 'matrices'");
    } else if (strcmp(key, "damper") == 0) {
      if (strcmp(rest, "asymmetric") == 0) c->damper = DAMPER_ASYMMETRIC;
      else if (strcmp(rest, "jenkins") == 0) c->damper = DAMPER_JENKINS;
      else if (strcmp(rest, "table") == 0) c->damper = DAMPER_TABLE;
      else return fail(c, f, msg, n, path, line, "unknown damper kind");
    } else if (strcmp(key, "M") == 0) file = c->M;
    else if (strcmp(key, "K") == 0) file = c->K;
    else if (strcmp(key, "C") == 0) file = c->C;
    else if (strcmp(key, "stress_K") == 0) file = c->stress_K;
    else if (strcmp(key, "stress_M") == 0) file = c->stress_M;
    else if (strcmp(key, "delta_M") == 0) c->has_delta_M = true, c->delta_M = x;
    /* the items that are case-file fields (fmu/parameters.h, from kernel/parameters.toml) */
#define CASE_ITEM(name, member, cast) else if (strcmp(key, name) == 0) c->member = cast x;
    UDMAP_CASE_ITEMS(CASE_ITEM)
#undef CASE_ITEM
    else if (strcmp(key, "table") == 0) {
      c->n = (int)x;
      if (c->n < 2 || c->n > 1000000 || c->gamma)
        return fail(c, f, msg, n, path, line, "a table needs 2 or more rows, once");
      c->gamma = malloc(c->n * sizeof(double));
      c->k_re = malloc(c->n * sizeof(double));
      c->k_im = malloc(c->n * sizeof(double));
      if (!c->gamma || !c->k_re || !c->k_im)
        return fail(c, f, msg, n, path, line, "out of memory");
    } else if (strcmp(key, "start") == 0 || strcmp(key, "absent") == 0) {
      char name[64];
      double value = 0.0;
      int got = sscanf(rest, "%63s %lf", name, &value);
      int i = got >= 1 ? variable_index(name) : -1;
      if (i < 0) return fail(c, f, msg, n, path, line, "unknown variable");
      if (key[0] == 'a') c->present[i] = false;
      else if (got == 2 && isfinite(value)) c->start[i] = value;
      else return fail(c, f, msg, n, path, line, "start needs a finite value");
    } else {
      return fail(c, f, msg, n, path, line, "unknown item");
    }
    if (file) snprintf(file, CASE_PATH_MAX, "%s%s", dir, rest);
  }
  fclose(f);
  if (rows < c->n) return fail(c, NULL, msg, n, path, line, "the table ends early");
  if (!c->token[0]) return fail(c, NULL, msg, n, path, line, "no token");
  if (c->blade == BLADE_MATRICES && (!c->M[0] || !c->K[0] || c->gamma_dof < 1 || c->exc_dof < 1))
    return fail(c, NULL, msg, n, path, line, "a matrices blade needs M, K, gamma_dof, exc_dof");
  if (c->damper == DAMPER_TABLE && !c->gamma)
    return fail(c, NULL, msg, n, path, line, "a table damper needs its table");
  return c;
}
