/*
 * Build-time generator: writes the FMI 2.0 and FMI 3.0 modelDescription.xml and the
 * documentation page from the variable table (variables.h), so that the descriptions, the
 * documentation and the binaries cannot disagree.
 *
 *   udmap-describe fmi2|fmi3|html OUTPUT
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config.h"

static const char *type_name3[] = {"Float64", "Int32", "Boolean"};
static const char *type_name2[] = {"Real", "Integer", "Boolean"};
static const char *causality_name[] = {"independent", "input", "parameter", "output"};

typedef struct {
  const char *name;
  int kg, m, s, rad;
  double factor;
  const char *description;
} UnitInfo;

static const UnitInfo units[] = {
#define UDMAP_X_UNIT(name, kg, m, s, rad, factor, desc) {name, kg, m, s, rad, factor, desc},
  UDMAP_UNITS(UDMAP_X_UNIT)
#undef UDMAP_X_UNIT
};

/* Shortest decimal that reads back as the same double. */
static const char *num(double x, char *buf);

/* A value of variable v as its XML type demands (xs:int for integers). */
static const char *value_text(const VariableInfo *v, double x, char *buf) {
  if (v->type == INTEGER) {
    snprintf(buf, 32, "%d", (int)x);
    return buf;
  }
  return num(x, buf);
}

static const char *num(double x, char *buf) {
  for (int prec = 1; prec <= 17; prec++) {
    snprintf(buf, 32, "%.*g", prec, x);
    if (strtod(buf, NULL) == x) break;
  }
  return buf;
}

/* Writes s with the XML special characters escaped. */
static void esc(FILE *f, const char *s) {
  for (; *s; s++) {
    switch (*s) {
      case '&': fputs("&amp;", f); break;
      case '<': fputs("&lt;", f); break;
      case '>': fputs("&gt;", f); break;
      case '"': fputs("&quot;", f); break;
      default: fputc(*s, f);
    }
  }
}

static int unit_known(const char *name) {
  for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
    if (strcmp(units[i].name, name) == 0) return 1;
  return 0;
}

static const char *variability(const VariableInfo *v) {
  if (v->causality == PARAMETER) return "tunable";
  return v->type == REAL ? "continuous" : "discrete";
}

/* Whether output `out` depends on input `in` (the ModelStructure dependencies). */
static int depends(const VariableInfo *out, const VariableInfo *in) {
  if (in->causality != INPUT) return 0;
  switch (out->group) {
    case GROUP_POINT: return 1;
    case GROUP_LIMIT: return in->group == GROUP_CF || in->group == GROUP_DAMPER;
    case GROUP_RATIO:
      return in->group == GROUP_CF || in->group == GROUP_DAMPER ||
             strcmp(in->name, "F_E") == 0;
    default: return 0;
  }
}

/* The dependencies and dependenciesKind attributes of output v: the inputs it depends on, by
 * index (FMI 2, offset 1) or value reference (FMI 3, offset 0). The outputs are non-linear
 * algebraic functions of the inputs: kind "dependent". */
static void write_dependencies(FILE *f, const VariableInfo *v, int offset) {
  const char *sep = "";
  fputs(" dependencies=\"", f);
  for (int j = 0; j < UDMAP_NVARS; j++) {
    if (!depends(v, &udmap_variables[j])) continue;
    fprintf(f, "%s%d", sep, j + offset);
    sep = " ";
  }
  fputs("\" dependenciesKind=\"", f);
  sep = "";
  for (int j = 0; j < UDMAP_NVARS; j++) {
    if (!depends(v, &udmap_variables[j])) continue;
    fprintf(f, "%sdependent", sep);
    sep = " ";
  }
  fputs("\"", f);
}

/* One element per output, opened by `open` (printf with its index or value reference, which
 * is the table position plus offset), with its dependencies if asked. */
static void write_outputs(FILE *f, const char *open, int offset, bool dependencies) {
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    if (v->causality != OUTPUT) continue;
    fprintf(f, open, i + offset);
    if (dependencies) write_dependencies(f, v, offset);
    fputs("/>\n", f);
  }
}

