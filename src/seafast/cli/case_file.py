"""``seafast init`` and ``seafast schema``: the case file format, as a commented file and as JSON Schema."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from seafast.cli.common import EXIT_OK, error

__all__ = ["add_init_subcommand", "add_schema_subcommand"]


def add_init_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """``seafast init``."""
    init = subparsers.add_parser(
        "init",
        help="write the base case as an editable, commented YAML file",
        epilog="example:\n  seafast init my_case.yaml && seafast run my_case.yaml",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    init.add_argument("file", help="path of the case file to write")
    init.add_argument("--force", action="store_true", help="overwrite an existing file")
    init.set_defaults(handler=_cmd_init)
    return init


def add_schema_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """``seafast schema``."""
    schema = subparsers.add_parser(
        "schema",
        help="print the JSON Schema of the case format",
        epilog="example:\n  seafast schema > seafast-case.schema.json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    schema.set_defaults(handler=_cmd_schema)
    return schema


def _cmd_init(args: argparse.Namespace) -> int:
    from seafast.config import base_case_text

    path = Path(args.file)
    if path.exists() and not args.force:
        return error(f"'{path}' exists; use --force to overwrite it")
    try:
        path.write_text(base_case_text(), encoding="utf-8")
    except OSError as exc:
        return error(f"cannot write '{path}': {exc.strerror}")
    print(f"wrote {path}: the base case; edit it and run 'seafast run {path}'")
    return EXIT_OK


def _cmd_schema(args: argparse.Namespace) -> int:
    from seafast.config import case_json_schema

    print(json.dumps(case_json_schema(), indent=2))
    return EXIT_OK
