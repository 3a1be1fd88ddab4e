"""LCH027: a launch file starts a keyboard teleoperation node with no terminal."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.launch import TERMINALS
from pkgtool.model.package import Package
from pkgtool.rules.call_graph import module_functions_reached
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

KEYBOARD_READERS = frozenset({("teleop_twist_keyboard", "teleop_twist_keyboard"),
                              ("turtlesim", "turtle_teleop_key"),
                              ("key_teleop", "key_teleop")})
"""Released nodes (package, executable) that read keys from their standard input, a terminal."""
_PREFIXES = frozenset({"prefix", "launch-prefix"})
"""How a Python, XML or YAML launch file runs a node inside another program (a terminal)."""
_FILE_PREFIX = lazy_pattern(
    r"""(?:SetLaunchConfiguration|DeclareLaunchArgument)\(\s*(?:name\s*=\s*)?"""
    r"""['"]launch-prefix['"]|<(?:let|arg)\s+name\s*=\s*['"]launch-prefix['"]|"""
    r"""name:\s*['"]?launch-prefix['"]?\s*$""", re.M)
"""A launch file setting ``launch-prefix`` for the nodes after it (``<let name=
"launch-prefix" value="xterm -e"/>``, an argument of that name), which launch uses for a
process given no prefix."""


@rule("LCH027", "keyboard-reader-without-terminal", Severity.ERROR,
      fix="Start it in a terminal of its own: `prefix='xterm -e'` (XML and YAML: "
          "`launch-prefix=\"xterm -e\"`) and `<exec_depend>xterm</exec_depend>`, or run it "
          "with `ros2 run` in another terminal")
def keyboard_reader_without_terminal(package: Package) -> Iterator[Hit]:
    """A launch file starts a node that reads the keyboard without giving it a terminal.

    ## What it does
    Reports a `Node` (`<node>`, YAML `node`) starting `teleop_twist_keyboard`,
    `turtlesim`'s `turtle_teleop_key` or `key_teleop` with no `prefix` (`launch-prefix`):
    the nodes that read keys from their standard input, or an executable of this package
    whose module puts its standard input in raw mode (`termios.tcgetattr(sys.stdin)`,
    `tty.setraw(sys.stdin)`) without asking whether it is a terminal (`isatty`), in a
    launch file that sets no
    terminal as `launch-prefix` for all its nodes (`<let name="launch-prefix" value="xterm
    -e"/>`, `SetLaunchConfiguration('launch-prefix', ...)`, an argument of that name).

    ## Why is this bad?
    `ros2 launch` gives the processes it starts a pipe, not the terminal, as their standard
    input (`emulate_tty=True` changes only their output): the node's first
    `termios.tcgetattr(sys.stdin)` fails with "Inappropriate ioctl for device" and it exits,
    or it runs and never sees a key. The robot cannot be driven.

    ## Example
    ```python
    Node(package='teleop_twist_keyboard', executable='teleop_twist_keyboard')
    ```

    ## Use instead
    ```python
    Node(package='teleop_twist_keyboard', executable='teleop_twist_keyboard',
         prefix='xterm -e')
    ```
    """
    readers = KEYBOARD_READERS | {(package.name, name) for name in _own_readers(package)}
    for launch in package.launch_files:
        if _terminal_for_all(package.texts.get(launch.path, "")):
            continue  # a prefix for every node of the file
        for node in launch.nodes:
            if (node.package, node.executable) in readers and not node.unused and \
                    not _PREFIXES & set(node.arguments) and "**" not in node.arguments:
                yield Hit(node.executable_span or node.span,
                          f"`{node.executable}` reads keys from its standard input, which "
                          "`ros2 launch` makes a pipe, not a terminal: it exits with "
                          "\"Inappropriate ioctl for device\" (or never sees a key)")


_RAW_STDIN = lazy_pattern(r"\b(?:termios\.tcgetattr|tty\.set(?:raw|cbreak))\(\s*sys\.stdin\b")
"""A module putting its standard input, a terminal it takes for granted, into raw mode."""


def _own_readers(package: Package) -> set[str]:
    """The console scripts of the package whose module reads keys from a terminal
    (``termios.tcgetattr(sys.stdin)``, ``tty.setraw(sys.stdin)``) without asking whether it
    has one (``isatty``) or opening ``/dev/tty``; of a module several scripts run, only those
    whose own function does it."""
    entries, modules = scripts_and_modules(package)
    trees = {module.path: tree for module, tree, _ in installed_trees(package)}
    found: set[str] = set()
    for entry in entries:
        path = modules.get(entry.module, "")
        text = package.texts.get(path, "") or ""
        if not _RAW_STDIN.search(text) or "isatty" in text or "/dev/tty" in text:
            continue  # it checks for a terminal, or opens the controlling one itself
        shared = sum(other.module == entry.module for other in entries) > 1
        if not shared or _RAW_STDIN.search(_function_text(text, trees.get(path), entry.attr)):
            found.add(entry.name)  # a module of several scripts: this one's function reads
    return found


def _function_text(text: str, tree: ast.Module | None, attr: str | None) -> str:
    """The source of the module function ``attr`` names and of the module functions it calls
    by name, theirs too (empty when not found)."""
    found = module_functions_reached(tree, (attr or "").split(".")[0]) if tree else []
    return "\n".join(ast.get_source_segment(text, function) or "" for function in found)


def _terminal_for_all(text: str) -> bool:
    """True when the launch file's text (comment lines aside) sets ``launch-prefix`` for all
    its nodes and names a terminal program."""
    lines = "\n".join(line for line in text.splitlines()
                      if not line.lstrip().startswith(("#", "<!--")))
    return _FILE_PREFIX.search(lines) is not None and any(t in lines for t in TERMINALS)
