"""LCH009: an import from a module of launch, launch_ros or ament_index_python that lacks the
name, or from a module those packages do not have."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.launch_api import MODULE_NAMES, homes
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.rules.imports import all_python
from pkgtool.rules.registry import rule


def _missing(module: str, name: str) -> tuple[str, str] | None:
    """(message, fix) when ``module`` (of the table) has no ``name`` but another module of
    the table has it, else None (a name no module has may be newer than the table)."""
    elsewhere = () if name in MODULE_NAMES[module] else homes(name)
    return (f"`{module}` has no `{name}`: it is in `{elsewhere[0]}`",
            f"Write `from {elsewhere[0]} import {name}`") if elsewhere else None


def _missing_module(dotted: str) -> tuple[str, str] | None:
    """(message, fix) when ``dotted`` is a module of the table's packages that does not
    exist, in the singular or plural of one that does (``launch_ros.substitution``) or a
    typo away from one (``launch_ros.actons``), else None."""
    parent, _, leaf = dotted.rpartition(".")
    if parent not in MODULE_NAMES or leaf in MODULE_NAMES[parent]:
        return None
    modules = {name for name in MODULE_NAMES[parent] if name.islower()}
    meant = next((f"{parent}.{other}" for other in (leaf + "s", leaf[:-1])
                  if f"{parent}.{other}" in MODULE_NAMES), None)
    typo = typo_of(leaf, modules) if meant is None else None
    meant = meant or (f"{parent}.{typo}" if typo else None)
    return (f"`{parent}` has no module `{leaf}` (did you mean `{meant}`?)",
            f"Import from `{meant}`") if meant else None


@rule("LCH009", "unknown-launch-import", Severity.ERROR,
      fix="Import the class from the module that defines it (see the message)")
def unknown_launch_import(package: Package) -> Iterator[Hit]:
    """An import from launch, launch_ros or ament_index_python names something not there.

    ## What it does
    Checks the unguarded `from ... import` statements of the package's Python files (launch
    files, nodes and tests) whose module is one of the package-level modules of `launch`,
    `launch_ros` (`launch.actions`, `launch.substitutions`, `launch_ros.actions`,
    `launch_ros.substitutions`, ...) and `ament_index_python` (`ament_index_python.packages`):
    a name the module does not define is reported when another of those modules does (`Node` is
    in `launch_ros.actions`, not `launch.actions`; `FindPackageShare` in
    `launch_ros.substitutions`, `PathJoinSubstitution` in `launch.substitutions`). A module
    that does not exist is reported when it is the singular or plural of one that does
    (`launch_ros.substitution`, `launch_ros.action`) or a typo away from one
    (`launch_ros.actons`, `launch.substiutions`, `ament_index_python.packges`). The names are
    those of Foxy to Rolling; a name no module of the table has is left alone (it may be newer
    than the table).

    ## Why is this bad?
    The import raises `ImportError` (`cannot import name 'Node' from 'launch.actions'`):
    `ros2 launch` stops before it starts anything, and a node or test that imports it fails
    the same way.

    ## Example
    ```python
    from launch.actions import Node
    from launch.substitutions import FindPackageShare, PathJoinSubstitution
    ```

    ## Use instead
    ```python
    from launch.substitutions import PathJoinSubstitution
    from launch_ros.actions import Node
    from launch_ros.substitutions import FindPackageShare
    ```
    """
    for module in all_python(package):
        for found in module.imports:
            if found.level or found.guarded or found.module.split(".")[0] not in (
                    "launch", "launch_ros", "ament_index_python"):
                continue
            problems = [_missing_module(found.module)] if found.module not in MODULE_NAMES \
                else [_missing(found.module, name) for name in found.names]
            for problem in problems:
                if problem:
                    yield Hit(found.span, *problem)
