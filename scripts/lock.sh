#!/usr/bin/env bash
# Re-resolve requirements/lock.txt from pyproject.toml (all extras). Run after changing dependencies.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/bootstrap.sh" 2>/dev/null || true
"$ROOT/.venv/bin/uv" pip compile -q --python-version 3.11 --all-extras \
    --output-file "$ROOT/requirements/lock.txt" "$ROOT/pyproject.toml"
