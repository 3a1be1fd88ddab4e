"""Benchmark the Gradescope bundle (not a test): its size, build and setup time, and the time
run_autograder takes per submission, against ``pkgtool grade --format gradescope`` on the same
submission in the same run (the peer: the ratio is the bundle's overhead).

    .venv/bin/python bench/bench_gradescope.py [--runs 2]

Prints a table and writes ``bench/results/gradescope-<UTC time>.json``. Batch throughput with
``--jobs 2`` is bench/bench_grade.py's.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from datetime import datetime, timezone
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "bench" / "results"
RUBRIC = ROOT / "docs" / "rubrics" / "robot_monitor" / "rubric.toml"
REFERENCE = ROOT / "reference_packages" / "robot_monitor"


def _timed(command: list[str], **env: str) -> float:
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, env={**os.environ, **env})
    return round(time.perf_counter() - start, 2)


def main() -> None:
    """Build, set up and run the bundle; time each against the direct grade."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=2)
    runs = parser.parse_args().runs
    pkgtool = str(Path(sys.executable).parent / "pkgtool")
    with tempfile.TemporaryDirectory() as scratch:
        base = Path(scratch)
        bundle = base / "autograder.zip"
        build = _timed([pkgtool, "grade", "-r", str(RUBRIC), "--export-gradescope", str(bundle)])
        size = bundle.stat().st_size
        root = base / "autograder"
        with zipfile.ZipFile(bundle) as archive:
            archive.extractall(root / "source")
        for script in ("setup.sh", "run_autograder"):
            (root / "source" / script).chmod(0o755)
        setup = _timed([str(root / "source" / "setup.sh")], PKGTOOL_AUTOGRADER_ROOT=str(root))
        shutil.copytree(REFERENCE, root / "submission")
        bundled, direct = [], []
        for _ in range(runs):
            bundled.append(_timed([str(root / "source" / "run_autograder")],
                                  PKGTOOL_AUTOGRADER_ROOT=str(root)))
            direct.append(_timed([pkgtool, "grade", str(REFERENCE), "-r", str(RUBRIC), "-f",
                                  "gradescope", "-o", str(base / "direct.json")]))
        score = json.loads((root / "results" / "results.json").read_text())["score"]
    record = {
        "machine": {"python": platform.python_version(), "cpus": os.cpu_count()},
        "bundle_bytes": size,
        "build_seconds": build, "setup_seconds": setup, "score": score,
        "run_autograder_seconds": bundled, "direct_grade_seconds": direct,
        "overhead_ratio": round(sum(bundled) / sum(direct), 2),
    }
    print(json.dumps(record, indent=2))
    RESULTS.mkdir(exist_ok=True)
    stamp = datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    (RESULTS / f"gradescope-{stamp}.json").write_text(json.dumps(record, indent=2) + "\n")


if __name__ == "__main__":
    main()
