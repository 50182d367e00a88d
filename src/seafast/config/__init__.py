"""Configuration: the case-file schema and its loader."""

from seafast.config.loader import CaseError, apply_overrides, base_case_text, case_json_schema, load_case, parse_overrides
from seafast.config.schema import Case

__all__ = ["Case", "CaseError", "load_case", "parse_overrides", "apply_overrides", "base_case_text", "case_json_schema"]
