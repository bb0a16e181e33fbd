/*
 * The FMU's variable table: value references, types, causalities, units, start values,
 * ranges and descriptions. model.c reads and writes values through it, and describe.c
 * generates both modelDescription.xml files and documentation/index.html from it at build
 * time. The table, UDMAP_VARIABLE_TABLE, is in fmu/parameters.h, generated from the
 * parameter table kernel/parameters.toml by cmake/generate_parameters.py; start values are
 * those of cases/blade_a.json.
 *
 * X(name, type, causality, group, unit, start, min, max, flags, description)
 *   type       REAL, INTEGER or BOOLEAN
 *   causality  INDEPENDENT, INPUT, PARAMETER (tunable) or OUTPUT
 *   group      what a change invalidates (inputs, parameters) or what computes it (outputs)
 *   unit       a unit of UDMAP_UNITS, or "" for dimensionless
 *   min, max   inclusive bounds (NOLIMIT for none); POSITIVE additionally excludes zero,
 *              OPEN excludes both bounds, EVEN asks for an even integer; the bounds are the
 *              physical ranges of the case-file schema (from the same parameter table)
 * The value reference of a variable is its position in the table.
 */
#ifndef UDMAP_FMU_VARIABLES_H
#define UDMAP_FMU_VARIABLES_H

#include "parameters.h" /* UDMAP_VARIABLE_TABLE, generated from kernel/parameters.toml */

/* X(name, kg, m, s, rad, factor, description) over the units used above. */
#define UDMAP_UNITS(X) \
  X("s", 0, 0, 1, 0, 1.0, "second") \
  X("N", 1, 1, -2, 0, 1.0, "newton") \
  X("Hz", 0, 0, -1, 0, 1.0, "hertz") \
  X("m", 0, 1, 0, 0, 1.0, "metre") \
  X("kg", 1, 0, 0, 0, 1.0, "kilogram") \
  X("kg.m2", 1, 2, 0, 0, 1.0, "kilogram square metre") \
  X("kg/m3", 1, -3, 0, 0, 1.0, "kilogram per cubic metre") \
  X("Pa", 1, -1, -2, 0, 1.0, "pascal") \
  X("N/m", 1, 0, -2, 0, 1.0, "newton per metre") \
  X("N.m/rad", 1, 2, -2, -1, 1.0, "newton metre per radian") \
  X("rad", 0, 0, 0, 1, 1.0, "radian") \
  X("deg", 0, 0, 0, 1, 0.017453292519943295, "degree")

#endif /* UDMAP_FMU_VARIABLES_H */
