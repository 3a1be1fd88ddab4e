"""Whether a package's console scripts are meant for `ros2 run` or for the shell's PATH.

Command-line tools (`ros2`, `rqt`, linters, code generators) install their scripts to `bin/`
on purpose. Scripts count as meant for `ros2 run` when there is evidence: a launch file of
the package starts one of the package's executables, the package's README names `ros2 run
<package>`, or a script's module imports rclpy's `Node` or spins one with `rclpy.spin()`
(it runs a node; `ros2` and `rqt` import rclpy for other things).
"""

from __future__ import annotations

import re

from pkgtool.model.installed import installed_modules
from pkgtool.model.memo import per_package
from pkgtool.model.modules import Import
from pkgtool.model.package import Package

README_NAMES = ("README.md", "README.rst", "README.txt", "README")


@per_package
def meant_for_ros2_run(package: Package) -> bool:
    """True when the evidence says `ros2 run` (or a launch file) starts the console scripts."""
    setup = package.setup_py
    if setup is None:
        return False
    if any(node.package == package.name for launch in package.launch_files
           for node in launch.nodes):
        return True
    command = re.compile(rf"ros2\s+run\s+{re.escape(package.name)}\b")
    if any(command.search(package.texts.get(name, "")) for name in README_NAMES):
        return True
    files = installed_modules(package) or {}
    for entry in setup.console_scripts:
        path = files.get(entry.module) or entry.module.replace(".", "/") + ".py"  # the file
        module = package.module(path)  # even where a missing __init__.py leaves it out
        if module is not None and any(_imports_node(i) for i in module.imports):
            return True
    return False


def _imports_node(imported: Import) -> bool:
    """``from rclpy.node import Node``, ``import rclpy.node``, rclpy's lifecycle nodes."""
    return imported.top_level == "rclpy" and (
        imported.module.startswith(("rclpy.node", "rclpy.lifecycle"))
        or any(name in ("Node", "LifecycleNode", "create_node") for name in imported.names))


def is_rqt_plugin(package: Package) -> bool:
    """package.xml exports an rqt_gui plugin."""
    if package.manifest is None:
        return False
    return any(child.tag == "rqt_gui" for export in package.manifest.root.children
               if export.tag == "export" for child in export.children)


_SCRIPT_COMMANDS = frozenset({"install", "develop", "install_scripts", "easy_install"})
"""setuptools commands whose replacement may choose where console scripts go (setting
``install_scripts`` or ``script_dir`` in code, as py_trees_ros_tutorials does)."""


def scripts_in_bin(package: Package) -> bool:
    """Console scripts install to `bin/`: no setup.cfg, or one without `[install]
    install_scripts` (and its near misses), and no ``cmdclass`` replacing a command that
    may move them (one ``cmdclass`` not written as a dict, versioneer's, replaces none of
    them)."""
    setup, cfg = package.setup_py, package.setup_cfg
    if setup is None or not setup.console_scripts:
        return False
    if set(setup.commands or ()) & _SCRIPT_COMMANDS:
        return False
    return cfg is None or not any(o.section == "install" and
                                  o.key.replace("-", "_") == "install_scripts"
                                  for o in cfg.options)
