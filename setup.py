"""Build step of pkgtool: ship the top-level resource folders inside the package.

Everything else is configured in pyproject.toml. ``build_py`` copies each folder named in
``pkgtool/resources.py`` (templates/, reference_packages/) to ``pkgtool/_resources/<name>/`` in
the build tree, where :func:`pkgtool.resources.resource_dir` finds it once installed. Editable
installs skip the copy: they read the folders from the checkout.
"""

import runpy
import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
RESOURCES = runpy.run_path(str(ROOT / "pkgtool" / "resources.py"))["RESOURCES"]


class BuildPyWithResources(build_py):
    """``build_py`` that also copies the resource folders into the built package."""

    def run(self) -> None:
        super().run()
        if getattr(self, "editable_mode", False):
            return
        for name in RESOURCES:
            source = ROOT / name
            if source.is_dir():
                shutil.copytree(source, Path(self.build_lib, "pkgtool", "_resources", name),
                                dirs_exist_ok=True,
                                ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))


setup(cmdclass={"build_py": BuildPyWithResources})