static void write_units(FILE *f) {
  fputs("  <UnitDefinitions>\n", f);
  for (size_t i = 0; i < sizeof units / sizeof units[0]; i++) {
    const UnitInfo *u = &units[i];
    char b[32];
    fprintf(f, "    <Unit name=\"");
    esc(f, u->name);
    fputs("\">\n      <BaseUnit", f);
    if (u->kg) fprintf(f, " kg=\"%d\"", u->kg);
    if (u->m) fprintf(f, " m=\"%d\"", u->m);
    if (u->s) fprintf(f, " s=\"%d\"", u->s);
    if (u->rad) fprintf(f, " rad=\"%d\"", u->rad);
    if (u->factor != 1.0) fprintf(f, " factor=\"%s\"", num(u->factor, b));
    fputs("/>\n    </Unit>\n", f);
  }
  fputs("  </UnitDefinitions>\n", f);
}

static void write_log_categories(FILE *f);

/* What both versions write between the interfaces and the variables. */
static void write_units_to_variables(FILE *f) {
  write_units(f);
  write_log_categories(f);
  fputs("  <DefaultExperiment startTime=\"0\" stopTime=\"1\" stepSize=\"0.1\"/>\n", f);
  fputs("  <ModelVariables>\n", f);
}

static void write_log_categories(FILE *f) {
  fputs("  <LogCategories>\n"
        "    <Category name=\"logStatusWarning\" description=\"Warnings (e.g. an unbounded "
        "response; plausibility: a value that looks typed in another unit)\"/>\n"
        "    <Category name=\"logStatusDiscard\" description=\"Rejected values\"/>\n"
        "    <Category name=\"logStatusError\" description=\"Errors (bad inputs, physics "
        "failures, calls in the wrong state)\"/>\n"
        "    <Category name=\"logEvents\" description=\"Rebuilds of the blade, damper and "
        "model\"/>\n"
        "    <Category name=\"logCalls\" description=\"Every FMI call\"/>\n"
        "  </LogCategories>\n", f);
}

/* The attributes shared by the FMI 2 type element and the FMI 3 variable element. */
static void write_type_attributes(FILE *f, const VariableInfo *v) {
  char b[32];
  if (v->unit[0]) {
    fputs(" unit=\"", f);
    esc(f, v->unit);
    fputs("\"", f);
  }
  if (v->type != BOOLEAN && v->min > -NOLIMIT) fprintf(f, " min=\"%s\"", value_text(v, v->min, b));
  if (v->type != BOOLEAN && v->max < NOLIMIT) fprintf(f, " max=\"%s\"", value_text(v, v->max, b));
  if (v->causality == INPUT || v->causality == PARAMETER) {
    if (v->type == BOOLEAN) fprintf(f, " start=\"%s\"", v->start != 0.0 ? "true" : "false");
    else fprintf(f, " start=\"%s\"", value_text(v, v->start, b));
  }
}

static void write_header(FILE *f, const char *version, const char *token_attr) {
  char token[64];
  udmap_fmu_token(token, sizeof token);
  fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<!-- Generated by udmap-describe from fmu/variables.h: do not edit. -->\n"
             "<fmiModelDescription\n"
             "  fmiVersion=\"%s\"\n"
             "  modelName=\"%s\"\n"
             "  %s=\"%s\"\n"
             "  description=\"", version, MODEL_NAME, token_attr, token);
  esc(f, MODEL_DESCRIPTION);
  fprintf(f, "\"\n"
             "  generationTool=\"udmap %s\"\n"
             "  version=\"%s\"\n"
             "  copyright=\"udmap authors\"\n"
             "  variableNamingConvention=\"flat\"%s>\n",
          UDMAP_FMU_VERSION, UDMAP_FMU_VERSION,
          strcmp(version, "2.0") == 0 ? "\n  numberOfEventIndicators=\"0\"" : "");
}

