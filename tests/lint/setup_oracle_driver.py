"""Run setup.py files with CPython and report the keywords their ``setup()`` calls received.

The oracle of tests/lint/test_setup_eval_oracle.py, started as ``python -I -S`` with the
folder holding setuptools as its only argument. It reads one package folder per line on stdin
and answers one JSON line per folder: ``{"calls": [...], "error": ...}``. setuptools' own
``find_packages`` runs; ``setup`` only records. Sockets and subprocesses are refused, each run
has a time limit, and a run's imports are forgotten before the next. Directory listings are
sorted, and so are the package finders' results (their order is unspecified; the evaluator
assumes sorted order).
"""

from __future__ import annotations

import glob
import json
import os
import runpy
import signal
import socket
import subprocess
import sys
from pathlib import Path
from typing import Any, NoReturn

TIME_LIMIT = 5


def _refuse(*_args: Any, **_kwargs: Any) -> NoReturn:
    raise PermissionError("refused in the setup.py oracle sandbox")


def _sandbox() -> None:
    socket.socket = _refuse  # type: ignore[assignment,misc]
    socket.create_connection = _refuse
    subprocess.Popen = _refuse  # type: ignore[assignment,misc]
    os.system = _refuse
    for name in ("execv", "execve", "fork", "spawnv", "spawnve", "posix_spawn"):
        if hasattr(os, name):
            setattr(os, name, _refuse)
    real_iglob, real_glob = glob.iglob, glob.glob
    glob.glob = lambda *a, **k: sorted(real_glob(*a, **k))
    glob.iglob = lambda *a, **k: iter(sorted(real_iglob(*a, **k)))
    real_path_glob, real_rglob = Path.glob, Path.rglob
    Path.glob = lambda self, *a, **k: iter(sorted(real_path_glob(self, *a, **k)))
    Path.rglob = lambda self, *a, **k: iter(sorted(real_rglob(self, *a, **k)))


def _plain(value: Any) -> Any:
    if isinstance(value, (list, tuple)):
        return [_plain(item) for item in value]
    if isinstance(value, (set, frozenset)):
        return sorted((_plain(item) for item in value), key=repr)
    if isinstance(value, dict):
        return {str(key): _plain(item) for key, item in value.items()}
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if value is None or isinstance(value, (str, int, float, bool)):
        return value
    return {"<unserializable>": type(value).__name__}


def _on_alarm(_signum: int, _frame: Any) -> NoReturn:
    raise TimeoutError("setup.py ran too long")


def _run(folder: str, calls: list[dict[str, Any]]) -> str | None:
    modules, path, argv = set(sys.modules), list(sys.path), list(sys.argv)
    os.chdir(folder)
    sys.path.insert(0, folder)
    sys.argv = ["setup.py"]
    signal.alarm(TIME_LIMIT)
    try:
        runpy.run_path("setup.py", run_name="__main__")
        return None
    except BaseException as error:  # noqa: BLE001  (SystemExit too: the run is what we record)
        return f"{type(error).__name__}: {error}"
    finally:
        signal.alarm(0)
        sys.path[:], sys.argv[:] = path, argv
        for name in set(sys.modules) - modules:
            del sys.modules[name]


def main() -> None:
    sys.path.append(sys.argv[1])
    import setuptools  # noqa: PLC0415  (from the folder given, after the sandbox path set-up)
    import distutils.core  # noqa: PLC0415  (setuptools' copy, installed by its import)

    calls: list[dict[str, Any]] = []

    def record(**kwargs: Any) -> None:
        calls.append(_plain(kwargs))

    setuptools.setup = distutils.core.setup = record
    for name in ("find_packages", "find_namespace_packages"):  # os.walk order, unspecified
        finder = getattr(setuptools, name)
        setattr(setuptools, name, lambda *a, _finder=finder, **k: sorted(_finder(*a, **k)))
    _sandbox()
    signal.signal(signal.SIGALRM, _on_alarm)
    out = os.fdopen(os.dup(1), "w")  # answers; whatever setup.py prints goes to stderr
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    for line in sys.stdin:
        calls.clear()
        error = _run(line.strip(), calls)
        out.write(json.dumps({"calls": calls, "error": error}) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
