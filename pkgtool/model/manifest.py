"""package.xml read with lxml (entities and network off), keeping line numbers."""

from __future__ import annotations


from pkgtool.model.condition import under_ros2
from pkgtool.model.span import ParseProblem, Span
from pkgtool.model.xml import XmlElement, parse_xml
from pkgtool.records import record, replace
from pkgtool.lazy_regex import lazy_pattern

CMAKE_BUILD_TYPES = frozenset({"ament_cmake", "cmake"})
"""Build types colcon builds with CMake, from the package's CMakeLists.txt."""


@record
class Text:
    """An element's stripped text content with its position."""

    value: str
    span: Span


@record
class Person:
    """A ``<maintainer>``."""

    name: str
    email: str | None
    span: Span


@record
class Dependency:
    """Any ``*depend`` tag (also format 1's ``run_depend``, and ``conflict``/``replace``)."""

    tag: str
    name: str
    span: Span
    attributes: tuple[tuple[str, str], ...] = ()

    @property
    def condition(self) -> str | None:
        """The REP 149 ``condition`` attribute, if any."""
        return dict(self.attributes).get("condition")


@record
class Manifest:
    """The parsed package.xml. ``root`` is the whole tree for structural rules."""

    path: str
    root: XmlElement
    format: int | None
    name: Text | None
    version: Text | None
    description: Text | None
    maintainers: tuple[Person, ...]
    licenses: tuple[Text, ...]
    dependencies: tuple[Dependency, ...]
    build_type: Text | None
    has_schema_line: bool = False
    schema_format: Text | None = None
    """The format of the schema the ``<?xml-model?>`` line names (``3`` for
    ``package_format3.xsd``), where that number is written."""
    is_ros1: bool = False
    """A ROS 1 (catkin) package: built by catkin, or with catkin as build tool. Tags whose
    ``condition`` is false under ROS 2 (``$ROS_VERSION == 1``) do not count: such a package is
    built by ament under ROS 2."""

    def depends(self, tags: frozenset[str] | set[str]) -> frozenset[str]:
        """Names declared with any of ``tags`` (``depend`` counts for every kind)."""
        return frozenset(d.name for d in self.dependencies if d.tag in tags or d.tag == "depend")


def parse_manifest(path: str, text: str) -> Manifest | ParseProblem:
    """Parse package.xml text; malformed XML or entity tricks give a ParseProblem."""
    root = parse_xml(path, text)
    if isinstance(root, ParseProblem):
        return root
    head = text.split("<package", 1)[0]
    schema = _SCHEMA.search(head)
    at = schema.start(1) if schema else 0
    where = Span.of_offset(path, head, at)
    return replace(_manifest(path, root, "package_format" in head),
                   schema_format=Text(schema.group(1), where) if schema else None)


_LATE_DECLARATION = lazy_pattern(r"\A\s+(<\?xml\s[^>]*\?>)")
"""An XML declaration after blank lines or spaces: XML allows it only at the very start."""


def read_past_late_declaration(path: str, text: str) -> Manifest | None:
    """The manifest of a package.xml whose only fault is whitespace before its XML declaration
    (SYN001 reports that), read with the declaration blanked out so every other check still
    runs, at the same lines and columns; None for any other fault."""
    late = _LATE_DECLARATION.match(text)
    if late is None:
        return None
    start, end = late.span(1)
    found = parse_manifest(path, text[:start] + " " * (end - start) + text[end:])
    return found if isinstance(found, Manifest) else None


_SCHEMA = lazy_pattern(r"<\?xml-model\s[^>]*?href\s*=\s*[\"'][^\"']*package_format(\d+)\.xsd")
"""The ``<?xml-model?>`` processing instruction naming a package.xml schema."""


def _text(element: XmlElement | None) -> Text | None:
    return None if element is None else Text(element.text, element.span)


def _build_type(export: XmlElement) -> XmlElement | None:
    """The ``<build_type>`` ROS 2 uses: the first whose ``condition`` is not false under ROS 2
    (``$ROS_VERSION == 2`` beside a ``$ROS_VERSION == 1`` catkin), else the first."""
    found = [c for c in export.children if c.tag == "build_type"]
    return next((c for c in found if under_ros2(c.attribute("condition")) is not False),
                found[0] if found else None)


def _first(root: XmlElement, tag: str) -> XmlElement | None:
    return next((c for c in root.children if c.tag == tag), None)


def _people(root: XmlElement, tag: str) -> tuple[Person, ...]:
    return tuple(
        Person(c.text, c.attribute("email"), c.span) for c in root.children if c.tag == tag
    )


def _format(root: XmlElement) -> int | None:
    value = root.attribute("format")
    if value is None:
        return 1
    return int(value) if value.strip().isdigit() else None


def _manifest(path: str, root: XmlElement, has_schema_line: bool) -> Manifest:
    export = _first(root, "export")
    build_type = _build_type(export) if export is not None else None
    dependencies = tuple(Dependency(c.tag, c.text, c.span, c.attributes) for c in root.children
                         if c.tag.endswith("depend") or c.tag in ("conflict", "replace"))
    return Manifest(
        path=path,
        root=root,
        format=_format(root),
        name=_text(_first(root, "name")),
        version=_text(_first(root, "version")),
        description=_text(_first(root, "description")),
        maintainers=_people(root, "maintainer"),
        licenses=tuple(Text(c.text, c.span) for c in root.children if c.tag == "license"),
        dependencies=dependencies,
        build_type=_text(build_type),
        has_schema_line=has_schema_line,
        is_ros1=build_type is not None and build_type.text == "catkin" or any(
            d.tag == "buildtool_depend" and d.name == "catkin" and under_ros2(d.condition)
            is not False for d in dependencies),
    )
