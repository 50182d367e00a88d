"""The user-supplied deck deflection table: reading, validation messages, interpolation."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seafast.excitation.deck_table import DECK_TABLE_COLUMNS, DeckDeflectionTable, read_deck_deflection_table

HEADER = "x_m,still_water_m,wave_amplitude_m,wave_phase_rad"


def _cubic(x):
    return 1e-3 * (0.5 + 0.02 * x - 3e-4 * x**2 + 2e-6 * x**3)


def _cubic_slope(x):
    return 1e-3 * (0.02 - 6e-4 * x + 6e-6 * x**2)


def _write(tmp_path: Path, text: str, name: str = "deck.csv") -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def _table_text(x, sw, amp, ph, header: str = HEADER) -> str:
    lines = [header] + [",".join(repr(float(v)) for v in row) for row in zip(x, sw, amp, ph, strict=True)]
    return "\n".join(lines) + "\n"


def test_columns_constant() -> None:
    assert DECK_TABLE_COLUMNS == ("x_m", "still_water_m", "wave_amplitude_m", "wave_phase_rad")


@pytest.mark.parametrize("n_rows", [4, 9, 30])
def test_cubic_interpolation_and_slope_are_exact(tmp_path: Path, n_rows: int) -> None:
    x = np.sort(np.concatenate([[0.0, 171.0], np.linspace(0, 171, n_rows)[1:-1] + 0.37]))
    sw = _cubic(x)
    amp = np.full_like(x, 2e-3)
    ph = np.full_like(x, 0.4)
    p = _write(tmp_path, _table_text(x, sw, amp, ph))
    tab = read_deck_deflection_table(p)
    assert tab.source == str(p)
    np.testing.assert_array_equal(tab.x_m, x)
    q = np.array([0.0, 3.3, 40.0, 85.5, 120.25, 171.0])
    z, s = tab.still_water_at(q)
    np.testing.assert_allclose(z, _cubic(q), rtol=0, atol=1e-12)
    np.testing.assert_allclose(s, _cubic_slope(q), rtol=0, atol=1e-13)
    zw, sw_ = tab.wave_at(q)
    np.testing.assert_allclose(zw, 2e-3 * np.exp(0.4j), rtol=1e-12)
    np.testing.assert_allclose(sw_, 0.0, atol=1e-14)


def test_wave_amplitude_and_phase_give_the_complex_harmonic(tmp_path: Path) -> None:
    """wave = A cos(omega t + phi) -> complex amplitude A exp(i phi); a cubic in each part is exact."""
    x = np.linspace(0.0, 100.0, 11)
    re = _cubic(x)
    im = -0.5 * _cubic(x[::-1])  # another cubic (reflected)
    c = re + 1j * im
    amp, ph = np.abs(c), np.angle(c)
    tab = read_deck_deflection_table(_write(tmp_path, _table_text(x, np.zeros_like(x), amp, ph)))
    np.testing.assert_allclose(tab.wave_complex_m, c, rtol=1e-12)
    q = np.array([5.0, 47.3, 99.0])
    z, s = tab.wave_at(q)
    np.testing.assert_allclose(z.real, _cubic(q), rtol=0, atol=1e-12)
    np.testing.assert_allclose(z.imag, -0.5 * _cubic(100.0 - q), rtol=0, atol=1e-12)
    np.testing.assert_allclose(s.real, _cubic_slope(q), rtol=0, atol=1e-13)
    np.testing.assert_allclose(s.imag, +0.5 * _cubic_slope(100.0 - q), rtol=0, atol=1e-13)
    # time signal at t = 0: Re(Z) = A cos(phi)
    np.testing.assert_allclose(tab.wave_complex_m.real, amp * np.cos(ph), rtol=1e-12, atol=1e-18)


@pytest.mark.parametrize("n_rows", [2, 3])
def test_short_tables_interpolate_linearly(tmp_path: Path, n_rows: int) -> None:
    x = np.linspace(10.0, 150.0, n_rows)
    sw = 1e-3 * (2.0 - 0.01 * x)  # linear: exact, slope -1e-5
    tab = read_deck_deflection_table(_write(tmp_path, _table_text(x, sw, 0 * x, 0 * x)))
    q = np.array([10.0, 33.0, 150.0])
    z, s = tab.still_water_at(q)
    np.testing.assert_allclose(z, 1e-3 * (2.0 - 0.01 * q), rtol=1e-12)
    np.testing.assert_allclose(s, -1e-5, rtol=1e-12)


def test_comments_blank_lines_extra_columns_and_column_order(tmp_path: Path) -> None:
    text = (
        "# deck deflection from another program\n"
        "\n"
        "wave_phase_rad, x_m ,note,still_water_m,wave_amplitude_m\n"
        "0.1,0,a,0.001,0.002\n"
        "   \n"
        "0.2,50,b,0.002,0.003\n"
        "# mid comment\n"
        "0.3,100,c,0.003,0.004\n"
    )
    tab = read_deck_deflection_table(_write(tmp_path, text))
    np.testing.assert_allclose(tab.x_m, [0, 50, 100])
    np.testing.assert_allclose(tab.still_water_m, [0.001, 0.002, 0.003])
    np.testing.assert_allclose(tab.wave_complex_m, np.array([0.002, 0.003, 0.004]) * np.exp(1j * np.array([0.1, 0.2, 0.3])))


# --------------------------------------------------------------------------- bad tables
GOOD_ROWS = "0,0.001,0.002,0.1\n50,0.002,0.003,0.2\n100,0.003,0.004,0.3\n120,0.002,0.001,0.0\n"


@pytest.mark.parametrize(
    "text, must_contain",
    [
        ("x_m,still_water_m,wave_amplitude_m\n0,0,0\n1,0,0\n", ["wave_phase_rad", "missing column"]),
        ("x,still_water_m,wave_amplitude_m,wave_phase_rad\n0,0,0,0\n1,0,0,0\n", ["x_m", "missing column"]),
        (HEADER + "\n0,0.001,0.002,0.1\n50,abc,0.003,0.2\n", ["line 3", "still_water_m", "'abc'", "not a number"]),
        (HEADER + "\n0,0.001,0.002,0.1\n50,0.002,0.003\n", ["line 3", "wave_phase_rad", "<missing>"]),
        (HEADER + "\n0,0.001,0.002,0.1\n50,0.002,nan,0.2\n", ["line 3", "wave_amplitude_m", "not finite"]),
        (HEADER + "\n0,0.001,0.002,0.1\n50,0.002,0.003,inf\n", ["line 3", "wave_phase_rad", "not finite"]),
        (HEADER + "\n0,0.001,0.002,0.1\n50,0.002,0.003,0.2\n50,0.002,0.003,0.2\n", ["line 4", "strictly increasing"]),
        (HEADER + "\n0,0.001,0.002,0.1\n50,0.002,0.003,0.2\n40,0.002,0.003,0.2\n", ["line 4", "x_m", "strictly increasing"]),
        (HEADER + "\n0,0.001,0.002,0.1\n", ["at least 2 data rows", "got 1"]),
        (HEADER + "\n", ["at least 2 data rows", "got 0"]),
        ("", ["empty"]),
        ("# only a comment\n\n", ["empty"]),
    ],
    ids=[
        "missing-phase",
        "missing-x",
        "non-number",
        "short-row",
        "nan",
        "inf",
        "x-repeated",
        "x-decreasing",
        "one-row",
        "no-rows",
        "empty-file",
        "only-comments",
    ],
)
def test_bad_tables_raise_value_error_naming_file_and_place(tmp_path: Path, text: str, must_contain: list[str]) -> None:
    p = _write(tmp_path, text, name="bad_deck.csv")
    with pytest.raises(ValueError, match=r"bad_deck\.csv") as exc:
        read_deck_deflection_table(p)
    msg = str(exc.value)
    assert "bad_deck.csv" in msg
    assert "deck_deflection_table" in msg
    for s in must_contain:
        assert s in msg, (s, msg)


def test_missing_file_raises_value_error_naming_it(tmp_path: Path) -> None:
    p = tmp_path / "nowhere.csv"
    with pytest.raises(ValueError, match=r"nowhere\.csv"):
        read_deck_deflection_table(p)


def test_non_utf8_file_raises_value_error(tmp_path: Path) -> None:
    p = tmp_path / "binary.csv"
    p.write_bytes(b"\xff\xfe\x00x_m\x00")
    with pytest.raises(ValueError, match=r"binary\.csv"):
        read_deck_deflection_table(p)


def test_query_outside_the_table_names_file_and_range(tmp_path: Path) -> None:
    p = _write(tmp_path, HEADER + "\n" + GOOD_ROWS, name="short_deck.csv")
    tab = read_deck_deflection_table(p)
    tab.still_water_at(np.array([0.0, 120.0]))  # ends are fine
    for q in (np.array([-1.0, 10.0]), np.array([50.0, 120.5])):
        with pytest.raises(ValueError, match=r"short_deck\.csv") as exc:
            tab.still_water_at(q)
        msg = str(exc.value)
        assert "short_deck.csv" in msg and "0.0 .. 120.0" in msg and "extend the table" in msg
        with pytest.raises(ValueError, match=r"short_deck\.csv"):
            tab.wave_at(q)


def test_direct_construction_validates() -> None:
    with pytest.raises(ValueError, match="at least 2 rows"):
        DeckDeflectionTable(np.array([1.0]), np.array([0.0]), np.array([0j]), source="t")
    with pytest.raises(ValueError, match="strictly increasing"):
        DeckDeflectionTable(np.array([1.0, 1.0]), np.zeros(2), np.zeros(2, complex), source="t")


@pytest.mark.parametrize(
    "bad_row, what",
    [("50,abc,0.003,0.2", "still_water_m"), ("-5,0.002,0.003,0.2", "strictly increasing")],
    ids=["non-number", "x-decreasing"],
)
def test_error_line_numbers_are_physical_lines(tmp_path: Path, bad_row: str, what: str) -> None:
    text = "# exported by hull program\n\n" + HEADER + "\n# stations\n0,0.001,0.002,0.1\n\n" + bad_row + "\n"
    # the bad row is physical line 7 of the file
    with pytest.raises(ValueError, match="line 7") as exc:
        read_deck_deflection_table(_write(tmp_path, text))
    assert what in str(exc.value)
    assert "line 7" in str(exc.value), str(exc.value)
