"""What the MAN rules share: the manifest tree a rule may check, and how findings name things."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.model.manifest import Manifest
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.records import record
from pkgtool.rules.manifest.schema import (FORMATS, SEQUENCES, VERSION_ATTRIBUTES, slot_index,
                                           tags_of)


@record
class Tree:
    """A parsed package.xml whose root is ``<package>`` with a known format (1, 2 or 3)."""

    manifest: Manifest
    root: XmlElement
    format: int

    def elements(self) -> Iterator[XmlElement]:
        """Children of ``<package>`` that this format defines, in document order."""
        known = tags_of(self.format)
        return (child for child in self.root.children if child.tag in known)

    def named(self, *tags: str) -> Iterator[XmlElement]:
        """Children of ``<package>`` with one of ``tags``, in document order."""
        return (child for child in self.root.children if child.tag in tags)


@record
class Misplaced:
    """An element the ``<package>`` sequence does not accept where it stands.

    ``duplicate`` is True for a second occurrence of a single-valued element; otherwise the
    element comes after ``before``, which the schema wants after it.
    """

    element: XmlElement
    before: XmlElement
    duplicate: bool


def misplaced(found: Tree) -> Iterator[Misplaced]:
    """Walk the format's children against its sequence, like the XSD validator does."""
    slots = SEQUENCES[found.format]
    first: dict[int, XmlElement] = {}
    highest = -1
    for element in found.elements():
        index = slot_index(element.tag, found.format)
        assert index is not None
        if index in first and not slots[index].repeats:
            yield Misplaced(element, first[index], True)
        elif index < highest:
            later = min(i for i in first if i > index)
            yield Misplaced(element, first[later], False)
        first.setdefault(index, element)
        highest = max(highest, index)


def package_root(package: Package) -> XmlElement | None:
    """The ``<package>`` root, or None without a parsed package.xml or with another root."""
    manifest = package.manifest
    if manifest is None or manifest.root.tag != "package":
        return None
    return manifest.root


def tree(package: Package) -> Tree | None:
    """The manifest tree when its format is one pkgtool knows; None means say nothing."""
    root = package_root(package)
    if root is None or package.manifest is None or package.manifest.format not in FORMATS:
        return None
    return Tree(package.manifest, root, package.manifest.format)


def snippet(element: XmlElement) -> str:
    """A short source-like rendering of a text element, e.g. ``<depend>rclpy</depend>``."""
    text = element.text if len(element.text) <= 60 else element.text[:57] + "..."
    return f"<{element.tag}>{text}</{element.tag}>"


def dependency_key(element: XmlElement) -> tuple[str, tuple[tuple[str, str], ...]]:
    """What catkin_pkg compares dependencies by: the name and the version/condition attributes."""
    attributes = tuple(sorted((k, v) for k, v in element.attributes
                              if k in VERSION_ATTRIBUTES or k == "condition"))
    return element.text, attributes


def build_types(found: Tree) -> list[XmlElement]:
    """Every ``<export><build_type>`` element, in document order."""
    return [child for export in found.named("export") for child in export.children
            if child.tag == "build_type"]


def names_its_schema(package: Package) -> bool:
    """True when package.xml names the schema a validator checks it against."""
    manifest = package.manifest
    return manifest is not None and (manifest.has_schema_line or any(
        name.endswith("noNamespaceSchemaLocation") for name, _ in manifest.root.attributes))
