"""Generated packages really build, install runnable nodes and pass their own tests with colcon.

One workspace holds two packages (every node kind with the default interfaces; the other
interfaces with format 2 and MIT), so one ``colcon build`` and one ``colcon test`` cover them.
"""

from __future__ import annotations

import os
import selectors
import signal
import subprocess
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from pkgtool.commands.create import run
from pkgtool.ros.colcon import colcon_build, colcon_env, colcon_test
from tests.create.conftest import ALL_KINDS, OTHER_TYPES, request

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

PACKAGES = {
    "demo_nodes": {"nodes": ALL_KINDS, "launch": True, "config": True, "library_name": "util",
                   "dependencies": ("numpy",)},
    "other_nodes": {"nodes": OTHER_TYPES, "license": "MIT", "package_format": 2},
}


def test_generated_packages_build_run_and_pass_colcon_test(tmp_path: Path,
                                                           ros_domain: int) -> None:
    """One test, not three sharing a fixture: xdist could build the workspace once per worker."""
    for name, values in PACKAGES.items():
        assert not run(request(tmp_path / "src", name, **values)).error
    env = colcon_env(tmp_path, domain_id=ros_domain)
    build = colcon_build(tmp_path, base_paths=[tmp_path / "src"], env=env, timeout=300)
    assert build.ok, build.output
    _check_console_scripts(tmp_path)
    _check_nodes_talk_and_stop_cleanly(tmp_path, env)
    _check_repeated_ctrl_c(tmp_path, env)
    _check_colcon_test(tmp_path, env)


def _script_env(root: Path, env: dict[str, str]) -> dict[str, str]:
    sites = [str(p) for name in PACKAGES
             for p in (root / "install" / name / "lib").glob("python3*/site-packages")]
    return dict(env, PYTHONPATH=os.pathsep.join(sites))


def _check_console_scripts(root: Path) -> None:
    """Every node is a console script under install/<pkg>/lib/<pkg>/; data files are there."""
    for name, values in PACKAGES.items():
        for spec in values["nodes"]:
            script = root / "install" / name / "lib" / name / spec.split(":")[0]
            assert script.is_file() and os.access(script, os.X_OK), script
    share = root / "install" / "demo_nodes" / "share" / "demo_nodes"
    assert (share / "launch" / "demo_nodes.launch.py").is_file()
    assert (share / "config" / "params.yaml").is_file()


def _wait_for(process: subprocess.Popen, text: str, timeout: float) -> str:
    """Read ``process``'s output until ``text`` shows up (or the time is up); return it."""
    seen = b""
    deadline = time.monotonic() + timeout
    with selectors.DefaultSelector() as selector:
        selector.register(process.stdout, selectors.EVENT_READ)
        while text.encode() not in seen and time.monotonic() < deadline:
            if selector.select(timeout=0.2):
                chunk = os.read(process.stdout.fileno(), 65536)
                if not chunk:
                    break
                seen += chunk
    return seen.decode(errors="replace")


def _check_nodes_talk_and_stop_cleanly(root: Path, env: dict[str, str]) -> None:
    """Start the installed talker and listener; the listener hears; SIGINT stops both with 0."""
    lib = root / "install" / "demo_nodes" / "lib" / "demo_nodes"
    topic = f"chatter_{os.getpid()}"  # ours alone, whoever else shares the domain
    processes = {name: _start(lib / name, _script_env(root, env), "--ros-args", "-p",
                              f"topic:={topic}") for name in ("talker", "listener")}
    try:
        said = _wait_for(processes["talker"], "Published message", timeout=60)
        heard = _wait_for(processes["listener"], "Received message", timeout=60)
    finally:
        for process in processes.values():
            process.send_signal(signal.SIGINT)
        codes = {name: _stopped(process, 30) for name, process in processes.items()}
    assert "Published message" in said, said
    assert "Received message" in heard, heard
    assert codes == {"talker": 0, "listener": 0}, said + heard
    rest = b"".join(process.stdout.read() for process in processes.values())
    assert b"Traceback" not in rest, rest.decode(errors="replace")


def _stopped(process: subprocess.Popen, timeout: float) -> int | str:
    """The exit code of ``process`` within ``timeout`` seconds; else it is killed (a node left
    spinning would slow every later test) and the answer says so."""
    try:
        return process.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
        return f"still running {timeout} s after SIGINT (killed)"


def _start(script: Path, env: dict[str, str], *args: str) -> subprocess.Popen:
    """Start an installed node the way a shell does: Ctrl-C (SIGINT) has its default effect."""
    return subprocess.Popen([str(script), *args], env=env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


def _check_repeated_ctrl_c(root: Path, env: dict[str, str]) -> None:
    """SIGINT again and again while the node shuts down (launch and the user both send one):
    each node, single- and multi-threaded, still exits 0 without a traceback."""
    lib = root / "install" / "demo_nodes" / "lib" / "demo_nodes"
    for name, ready in (("beat", "Tick"), ("fib_server", "Serving action"),
                        ("server", "Serving service")):
        process = _start(lib / name, _script_env(root, env))
        seen = _wait_for(process, ready, timeout=60)
        assert ready in seen, seen
        deadline = time.monotonic() + 30
        while process.poll() is None and time.monotonic() < deadline:
            process.send_signal(signal.SIGINT)
            time.sleep(0.002)
        rest = process.stdout.read().decode(errors="replace")
        assert _stopped(process, 5) == 0, name + ":\n" + seen + rest
        assert "Traceback" not in rest and "Exception ignored" not in rest, rest


def _check_colcon_test(root: Path, env: dict[str, str]) -> None:
    """``colcon test`` passes, and every node's own test really ran (not skipped)."""
    result = colcon_test(root, base_paths=[root / "src"], env=env, timeout=300)
    assert result.ok, result.output
    for name, values in PACKAGES.items():
        suite = ET.parse(root / "build" / name / "pytest.xml").getroot()
        cases = {case.get("name"): case for case in suite.iter("testcase")}
        assert not [n for n, c in cases.items() if c.find("failure") is not None
                    or c.find("error") is not None], name
        ran = {n for n, c in cases.items() if c.find("skipped") is None}
        nodes = {spec.split(":")[0] for spec in values["nodes"]}
        assert all(any(n.startswith(f"test_{node}_") for n in ran) for node in nodes), sorted(ran)
        assert {"test_flake8", "test_pep257"} <= ran
