"""The README is a newcomer's page: short, without the project's history; its examples are real (its case file
and study file load, its commands exist)."""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from seafast.cli import build_parser
from seafast.config.loader import case_from_mapping
from seafast.studies.spec import study_spec_from_mapping

README = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")


def _yaml_blocks() -> list[dict]:
    return [yaml.safe_load(b) for b in re.findall(r"```yaml\n(.*?)```", README, re.S)]


def test_readme_case_file_is_valid():
    cases = [b for b in _yaml_blocks() if "cargo" in b]
    assert cases, "the README shows an example case file"
    for block in cases:
        case = case_from_mapping(block, "README")
        assert case.seafastening.saddle_count == 4


def test_readme_study_file_is_valid():
    studies = [b for b in _yaml_blocks() if "axes" in b]
    assert studies
    for block in studies:
        spec = study_spec_from_mapping({k: v for k, v in block.items() if k != "base"}, "README")  # its base file is illustrative
        assert [a.key for a in spec.axes] == ["seafastening.saddle_count", "seafastening.saddle_stiffness_N_per_m"]


def test_quick_start_is_two_commands_and_they_are_the_ci_command():
    block = re.search(r"## Quick start.*?```bash\n(.*?)```", README, re.S).group(1)
    commands = [line.split("#")[0].strip() for line in block.strip().splitlines()]
    assert commands == ["pip install . && seafast run", "pip install '.[test]' && python -m pytest"]
    ci = (Path(__file__).resolve().parents[1] / ".ci" / "run").read_text(encoding="utf-8")
    assert commands[1] in ci


def test_every_command_the_readme_names_exists():
    sub = build_parser()._subparsers._group_actions[0].choices  # argparse has no public accessor
    for name in set(re.findall(r"`seafast (\w+)", README)):
        assert name in sub, name


MAX_README_LINES = 300
ISSUE_NUMBER = re.compile(r"\bissue\s*#?\d+", re.IGNORECASE)


def test_readme_is_at_most_300_lines():
    lines = README.count("\n") + (not README.endswith("\n"))
    assert lines <= MAX_README_LINES, f"README.md has {lines} lines; theory, tables and history belong in docs/ and CHANGELOG.md"


def test_readme_cites_no_issue_number():
    found = sorted({m.group(0) for m in ISSUE_NUMBER.finditer(README)})
    assert not found, f"README.md cites issue numbers {found}: the history goes to CHANGELOG.md"


def test_issue_number_pattern_catches_the_forms_used():
    for text in ("issue 12", "Issue 13, item 6", "issue #4", "(issue12)"):
        assert ISSUE_NUMBER.search(text), text
    for text in ("issues", "the issue's target", "tissue 3", "issue-free"):
        assert not ISSUE_NUMBER.search(text), text
