"""MAN025: the ``<?xml-model?>`` line names the schema of another format than ``<package>``."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.registry import rule


@rule("MAN025", "schema-of-another-format", Severity.WARNING,
      fix="Name the schema of the declared format: `package_format3.xsd` for "
          "`<package format=\"3\">`")
def schema_of_another_format(package: Package) -> Iterator[Hit]:
    """The ``<?xml-model?>`` line names the schema of another format than ``<package>``.

    ## What it does
    Reports a package.xml whose ``<?xml-model href=".../package_formatN.xsd"?>`` line names
    the schema of a format other than the one its ``<package format>`` declares (format 1
    when it declares none), for example a ``format="2"`` manifest that kept the format 3
    schema line ``ros2 pkg create`` writes.

    ## Why is this bad?
    Each schema fixes the ``format`` attribute to its own number, so the manifest never
    validates against the schema it names: ``ament_xmllint`` (part of ``ament_lint_auto``'s
    default linters) fails, and editors that validate XML underline the whole file. It also
    leaves open which format the author meant: format 3 tags (``condition``,
    ``member_of_group``) in a format 2 manifest are errors (MAN006).

    ## Example
    ```xml
    <?xml-model href="http://download.ros.org/schema/package_format3.xsd"
      schematypens="http://www.w3.org/2001/XMLSchema"?>
    <package format="2">
    ```

    ## Use instead
    ```xml
    <?xml-model href="http://download.ros.org/schema/package_format3.xsd"
      schematypens="http://www.w3.org/2001/XMLSchema"?>
    <package format="3">
    ```
    """
    found = tree(package)
    schema = found.manifest.schema_format if found is not None else None
    if found is None or schema is None or schema.value == str(found.format):
        return
    yield Hit(schema.span, f"The `<?xml-model?>` line names the schema of package.xml format "
              f"{schema.value}, but the manifest declares format {found.format}: it never "
              "validates against that schema (`ament_xmllint` fails)",
              f"Name `package_format{found.format}.xsd`, or declare "
              f"`<package format=\"{schema.value}\">` if the manifest is written in that format")
