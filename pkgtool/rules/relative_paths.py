"""Which file of a package a path relative to some working folder names (LCH012, DAT017)."""

from __future__ import annotations

import posixpath

from pkgtool.model.package import Package


def package_file_named(text: str, package: Package, *, absent: bool = False
                       ) -> tuple[str, bool] | None:
    """The file of ``package`` a relative path names, and whether it is written from a
    workspace's or a repository's folder (``src/<name>/config/x.yaml``,
    ``<name>/config/x.yaml``, ``ws/src/<name>/...``, ``robots/<name>/...``) rather than
    from the package's own (``config/x.yaml``); None for an absolute path or one naming no
    file of the package. With ``absent``, a path through
    a workspace's ``src/<name>/`` names a file of the package even when the package lacks it
    (a model kept out of git: the path still reads the source tree)."""
    if not text or posixpath.isabs(text) or text.startswith(("~", "$")):
        return None
    path = posixpath.normpath(text)
    if package.has_file(path):
        return path, False
    parts = path.split("/")
    for at in range(len(parts) - 1):
        if parts[at] != package.name:
            continue
        inside = "/".join(parts[at + 1:])
        if package.has_file(inside) or absent and at > 0 and parts[at - 1] == "src":
            return inside, True
    return None
