"""Hostile case files through `response` (fuzz_cases.command_test; the loader alone and real
processes: test_fuzz_cases.py)."""
import fuzz_cases

test_mutated_cases_fail_cleanly_in_response = fuzz_cases.command_test("response")
