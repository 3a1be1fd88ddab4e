"""LCH019: an XML or YAML launch file whose root is not ``launch``."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.launch_reader import yaml_problem
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.xml import XmlElement, parse_xml
from pkgtool.rules.registry import rule


@rule("LCH019", "launch-file-root", Severity.ERROR,
      fix="Put everything inside the one root: `<launch>...</launch>`, or `launch:` in YAML")
def launch_file_root(package: Package) -> Iterator[Hit]:
    """An XML or YAML launch file's root is not `launch`, or a YAML one has several roots.

    ## What it does
    Reports an XML launch file whose root element is not `<launch>`, and a YAML launch file
    whose top level is not a mapping with the single key `launch` (a `version:` or
    `substitutions:` key beside it, a list, another key). Files that do not parse are
    SYN001's.

    ## Why is this bad?
    `ros2 launch` stops before starting anything: the YAML loader raises "Expected only one
    root" for several top-level keys, and the front end wants `launch` as the root's name.

    ## Example
    ```yaml
    version: 1
    launch:
      - node: {pkg: demo, exec: talker}
    ```

    ## Use instead
    ```yaml
    launch:
      - node: {pkg: demo, exec: talker}
    ```
    """
    for launch in package.launch_files:
        text = package.texts.get(launch.path)
        if text is None or launch.problem is not None or launch.kind == "python":
            continue
        found = _xml_root(launch.path, text) if launch.kind == "xml" else \
            _yaml_root(launch.path, text)
        if found is not None:
            yield Hit(*found)


def _xml_root(path: str, text: str) -> tuple[Span, str] | None:
    root = parse_xml(path, text)
    if not isinstance(root, XmlElement) or root.tag == "launch":
        return None
    return root.span, f"The root element is `<{root.tag}>`, not `<launch>`: `ros2 launch` " \
        "cannot read the file"


def _yaml_root(path: str, text: str) -> tuple[Span, str] | None:
    root = yaml_problem(path, text, documents=False)
    keys = [getattr(k, "value", None) for k, _ in getattr(root, "value", ())] \
        if getattr(root, "tag", "").endswith(":map") else None
    if root is None or keys == ["launch"] or not hasattr(root, "start_mark"):
        return None
    mark = root.start_mark  # type: ignore[attr-defined]
    span = Span(path, mark.line + 1, mark.column + 1)
    if keys is None:
        return span, "The file is not a mapping with the key `launch`: `ros2 launch` cannot " \
            "read it"
    shown = ", ".join(f"`{k}`" for k in keys)
    if "launch" in keys:
        return span, f"The file has {len(keys)} top-level keys ({shown}): the YAML launch " \
            "loader takes exactly one, `launch`, and raises 'Expected only one root'"
    return span, f"The top-level key is {shown}, not `launch`: `ros2 launch` cannot read the file"
