"""Leave a valid Gradescope results.json: pkgtool's own, or a score of 0 with the reason.

Called by run_autograder as ``ensure_results.py RESULTS EXIT_STATUS LIMIT_SECONDS``.
"""

import json
import sys

path, status, limit = sys.argv[1], int(sys.argv[2]), sys.argv[3]
try:
    with open(path, encoding="utf-8") as handle:
        results = json.load(handle)
    valid = isinstance(results, dict) and isinstance(results.get("score"), (int, float))
except (OSError, ValueError):
    valid = False
if not valid:
    if status in (124, 137):
        reason = f"Grading did not finish within {limit} s and was stopped."
    else:
        reason = f"The grader stopped with exit status {status} before writing results."
    results = {"score": 0, "output": f"{reason} Your submission scored 0; please tell your "
               "instructor, who can see the autograder's log.", "tests": [],
               "stdout_visibility": "visible"}
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(results, handle, indent=1)
