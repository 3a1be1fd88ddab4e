"""Benchmark ``pkgtool lint`` against a plain ``flake8`` run on the same files (not a test).

``flake8`` is the one in the same virtual environment, with the plugins installed there (those
of ament's settings), run with no options; the generated packages are correct, so both tools
report (almost) nothing and the times measure the checks, not the reporting.

Measures, each as wall time of a fresh process (cold start included):

- one package: ``pkgtool lint --no-cache PKG`` versus ``flake8 PKG`` (median of ``--repeat``
  runs, the two tools taking turns), and ``pkgtool lint PKG`` with a warm cache;
- one package of many modules (``--large``, default 50 and 200 sub-packages of bench nodes,
  ~300 and ~1,200 modules) without a cache, its time per module (flat when linear in the
  package's size) and its parse floor;
- generated workspaces (default 100, 500 and 1,000 packages): with the cache emptied before
  each run (cold), packages per second and the time per package at each size (linear in N
  means a flat time per package), versus ``flake8 WS`` (up to ``--flake8-up-to`` packages);
  again with nothing changed (warm cache); and with one module of one package changed.

With ``--hook-venv`` the one-package case, and the warm and one-file-changed workspace runs,
are also timed where pre-commit runs the hook: a fresh virtual environment holding
``pkgtool-ros[style]`` alone (no ROS wheels, whose ``.pth`` re-executes every Python start in
the project's venv, and no editable-install finder). Each workspace also gets its walk floor:
a bare Python process listing every folder and examining every file, the least any cache
keyed by file sizes and times does (the peer of the warm runs), and its parse floor: a bare
Python process reading every ``.py`` file and ``ast.parse``-ing it once, on one core (the peer
of the cold runs: issue 15 set its cold target at about 2.8x that floor's time, measured at
1,400 packages/s where 500 packages/s on 2 cores was asked).

Prints a table and writes the numbers to ``bench/results/lint-<UTC time>.json``; the time of
``python -c pass`` and of flake8 on one package calibrate the machine's load.
Targets (issue 15): one package <= 0.6x flake8; cold >= 500 packages/s on 2 cores, linear to
5,000 (on this machine's speed: cold/parse floor <= ~2.8); warm >= 3,000 packages/s; one file
changed in 500 packages <= 0.3 s.

    .venv/bin/python bench/bench_lint.py [--repeat 5] [--sizes 100 500 1000 5000] [--hook-venv]
"""

from __future__ import annotations

import argparse
import compileall
import json
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable

SCHEMA_LINE = ('<?xml-model href="http://download.ros.org/schema/package_format3.xsd" '
               'schematypens="http://www.w3.org/2001/XMLSchema"?>')
RESULTS = Path(__file__).resolve().parent / "results"
BIN = Path(sys.executable).parent


def _module(index: int) -> str:
    """A plausible node module (~60 lines) importing ROS and third-party code."""
    return f'''"""Node {index}: filters readings and republishes them."""

import math

import numpy as np
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32


class Filter{index}(Node):
    """Publish the smoothed minimum range of a scan."""

    def __init__(self):
        super().__init__('filter_{index}')
        self.declare_parameter('alpha', 0.5)
        self.alpha = self.get_parameter('alpha').value
        self.smoothed = math.inf
        self.subscription = self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
        self.publisher = self.create_publisher(Float32, 'closest', 10)

    def on_scan(self, scan):
        """Smooth the closest valid range."""
        ranges = np.asarray(scan.ranges, dtype=float)
        valid = ranges[np.isfinite(ranges)]
        if valid.size == 0:
            return
        closest = float(valid.min())
        if math.isinf(self.smoothed):
            self.smoothed = closest
        else:
            self.smoothed = self.alpha * closest + (1 - self.alpha) * self.smoothed
        message = Float32()
        message.data = self.smoothed
        self.publisher.publish(message)


def main(args=None):
    """Spin the node until shutdown."""
    rclpy.init(args=args)
    node = Filter{index}()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
'''


