"""Packages grown with ``pkgtool add`` build, install and pass their tests with real colcon.

One workspace, one ``colcon build`` and one ``colcon test`` for every operation: a package
created with one node and grown by ``add node`` (several kinds), ``add launch``, ``add config``
and ``add dependency``, and a package that ``create --force`` gave its first nodes.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from pkgtool.commands import add
from pkgtool.commands.create import run
from pkgtool.ros.colcon import colcon_build, colcon_env, colcon_test
from tests.add.conftest import created, strict_findings
from tests.create.conftest import request

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

GROWN_NODES = ("talker", "listener", "server", "fib_client", "beat")
FORCED_NODES = ("caller", "ticker")


def _grow(src: Path) -> tuple[Path, Path]:
    grown = created(src, "grown")
    for step in (lambda: add.node(grown, "listener:subscriber", year=2026),
                 lambda: add.node(grown, "server:service", year=2026),
                 lambda: add.launch(grown, year=2026),
                 lambda: add.config(grown, year=2026),
                 lambda: add.node(grown, "fib_client:action-client", year=2026),
                 lambda: add.node(grown, "beat:timer", year=2026),
                 lambda: add.dependency(grown, ("numpy",))):
        result = step()
        assert not result.error, result.error
    forced = created(src, "forced", nodes=())
    again = run(request(src, "forced", nodes=("caller:client", "ticker:timer"), config=True),
                force=True)
    assert not again.error, again.error
    return grown, forced


def test_grown_packages_build_install_and_pass_colcon_test(
        tmp_path: Path, ros_domain: int) -> None:
    grown, forced = _grow(tmp_path / "src")
    for package in (grown, forced):
        assert [f for f in strict_findings(package) if not f.startswith("DEP006")] == []
    env = colcon_env(tmp_path, domain_id=ros_domain)
    build = colcon_build(tmp_path, base_paths=[tmp_path / "src"], env=env, timeout=300)
    assert build.ok, build.output
    for name, nodes in (("grown", GROWN_NODES), ("forced", FORCED_NODES)):
        for node in nodes:
            script = tmp_path / "install" / name / "lib" / name / node
            assert script.is_file() and os.access(script, os.X_OK), script
    share = tmp_path / "install" / "grown" / "share" / "grown"
    assert (share / "launch" / "grown.launch.py").is_file()
    assert (share / "config" / "params.yaml").is_file()
    assert (tmp_path / "install" / "forced" / "share" / "forced" / "config" / "params.yaml"
            ).is_file()
    result = colcon_test(tmp_path, base_paths=[tmp_path / "src"], env=env, timeout=300)
    assert result.ok, result.output
    for name, nodes in (("grown", GROWN_NODES), ("forced", FORCED_NODES)):
        suite = ET.parse(tmp_path / "build" / name / "pytest.xml").getroot()
        cases = {case.get("name"): case for case in suite.iter("testcase")}
        ran = {n for n, c in cases.items() if c.find("skipped") is None
               and c.find("failure") is None and c.find("error") is None}
        assert all(any(n.startswith(f"test_{node}_") for n in ran) for node in nodes), \
            sorted(cases)
        assert {"test_flake8", "test_pep257"} <= ran, sorted(cases)
