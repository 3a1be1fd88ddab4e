"""In-memory package builders for rule tests (catkin_lint style): write files, load, check."""

from __future__ import annotations

import os
import shutil
import textwrap
import time
from pathlib import Path
from typing import TYPE_CHECKING

from pkgtool.engine import check_package
from pkgtool.findings import Finding
from pkgtool.model.package import Package, load_package
from pkgtool.rules.registry import load_all

if TYPE_CHECKING:
    from typer.testing import Result

SCHEMA_LINE = ('<?xml-model href="http://download.ros.org/schema/package_format3.xsd" '
               'schematypens="http://www.w3.org/2001/XMLSchema"?>')
MINIMAL_MANIFEST = """<?xml version="1.0"?>
""" + SCHEMA_LINE + """
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>A package for tests.</description>
  <maintainer email="dev@example.com">Dev</maintainer>
  <license>Apache-2.0</license>
  <exec_depend>rclpy</exec_depend>
  <test_depend>python3-pytest</test_depend>
  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""


PROJECT = Path(__file__).resolve().parents[1]
PROJECT_SOURCES = ("pyproject.toml", "setup.py", "MANIFEST.in", "README.md", "pkgtool",
                   "templates", "reference_packages")
"""What building pkgtool's distribution reads from the checkout."""


def copy_project_sources(into: Path) -> Path:
    """Copy what building pkgtool reads into ``into`` (no caches, no egg-info): a build from
    there never writes into the checkout."""
    into.mkdir(parents=True, exist_ok=True)
    for name in PROJECT_SOURCES:
        if (PROJECT / name).is_dir():
            shutil.copytree(PROJECT / name, into / name,
                            ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
        else:
            shutil.copy2(PROJECT / name, into / name)
    return into


def write_tree(root: Path, files: dict[str, str | bytes]) -> Path:
    """Write ``files`` (relative path -> text, dedented, or bytes) under ``root``."""
    for relpath, content in files.items():
        path = root / relpath
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(textwrap.dedent(content).lstrip("\n"))
    return root


def make_package(root: Path, files: dict[str, str | bytes]) -> Package:
    """Write a package tree and load it."""
    return load_package(write_tree(root, files))


def findings(package: Package, *codes: str) -> list[Finding]:
    """Findings of the rules ``codes`` (all rules when none given) on ``package``."""
    catalogue = load_all()
    rules = [catalogue[c] for c in codes] if codes else list(catalogue.values())
    return check_package(package, rules, root_label=str(package.root))


def codes(package: Package, *only: str) -> list[str]:
    """Just the codes of :func:`findings`, sorted."""
    return sorted(f.code for f in findings(package, *only))


def correct_package_files(name: str = "demo") -> dict[str, str | bytes]:
    """A complete, correct ament_python package (node, launch file, test) that lints clean."""
    manifest = MINIMAL_MANIFEST.format(name=name).replace(
        "  <exec_depend>rclpy</exec_depend>\n",
        "  <exec_depend>rclpy</exec_depend>\n  <exec_depend>std_msgs</exec_depend>\n"
        "  <exec_depend>launch</exec_depend>\n  <exec_depend>launch_ros</exec_depend>\n")
    return {
        "package.xml": manifest,
        "setup.py": f'''
            from glob import glob
            import os

            from setuptools import find_packages, setup

            package_name = '{name}'

            setup(
                name=package_name,
                version='0.1.0',
                packages=find_packages(exclude=['test']),
                data_files=[
                    ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
                    ('share/' + package_name, ['package.xml']),
                    (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
                ],
                install_requires=['setuptools'],
                zip_safe=True,
                maintainer='Dev',
                maintainer_email='dev@example.com',
                description='A package for tests.',
                license='Apache-2.0',
                extras_require={{'test': ['pytest']}},
                entry_points={{
                    'console_scripts': [
                        'talker = {name}.talker:main',
                    ],
                }},
            )
            ''',
        "setup.cfg": f"""
            [develop]
            script_dir=$base/lib/{name}
            [install]
            install_scripts=$base/lib/{name}
            """,
        f"resource/{name}": "",
        f"{name}/__init__.py": "",
        f"{name}/talker.py": """
            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import String


            class Talker(Node):

                def __init__(self):
                    super().__init__('talker')
                    self.publisher = self.create_publisher(String, 'chatter', 10)


            def main(args=None):
                rclpy.init(args=args)
                rclpy.spin(Talker())
            """,
        f"launch/{name}.launch.py": f"""
            from launch import LaunchDescription
            from launch_ros.actions import Node


            def generate_launch_description():
                return LaunchDescription([Node(package='{name}', executable='talker')])
            """,
        "test/test_talker.py": """
            import pytest


            @pytest.mark.parametrize('value', [1])
            def test_value(value):
                assert value == 1
            """,
    }


def run_cli(*args: str, cwd: Path) -> Result:
    """Invoke ``pkgtool ARGS`` in-process from ``cwd`` with typer's CliRunner."""
    from typer.testing import CliRunner

    from pkgtool import cli

    if not cli.app.registered_commands:
        cli._register()
    previous = os.getcwd()
    os.chdir(cwd)
    try:
        return CliRunner().invoke(cli.app, list(args))
    finally:
        os.chdir(previous)


def make_finding(code: str = "SYN001", severity: str = "error", *, root: str = "src/pkg",
                 path: str = "pkg/node.py", line: int = 3, col: int = 5,
                 message: str = "Python syntax error: invalid syntax",
                 fix: str | None = "Fix the syntax at the reported line and column") -> Finding:
    """A finding for report tests, built without running rules."""
    from pkgtool.findings import Severity
    from pkgtool.model.span import Span

    return Finding(code, Severity(severity), root.rsplit("/", 1)[-1], root, Span(path, line, col),
                   message, fix)


def processes_with(marker: str) -> list[int]:
    """Pids of this machine's processes (but this one) whose command line holds ``marker``."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and entry.name != str(os.getpid()):
            try:
                if marker.encode() in (entry / "cmdline").read_bytes():
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


def no_process_with(marker: str, within: float = 10.0) -> bool:
    """True once no process holds ``marker`` (polled: the kernel reaps asynchronously)."""
    deadline = time.monotonic() + within
    while processes_with(marker):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True