def write_package(root: Path, name: str, modules: int = 4) -> None:
    """A complete ament_python package: manifest, setup files, nodes, launch file, tests."""
    scripts = "".join(f"            'node_{i} = {name}.node_{i}:main',\n" for i in range(modules))
    files = {
        "package.xml": f'''<?xml version="1.0"?>
{SCHEMA_LINE}
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>Benchmark package {name}.</description>
  <maintainer email="dev@example.com">Dev</maintainer>
  <license>Apache-2.0</license>
  <depend>rclpy</depend>
  <exec_depend>sensor_msgs</exec_depend>
  <exec_depend>std_msgs</exec_depend>
  <exec_depend>python3-numpy</exec_depend>
  <exec_depend>launch</exec_depend>
  <exec_depend>launch_ros</exec_depend>
  <test_depend>python3-pytest</test_depend>
  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
''',
        "setup.py": f'''from glob import glob
import os

from setuptools import find_packages, setup

package_name = '{name}'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Dev',
    maintainer_email='dev@example.com',
    description='Benchmark package {name}.',
    license='Apache-2.0',
    extras_require={{'test': ['pytest']}},
    entry_points={{
        'console_scripts': [
{scripts}        ],
    }},
)
''',
        "setup.cfg": f"[develop]\nscript_dir=$base/lib/{name}\n"
                     f"[install]\ninstall_scripts=$base/lib/{name}\n",
        f"resource/{name}": "",
        f"{name}/__init__.py": "",
        f"launch/{name}.launch.py": "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\ndef generate_launch_description():\n"
        "    return LaunchDescription([\n" + "".join(
            f"        Node(package='{name}', executable='node_{i}'),\n" for i in range(modules))
        + "    ])\n",
        "test/test_filter.py": f"import pytest\n\nfrom {name}.node_0 import Filter0\n\n\n"
        "@pytest.mark.parametrize('alpha', [0.1, 0.9])\ndef test_alpha(alpha):\n"
        "    assert Filter0 is not None and 0 < alpha < 1\n",
    }
    files.update({f"{name}/node_{i}.py": _module(i) for i in range(modules)})
    for relpath, text in files.items():
        path = root / relpath
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def _time(command: list[str], cwd: Path, repeat: int,
          before: Callable[[int], None] | None = None) -> tuple[float, float, int]:
    """Median wall and CPU (user + system, children included) time of ``repeat`` fresh runs,
    and the exit code of the last. CPU time is less disturbed by other load on the machine.
    ``before(i)`` runs untimed before run ``i`` (empty the cache, change a file).
    """
    walls, cpus, code = [], [], 0
    for run in range(repeat):
        if before is not None:
            before(run)
        start_usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        code = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL).returncode
        walls.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - start_usage.ru_utime + after.ru_stime - start_usage.ru_stime)
    return statistics.median(walls), statistics.median(cpus), code


def _emptied(cache: Path) -> Callable[[int], None]:
    return lambda _: shutil.rmtree(cache, ignore_errors=True)


def _one_file_changed(workspace: Path, size: int) -> Callable[[int], None]:
    """Append a comment to a node module of another package before each run."""
    def change(run: int) -> None:
        name = f"pkg_{(run * 7919) % size:04d}"
        with open(workspace / "src" / name / name / "node_1.py", "a", encoding="utf-8") as f:
            f.write(f"# edited {run}\n")
    return change


