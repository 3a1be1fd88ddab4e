"""What the rules on Python launch files share: which files they read, the function's name."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package

FUNCTION = "generate_launch_description"
"""The function ``ros2 launch`` calls in a Python launch file."""


def python_launch_files(package: Package) -> Iterator[tuple[str, PythonModule, str]]:
    """(path, module, text) of each Python launch file that parses and is not a test."""
    for launch in package.launch_files:
        module = launch.python
        text = package.texts.get(launch.path)
        if module is not None and not module.syntax_error and text is not None and \
                not module.is_test:
            yield launch.path, module, text
