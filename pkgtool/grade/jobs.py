"""Run grading jobs in child processes, ``jobs`` at a time, each under a deadline.

Each job is a fresh (spawned) process, with an address-space cap, that dies with its parent
(``PR_SET_PDEATHSIG``); its
sandboxed steps die with it in turn, and its private mount namespace (the job's tmpfs) with
them. A job that outlives its deadline is killed and scored by ``on_timeout``; one that
dies is reported as such; results are handed to ``on_done`` as each job ends. Whatever way
the parent leaves (an exception, Ctrl-C, SIGTERM), every running job is killed and the
cgroups of every finished or killed job are removed.
"""

from __future__ import annotations

import multiprocessing
import resource
import signal
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from multiprocessing.connection import Connection, wait
from typing import Any

from pkgtool.grade.cgroup import sweep
from pkgtool.grade.sandbox import remove_job_folders
from pkgtool.records import record


@record
class Task:
    """One job: ``function(*args)`` in a child process, killed after ``deadline`` seconds.

    ``failed(reason)`` builds the result of a job that timed out or died.
    """

    function: Callable[..., Any]
    args: tuple[Any, ...]
    deadline: float
    failed: Callable[[str], Any]
    memory_mb: int = 4096
    """Address space of the job's own process (its reading of untrusted files, lint, the
    setup.py evaluator); its sandboxed steps have their own limits."""


def run_tasks(tasks: Sequence[Task], *, jobs: int = 1,
              on_done: Callable[[Any], None] | None = None) -> list[Any]:
    """The result of every task, in order; at most ``jobs`` run at once."""
    context = multiprocessing.get_context("spawn")
    results: dict[int, Any] = {}
    running: dict[int, tuple[Any, Connection, float]] = {}
    waiting = list(range(len(tasks)))
    with _terminate_as_exit():
        try:
            while waiting or running:
                while waiting and len(running) < max(1, jobs):
                    index = waiting.pop(0)
                    receive, send = context.Pipe(duplex=False)
                    process = context.Process(target=_child, args=(send, tasks[index]),
                                              daemon=True)
                    process.start()
                    send.close()
                    running[index] = (process, receive, time.monotonic() + tasks[index].deadline)
                for index, result in _finished(tasks, running):
                    results[index] = result
                    if on_done:
                        on_done(result)
        finally:
            for process, receive, _ in running.values():
                _stop(process, receive)
    return [results[i] for i in range(len(tasks))]


def _finished(tasks: Sequence[Task], running: dict[int, tuple[Any, Connection, float]]
              ) -> Iterator[tuple[int, Any]]:
    """Wait a little; yield (index, result) of every job that ended or ran out of time."""
    soonest = min(deadline for _, _, deadline in running.values())
    ready = wait([r for _, r, _ in running.values()],
                 timeout=max(0.0, min(1.0, soonest - time.monotonic())))
    for index, (process, receive, deadline) in list(running.items()):
        result = None
        if receive in ready:
            try:
                status, value = receive.recv()
                result = value if status == "ok" else tasks[index].failed(value)
            except (EOFError, OSError):
                result = tasks[index].failed(f"the grading process died (exit status "
                                             f"{_exit_status(process)})")
        elif time.monotonic() > deadline:
            result = tasks[index].failed(f"the job ran out of time (deadline "
                                         f"{tasks[index].deadline:g} s)")
        if result is not None:
            del running[index]
            _stop(process, receive)
            yield index, result


def _exit_status(process: Any) -> object:
    process.join(timeout=5)
    return process.exitcode


def _stop(process: Any, receive: Connection) -> None:
    """Kill the job's process (its steps die with it), then remove its cgroups and folder."""
    if process.is_alive():
        process.kill()
    process.join()
    receive.close()
    sweep(process.pid)
    remove_job_folders(process.pid)


def _child(send: Connection, task: Task) -> None:
    from pkgtool.grade.seccomp import die_with_parent

    die_with_parent()
    signal.signal(signal.SIGTERM, _exit)
    size = task.memory_mb * 1024 * 1024  # soft only: the sandbox sets its steps' own limits
    resource.setrlimit(resource.RLIMIT_AS, (size, resource.getrlimit(resource.RLIMIT_AS)[1]))
    try:
        send.send(("ok", task.function(*task.args)))
    except Exception as crash:  # noqa: BLE001 - reported as the job's failure
        send.send(("failed", f"internal error: {type(crash).__name__}: {crash}"))
    finally:
        send.close()


def _exit(signum: int, frame: object) -> None:
    raise SystemExit(128 + signum)


@contextmanager
def _terminate_as_exit() -> Iterator[None]:
    """While jobs run, SIGTERM unwinds like Ctrl-C does, so the jobs are cleaned up."""
    try:
        previous = signal.signal(signal.SIGTERM, _exit)
    except ValueError:  # not the main thread: nothing to install
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)
