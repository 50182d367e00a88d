"""MkDocs hook: a stand-in page for each documentation page that another branch is writing.

The index links ``seastate.md`` and ``axial.md`` before their features are merged. While a page
is missing, this hook adds a short generated page in its place, so that the strict build keeps
checking every other link and anchor; once the real page is in ``docs/`` the hook does nothing
(and can be deleted when both have landed).
"""

from __future__ import annotations

from typing import Any

from mkdocs.structure.files import File, Files

PENDING: dict[str, tuple[str, str]] = {
    "seastate.md": (
        "Irregular seas",
        (
            "short-term extremes in an irregular head sea (`seafast seastate`, `seafast operability`, "
            "the `sea_state.*` and `limits.*` case keys)"
        ),
    ),
    "axial.md": (
        "Axial sliding and friction",
        (
            "saddle friction, lashing angle and stoppers (`seafastening.friction_coefficient`, "
            "`seafastening.lashing.angle_deg`, `seafastening.stopper.*`)"
        ),
    ),
}


def on_files(files: Files, config: Any) -> Files:
    """Add a generated stand-in for every pending page that is not in ``docs/`` yet."""
    for name, (title, scope) in PENDING.items():
        if files.get_file_from_path(name) is None:
            text = (
                f"# {title}\n\n"
                f"This page is being written together with its feature: {scope}. "
                "Until it lands, the case keys and output columns of the contract are listed in "
                "[the scriptable interface](interface.md).\n"
            )
            files.append(File.generated(config, name, content=text))
    return files
