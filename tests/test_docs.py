"""The documentation in docs/ stays true to the code: anchors, case keys, columns, commands, tests.

docs/interface.md is the contract scripts rely on, so every case key of the schema, every output
column, every results.nc variable and every command must be written there (or on a feature's own
page); every test file must be described on some page (docs/verification.md, or a feature page);
every ``docs/<page>.md#<anchor>`` cited anywhere in the repository must exist, with the same
anchor on GitHub and in the MkDocs site. The site itself is built strictly by docs/build.sh.
"""

from __future__ import annotations

import os
import re
import typing
import unicodedata
from pathlib import Path

import pytest
from pydantic import BaseModel

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PAGES = sorted(DOCS.rglob("*.md"))
# Where docs/...#anchor citations are looked for (and checked).
CITING = ("src", "tests", "benchmarks", "examples", "docs", "README.md")
# Trees that must cite only files of the repository (not the engineering-model and interface notes
# the project was started from, which a clone does not contain).
CITATION_CHECKED = ("docs", "src", "examples", "benchmarks", "README.md")


def _text(path: Path) -> str:
    return path.read_text(encoding="utf-8")


ALL_DOCS = "\n".join(_text(p) for p in PAGES)
INTERFACE = _text(DOCS / "interface.md")


def github_slug(heading: str) -> str:
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"`", "", heading).strip().lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def mkdocs_slug(heading: str) -> str:
    """Python-Markdown's default anchor (the toc extension's slugify), as MkDocs builds it."""
    text = unicodedata.normalize("NFKD", re.sub(r"`", "", heading)).encode("ascii", "ignore").decode("ascii")
    text = re.sub(r"[^\w\s-]", "", text).strip().lower()
    return re.sub(r"[-\s]+", "-", text)


def _headings(path: Path) -> list[str]:
    out, fenced = [], False
    for line in _text(path).splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"#{1,6} ", line):
            out.append(line.lstrip("#").strip())
    return out


def test_slug_functions_follow_their_renderers():
    assert github_slug("5. Harmonic balance") == "5-harmonic-balance" == mkdocs_slug("5. Harmonic balance")
    assert github_slug("5.1 summary.csv") == "51-summarycsv" == mkdocs_slug("5.1 summary.csv")
    # where the two renderers differ (runs of spaces and hyphens), the docs must avoid the form
    assert github_slug("a - b") == "a---b" != mkdocs_slug("a - b") == "a-b"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(DOCS)))
def test_every_heading_has_the_same_anchor_on_github_and_in_mkdocs(page: Path):
    headings = _headings(page)
    assert headings, f"{page.name} has no heading"
    for h in headings:
        assert github_slug(h) == mkdocs_slug(h), f"{page.name}: heading {h!r} gets different anchors"
    slugs = [github_slug(h) for h in headings]
    assert len(slugs) == len(set(slugs)), f"{page.name}: two headings share an anchor"


def _citations() -> list[tuple[str, str, str]]:
    """(where, page, anchor) of every docs/<page>.md#anchor and relative page link in the repository."""
    found = []
    for root in CITING:
        base = ROOT / root
        files = [base] if base.is_file() else [p for p in base.rglob("*") if p.suffix in (".py", ".md", ".yaml", ".csv")]
        for f in files:
            text = _text(f)
            where = str(f.relative_to(ROOT))
            for page, anchor in re.findall(r"docs/([\w/-]+\.md)(?:#([\w-]+))?", text):
                found.append((where, page, anchor))
            if f.is_relative_to(DOCS) and f.suffix == ".md":
                here = f.parent.relative_to(DOCS)
                for target, anchor in re.findall(r"\]\(([\w./-]*?\.md)?(?:#([\w-]+))?\)", text):
                    if target or anchor:
                        page = os.path.normpath(here / target) if target else str(f.relative_to(DOCS))
                        found.append((where, Path(page).as_posix(), anchor))
    return found


def test_every_cited_page_and_anchor_exists():
    citations = _citations()
    assert len(citations) > 50  # the docs cross-reference themselves
    for where, page, anchor in citations:
        path = DOCS / page
        assert path.is_file(), f"{where} cites docs/{page}, which does not exist"
        if anchor:
            anchors = {github_slug(h) for h in _headings(path)}
            assert anchor in anchors, f"{where} cites docs/{page}#{anchor}; the page's anchors are {sorted(anchors)}"


