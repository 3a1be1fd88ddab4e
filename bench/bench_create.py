"""Benchmark ``pkgtool create`` against peers timed in the same run (not a test).

Each figure is the median wall time of ``--repeat`` fresh processes, after one warm-up run:

- ``create-small``: ``pkgtool create`` of a package with one node;
- ``create-full``: every node kind, a library, a launch file and a parameters file;
- ``python -c pass``: the interpreter's own start (the floor for any Python CLI);
- ``cp -r``: copying the full package's tree (the floor for writing those files).

Also reported: the in-process time of ``commands.create.run`` (full package, warm), which is
what ``create`` adds on top of starting the CLI. Prints a table and writes the numbers to
``bench/results/create-<UTC time>.json``. Target: ``create-full`` well under 0.3 s.

Child processes run without PYTHONDONTWRITEBYTECODE, as a normal install would: with it set
and a venv installed without bytecode (uv's default), every start recompiles jinja2 and typer.

    .venv/bin/python bench/bench_create.py [--repeat 15]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"
BIN = Path(sys.executable).parent
MAINTAINER = ["--maintainer-name", "Bench Mark", "--maintainer-email", "bench@example.com",
              "--copyright-year", "2026"]
NODES = ["talker:publisher", "listener:subscriber", "server:service", "caller:client",
         "fib_server:action-server", "fib_client:action-client", "beat:timer"]
FULL = [arg for spec in NODES for arg in ("--node", spec)] + [
    "--launch", "--config", "--library-name", "util", "--dependencies", "numpy"]
TARGET = 0.3


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def _timed(make_args, repeat: int) -> list[float]:
    """Wall times of ``repeat`` runs of ``make_args(i)`` (fresh commands), after a warm-up."""
    times = []
    for index in range(repeat + 1):
        args = make_args(index)
        start = time.perf_counter()
        subprocess.run(args, env=_env(), stdout=subprocess.DEVNULL, check=True)
        if index:
            times.append(time.perf_counter() - start)
    return times


def _in_process(work: Path, repeat: int) -> list[float]:
    from pkgtool.commands.create import Request, run

    times = []
    for index in range(repeat + 1):
        request = Request(name="inproc", destination=work / f"inproc{index}", nodes=tuple(NODES),
                          launch=True, config=True, library_name="util",
                          dependencies=("numpy",), maintainer_name="Bench Mark",
                          maintainer_email="bench@example.com", year=2026)
        start = time.perf_counter()
        assert not run(request).error
        if index:
            times.append(time.perf_counter() - start)
    return times


def main() -> int:
    """Run the benchmark, print the table and write the JSON file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=15)
    args = parser.parse_args()
    pkgtool = [str(BIN / "python"), "-m", "pkgtool", "create"]
    with tempfile.TemporaryDirectory(prefix="bench-create-") as tmp:
        work = Path(tmp)
        rows = {
            "python -c pass": _timed(lambda i: [str(BIN / "python"), "-c", "pass"], args.repeat),
            "create-small": _timed(lambda i: [*pkgtool, "small", "--destination-directory",
                                              str(work / f"s{i}"), *MAINTAINER, "--node",
                                              "talker:publisher"], args.repeat),
            "create-full": _timed(lambda i: [*pkgtool, "full", "--destination-directory",
                                             str(work / f"f{i}"), *MAINTAINER, *FULL],
                                  args.repeat),
            "cp -r (full tree)": _timed(lambda i: ["cp", "-r", str(work / "f0" / "full"),
                                                   str(work / f"copy{i}")], args.repeat),
            "run() in-process (full)": _in_process(work, args.repeat),
        }
    medians = {name: statistics.median(times) for name, times in rows.items()}
    full = medians["create-full"]
    print(f"{'what':<26}{'median s':>10}{'min s':>9}{'max s':>9}")
    for name, times in rows.items():
        print(f"{name:<26}{medians[name]:>10.4f}{min(times):>9.4f}{max(times):>9.4f}")
    ratios = {"create-full / python -c pass": full / medians["python -c pass"],
              "create-full / cp -r": full / medians["cp -r (full tree)"]}
    for name, value in ratios.items():
        print(f"{name:<34}{value:>8.2f}x")
    verdict = "met" if full < TARGET else "MISSED"
    print(f"target: create-full < {TARGET} s: {verdict} ({full:.3f} s)")
    RESULTS.mkdir(exist_ok=True)
    stamp = datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    out = RESULTS / f"create-{stamp}.json"
    out.write_text(json.dumps({
        "benchmark": "create", "utc": stamp, "repeat": args.repeat,
        "machine": {"python": platform.python_version(), "cpus": os.cpu_count(),
                    "platform": platform.platform()},
        "median_seconds": medians, "seconds": rows, "ratios": ratios,
        "target_seconds": TARGET, "target_met": full < TARGET,
        "cp": shutil.which("cp")}, indent=2) + "\n")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
