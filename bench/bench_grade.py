"""Benchmark `pkgtool grade`: time to grade N submissions with --jobs 1 and --jobs 2 (not a test).

The submissions are the synthetic ``talker_pkg`` assignment of tests/grade/synthetic.py, in a
realistic mix (mostly correct, some with a failing test, an undeclared dependency, a missing
entry point, a build failure), graded with its 11-point rubric: colcon build, console-script
check, lint, style, the student's tests and instructor tests, each in the sandbox. Every run is
the real CLI in a fresh process (``pkgtool grade DIR --batch --jobs J --format json``).

Prints a table and writes ``bench/results/grade-<UTC time>.json``. Target: 100 submissions
within 10 minutes on 2 cores, i.e. at most 6 s of wall time per submission with --jobs 2.

    .venv/bin/python bench/bench_grade.py [--submissions 20] [--jobs 1 2]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from datetime import datetime, timezone
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "bench" / "results"
TARGET_PER_SUBMISSION = 600.0 / 100
MIX = ("correct", "correct", "correct", "failing_test", "undeclared_dependency", "correct",
       "missing_entry_point", "correct", "build_failure", "correct")

sys.path.insert(0, str(ROOT))
from tests.grade import synthetic  # noqa: E402


def _prepare(folder: Path, count: int) -> Path:
    """``count`` submissions under ``folder/submissions`` and the rubric; returns the rubric."""
    subs = folder / "submissions"
    markers = {"tmp": folder / "tmp-marker", "root": folder / "root-marker"}
    names = [f"student{i:03d}" for i in range(count)]
    kinds = {name: MIX[i % len(MIX)] for i, name in enumerate(names)}
    variants = synthetic.variants(defaultdict(lambda: subs), markers)
    for name in names:
        synthetic.write_submission(subs / name, variants[kinds[name]])
    rubric = folder / "rubric.toml"
    rubric.write_text(synthetic.RUBRIC.format(timeout=300, hidden=synthetic.HIDDEN))
    return rubric


def _grade(folder: Path, rubric: Path, jobs: int) -> tuple[float, list[dict[str, object]]]:
    command = [str(Path(sys.executable).parent / "pkgtool"), "grade", "submissions", "--batch",
               "--rubric", str(rubric), "--jobs", str(jobs), "--format", "json"]
    start = time.perf_counter()
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True, check=True)
    seconds = time.perf_counter() - start
    return seconds, json.loads(done.stdout)["submissions"]


def main() -> None:
    """Run the benchmark and report."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--submissions", type=int, default=20)
    parser.add_argument("--jobs", type=int, nargs="+", default=[1, 2])
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory(prefix="pkgtool-bench-grade-") as tmp:
        folder = Path(tmp)
        rubric = _prepare(folder, args.submissions)
        for jobs in args.jobs:
            seconds, graded = _grade(folder, rubric, jobs)
            per = seconds / args.submissions
            rows.append({"jobs": jobs, "submissions": args.submissions,
                         "seconds": round(seconds, 1), "per_submission": round(per, 2),
                         "projected_100": round(per * 100, 1),
                         "full_marks": sum(1 for s in graded if s["score"] == s["max_score"]),
                         "errors": sum(1 for s in graded if s["error"])})
    print(f"{'jobs':>4} {'subs':>5} {'total s':>8} {'s/sub':>6} {'100 subs s':>10} "
          f"{'full':>5} {'errors':>6}")
    for row in rows:
        print(f"{row['jobs']:>4} {row['submissions']:>5} {row['seconds']:>8} "
              f"{row['per_submission']:>6} {row['projected_100']:>10} {row['full_marks']:>5} "
              f"{row['errors']:>6}")
    print(f"target: 100 submissions in {TARGET_PER_SUBMISSION * 100:.0f} s with --jobs 2")
    stamp = datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    RESULTS.mkdir(exist_ok=True)
    record = {"benchmark": "grade", "utc": stamp, "python": platform.python_version(),
              "cpus": os.cpu_count(), "load_average": os.getloadavg(),
              "target_seconds_per_100": TARGET_PER_SUBMISSION * 100, "runs": rows}
    (RESULTS / f"grade-{stamp}.json").write_text(json.dumps(record, indent=2) + "\n")


if __name__ == "__main__":
    main()
