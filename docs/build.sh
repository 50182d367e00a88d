#!/usr/bin/env bash
# Build the documentation site strictly: every warning (a broken link or anchor, a docstring
# griffe cannot parse, a page missing from the nav) is an error.
#   pip install -e '.[docs]'      # once: mkdocs, mkdocstrings-python, pymdown-extensions
#   bash docs/build.sh            # -> build/site/index.html
#   bash docs/build.sh DIR        # -> DIR/index.html
set -euo pipefail
cd "$(dirname "$0")/.."
if ! python -c "import mkdocs, mkdocstrings_handlers.python, pymdownx" 2>/dev/null; then
  echo "docs/build.sh: the documentation tools are not installed; run: pip install -e '.[docs]'" >&2
  exit 2
fi
python -m mkdocs build --strict --site-dir "${1:-build/site}"
