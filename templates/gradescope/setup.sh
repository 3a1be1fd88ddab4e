#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder image (Ubuntu 22.04 or
# 24.04 base). It installs a Python 3.11 (the one pkgtool's ROS 2 Jazzy wheels are locked for),
# a venv with the locked requirements and pkgtool's own wheel, all from this bundle's lists.
# PKGTOOL_AUTOGRADER_ROOT (default /autograder) moves everything for a trial run elsewhere;
# PKGTOOL_PYTHON names a Python 3.11 to use instead of looking for one.
set -euo pipefail
ROOT="${PKGTOOL_AUTOGRADER_ROOT:-/autograder}"
SOURCE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
UV_VERSION="{{ uv_version }}"

python="${PKGTOOL_PYTHON:-$(command -v python3.11 || true)}"
if [ -z "$python" ]; then
    # No Python 3.11 on the image (24.04 ships 3.12): uv fetches a standalone build of it.
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q >/dev/null
    apt-get install -y -q python3 python3-venv ca-certificates >/dev/null
    python3 -m venv "$ROOT/.uv"
    "$ROOT/.uv/bin/python" -m pip install -q "uv==$UV_VERSION"
    "$ROOT/.uv/bin/uv" python install 3.11
    python="$("$ROOT/.uv/bin/uv" python find 3.11)"
fi
"$python" -m venv "$ROOT/venv"
"$ROOT/venv/bin/python" -m pip install -q --disable-pip-version-check "uv==$UV_VERSION"
export UV_LINK_MODE=copy
"$ROOT/venv/bin/uv" pip install -q --python "$ROOT/venv/bin/python" -r "$SOURCE/requirements.txt"
"$ROOT/venv/bin/uv" pip install -q --python "$ROOT/venv/bin/python" --no-deps "$SOURCE"/wheels/*.whl
"$ROOT/venv/bin/python" -m pkgtool.ros.wheel_fixups "$ROOT/venv"
"$ROOT/venv/bin/python" -c "import pkgtool, rclpy"  # the ROS wheels load
echo "pkgtool autograder ready in $ROOT/venv"
