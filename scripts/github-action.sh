#!/usr/bin/env bash
# The steps of action.yml: install pkgtool (unless INPUT_INSTALL=false), write the SARIF report,
# print GitHub annotations, optionally check that no fix is pending, and record the exit code.
# Inputs arrive as INPUT_* variables; the exit code goes to $GITHUB_OUTPUT as `exit-code`, and
# the script itself exits 0 so that the SARIF upload step runs before the job fails.
set -uo pipefail
ACTION_PATH="${GITHUB_ACTION_PATH:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
OUTPUT="${GITHUB_OUTPUT:-/dev/null}"

if [ "${INPUT_INSTALL:-true}" = "true" ]; then
    python -m pip install --quiet --disable-pip-version-check "$ACTION_PATH" || {
        echo "::error title=pkgtool::could not install pkgtool from $ACTION_PATH"
        echo "exit-code=2" >> "$OUTPUT"
        exit 0
    }
fi

read -r -a paths <<< "$(echo "${INPUT_PATHS:-.}" | tr '\n' ' ')"
args=()
[ -n "${INPUT_SELECT:-}" ] && args+=(--select "$INPUT_SELECT")
[ -n "${INPUT_IGNORE:-}" ] && args+=(--ignore "$INPUT_IGNORE")
[ "${INPUT_STRICT:-false}" = "true" ] && args+=(--strict)
sarif="${INPUT_SARIF_FILE:-pkgtool.sarif}"

pkgtool lint "${args[@]}" --format sarif --output "$sarif" "${paths[@]}" --exit-zero
pkgtool lint "${args[@]}" --format github "${paths[@]}"
status=$?

if [ "$status" -lt 2 ] && [ "${INPUT_FIX_CHECK:-false}" = "true" ]; then
    if ! pkgtool lint --help | grep -q -- "--diff"; then
        echo "::error title=pkgtool fix-check::this pkgtool has no \`lint --diff\`; set fix-check: false"
        status=2
    else
        pending="$(pkgtool lint "${args[@]}" --diff "${paths[@]}" 2>/dev/null)"
        if [ -n "$pending" ]; then
            echo "::error title=pkgtool fix-check::\`pkgtool lint --fix\` would change files; run it and commit the result"
            printf '%s\n' "$pending"
            [ "$status" -eq 0 ] && status=1
        fi
    fi
fi

echo "exit-code=$status" >> "$OUTPUT"
if [ -n "${GITHUB_STEP_SUMMARY:-}" ]; then
    echo "pkgtool lint exited $status (0 clean, 1 findings, 2 usage or input error, 3 internal error)" >> "$GITHUB_STEP_SUMMARY"
fi
exit 0