static void write_fmi2(FILE *f) {
  write_header(f, "2.0", "guid");
  static const char *const common =
      "    canNotUseMemoryManagementFunctions=\"true\"\n"
      "    canGetAndSetFMUstate=\"true\"\n"
      "    canSerializeFMUstate=\"true\"\n"
      "    providesDirectionalDerivative=\"true\"";
  fprintf(f, "  <ModelExchange\n"
             "    modelIdentifier=\"%s\"\n"
             "    completedIntegratorStepNotNeeded=\"true\"\n%s/>\n", MODEL_IDENTIFIER, common);
  fprintf(f, "  <CoSimulation\n"
             "    modelIdentifier=\"%s\"\n"
             "    canHandleVariableCommunicationStepSize=\"true\"\n%s/>\n", MODEL_IDENTIFIER,
          common);
  write_units_to_variables(f);
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    fprintf(f, "    <!-- index %d -->\n    <ScalarVariable name=\"%s\" valueReference=\"%d\" "
               "description=\"", i + 1, v->name, i);
    esc(f, v->description);
    fprintf(f, "\" causality=\"%s\" variability=\"%s\"", causality_name[v->causality],
            variability(v));
    if (v->causality == PARAMETER) fputs(" initial=\"exact\"", f);
    if (v->causality == OUTPUT) fputs(" initial=\"calculated\"", f);
    fprintf(f, ">\n      <%s", type_name2[v->type]);
    write_type_attributes(f, v);
    fputs("/>\n    </ScalarVariable>\n", f);
  }
  fputs("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n", f);
  write_outputs(f, "      <Unknown index=\"%d\"", 1, true);
  fputs("    </Outputs>\n    <InitialUnknowns>\n", f);
  write_outputs(f, "      <Unknown index=\"%d\"", 1, false);
  fputs("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n", f);
}

static void write_fmi3(FILE *f) {
  write_header(f, "3.0", "instantiationToken");
  static const char *const common =
      "    canGetAndSetFMUState=\"true\"\n"
      "    canSerializeFMUState=\"true\"\n"
      "    providesDirectionalDerivatives=\"true\"";
  fprintf(f, "  <ModelExchange\n"
             "    modelIdentifier=\"%s\"\n"
             "    needsCompletedIntegratorStep=\"false\"\n%s/>\n", MODEL_IDENTIFIER, common);
  fprintf(f, "  <CoSimulation\n"
             "    modelIdentifier=\"%s\"\n"
             "    canHandleVariableCommunicationStepSize=\"true\"\n%s\n"
             "    hasEventMode=\"false\"\n"
             "    providesIntermediateUpdate=\"false\"/>\n", MODEL_IDENTIFIER, common);
  write_units_to_variables(f);
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    fprintf(f, "    <%s name=\"%s\" valueReference=\"%d\" description=\"", type_name3[v->type],
            v->name, i);
    esc(f, v->description);
    fprintf(f, "\" causality=\"%s\" variability=\"%s\"", causality_name[v->causality],
            variability(v));
    write_type_attributes(f, v);
    fputs("/>\n", f);
  }
  fputs("  </ModelVariables>\n  <ModelStructure>\n", f);
  write_outputs(f, "    <Output valueReference=\"%d\"", 0, true);
  write_outputs(f, "    <InitialUnknown valueReference=\"%d\"", 0, false);
  fputs("  </ModelStructure>\n</fmiModelDescription>\n", f);
}

