"""Issue 11, mounted for real: one `pkgtool grade --batch --jobs 2` over attacking submissions.

Each attack (tests/grade/attacks.py) tries to gain instructor-test points, read secrets,
or leave traces on this machine; every one of them worked against the grader before.
The batch runs once; each test checks one attack's score and what the machine shows.
"""

from __future__ import annotations

import json
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
import uuid
from pathlib import Path
from typing import Any

import pytest

from pkgtool.grade.jail import jail_support
from tests.grade import attacks, synthetic
from tests.helpers import no_process_with, processes_with, run_cli

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

Batch = dict[str, Any]
HIDDEN_POINTS = 4


@pytest.fixture(scope="module")
def batch(tmp_path_factory: pytest.TempPathFactory) -> Batch:
    if jail_support().mode != "root":
        pytest.skip(f"the full sandbox needs root with namespaces: {jail_support().reason}")
    root = tmp_path_factory.mktemp("attacks")
    subs = root / "submissions"
    for name, files in attacks.variants(subs / "correct").items():
        synthetic.write_submission(subs / name, files)
    attacks.write_link_attack(subs / "link_to_bob", subs / "correct")
    victim = root / "victim" / "notes.txt"
    victim.parent.mkdir()
    victim.write_text("original\n")
    attacks.write_tar_escape(subs / "tar_escape.tar.gz", victim)
    token = uuid.uuid4().hex[:12]
    ipc_key = int(token[:7], 16)
    listener = socket.socket(socket.AF_UNIX)
    listener.bind(str(root / "host.sock"))
    listener.listen()
    abstract = socket.socket(socket.AF_UNIX)
    abstract.bind(f"\0pkgtool-{token}")
    abstract.listen()
    rubric = root / "rubric.toml"
    probes = {"rubric": str(rubric), "hidden tests": str(attacks.HIDDEN),
              "submissions": str(subs), "bob": str(subs / "correct"),
              "host socket": f"socket:{root / 'host.sock'}",
              "abstract socket": f"socket:@pkgtool-{token}"}
    synthetic.write_submission(subs / "harm", attacks.harm(probes, ipc_key))
    rubric.write_text(attacks.RUBRIC.format(disk_mb=64, hidden_points=HIDDEN_POINTS,
                                            hidden=attacks.HIDDEN))
    try:
        result = run_cli("grade", "submissions", "--batch", "--rubric", "rubric.toml",
                         "--jobs", "2", "--format", "json", "--output", "report.json", cwd=root)
    finally:
        listener.close()
        abstract.close()
    assert result.exit_code == 0, result.output
    report = json.loads((root / "report.json").read_text())
    return {"graded": {s["label"]: s for s in report["submissions"]}, "ipc_key": ipc_key,
            "victim": victim}


def _criterion(entry: dict[str, Any], kind: str) -> dict[str, Any]:
    return next(c for c in entry["criteria"] if c["kind"] == kind)


def _hidden(batch: Batch, label: str) -> tuple[float, str]:
    criterion = _criterion(batch["graded"][label], "hidden")
    return criterion["score"], "\n".join(criterion["feedback"])


def test_the_correct_submission_gets_full_marks(batch: Batch) -> None:
    entry = batch["graded"]["correct"]
    assert entry["score"] == entry["max_score"], json.dumps(entry, indent=1)


@pytest.mark.parametrize(("label", "passed"), [
    ("plugin_entry_point", 1), ("sitecustomize", 1), ("fake_pytest", 1),
    ("shadow_std_msgs", 0),  # the shadow breaks the student's own node: its test fails too
])
def test_the_submission_cannot_change_the_instructors_pytest(batch: Batch, label: str,
                                                             passed: int) -> None:
    score, feedback = _hidden(batch, label)
    assert score == HIDDEN_POINTS * passed / attacks.HIDDEN_TESTS, feedback
    words = f"{passed} passed, {attacks.HIDDEN_TESTS - passed} failed" if passed else \
        f"{attacks.HIDDEN_TESTS} failed"
    assert words in feedback, feedback
    for name in ("format", "keeps_spaces", "fits_a_message"):
        assert f"FAILED test_attack.test_greeting_{name}" in feedback, feedback


def test_a_node_cannot_forge_the_results(batch: Batch) -> None:
    score, feedback = _hidden(batch, "forger")
    assert score == HIDDEN_POINTS / attacks.HIDDEN_TESTS, feedback
    assert "1 passed, 3 failed" in feedback, feedback


def test_a_spoofed_probe_answer_is_the_students_failure(batch: Batch) -> None:
    entry = batch["graded"]["spoof_probe"]
    assert entry["error"] is None, entry["error"]
    feedback = "\n".join(_criterion(entry, "executables")["feedback"])
    assert _criterion(entry, "executables")["score"] == 0
    assert "`talker_pkg.talker:main` cannot be loaded: SystemExit" in feedback, feedback


def test_a_link_to_another_submission_is_not_graded_as_it(batch: Batch) -> None:
    entry = batch["graded"]["link_to_bob"]
    assert entry["score"] == 0 and "no package named `talker_pkg`" in entry["error"], entry


