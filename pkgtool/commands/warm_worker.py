"""A process forked at the start of a cached lint run, to check what changed since the last one.

After an edit in a large workspace, a lint run spends its time on two things that need not
wait for each other: reading the cache (a ``stat`` of every file, the record of the last run,
the settings and the lookups) and importing the linter (the model, the rules, lxml) to check
the few packages that changed. On one core they add up. :func:`start` forks a worker that
imports the linter while the run reads the cache on another core; :meth:`WarmWorker.map` then
hands it the packages to check and waits for their outcomes, and :meth:`WarmWorker.close`
stops it when the run needs nothing from it (nothing changed, or enough changed that a pool of
processes checks them).

Only on Linux (where forking a process without threads is safe and cheap) and never when
``$PKGTOOL_LINT_JOBS`` is 1. Whatever goes wrong with the worker (it died, its answer cannot be
read), :meth:`WarmWorker.map` returns None and the run checks the packages itself: the
findings never depend on it.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable, Sequence
from typing import Any, Optional


class WarmWorker:
    """The forked worker: its process id and the two ends of the pipes the parent keeps."""

    def __init__(self, pid: int, send: int, receive: int) -> None:
        self._pid: Optional[int] = pid
        self._send = send
        self._receive = receive

    def map(self, function: Callable[[Any], Any], items: Sequence[Any]) -> Optional[list[Any]]:
        """``function`` applied to each item in the worker, in order; None when the worker is
        gone or failed (the caller then does the work). The worker serves one call."""
        if self._pid is None:
            return None
        import pickle  # only here: a run that needs no worker does not pay for it

        results: Any = None
        try:
            with os.fdopen(self._send, "wb") as pipe:
                self._send = -1
                pickle.dump((function, list(items)), pipe, protocol=pickle.HIGHEST_PROTOCOL)
            with os.fdopen(self._receive, "rb") as pipe:
                self._receive = -1
                results = pickle.load(pipe)
        except (OSError, EOFError, pickle.PickleError, AttributeError, ValueError, TypeError):
            results = None
        self.close()
        return results if isinstance(results, list) and len(results) == len(items) else None

    def close(self) -> None:
        """Stop the worker (whatever it is doing) and release its pipes; idempotent."""
        for end in (self._send, self._receive):
            if end >= 0:
                os.close(end)
        self._send = self._receive = -1
        if self._pid is not None:
            import signal  # only here, as select below: a run that forks nothing skips both

            try:
                os.kill(self._pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            os.waitpid(self._pid, 0)
            self._pid = None


def start(warm_up: Callable[[], Iterable[Callable[[], None]]]) -> Optional[WarmWorker]:
    """Fork a worker that runs the steps ``warm_up()`` gives (imports, tables) until the call
    of :meth:`WarmWorker.map` comes, then serves it; None where a worker is not used (not
    Linux, one core, threads running, one job asked for)."""
    if not may_fork():
        return None
    from_parent, to_child = os.pipe()
    from_child, to_parent = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        os.close(to_child)
        os.close(from_child)
        _serve(warm_up, from_parent, to_parent)
    os.close(from_parent)
    os.close(to_parent)
    return WarmWorker(pid, to_child, from_child)


def forked(call: Callable[[], Any]) -> Optional[Callable[[], Any]]:
    """Start ``call()`` in a forked child now; a function that waits for the child and gives
    what ``call`` returned (None when the child failed or its answer cannot be read). None
    where a child is not used (the same conditions as :func:`start`)."""
    if not may_fork():
        return None
    import gc

    receive, send = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    gc.freeze()  # the child's collections never walk (and copy) what it inherits
    pid = os.fork()
    if pid == 0:
        os.close(receive)
        _answer(call, send)
    gc.unfreeze()
    os.close(send)
    return lambda: _answer_of(pid, receive)


def _answer(call: Callable[[], Any], send: int) -> None:
    """The forked child's life: run ``call``, send its result, exit (without the parent's exit
    handlers or buffers)."""
    code = 1
    try:
        import pickle

        result = call()
        with os.fdopen(send, "wb") as pipe:
            pickle.dump(result, pipe, protocol=pickle.HIGHEST_PROTOCOL)
        code = 0
    except BaseException:  # noqa: BLE001 - anything: the parent does the work itself
        pass
    finally:
        os._exit(code)


def _answer_of(pid: int, receive: int) -> Any:
    """What the child ``pid`` sends on ``receive`` (None when it failed); waits for its end."""
    import pickle

    try:
        with os.fdopen(receive, "rb") as pipe:
            result = pickle.load(pipe)
    except (OSError, EOFError, pickle.PickleError, AttributeError, ValueError, TypeError):
        result = None
    _, status = os.waitpid(pid, 0)
    return result if status == 0 else None


def may_fork() -> bool:
    """True where a helper process is forked: on Linux (forking a process without threads is
    safe and cheap there), with two cores or more (on one, a helper only slows the run down),
    unless one job is asked for, and never while this process runs threads (unsafe)."""
    return sys.platform.startswith("linux") and chosen_jobs() != 1 and cores() >= 2 and \
        not threads_running()


def chosen_jobs() -> int:
    """The number of processes ``$PKGTOOL_LINT_JOBS`` asks for (1: no pool, no worker); 0
    when it is not set or not a number."""
    try:
        return max(0, int(os.environ.get("PKGTOOL_LINT_JOBS", "0")))
    except ValueError:
        return 0


def cores() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        return os.cpu_count() or 1


def threads_running() -> bool:
    """True when this process runs other threads (forking it then is unsafe): Python's, or
    native ones a library started (a DDS middleware's, after rclpy ran in the process), as
    Linux lists them in ``/proc/self/task``. Elsewhere, a process that never imported
    ``threading`` started no Python thread (importing it costs a small run ~1 ms)."""
    try:
        return len(os.listdir("/proc/self/task")) > 1
    except OSError:
        threading = sys.modules.get("threading")
        return threading is not None and threading.active_count() > 1


def _serve(warm_up: Callable[[], Iterable[Callable[[], None]]], receive: int, send: int
           ) -> None:
    """The worker's life: warm up until the call comes (a step left undone is done when the
    call needs it), answer it, exit (without running the parent's exit handlers or flushing
    its buffers)."""
    import select

    code = 1
    try:
        for step in warm_up():
            if select.select([receive], [], [], 0)[0]:
                break
            step()
        import pickle

        with os.fdopen(receive, "rb") as pipe:
            function, items = pickle.load(pipe)
        results = [function(item) for item in items]
        with os.fdopen(send, "wb") as pipe:
            pickle.dump(results, pipe, protocol=pickle.HIGHEST_PROTOCOL)
        code = 0
    except BaseException:  # noqa: BLE001 - EOF (not needed), Ctrl-C, anything: the parent copes
        pass
    finally:
        os._exit(code)