def _single(bin_folder: Path, single: Path, repeat: int) -> dict[str, Any]:
    """pkgtool (no cache, warm cache) and flake8 of ``bin_folder`` on one package, taking
    turns run by run: the machine's speed drifts, and a ratio must compare like with like."""
    lint, flake8 = [str(bin_folder / "pkgtool"), "lint"], [str(bin_folder / "flake8")]
    runs = [(_time(lint + ["--no-cache", "."], single, 1), _time(lint + ["."], single, 1),
             _time(flake8 + ["."], single, 1)) for _ in range(repeat)]
    lint_one, lint_cpu = (statistics.median(r[0][i] for r in runs) for i in range(2))
    warm_one = statistics.median(r[1][0] for r in runs)
    flake8_one, flake8_cpu = (statistics.median(r[2][i] for r in runs) for i in range(2))
    return {"pkgtool_s": lint_one, "pkgtool_cpu_s": lint_cpu, "flake8_s": flake8_one,
            "flake8_cpu_s": flake8_cpu, "pkgtool_warm_s": warm_one,
            "ratio_pkgtool_over_flake8": lint_one / flake8_one,
            "ratio_warm_over_flake8": warm_one / flake8_one,
            "pkgtool_exit_code": runs[-1][0][2]}


def hook_environment(work: Path) -> Path:
    """A virtual environment like the one pre-commit gives the hook: pkgtool-ros[style]
    installed from this checkout (not editable, bytecode compiled), no ROS wheels. Its
    ``bin`` folder."""
    venv = work / "hook-venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    checkout = Path(__file__).resolve().parents[1]
    subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--quiet",
                    "--disable-pip-version-check", f"{checkout}[style]"],
                   check=True, env={**os.environ, "PYTHONDONTWRITEBYTECODE": ""})
    return venv / "bin"