static void html_table(FILE *f, Causality causality, const char *title) {
  char b[32];
  fprintf(f, "<h2>%s</h2>\n<table>\n<tr><th>name</th><th>value reference</th><th>type</th>"
             "<th>unit</th><th>start</th><th>range</th><th>description</th></tr>\n", title);
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    if (v->causality != causality) continue;
    fprintf(f, "<tr><td><code>%s</code></td><td>%d</td><td>%s / %s</td><td>", v->name, i,
            type_name2[v->type], type_name3[v->type]);
    esc(f, v->unit[0] ? v->unit : "1");
    fputs("</td><td>", f);
    if (causality == INPUT || causality == PARAMETER) fputs(value_text(v, v->start, b), f);
    fputs("</td><td>", f);
    if (v->type != BOOLEAN && (v->min > -NOLIMIT || v->max < NOLIMIT)) {
      fputs(v->min > -NOLIMIT ? value_text(v, v->min, b) : "-inf", f);
      fputs(v->flags & (POSITIVE | OPEN) ? " &lt; x" : " &le; x", f);
      if (v->max < NOLIMIT)
        fprintf(f, " %s %s", v->flags & OPEN ? "&lt;" : "&le;", value_text(v, v->max, b));
      if (v->flags & EVEN) fputs(", even", f);
    }
    fputs("</td><td>", f);
    esc(f, v->description);
    fputs("</td></tr>\n", f);
  }
  fputs("</table>\n", f);
}

