"""Case files (INTERFACES.md "Case files"): the schema (:mod:`.schema`), loading and validation
(:mod:`.load`), the ``fe`` blade and its reduction (:mod:`.fe`), and the kernel objects of a
case (:mod:`.build`)."""
from .build import (ASYMMETRIC_KEYS, beam_params, build_blade, build_contact, build_damper,
                    build_model, contact_from_section, damper_from_section)
from .load import DEFAULT_CASE, Case, load_case, loads_case, read_table_csv, validate
from .schema import (ANALYSIS_DEFAULTS, EIGEN_METHODS, OPTIONAL, REQUIRED, SCHEMA, SECTIONS,
                     TABLE_GAMMA, TABLE_K, TOP_LEVEL, Field, check_field, flat_params, fmt_number,
                     range_text, schema_markdown)

__all__ = ["ASYMMETRIC_KEYS", "beam_params", "build_blade", "build_contact", "build_damper",
           "build_model", "contact_from_section", "damper_from_section", "DEFAULT_CASE", "Case",
           "load_case", "loads_case", "read_table_csv", "validate", "ANALYSIS_DEFAULTS",
           "EIGEN_METHODS", "OPTIONAL", "REQUIRED", "SCHEMA", "SECTIONS", "TABLE_GAMMA",
           "TABLE_K", "TOP_LEVEL", "Field", "check_field", "flat_params", "fmt_number", "range_text",
           "schema_markdown"]
