"""SYN003: an XML package file that declares a DOCTYPE or entities."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax._problems import problem_hits


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
    yield from problem_hits(package, {"xml-entity": "entity or DOCTYPE declaration"})
