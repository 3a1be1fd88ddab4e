"""LCH027: a launch file starts a keyboard teleoperation node with no terminal."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.launch import TERMINALS
from pkgtool.model.package import Package
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.registry import rule

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
    has one (``isatty``)."""
    entries, modules = scripts_and_modules(package)
    found: set[str] = set()
    for entry in entries:
        text = package.texts.get(modules.get(entry.module, ""), "") or ""
        if _RAW_STDIN.search(text) and "isatty" not in text:
            found.add(entry.name)
    return found


def _terminal_for_all(text: str) -> bool:
    """True when the launch file's text (comment lines aside) sets ``launch-prefix`` for all
    its nodes and names a terminal program."""
    lines = "\n".join(line for line in text.splitlines()
                      if not line.lstrip().startswith(("#", "<!--")))
    return _FILE_PREFIX.search(lines) is not None and any(t in lines for t in TERMINALS)
