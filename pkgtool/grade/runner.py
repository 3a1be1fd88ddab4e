"""Build and test the packages of a job's workspace (``<ws>/src``) with colcon, in the sandbox.

Used by ``pkgtool test`` and by the grading criteria. Every command runs through
:meth:`pkgtool.grade.sandbox.Sandbox.run` with an isolated ROS environment of its own.
"""

from __future__ import annotations

import json
import os
import sys
import sysconfig
from collections.abc import Sequence
from pathlib import Path

from pkgtool.grade.hidden import run_hidden, timeout_args
from pkgtool.testresults import TestSummary, parse_junit
from pkgtool.grade.sandbox import Sandbox
from pkgtool.ros.colcon import ColconRun, colcon_build, colcon_env, colcon_test
from pkgtool.lazy_regex import lazy_pattern

_ERROR_LINE = lazy_pattern(r"^(error: |[\w.]*(Error|Exception)\b)")

_ENTRY_POINT_PROBE = """
import importlib.metadata as md, json, os, sys
fd = int(os.environ.pop('PKGTOOL_RESULTS_FD'))
os.set_inheritable(fd, False)
paths = [p for p in sys.argv[1].split(':') if p]
sys.path.extend(paths)
name = sys.argv[2]
scripts = {ep.name: ep for dist in md.distributions(path=paths) for ep in dist.entry_points
           if ep.group == 'console_scripts'}
ep = scripts.get(name)
if ep is None:
    problem = f'`{name}` is not declared in `console_scripts`'
else:
    try:
        problem = '' if callable(ep.load()) else f'`{ep.value}` is not callable'
    except BaseException as error:
        problem = f'`{ep.value}` cannot be loaded: {type(error).__name__}: {error}'
os.write(fd, json.dumps([name, problem]).encode() + b'\\n')
"""
"""Loads one console script's function in the sandbox; the answer goes to the private pipe
only (``-I``: the submission cannot customise the interpreter before the probe runs)."""


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
        args = [*timeout_args(test_timeout), *(f"--ignore={path}" for path in ignore)]
        run = colcon_test(self.workspace, base_paths=[self.src], env=self.env,
                          packages=[package], pytest_args=args, runner=self.box.run,
                          timeout=self.box.limits.timeout)
        report = self.workspace / "build" / package / "pytest.xml"
        return run, _checked(run, parse_junit(report, within=self.workspace))

    def installed_env(self) -> dict[str, str]:
        """The environment with every installed package of the workspace on the paths.

        The grader's own prefixes stay first on ``AMENT_PREFIX_PATH``: the submission adds
        its packages, it does not replace anyone else's.
        """
        env = dict(self.env)
        env["AMENT_PREFIX_PATH"] = os.pathsep.join([env.get("AMENT_PREFIX_PATH", ""),
                                                    *map(str, self._prefixes())]).strip(":")
        env["PYTHONPATH"] = os.pathsep.join(map(str, self.student_paths()))
        return env

    def _prefixes(self) -> list[Path]:
        install = self.workspace / "install"
        return sorted(p for p in install.iterdir() if p.is_dir() and not p.is_symlink()) \
            if install.is_dir() else []

    def student_paths(self) -> list[Path]:
        """The site-packages folders of the workspace's installed packages."""
        return _site_packages(self._prefixes())

    def pytest(self, source: Path, *,
               test_timeout: float | None = None) -> tuple[ColconRun, TestSummary]:
        """Run the instructor's test folder ``source`` (see :mod:`pkgtool.grade.hidden`)."""
        return run_hidden(self.box, source, self.installed_env(), self.student_paths(),
                          test_timeout)

    def entry_points(self, package: str, names: Sequence[str], *,
                     timeout: float | None = None) -> dict[str, str]:
        """For each console script name, "" when installed and loadable, else the problem.

        Each name is loaded in its own run of at most ``timeout`` seconds: a module that
        hangs at import costs that name only.
        """
        return {name: self._entry_point(package, name, timeout) for name in names}

    def _entry_point(self, package: str, name: str, timeout: float | None) -> str:
        prefixes = [self.workspace / "install" / package]
        command = [sys.executable, "-I", "-B", "-c", _ENTRY_POINT_PROBE,
                   ":".join(map(str, _site_packages(prefixes))), name]
        run = self.box.run(command, self.workspace, self.installed_env(), timeout=timeout,
                           channel=True)
        answer = _answer(run.channel, name)
        if answer is None and run.timed_out:
            return (f"`{name}` did not finish loading ({run.limit}): its module must not run "
                    "the node when imported; start the node in the entry point's function")
        if answer is None:
            return (f"`{name}` could not be checked: its module ended the check while "
                    f"loading ({run.limit or f'exit status {run.returncode}'})")
        if not answer and not os.access(self.workspace / "install" / package / "lib" / package
                                        / name, os.X_OK):
            return (f"`{name}` is not installed in `lib/{package}` (`ros2 run` cannot "
                    "find it; check `setup.cfg`'s script_dir)")
        return answer


def _answer(channel: bytes, name: str) -> str | None:
    """The probe's problem text for ``name`` ("" when fine), or None without a valid answer."""
    try:
        found = json.loads(channel.splitlines()[-1]) if channel.strip() else None
    except ValueError:
        return None
    if not (isinstance(found, list) and len(found) == 2 and found[0] == name
            and isinstance(found[1], str)):
        return None
    return found[1]


def first_error(output: str) -> str | None:
    """The first line of a colcon log that names an error (``SyntaxError: ...``), if any.

    colcon reads what setup.py prints as the package's metadata: output there makes that
    reading fail, which is said in those words, with the printed line.
    """
    if "_get_setup_information" in output and "literal_eval" in output:
        lines = output.splitlines()
        printed = next((lines[i + 1].strip() for i, line in enumerate(lines[:-1])
                        if line.strip().startswith('File "<unknown>"')), "")
        shown = f" (`{printed[:80]}`)" if printed else ""
        return (f"setup.py printed to standard output{shown}: colcon reads that output as "
                "the package's metadata; remove the print (or print to sys.stderr)")
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


def _site_packages(prefixes: Sequence[Path]) -> list[Path]:
    relative = Path(sysconfig.get_path("purelib")).relative_to(sys.prefix)
    return [p / relative for p in prefixes if (p / relative).is_dir()]
