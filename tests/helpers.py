"""In-memory package builders for rule tests (catkin_lint style): write files, load, check."""

from __future__ import annotations

import textwrap
from pathlib import Path

from pkgtool.engine import check_package
from pkgtool.findings import Finding
from pkgtool.model.package import Package, load_package
from pkgtool.rules.registry import load_all

MINIMAL_MANIFEST = """<?xml version="1.0"?>
<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
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
