"""Progress of long runs: plain lines every few per cent off a terminal, a tqdm bar on one, one helper for all."""

from __future__ import annotations

import io
import logging
import re
from pathlib import Path

import pytest

import seafast.parallel.progress as progress_module
from seafast.parallel.progress import PlainProgress, format_duration, progress

SRC = Path(__file__).resolve().parents[2] / "src" / "seafast"


class Clock:
    """A clock the test moves."""

    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_a_plain_line_every_five_per_cent_with_the_time_left():
    clock = Clock()
    bar = PlainProgress(120, 0, "study saddles", "points", min_interval_s=0.0, clock=clock)
    for _ in range(120):
        clock.now += 0.5  # 0.5 s a point
        bar.update(1)
    bar.close()
    assert len(bar.lines) == 20  # every 6 points (5 % of 120)
    assert bar.lines[4] == "study saddles: 30/120 points (25 %), 15 s elapsed, ~45 s left"
    assert bar.lines[-1] == "study saddles: 120/120 points (100 %), 60 s elapsed"


def test_lines_are_at_least_the_interval_apart_and_the_last_count_is_printed():
    clock = Clock()
    bar = PlainProgress(100, 0, "run", "items", min_interval_s=10.0, clock=clock)
    for _ in range(99):
        clock.now += 1.0
        bar.update(1)
    # due every 5 items (5 s) but at most one per 10 s: at 10, 20, ... 90 items
    assert [int(line.split("/")[0].split()[-1]) for line in bar.lines] == list(range(10, 100, 10))
    clock.now += 0.2
    bar.update(1)  # the last item, 9.2 s after the line at 90: not due by the interval ...
    assert len(bar.lines) == 9
    bar.close()  # ... but the end prints the final count
    assert bar.lines[-1] == "run: 100/100 items (100 %), 99 s elapsed"


def test_a_resumed_run_counts_only_its_own_items_for_the_time_left():
    clock = Clock()
    bar = PlainProgress(120, 60, "study saddles", "points", min_interval_s=0.0, clock=clock)
    clock.now += 30.0
    bar.update(6)  # 6 points in 30 s: 5 s a point, 54 left
    assert bar.lines == ["study saddles: 66/120 points (55 %), 30 s elapsed, ~4.5 min left"]


def test_a_fast_run_prints_nothing_and_durations_read_well():
    clock = Clock()
    bar = PlainProgress(16, 0, "study small", "points", clock=clock)  # the default interval: 2 s
    for _ in range(16):
        clock.now += 0.01
        bar.update(1)
    bar.close()
    assert bar.lines == []
    assert [format_duration(s) for s in (14.2, 99.4, 192.0, 7200.0)] == ["14 s", "99 s", "3.2 min", "2.0 h"]


def test_the_bar_on_a_terminal_the_lines_elsewhere_nothing_when_off(monkeypatch: pytest.MonkeyPatch):
    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    bar = progress(10, 2, label="study x", unit="points")
    assert type(bar).__mro__[1].__name__ == "tqdm" and bar.monitor_interval == 0  # no monitor thread (forks follow)
    bar.update(3)
    bar.close()
    assert "study x" in terminal.getvalue() and "5/10" in terminal.getvalue()
    monkeypatch.setattr("sys.stderr", io.StringIO())
    assert isinstance(progress(10, 0, label="study x", unit="points"), PlainProgress)
    off = progress(10, 0, label="study x", unit="points", enabled=False)
    assert not isinstance(off, PlainProgress) and off.update(5) is None


def test_the_plain_lines_are_logged_for_the_command_to_print(monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture):
    monkeypatch.setattr(progress_module, "PROGRESS_MIN_INTERVAL_S", 0.0)
    monkeypatch.setattr("sys.stderr", io.StringIO())
    with caplog.at_level(logging.INFO, logger="seafast.parallel.progress"):
        bar = progress(4, 0, label="Monte Carlo base", unit="realisations")
        for _ in range(4):
            bar.update(1)
        bar.close()
    lines = [r.getMessage() for r in caplog.records if r.name == "seafast.parallel.progress"]
    assert len(lines) == 4 and re.fullmatch(r"Monte Carlo base: 2/4 realisations \(50 %\), \d+ s elapsed, ~\d+ s left", lines[1])


def test_one_progress_helper_in_the_package():
    """The study runner and the Monte Carlo both report through seafast.parallel.progress; no other module draws a bar."""
    users = sorted(str(p.relative_to(SRC)) for p in SRC.rglob("*.py") if re.search(r"^\s*(from|import) tqdm", p.read_text(), re.M))
    assert users == ["parallel/progress.py"]
    for module in ("studies/runner.py", "analyses/seastate/monte_carlo.py"):
        assert re.search(r"^from seafast\.parallel\.progress import progress\b", (SRC / module).read_text(), re.M), module
