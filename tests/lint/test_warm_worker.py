"""The warm worker: forked at a cached run's start, it checks what the cache has no entry for.

Each case runs in a fresh interpreter: the worker is forked only from a process without
threads, and the test runner's may have some.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import pytest

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"),
                                reason="the warm worker is forked on Linux only")


def _run(body: str) -> str:
    script = textwrap.dedent("""\
        import os, time
        from pkgtool.commands import warm_worker
        done = []
        def steps():
            return [lambda: done.append("imported")]
        def whose(item):
            return item, os.getpid()
        """) + textwrap.dedent(body)
    environment = {k: v for k, v in os.environ.items() if k != "PKGTOOL_LINT_JOBS"}
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         timeout=60, env=environment)
    assert run.returncode == 0, run.stderr
    return run.stdout


def test_the_worker_answers_in_another_process_in_order() -> None:
    out = _run("""\
        worker = warm_worker.start(steps)
        if worker is None:  # one core: the run checks its packages itself
            print("no worker")
        else:
            answers = worker.map(whose, ["a", "b", "c"])
            print([item for item, _ in answers], {pid for _, pid in answers} - {os.getpid()})
        """)
    if len(os.sched_getaffinity(0)) > 1:  # CI's two cores: a worker must be forked
        assert out.startswith("['a', 'b', 'c'] {") and "set()" not in out, out
    else:
        assert out == "no worker\n"


def test_a_worker_that_is_gone_answers_none_and_closing_twice_is_harmless() -> None:
    out = _run("""\
        worker = warm_worker.start(steps)
        if worker is None:
            print("None")
        else:
            worker.close()
            print(worker.map(abs, [-1]))
            worker.close()
        """)
    assert out == "None\n"


def test_a_worker_that_dies_answers_none() -> None:
    out = _run("""\
        worker = warm_worker.start(steps)
        print(None if worker is None else worker.map(os._exit, [5]))
        """)
    assert out == "None\n"


def test_a_worker_is_not_forked_when_one_job_is_asked_for() -> None:
    out = _run("""\
        os.environ["PKGTOOL_LINT_JOBS"] = "1"
        print(warm_worker.start(steps))
        """)
    assert out == "None\n"


def test_a_closed_worker_leaves_no_process_behind() -> None:
    out = _run("""\
        worker = warm_worker.start(lambda: [lambda: time.sleep(30)])
        if worker is not None:
            pid = worker._pid
            worker.close()
            try:
                os.kill(pid, 0)
                print("alive")
            except ProcessLookupError:
                print("gone")
        else:
            print("gone")
        """)
    assert out == "gone\n"


def test_no_worker_is_forked_while_a_thread_the_threading_module_never_saw_runs() -> None:
    """A thread started below ``threading`` (``_thread``, as a native library's are) makes
    forking unsafe as much as any other: it is seen in ``/proc/self/task``."""
    out = _run("""\
        import _thread, sys
        _thread.start_new_thread(time.sleep, (30,))
        time.sleep(0.1)
        print("threading" in sys.modules, warm_worker.threads_running(),
              warm_worker.start(steps))
        """)
    assert out == "False True None\n"
