"""Build and test the packages of a job's workspace (``<ws>/src``) with colcon, in the sandbox.

Used by ``pkgtool test`` and by the grading criteria. Every command runs through
:meth:`pkgtool.grade.sandbox.Sandbox.run` with an isolated ROS environment of its own.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import secrets
import shutil
import sys
import sysconfig
from collections.abc import Sequence
from pathlib import Path

from pkgtool.testresults import TestSummary, parse_junit
from pkgtool.grade.sandbox import Sandbox
from pkgtool.ros.colcon import ColconRun, colcon_build, colcon_env, colcon_test

_ERROR_LINE = re.compile(r"^(error: |[\w.]*(Error|Exception)\b)")

_ENTRY_POINT_PROBE = """
import importlib.metadata as md, json, sys
scripts = {}
for dist in md.distributions(path=sys.argv[1].split(':')):
    for ep in dist.entry_points:
        if ep.group == 'console_scripts':
            scripts[ep.name] = ep
for name in sys.argv[2:]:
    ep = scripts.get(name)
    if ep is None:
        problem = f'`{name}` is not declared in `console_scripts`'
    else:
        try:
            problem = '' if callable(ep.load()) else f'`{ep.value}` is not callable'
        except BaseException as error:
            problem = f'`{ep.value}` cannot be loaded: {type(error).__name__}: {error}'
    print('PKGTOOL-ENTRY-POINT ' + json.dumps([name, problem]), flush=True)
"""


class WorkspaceRunner:
    """colcon build/test and pytest runs in ``box.workspace`` (sources under ``src``)."""

    def __init__(self, box: Sandbox, *, domain_id: int) -> None:
        """Prepare the isolated ROS environment (domain ``domain_id``) of this workspace."""
        self.box = box
        self.workspace = box.workspace
        self.env = colcon_env(self.workspace, domain_id=domain_id, base=box.base_env())
        box.give(self.workspace)

    @property
    def src(self) -> Path:
        """Where the sources to build live."""
        return self.workspace / "src"

    def build(self, packages: Sequence[str]) -> ColconRun:
        """``colcon build --packages-up-to`` the given packages."""
        return colcon_build(self.workspace, base_paths=[self.src], env=self.env,
                            packages=packages, runner=self.box.run,
                            timeout=self.box.limits.timeout)

    def test(self, package: str, *, test_timeout: float | None = None,
             ignore: Sequence[str] = ()) -> tuple[ColconRun, TestSummary]:
        """``colcon test`` one package and read its ``pytest.xml``."""
        args = [*_timeout_args(test_timeout), *(f"--ignore={path}" for path in ignore)]
        run = colcon_test(self.workspace, base_paths=[self.src], env=self.env,
                          packages=[package], pytest_args=args, runner=self.box.run,
                          timeout=self.box.limits.timeout)
        report = self.workspace / "build" / package / "pytest.xml"
        return run, _checked(run, parse_junit(report, within=self.workspace))

    def installed_env(self) -> dict[str, str]:
        """The environment with every installed package of the workspace on the paths."""
        env = dict(self.env)
        install = self.workspace / "install"
        prefixes = sorted(p for p in install.iterdir() if p.is_dir()) if install.is_dir() else []
        env["AMENT_PREFIX_PATH"] = os.pathsep.join([*map(str, prefixes),
                                                    env.get("AMENT_PREFIX_PATH", "")])
        env["PYTHONPATH"] = os.pathsep.join(str(p) for p in _site_packages(prefixes))
        return env

    def pytest(self, source: Path, *, into: Path,
               test_timeout: float | None = None) -> tuple[ColconRun, TestSummary]:
        """Copy the instructor's test folder ``source`` into ``into`` and run it there.

        ``into`` (a folder of the package copy) gets a fresh, randomly named, root-owned
        folder holding the tests and an empty pytest configuration: only the tests' own
        conftest files apply, nothing of the package around them (setup.cfg, pytest.ini,
        conftest.py) can change the run, and the sandboxed user cannot edit the tests.
        """
        token = secrets.token_hex(6)
        home = Path(os.path.realpath(into)) / f"pkgtool_hidden_{token}"
        if not str(home).startswith(os.path.realpath(self.workspace) + os.sep):
            return _refused("the package folder was replaced by a link out of the workspace")
        home.mkdir(mode=0o755)
        tests = home / source.name
        shutil.copytree(source, tests, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        config = home / "pytest.ini"
        config.write_text("[pytest]\n")
        report = self.workspace / f"hidden-{token}.xml"
        command = [sys.executable, "-m", "pytest", "-c", str(config), "--rootdir", str(tests),
                   "--confcutdir", str(tests), "-p", "no:cacheprovider", "-o",
                   "junit_family=xunit2", f"--junit-xml={report}", *_timeout_args(test_timeout),
                   str(tests)]
        run = self.box.run(command, tests, self.installed_env())
        return run, _checked(run, parse_junit(report, within=self.workspace))

    def entry_points(self, package: str, names: Sequence[str], *,
                     timeout: float | None = None) -> dict[str, str]:
        """For each console script name, "" when installed and loadable, else the problem.

        Each name is loaded in its own run of at most ``timeout`` seconds: a module that
        hangs at import costs that name only.
        """
        return {name: self._entry_point(package, name, timeout) for name in names}

    def _entry_point(self, package: str, name: str, timeout: float | None) -> str:
        prefixes = [self.workspace / "install" / package]
        command = [sys.executable, "-c", _ENTRY_POINT_PROBE,
                   ":".join(map(str, _site_packages(prefixes))), name]
        run = self.box.run(command, self.workspace, self.installed_env(), timeout=timeout)
        found = dict(json.loads(line.split(" ", 1)[1]) for line in run.output.splitlines()
                     if line.startswith("PKGTOOL-ENTRY-POINT "))
        if name not in found and run.timed_out:
            return (f"`{name}` did not finish loading ({run.limit}): its module must not run "
                    "the node when imported; start the node in the entry point's function")
        problem = found.get(name, f"`{name}` could not be checked ({run.limit or 'crashed'})")
        if not problem and not os.access(self.workspace / "install" / package / "lib" / package
                                         / name, os.X_OK):
            problem = (f"`{name}` is not installed in `lib/{package}` (`ros2 run` cannot "
                       "find it; check `setup.cfg`'s script_dir)")
        return problem


def first_error(output: str) -> str | None:
    """The first line of a colcon log that names an error (``SyntaxError: ...``), if any."""
    return next((line.strip() for line in output.splitlines()
                 if _ERROR_LINE.match(line.strip())), None)


def _refused(problem: str) -> tuple[ColconRun, TestSummary]:
    return ColconRun((), 1, problem, 0.0), TestSummary(problem=problem)


def _checked(run: ColconRun, summary: TestSummary) -> TestSummary:
    """``summary``, unless the run failed while its report says every test passed.

    The report is written by a process that also runs the submission's code: a report of
    success from a failed run is not believed.
    """
    if summary.ok and run.returncode != 0:
        return TestSummary(problem="the test report claims success but the test run failed "
                                   f"(exit status {run.returncode}); it is not counted")
    return summary


def _timeout_args(seconds: float | None) -> list[str]:
    """pytest-timeout's per-test limit, when that plugin is installed."""
    if not seconds or importlib.util.find_spec("pytest_timeout") is None:
        return []
    return [f"--timeout={seconds:g}"]


def _site_packages(prefixes: Sequence[Path]) -> list[Path]:
    relative = Path(sysconfig.get_path("purelib")).relative_to(sys.prefix)
    return [p / relative for p in prefixes if (p / relative).is_dir()]