static void write_html(FILE *f) {
  char token[64];
  udmap_fmu_token(token, sizeof token);
  fprintf(f,
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    "<title>udmap FMU %s</title>\n"
    "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.4}"
    "table{border-collapse:collapse}td,th{border:1px solid #999;padding:2px 6px;"
    "vertical-align:top}th{background:#eee}code{white-space:nowrap}</style>\n"
    "</head>\n<body>\n<!-- Generated by udmap-describe from fmu/variables.h: do not edit. -->\n"
    "<h1>udmap FMU %s</h1>\n<p>", UDMAP_FMU_VERSION, UDMAP_FMU_VERSION);
  esc(f, MODEL_DESCRIPTION);
  fprintf(f, ". Model identifier <code>%s</code>, instantiation token / GUID <code>%s</code>. "
    "The same binary layer is packaged as an FMI 2.0 FMU "
    "(<code>udmap.fmu</code>, <code>binaries/linux64</code>) and an FMI 3.0 "
    "FMU (<code>udmap-fmi3.fmu</code>, <code>binaries/x86_64-linux</code>), each with both "
    "interfaces, model exchange and co-simulation.</p>\n",
    MODEL_IDENTIFIER, token);
  fputs(
    "<h2>What it computes</h2>\n"
    "<p>The FMU embeds a turbine blade (a clamped Euler-Bernoulli beam: neck, rigid platform, "
    "airfoil) vibrating in its first bending mode, and an asymmetric flat/curved underplatform "
    "damper between neighbouring platforms. By default it is blade A of "
    "<code>cases/blade_a.json</code>. The FMU is algebraic (quasi-steady): at every "
    "communication point its outputs are the steady forced response of the blade for the "
    "current inputs, at the resonance peak (<code>f_exc = 0</code>) or at the excitation "
    "frequency <code>f_exc</code>. There are no states and no events; any communication step "
    "size is accepted.</p>\n"
    "<p>Model exchange (no continuous states, no event indicators) gives the outputs for the "
    "inputs of the same instant, so that an importer can solve algebraic loops through the "
    "FMU; in co-simulation the outputs at the end of a step answer the inputs set at its "
    "start. The dependencies of every output on the inputs are declared "
    "(<code>dependenciesKind=\"dependent\"</code>).</p>\n"
    "<h2>Directional derivatives</h2>\n"
    "<p>Both interfaces provide the directional derivatives of every real output with respect "
    "to the real inputs and tunable parameters (one call per seed vector). With respect to "
    "<code>F_E</code> they are analytic: <code>gamma_P</code> solves "
    "<code>F_bb(gamma) = F_E</code> and the slope of the backbone follows from the envelope "
    "theorem (the partial derivative of the layer's peak at the peak frequency, with the "
    "damper's <code>dk/dgamma</code>); <code>f_res</code>, <code>sigma_a</code> and "
    "<code>u_E</code> by the chain rule, their slope along the backbone by a five-point "
    "difference of relative step 1e-4 in <code>gamma</code>. With respect to <code>CF</code> "
    "they are exact by the scaling law <code>k(gamma; lambda CF) = k(gamma / lambda; CF)</code> "
    "(Euler's theorem for functions homogeneous in <code>F_E</code> and <code>CF</code>). "
    "With respect to every other known, one central difference along the seed vector with a "
    "largest relative change of 1e-4 (one-sided of second order where a known would leave its "
    "range, e.g. <code>zeta = 0</code>), evaluated on a second instance so that this one keeps "
    "its caches. <code>f_exc = 0</code> (at resonance) is a switch: its derivative there is "
    "0. An unbounded response has no derivative: <code>Error</code>.</p>\n"
    "<p>The response is found without iterations on the non-linear equations: the damper is "
    "replaced by its complex stiffness <code>k(gamma) = k_re + i k_im</code> (describing "
    "function of the traced hysteresis loop), each amplitude layer of the platform rotation "
    "is a linear problem solved exactly by a rank-one update of the bare-blade receptances, "
    "and the peak follows from the backbone <code>F_bb(gamma)</code>. The limit force "
    "<code>F_lim = 2 Delta_M / (pi |phi_E / phi_gamma|)</code> is the force above which "
    "friction alone cannot bound the response.</p>\n"
    "<h2>What a change costs</h2>\n"
    "<p>Outputs are computed when they are read, and only what depends on a changed value is "
    "recomputed:</p>\n<ul>\n"
    "<li>a new <code>F_E</code> or <code>f_exc</code>: only the response point (no damper "
    "tracing, no receptances);</li>\n"
    "<li>a new <code>CF</code>: the damper table is rescaled (exact scaling law "
    "<code>k(gamma; lambda CF) = k(gamma / lambda; CF)</code>), not traced again. The damper is "
    "always traced at the start value of <code>CF</code> and rescaled to the current one, so "
    "the outputs depend only on the current values, never on the order of changes;</li>\n"
    "<li>a new <code>mu</code>, contact stiffness or damper geometry parameter: the damper is "
    "traced again and coupled to the model, which keeps the bare-blade data;</li>\n"
    "<li>a new blade parameter: the blade is rebuilt; a new band or <code>sigma_all</code>: "
    "the model over the same blade and damper is rebuilt;</li>\n"
    "<li><code>F_lim</code> and <code>lift_off</code> need no response point; outputs that are "
    "never read are never computed.</li>\n</ul>\n"
    "<p>The peak search starts from the eigenvalue given by the secular equation of the "
    "rank-one damper update over the bare modes (exact here: all modes of the beam are "
    "known), so the FMU needs no dense eigen-solve per damper; it uses LAPACK only (no "
    "ARPACK). <code>F_E = 0</code> is allowed and gives the limit of small forces: zero "
    "amplitudes, the stuck resonance frequency and stiffness.</p>\n"
    "<p>Several instances may live in one process with different parameters: they share "
    "nothing. The FMU state (get/set, serialize) holds the values of all inputs and "
    "parameters and the time; restoring it reproduces the outputs bit for bit.</p>\n"
    "<h2>Status codes</h2>\n<ul>\n"
    "<li>Setting a NaN, an infinity, a value outside its range, a non-positive value where "
    "zero is excluded, or an odd <code>airfoil_elements</code>: <code>Discard</code>, the "
    "value is not taken and the FMU stays as it was; the message names the variable.</li>\n"
    "<li>A failure while computing outputs (no resonance in the band, jammed damper, "
    "<code>f_exc</code> outside <code>[f_min, f_max]</code>, <code>f_min &gt;= f_max</code>, "
    "a numerical failure): <code>Error</code> from the get call, with the kernel's message "
    "through the logger. The instance stays usable: once valid values arrive, the next read "
    "computes normally.</li>\n"
    "<li>Values inside every range that look typed in another unit (the platform mass in "
    "grams, contact stiffnesses in N/mm, a band missing the first mode): a plausibility "
    "warning through the logger (<code>logStatusWarning</code>), once after the model is "
    "built and again when a change brings a new kind; the status and the outputs stay "
    "what they are.</li>\n"
    "<li><code>zeta = 0</code> and <code>F_E &gt;= F_lim</code>: <code>Warning</code>, "
    "<code>regime = 3</code>, <code>hcf_ok = false</code>, the amplitudes "
    "<code>gamma_P</code>, <code>sigma_a</code>, <code>u_E</code> are <code>+inf</code> "
    "(unbounded), <code>k_re = k_im = 0</code> (their limit) and <code>f_res</code> is the "
    "bare-blade natural frequency; never NaN. With <code>zeta &gt; 0</code> the response "
    "above <code>F_lim</code> is finite (<code>regime = 3</code>).</li>\n"
    "<li>A call in a state where FMI does not allow it: <code>Error</code> with a message, "
    "nothing changes.</li>\n</ul>\n", f);
  html_table(f, INPUT, "Inputs (continuous)");
  html_table(f, PARAMETER, "Parameters (tunable)");
  html_table(f, OUTPUT, "Outputs");
  fputs("<p>Boolean and Integer outputs have discrete variability; the independent variable "
        "is <code>time</code> [s].</p>\n", f);
  fputs("<h2>Units</h2>\n<table>\n<tr><th>unit</th><th>meaning</th><th>in SI base "
        "units</th></tr>\n", f);
  for (size_t i = 0; i < sizeof units / sizeof units[0]; i++) {
    char b[32];
    fputs("<tr><td>", f);
    esc(f, units[i].name);
    fprintf(f, "</td><td>%s</td><td>", units[i].description);
    if (units[i].factor != 1.0) fprintf(f, "%s ", num(units[i].factor, b));
    if (units[i].kg) fprintf(f, "kg<sup>%d</sup> ", units[i].kg);
    if (units[i].m) fprintf(f, "m<sup>%d</sup> ", units[i].m);
    if (units[i].s) fprintf(f, "s<sup>%d</sup> ", units[i].s);
    if (units[i].rad) fprintf(f, "rad<sup>%d</sup>", units[i].rad);
    fputs("</td></tr>\n", f);
  }
  fputs("</table>\n", f);
  fputs(
    "<h2>Binaries and licences</h2>\n"
    "<p>The Linux shared object holds the udmap kernel (Fortran, compiled without ARPACK) "
    "and everything it calls, and exports only the FMI functions: it needs only the C "
    "library and libm, and nothing lies beside it. Linked into it:</p>\n<ul>\n"
    "<li>the GCC runtime libraries libgfortran and libgcc (GPL 3 with the GCC Runtime Library "
    "Exception) and libquadmath (LGPL 2.1), linked in statically: "
    "<a href=\"licenses/gcc-runtime-copyright.txt\">copyright</a>, "
    "<a href=\"licenses/GPL-3.txt\">GPL-3</a>, "
    "<a href=\"licenses/LGPL-2.1.txt\">LGPL-2.1</a>;</li>\n"
    "<li>reference LAPACK and BLAS 3.11 (BSD-3-clause licence, one Debian source "
    "package): <a href=\"licenses/lapack-copyright.txt\">copyright</a>.</li>\n</ul>\n"
    "<p>See <a href=\"licenses/license.txt\">licenses/license.txt</a> for the overview.</p>\n"
    "</body>\n</html>\n", f);
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s fmi2|fmi3|html OUTPUT\n", argv[0]);
    return 2;
  }
  for (int i = 0; i < UDMAP_NVARS; i++) {
    const VariableInfo *v = &udmap_variables[i];
    if (v->unit[0] && !unit_known(v->unit)) {
      fprintf(stderr, "%s: unit '%s' of '%s' is not in UDMAP_UNITS\n", argv[0], v->unit,
              v->name);
      return 1;
    }
  }
  FILE *f = fopen(argv[2], "w");
  if (!f) {
    perror(argv[2]);
    return 1;
  }
  if (strcmp(argv[1], "fmi2") == 0) write_fmi2(f);
  else if (strcmp(argv[1], "fmi3") == 0) write_fmi3(f);
  else if (strcmp(argv[1], "html") == 0) write_html(f);
  else {
    fprintf(stderr, "%s: unknown target '%s'\n", argv[0], argv[1]);
    fclose(f);
    return 2;
  }
  return fclose(f) == 0 ? 0 : 1;
}