@pytest.mark.parametrize("root", CITATION_CHECKED)
def test_docs_cite_only_files_of_the_repository(root: str):
    base = ROOT / root
    for f in [base] if base.is_file() else base.rglob("*"):
        if f.is_file() and f.suffix in (".md", ".py", ".yaml"):
            for name in ("MODEL.md", "INTERFACE.md"):
                assert name not in _text(f), f"{f.relative_to(ROOT)} cites {name}, a file outside the repository"


def _case_keys(model: type[BaseModel], prefix: str = "") -> list[str]:
    """Dotted keys of the case schema; a list of sub-models gives its key and each field."""
    keys = []
    for name, field in model.model_fields.items():
        key = prefix + name
        args = typing.get_args(field.annotation)
        sub = [a for a in (field.annotation, *args) if isinstance(a, type) and issubclass(a, BaseModel)]
        items = [t for a in args for t in typing.get_args(a) if isinstance(t, type) and issubclass(t, BaseModel)]
        if sub:
            keys += _case_keys(sub[0], key + ".")
        elif items:
            keys.append(key)
            keys += [f"{key}[].{f}" for f in items[0].model_fields]
        else:
            keys.append(key)
    return keys


def test_every_case_key_is_documented():
    from seafast.config.schema import Case

    keys = _case_keys(Case)
    assert "seafastening.lashing.pretension_N" in keys and "cargo.sections[].wall_thickness_m" in keys
    missing = []
    for key in keys:
        if "[]." in key:
            if key.split("[].")[1] not in ALL_DOCS:
                missing.append(key)
        elif f"`{key}`" not in ALL_DOCS:
            missing.append(key)
    assert not missing, f"case keys not documented in docs/ (interface.md#2-case-keys): {missing}"


def test_every_output_column_is_documented_exactly():
    from seafast.analyses.sweep.table import STRUCTURAL_COLUMNS, WAVE_COLUMNS
    from seafast.excitation.deck_table import DECK_TABLE_COLUMNS
    from seafast.output.sweep import COLUMNS as SWEEP_COLUMNS
    from seafast.results.dataset import SUMMARY_COLUMNS
    from seafast.studies.assembly import CORE_COLUMNS
    from seafast.studies.limits import COMPLIANCE_COLUMNS, RANKING_COLUMNS

    assert ",".join(SUMMARY_COLUMNS) in INTERFACE
    assert ",".join(SWEEP_COLUMNS) in INTERFACE
    assert ",".join(STRUCTURAL_COLUMNS) in INTERFACE
    assert ",".join(WAVE_COLUMNS[len(STRUCTURAL_COLUMNS) :]) in INTERFACE
    assert ",".join(CORE_COLUMNS) in INTERFACE
    assert ",".join(COMPLIANCE_COLUMNS) in INTERFACE
    assert ",".join(RANKING_COLUMNS[2:]) in INTERFACE
    for column in DECK_TABLE_COLUMNS:
        assert f"`{column}`" in INTERFACE


def test_every_results_variable_is_documented():
    from seafast.analyses.run import run_case
    from seafast.config import load_case

    ds = run_case(load_case(overrides={"vessel.motions": "none", "solver.time_samples": 16, "solver.harmonics": 3})).dataset
    missing = [name for name in ds.data_vars if f"`{name}`" not in ALL_DOCS]
    assert not missing, f"results.nc variables not documented in docs/ (interface.md#52-resultsnc): {missing}"


def test_every_command_is_documented():
    from seafast.cli import build_parser

    commands = build_parser()._subparsers._group_actions[0].choices  # argparse has no public accessor
    assert {"run", "init", "schema", "study", "sweep", "report"} <= set(commands)
    for name in commands:
        assert f"seafast {name}" in INTERFACE, f"`seafast {name}` is not in docs/interface.md#4-commands"


def test_every_test_file_is_described():
    files = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "tests").rglob("test_*.py"))
    assert "tests/test_docs.py" in files
    missing = [f for f in files if f"`{f}`" not in ALL_DOCS]
    assert not missing, f"test files not described in docs/ (verification.md, or the feature's page): {missing}"


def test_no_page_docstring_comment_or_test_cites_an_issue_number():
    """The software's own words describe it as it is: history goes to CHANGELOG.md, and no page, docstring,
    comment or test refers to an issue (the pattern is tests/test_readme.py's, checked there on its forms)."""
    from test_readme import ISSUE_NUMBER

    found = []
    for root in ("src", "tests", "docs", "benchmarks", "examples"):
        for path in (ROOT / root).rglob("*"):
            if path.suffix in (".py", ".md", ".yaml") and path.name != "test_readme.py" and "egg-info" not in str(path):
                found += [f"{path.relative_to(ROOT)}: {m.group(0)}" for m in ISSUE_NUMBER.finditer(_text(path))]
    assert not found, found
