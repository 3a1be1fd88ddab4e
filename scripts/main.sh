#!/usr/bin/env bash
# The main job: generate every reference package, lint, build and test it, print a summary table.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/bootstrap.sh"
cd "$ROOT"
exec pkgtool reference test --all "$@"
