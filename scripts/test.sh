#!/usr/bin/env bash
# The whole test suite: sets up .venv on first use (ROS 2 Jazzy wheels included), then pytest.
# Extra arguments go to pytest, e.g. scripts/test.sh -k lint -x
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/bootstrap.sh"
bash "$ROOT/scripts/system-packages.sh"
cd "$ROOT"
jobs="${PKGTOOL_TEST_JOBS:-auto}"
set +e
python -m pytest -n "$jobs" --dist loadgroup --timeout 900 "$@"
status=$?
set -e
if [ "$status" -eq 5 ]; then
    echo "test.sh: pytest collected no tests; that is a failure here" >&2
    exit 1
fi
exit "$status"
