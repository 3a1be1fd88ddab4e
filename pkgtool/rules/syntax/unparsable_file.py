"""SYN001-SYN004: files that could not be read or parsed become findings, never tracebacks."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule

_PARSE_KINDS = {
    "xml-syntax": "XML is not well-formed",
    "python-syntax": "Python syntax error",
    "yaml-syntax": "YAML syntax error",
    "cfg-syntax": "setup.cfg syntax error",
}


def _hits(package: Package, kinds: set[str] | dict[str, str], label: str = "") -> Iterator[Hit]:
    for problem in package.problems:
        if problem.kind in kinds:
            prefix = kinds[problem.kind] if isinstance(kinds, dict) else label
            yield Hit(problem.span, f"{prefix}: {problem.detail}")


@rule("SYN001", "unparsable-file", Severity.ERROR,
      fix="Fix the syntax at the reported line and column")
def unparsable_file(package: Package) -> Iterator[Hit]:
    """A package file (package.xml, setup.py, setup.cfg, a module, a launch file) does not parse.

    ## What it does
    Reports XML that is not well-formed, Python with a syntax error, YAML (launch and
    parameter files) or setup.cfg that does not parse, at the line and column the parser gave.

    ## Why is this bad?
    colcon, rosdep and ``ros2 launch`` stop at the first unparsable file, and an installed
    module with a syntax error fails only when a node imports it, on the robot.

    ## Example
    ```xml
    <name>my_pkg</nam>
    ```

    ## Use instead
    ```xml
    <name>my_pkg</name>
    ```
    """
    yield from _hits(package, _PARSE_KINDS)


@rule("SYN002", "unreadable-file", Severity.ERROR,
      fix="Make the file a readable UTF-8 text file, or remove it")
def unreadable_file(package: Package) -> Iterator[Hit]:
    """A package file that must be text is binary, not UTF-8, too large, or cannot be opened.

    ## What it does
    Reports package.xml, setup.py, setup.cfg, Python modules and launch files that contain NUL
    bytes, are not valid UTF-8, exceed the size pkgtool reads (2 MiB), or cannot be opened.

    ## Why is this bad?
    Python 3 and ROS tools read these files as UTF-8 text; anything else fails at build or run
    time, often with an error far from the cause.

    ## Example
    A ``setup.py`` saved as UTF-16 by an editor, or a ``package.xml`` in Latin-1 with an
    accented maintainer name.

    ## Use instead
    Save the file as UTF-8 (without a byte-order mark).
    """
    labels = {"binary": "binary file", "not-utf8": "not UTF-8 text",
              "too-large": "file too large to check", "unreadable": "file cannot be read"}
    yield from _hits(package, labels)


@rule("SYN003", "xml-entity-declaration", Severity.ERROR,
      fix="Remove the DOCTYPE and entity declarations")
def xml_entity_declaration(package: Package) -> Iterator[Hit]:
    """An XML package file declares a DOCTYPE or entities.

    ## What it does
    Reports ``<!DOCTYPE>`` and ``<!ENTITY>`` declarations in package.xml and XML launch files.
    pkgtool never expands entities or loads external files; it refuses to read such files.

    ## Why is this bad?
    package.xml has no DTD (REP 149 defines it by an XML schema). Entity declarations are used
    for XXE and "billion laughs" attacks against tools that read package files, such as
    rosdep, bloom and autograders.

    ## Example
    ```xml
    <!DOCTYPE package [<!ENTITY who SYSTEM "file:///etc/passwd">]>
    <package format="3"><maintainer email="a@b.c">&who;</maintainer></package>
    ```

    ## Use instead
    ```xml
    <package format="3"><maintainer email="a@b.c">Ada</maintainer></package>
    ```
    """
    yield from _hits(package, {"xml-entity"}, "entity or DOCTYPE declaration")
