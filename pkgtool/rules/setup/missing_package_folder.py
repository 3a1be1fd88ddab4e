"""SET011: packages= names a package whose folder does not exist."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.submodules import under
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import listed_packages


_MAKERS = frozenset({"mkdir", "makedirs", "copytree", "copy", "copyfile", "system", "run",
                     "call", "check_call", "check_output", "Popen", "write_text"})
"""Calls through which a setup.py may create files before ``setup()`` (folders, copies, a
code generator it runs: ``subprocess.run``, and ``grpc_tools.protoc.main``)."""


def _makes_files(package: Package) -> bool:
    """True when setup.py calls something that may create the folders it lists."""
    text = package.texts.get("setup.py")
    tree = parse_tree("setup.py", text) if text is not None else None
    return isinstance(tree, ast.Module) and any(
        _maker(node.func) for node in nodes_of_class(tree, ast.Call))  # type: ignore


def _maker(func: ast.expr) -> bool:
    if isinstance(func, ast.Attribute):
        return func.attr in _MAKERS or func.attr == "main" and "protoc" in ast.unparse(func.value)
    return isinstance(func, ast.Name) and func.id in _MAKERS


@rule("SET011", "missing-package-folder", Severity.ERROR,
      fix="List the folder that holds the Python package (with `__init__.py`), or rename it")
def missing_package_folder(package: Package) -> Iterator[Hit]:
    """`packages=[...]` lists a package whose folder does not exist.

    ## What it does
    For an explicit `packages` list, maps each name to its folder the way setuptools does
    (respecting `package_dir`) and reports names whose folder holds no files. Not when
    setup.py makes files before `setup()` (`mkdir`, `makedirs`, copies, `subprocess`,
    `grpc_tools.protoc`): the folder may be generated, as gRPC or message code often is.

    ## Why is this bad?
    The build stops with "error: package directory 'x' does not exist". It typically happens
    when the Python package folder is renamed, or `package_name` (the ROS name) is used for a
    folder called differently.

    ## Example
    ```python
    package_name = 'robot_monitor'
    setup(name=package_name, packages=[package_name])   # the code is in monitor/
    ```

    ## Use instead
    ```python
    setup(name=package_name, packages=['monitor'])
    ```
    """
    folders = {f.rsplit("/", 1)[0] for f in package.files if "/" in f}
    if _makes_files(package):
        return  # the folder may be what setup.py generates before setup() runs
    for name, folder, span in listed_packages(package):
        if folder and not any(f == folder or f.startswith(folder + "/") for f in folders) \
                and not under(folder, package.unfetched):
            yield Hit(span, f"`packages` lists `{name}`, but there is no folder `{folder}`")
