"""Comparing a command's table with the one it wrote before, on any machine.

A file written on one machine and read back on another is equal only to the solvers' round-off: the BLAS a machine
loads (its kernels for that CPU) changes the last bits of every converged solve, and a converged answer carries its
solver's tolerance (1e-9 of the scale for the shooting and the harmonic balance). "Today's output, unchanged" is
therefore checked as: the same columns, the same labels and flags, the same number of rows, and every number within
:data:`SOLVER_RTOL` of today's (measured: 2e-10 between an Intel and an AMD machine; a changed result moves by 1e-3 or
more).
"""

from __future__ import annotations

import csv
import io
import math

SOLVER_RTOL = 1e-8
"""Relative tolerance of a number written by a converged solve, across machines [-]."""


def _number(cell: str) -> float | None:
    try:
        return float(cell)
    except ValueError:
        return None


def assert_same_table(got: str, expected: str, rtol: float = SOLVER_RTOL) -> None:
    """Assert two CSV texts are the same table: headers, text cells and empty cells exact, numbers within ``rtol``."""
    rows_got, rows_expected = list(csv.reader(io.StringIO(got))), list(csv.reader(io.StringIO(expected)))
    assert len(rows_got) == len(rows_expected), (len(rows_got), len(rows_expected))
    assert rows_got[:1] == rows_expected[:1]
    header = rows_expected[0] if rows_expected else []
    for i, (row, want) in enumerate(zip(rows_got[1:], rows_expected[1:], strict=True), start=1):
        assert len(row) == len(want), (i, row, want)
        for name, cell, expected_cell in zip(header, row, want, strict=True):
            a, b = _number(cell), _number(expected_cell)
            if a is None or b is None or math.isinf(b) or math.isnan(b):
                assert cell == expected_cell, (i, name, cell, expected_cell)
            else:
                assert math.isclose(a, b, rel_tol=rtol, abs_tol=0.0), (i, name, cell, expected_cell)
