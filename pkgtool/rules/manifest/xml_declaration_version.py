"""MAN027: package.xml declares an XML version that XML has not (``<?xml version="2.0"?>``)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.xml import foreign_xml_version
from pkgtool.rules.registry import rule


@rule("MAN027", "xml-declaration-version", Severity.WARNING,
      fix="Declare `<?xml version=\"1.0\"?>`")
def xml_declaration_version(package: Package) -> Iterator[Hit]:
    """package.xml's XML declaration names a version of XML other than 1.0 or 1.1.

    ## What it does
    Reports a `<?xml version="..."?>` line whose version is not `1.0` or `1.1` (the two
    versions XML has). pkgtool reads the manifest as XML 1.0 and checks it as usual.

    ## Why is this bad?
    Conforming XML parsers refuse the whole document: `ament_xmllint` (one of
    `ament_lint_auto`'s default tests) and xmllint report it as not well-formed, and so do
    editors and other tools built on libxml2. colcon, rosdep and catkin_pkg happen to read it
    (Python's expat ignores the number), so the mistake goes unnoticed until such a tool runs.

    ## Example
    ```xml
    <?xml version="2.0"?>
    <package format="3">
    ```

    ## Use instead
    ```xml
    <?xml version="1.0"?>
    <package format="3">
    ```
    """
    text = package.texts.get("package.xml")
    declared = foreign_xml_version(text) if text is not None else None
    if declared is None:
        return
    line = text[:declared.start(1)].count("\n") + 1 if text else 1
    column = declared.start(1) - (text.rfind("\n", 0, declared.start(1)) + 1) + 1 if text else 1
    yield Hit(Span("package.xml", line, column),
              f"package.xml declares XML version `{declared.group(1)}`: XML has only 1.0 and "
              "1.1, and conforming parsers (`ament_xmllint`, xmllint) refuse the file",
              "Write `<?xml version=\"1.0\"?>`")