def measure(repeat: int, sizes: list[int], flake8_up_to: int, work: Path,
            hook_venv: Path | None = None, large: list[int] | None = None) -> dict[str, Any]:
    """Every measurement as a JSON-ready dict (``hook_venv``: also the one-package case with
    that environment's pkgtool and flake8; ``large``: one package of that many sub-packages
    per size)."""
    lint, flake8 = [str(BIN / "pkgtool"), "lint"], [str(BIN / "flake8")]
    single = work / "single"
    write_package(single, "bench_single")
    python_s, _, _ = _time([sys.executable, "-c", "pass"], work, repeat)
    single_result = _single(BIN, single, repeat)
    result: dict[str, Any] = {
        "calibration": {"python_startup_s": python_s,
                        "flake8_single_s": single_result["flake8_s"]},
        "single": single_result}
    if hook_venv is not None:
        result["single_hook_venv"] = _single(hook_venv, single, repeat)
    workspaces: list[dict[str, Any]] = []
    runs = max(1, repeat // 2)
    for size in sizes:
        workspace = work / f"ws{size}"
        for index in range(size):
            write_package(workspace / "src" / f"pkg_{index:04d}", f"pkg_{index:04d}")
        cache = workspace / ".pkgtool_cache"
        lint_ws, lint_cpu, code = _time(lint + ["."], workspace, runs, _emptied(cache))
        time.sleep(2.1)  # files older than 2 s are trusted by size and time, as in real use
        warm_ws, _, _ = _time(lint + ["."], workspace, repeat)
        changed_ws, _, _ = _time(lint + ["."], workspace, repeat,
                                 _one_file_changed(workspace, size))
        flake8_ws = _time(flake8 + ["."], workspace, 1)[0] if size <= flake8_up_to else None
        floor_ws, _, _ = _time([sys.executable, "-S", "-c", WALK_FLOOR, "."], workspace, repeat)
        parse_ws, _, _ = _time([sys.executable, "-S", "-c", PARSE_FLOOR, "."], workspace, runs)
        hooked = _hook_workspace(hook_venv, workspace, size, repeat) if hook_venv else {}
        workspaces.append({
            "packages": size, "pkgtool_s": lint_ws, "pkgtool_cpu_s": lint_cpu,
            "packages_per_s": size / lint_ws, "ms_per_package": 1000 * lint_ws / size,
            "cpu_ms_per_package": 1000 * lint_cpu / size, "warm_s": warm_ws,
            "warm_packages_per_s": size / warm_ws, "one_file_changed_s": changed_ws,
            "flake8_s": flake8_ws,
            "ratio_pkgtool_over_flake8": lint_ws / flake8_ws if flake8_ws else None,
            "walk_floor_s": floor_ws, "parse_floor_s": parse_ws,
            "ratio_cold_over_parse_floor": lint_ws / parse_ws,
            "pkgtool_exit_code": code, **hooked})
    result["workspaces"] = workspaces
    result["large_packages"] = [_large_package(work, size, runs) for size in large or []]
    return result


def _large_package(work: Path, size: int, runs: int) -> dict[str, Any]:
    """One package holding ``size`` Python sub-packages of bench nodes, linted without a cache:
    the time per module stays flat as the package grows when no work is repeated per module."""
    package = work / f"large{size}"
    for index in range(size):
        write_package(package, f"pkg_{index:04d}")  # one manifest; the node folders add up
    modules = sum(1 for _ in package.rglob("*.py"))
    lint_s, lint_cpu, _ = _time([str(BIN / "pkgtool"), "lint", "--no-cache", "."], package, runs)
    parse_s, _, _ = _time([sys.executable, "-S", "-c", PARSE_FLOOR, "."], package, runs)
    return {"sub_packages": size, "modules": modules, "pkgtool_s": lint_s,
            "pkgtool_cpu_s": lint_cpu, "ms_per_module": 1000 * lint_s / modules,
            "parse_floor_s": parse_s, "ratio_over_parse_floor": lint_s / parse_s}


WALK_FLOOR = """
import os, sys
stack, found = [sys.argv[1]], 0
while stack:
    with os.scandir(stack.pop()) as entries:
        for entry in entries:
            if entry.is_dir(follow_symlinks=False):
                stack.append(entry.path)
            else:
                entry.stat()
                found += 1
"""
"""The floor of a warm run: a bare Python process listing every folder and examining every
file (what any cache keyed by file sizes and times must do), with no imports beyond ``os``."""

PARSE_FLOOR = """
import ast, os, sys
for folder, folders, files in os.walk(sys.argv[1]):
    folders[:] = [name for name in folders if not name.startswith(".")]
    for name in files:
        if name.endswith(".py"):
            with open(os.path.join(folder, name), "rb") as stream:
                ast.parse(stream.read())
"""
"""The floor of a cold run (issue 15's yardstick): every Python file read and parsed once,
single-threaded, nothing else."""


def _hook_workspace(hook_venv: Path, workspace: Path, size: int, repeat: int
                    ) -> dict[str, Any]:
    """Warm and one-file-changed runs with the hook environment's pkgtool (no ROS ``.pth``
    re-executing every Python start), after one cold run that fills its own cache."""
    lint = [str(hook_venv / "pkgtool"), "lint", "--cache-dir", ".pkgtool_cache_hook", "."]
    subprocess.run(lint, cwd=workspace, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(2.1)
    warm, _, _ = _time(lint, workspace, repeat)
    changed, _, _ = _time(lint, workspace, repeat, _one_file_changed(workspace, size))
    return {"hook_warm_s": warm, "hook_warm_packages_per_s": size / warm,
            "hook_one_file_changed_s": changed}


def _cell(value: float | None, form: str) -> str:
    return "-" if value is None else format(value, form)


def _single_row(label: str, single: dict[str, Any]) -> tuple[str, ...]:
    return (label, f"{single['pkgtool_s']:.3f}", f"{single['pkgtool_cpu_s']:.3f}",
            f"{single['flake8_s']:.3f}", f"{single['ratio_pkgtool_over_flake8']:.2f}", "", "",
            f"{single['pkgtool_warm_s']:.3f}", "", "")


def table(result: dict[str, Any]) -> str:
    """The measurements as an aligned text table."""
    rows = [("case", "pkgtool s", "cpu s", "flake8 s", "pkgtool/flake8", "packages/s",
             "ms/package", "warm s", "warm pkg/s", "1 changed s"),
            *(_single_row(label, result[key]) for label, key in
              (("1 package", "single"), ("1 package, hook venv", "single_hook_venv"))
              if key in result)]
    for ws in result["workspaces"]:
        rows.append((f"{ws['packages']} packages", f"{ws['pkgtool_s']:.3f}",
                     f"{ws['pkgtool_cpu_s']:.3f}", _cell(ws["flake8_s"], ".3f"),
                     _cell(ws["ratio_pkgtool_over_flake8"], ".2f"),
                     f"{ws['packages_per_s']:.0f}", f"{ws['ms_per_package']:.2f}",
                     f"{ws['warm_s']:.3f}", f"{ws['warm_packages_per_s']:.0f}",
                     f"{ws['one_file_changed_s']:.3f}"))
        if "hook_warm_s" in ws:
            rows.append((f"{ws['packages']} packages, hook venv", "", "", "", "", "", "",
                         f"{ws['hook_warm_s']:.3f}", f"{ws['hook_warm_packages_per_s']:.0f}",
                         f"{ws['hook_one_file_changed_s']:.3f}"))
        rows.append((f"{ws['packages']} packages, walk floor", "", "", "", "", "", "",
                     f"{ws['walk_floor_s']:.3f}", f"{ws['packages'] / ws['walk_floor_s']:.0f}",
                     ""))
        rows.append((f"{ws['packages']} packages, parse floor", f"{ws['parse_floor_s']:.3f}",
                     "", "", f"cold/floor {ws['ratio_cold_over_parse_floor']:.1f}",
                     f"{ws['packages'] / ws['parse_floor_s']:.0f}", "", "", "", ""))
    for big in result.get("large_packages", []):
        rows.append((f"1 package of {big['modules']} modules", f"{big['pkgtool_s']:.3f}",
                     f"{big['pkgtool_cpu_s']:.3f}", "", f"cold/floor "
                     f"{big['ratio_over_parse_floor']:.1f}", "",
                     f"{big['ms_per_module']:.2f}/module", "", "", ""))
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    lines = ["  ".join(c.rjust(w) for c, w in zip(row, widths)) for row in rows]
    calibration = result["calibration"]
    lines.append(f"\ncalibration: python -c pass {calibration['python_startup_s']:.3f} s, "
                 f"flake8 on one package {calibration['flake8_single_s']:.3f} s")
    return "\n".join(lines)


def main() -> int:
    """Run the benchmark, print the table, save the JSON."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--sizes", type=int, nargs="+", default=[100, 500, 1000])
    parser.add_argument("--large", type=int, nargs="*", default=[50, 200],
                        help="also lint one package holding this many sub-packages of bench "
                             "nodes (time per module: flat when linear)")
    parser.add_argument("--flake8-up-to", type=int, default=500,
                        help="time flake8 on workspaces up to this many packages")
    parser.add_argument("--hook-venv", action="store_true",
                        help="also time one package, and warm workspaces, in a fresh venv "
                             "holding pkgtool-ros[style] alone, as pre-commit installs the "
                             "hook (needs the package index)")
    args = parser.parse_args()
    # An installed pkgtool has its bytecode compiled; a checkout run with
    # PYTHONDONTWRITEBYTECODE would compile every module on every start.
    compileall.compile_dir(str(Path(__file__).resolve().parents[1] / "pkgtool"), quiet=1)
    with tempfile.TemporaryDirectory(prefix="pkgtool-bench-") as work:
        hook = hook_environment(Path(work)) if args.hook_venv else None
        result = measure(args.repeat, args.sizes, args.flake8_up_to, Path(work), hook,
                         args.large)
    result["machine"] = {"cpus": os.cpu_count(), "python": platform.python_version(),
                         "platform": platform.platform(),
                         "load_average": os.getloadavg()}
    stamp = datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    RESULTS.mkdir(parents=True, exist_ok=True)
    output = RESULTS / f"lint-{stamp}.json"
    output.write_text(json.dumps(result, indent=2) + "\n")
    print(table(result))
    print(f"\nsaved {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
