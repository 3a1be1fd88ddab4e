"""Packages a package's robot description, world and RViz files name.

A URDF or xacro file includes other packages' files (``$(find other)/urdf/arm.xacro``) and
points at their meshes (``package://other/meshes/base.dae``); SDF worlds and RViz settings do
the same. Such a name is a package the package really uses, whatever its spelling looks like.
The files are read only when a rule asks (most runs never do), each once per package; what a
comment holds names nothing (nor xacro's escaped ``$$(find x)``).
"""

from __future__ import annotations

from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.files import DESCRIPTION_SUFFIXES, TextFile, read_text
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.text_comments import without_comments
from pkgtool.records import record

_NAMED = lazy_pattern(r"(?<!\$)\$\(\s*find(?:-pkg-share)?\s+([A-Za-z][\w.-]*)\s*\)|"
                      r"package://([A-Za-z][\w.-]*)/")


@record
class PackageMention:
    """A package a description file names, and where."""

    package: str
    span: Span


MODEL_SUFFIXES = (*DESCRIPTION_SUFFIXES, ".wbt")
"""Robot descriptions, worlds and RViz settings, and Webots worlds (which name no package)."""


@per_package
def model_texts(package: Package) -> dict[str, str]:
    """The text of each file of the package ending in :data:`MODEL_SUFFIXES`, by path, in
    the package's file order: read once, when a rule asks (most runs never do); unreadable
    files are left out."""
    found: dict[str, str] = {}
    for relpath in package.files:
        if relpath.endswith(MODEL_SUFFIXES):
            read = read_text(package.root, relpath)
            if isinstance(read, TextFile):
                found[relpath] = read.text
    return found


@per_package
def package_mentions(package: Package) -> tuple[PackageMention, ...]:
    """Every package the package's description, world and RViz files name (``$(find x)``,
    ``$(find-pkg-share x)``, ``package://x/...``) outside XML comments, in file order;
    unreadable files name none."""
    found: list[PackageMention] = []
    for relpath, text in model_texts(package).items():
        if relpath.endswith(DESCRIPTION_SUFFIXES):
            found.extend(_mentions(relpath, without_comments(text, comment_kind(relpath))))
    return tuple(found)


def comment_kind(relpath: str) -> str:
    """How comments are written in the model file ``relpath`` (for
    :func:`~pkgtool.model.text_comments.without_comments`): RViz settings are YAML."""
    return "yaml" if relpath.endswith(".rviz") else "xml"


@per_package
def described_packages(package: Package) -> frozenset[str]:
    """The packages the package's description, world and RViz files name."""
    return frozenset(mention.package for mention in package_mentions(package))


def _mentions(relpath: str, text: str) -> list[PackageMention]:
    """The packages ``text``, the content of ``relpath``, names, with their lines counted
    once through the file."""
    mentions: list[PackageMention] = []
    line, start = 1, 0
    for match in _NAMED.finditer(text):
        line += text.count("\n", start, match.start())
        start = match.start()
        column = start - text.rfind("\n", 0, start)
        mentions.append(PackageMention(match.group(1) or match.group(2),
                                       Span(relpath, line, column)))
    return mentions
