#!/usr/bin/env bash
# Create .venv (if missing) and install pkgtool with every extra from the lock file.
# Sourced by scripts/main.sh and scripts/test.sh; fast when nothing changed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="$ROOT/.venv"
PY="${PKGTOOL_PYTHON:-python3}"
UV_VERSION="0.13.9"
export UV_CACHE_DIR="${UV_CACHE_DIR:-$HOME/.cache/pkgtool-uv}"
# Copy, never hard-link, from the cache: wheel_fixups edits installed files in place.
export UV_LINK_MODE=copy

if [ ! -x "$VENV/bin/python" ]; then
    echo "bootstrap: creating $VENV" >&2
    "$PY" -m venv "$VENV"
fi
if [ ! -x "$VENV/bin/uv" ]; then
    "$VENV/bin/python" -m pip install -q "uv==$UV_VERSION"
fi

stamp="$VENV/.pkgtool-installed"
want="$(cat "$ROOT/requirements/lock.txt" "$ROOT/pyproject.toml" | sha256sum | cut -d' ' -f1)"
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
    echo "bootstrap: installing the locked requirements into $VENV" >&2
    "$VENV/bin/uv" pip install -q --compile-bytecode --python "$VENV/bin/python" -r "$ROOT/requirements/lock.txt"
    # The distribution was first named `pkgtool`: drop that editable install from an older venv.
    "$VENV/bin/uv" pip uninstall -q --python "$VENV/bin/python" pkgtool 2>/dev/null || true
    "$VENV/bin/uv" pip install -q --python "$VENV/bin/python" --no-deps -e "$ROOT"
    "$VENV/bin/python" -m pkgtool.ros.wheel_fixups "$VENV"
    echo "$want" > "$stamp"
fi
export PATH="$VENV/bin:$PATH"
export VIRTUAL_ENV="$VENV"