def test_an_archive_cannot_write_outside_the_job(batch: Batch) -> None:
    """CVE-2025-4517's link chain: refused with the reason; the victim folder is untouched."""
    entry = batch["graded"]["tar_escape"]
    assert entry["score"] == 0 and "longer than 1024 bytes" in entry["error"], entry
    victim = batch["victim"]
    assert victim.read_text() == "original\n"
    assert sorted(p.name for p in victim.parent.iterdir()) == [victim.name]


def test_output_of_setup_py_gets_a_precise_reason(batch: Batch) -> None:
    entry = batch["graded"]["printing_setup"]
    feedback = "\n".join(_criterion(entry, "build")["feedback"])
    assert "setup.py printed to standard output (`hello from setup.py`)" in feedback, feedback
    assert "internal error" not in json.dumps(entry)


def test_a_fifo_for_a_report_does_not_hang_the_grader(batch: Batch) -> None:
    entry = batch["graded"]["fifo_report"]
    tests = _criterion(entry, "tests")
    assert tests["score"] == 0 and "not a plain file" in "\n".join(tests["feedback"])
    assert _criterion(entry, "hidden")["score"] == HIDDEN_POINTS


def test_secrets_and_other_jobs_are_out_of_reach(batch: Batch) -> None:
    entry = batch["graded"]["harm"]
    output = _criterion(entry, "tests")["output"]
    assert "PASSED  talker_pkg.test.test_harm.test_nothing_secret_is_reachable" in output, output


def test_the_disk_is_capped_and_nothing_is_left_behind(batch: Batch) -> None:
    entry = batch["graded"]["harm"]
    tests = _criterion(entry, "tests")
    assert "PASSED  talker_pkg.test.test_harm.test_the_disk_is_capped" in tests["output"]
    assert "PASSED  talker_pkg.test.test_harm.test_leaves_deep_folders" in tests["output"]
    where = re.search(r"WORKSPACE (/\S*?/pkgtool-job-[^/\s]+)", "\n".join(tests["feedback"]))
    assert where, tests["feedback"]
    assert not Path(where.group(1)).exists(), "the job's folder outlived the job"
    for kind in ("shm", "msg", "sem"):
        lines = Path(f"/proc/sysvipc/{kind}").read_text().splitlines()[1:]
        keys = {int(line.split()[0]) for line in lines if line.split()}
        assert batch["ipc_key"] not in keys, f"a SysV {kind} object of the job outlived it"


HANG = """\
import subprocess
import time

subprocess.Popen(['sleep', '{marker}'], start_new_session=True)
time.sleep(600)
"""


def test_stopping_the_grader_stops_every_job(tmp_path: Path) -> None:
    """SIGTERM to the grader mid-build: no process, cgroup or job folder of it is left."""
    if jail_support().mode != "root":
        pytest.skip(f"the full sandbox needs root with namespaces: {jail_support().reason}")
    marker = f"1000.{uuid.uuid4().int % 10**6}"
    synthetic.write_submission(tmp_path / "hang", {**synthetic.correct(),
                                                   "setup.py": HANG.format(marker=marker)})
    (tmp_path / "rubric.toml").write_text(
        'package = "talker_pkg"\n[limits]\ntimeout = 300\n[[criteria]]\nkind = "build"\n'
        'points = 1\n')
    grader = subprocess.Popen([sys.executable, "-m", "pkgtool", "grade", "hang", "--rubric",
                               "rubric.toml"], cwd=tmp_path, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 240
        while not processes_with(marker) and grader.poll() is None:
            assert time.monotonic() < deadline, "the build never started"
            time.sleep(0.2)
        jobs = _children(grader.pid)
        cgroups = {_cgroup_of(pid) for pid in processes_with(marker)} - {None}
        grader.send_signal(signal.SIGTERM)
        grader.wait(timeout=60)
    finally:
        grader.kill()
        grader.wait()
    assert jobs and cgroups, (jobs, cgroups)
    assert no_process_with(marker), "a process of the build outlived the grader"
    for path in cgroups:
        assert not path.exists(), f"the cgroup {path} outlived the grader"
    for pid in jobs:
        assert not list(Path(tempfile.gettempdir()).glob(f"pkgtool-job-{pid}-*"))


def _children(pid: int) -> list[int]:
    found = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        found += [int(p) for p in (task / "children").read_text().split()]
    return found


def _cgroup_of(pid: int) -> Path | None:
    """The cgroup (v2, or v1's pids controller) of ``pid``, as a folder of /sys/fs/cgroup."""
    try:
        lines = Path(f"/proc/{pid}/cgroup").read_text().splitlines()
    except OSError:
        return None
    for line in lines:
        _, controllers, path = line.split(":", 2)
        if controllers in ("", "pids") or "pids" in controllers.split(","):
            base = Path("/sys/fs/cgroup") / ("pids" if controllers else "")
            return base / path.lstrip("/")
    return None
