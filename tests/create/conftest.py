"""Builders for the create tests: a request with fixed maintainer and year, created on disk."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from pkgtool.commands.create import CreateResult, Request, run

ALL_KINDS = ("talker:publisher", "listener:subscriber", "server:service", "caller:client",
             "fib_server:action-server", "fib_client:action-client", "beat:timer")
"""Every node kind with its default interface."""
OTHER_TYPES = ("twist_pub:publisher:geometry_msgs/msg/Twist",
               "twist_sub:subscriber:geometry_msgs/msg/Twist",
               "switch:service:std_srvs/srv/SetBool", "switcher:client:std_srvs/srv/SetBool",
               "empty:service:std_srvs/srv/Empty", "empty_caller:client:std_srvs/srv/Empty",
               "nested:action-server:test_msgs/action/NestedMessage",
               "nested_client:action-client:test_msgs/action/NestedMessage")
"""Interfaces the templates know nothing about (sent default-constructed), and SetBool."""


def request(destination: Path, name: str = "demo_pkg", **values: object) -> Request:
    """A request as the CLI would build it, with the defaults pinned for determinism."""
    values.setdefault("maintainer_name", "Jane Doe")
    values.setdefault("maintainer_email", "jane@example.com")
    values.setdefault("year", 2026)
    return Request(name=name, destination=destination, **values)  # type: ignore[arg-type]


@pytest.fixture
def create(tmp_path: Path) -> Callable[..., CreateResult]:
    """Create a package under ``tmp_path`` (or ``destination=``) and return the result."""

    def make(name: str = "demo_pkg", *, destination: Path | None = None, dry_run: bool = False,
             force: bool = False, **values: object) -> CreateResult:
        return run(request(destination or tmp_path, name, **values), dry_run=dry_run,
                   force=force)

    return make


def expected_files(name: str, nodes: tuple[str, ...] = (), *, launch: bool = False,
                   config: bool = False) -> list[str]:
    """The files ``create`` writes, from the template list: the package's own files, a module
    and a test per node (``NAME:KIND``) plus a conftest, each linter test template, launch and
    config; sorted as ``CreateResult.written`` lists them."""
    from pkgtool.resources import resource_dir

    node_names = [spec.split(":")[0] for spec in nodes]
    linter_tests = [p.name.removesuffix(".jinja")
                    for p in (resource_dir("templates") / "tests").glob("test_*.py.jinja")]
    files = ["package.xml", "setup.py", "setup.cfg", f"resource/{name}", "LICENSE",
             f"{name}/__init__.py", *(f"{name}/{n}.py" for n in node_names),
             *(f"test/test_{n}.py" for n in node_names), *(["test/conftest.py"] * bool(nodes)),
             *(f"test/{t}" for t in linter_tests), *([f"launch/{name}.launch.py"] * launch),
             *(["config/params.yaml"] * config)]
    return sorted(files)
