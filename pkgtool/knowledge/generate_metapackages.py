"""Generate the metapackage table from the package.xml files of released repositories.

``python -m pkgtool.knowledge.generate_metapackages`` reads each repository and commit that
``data/metapackage_sources.txt`` lists from a local git mirror (``--mirrors``, default
``/work/.mirror``: ``<owner>+<name>/repo``, as ``git`` reads it) and writes
``data/metapackages.txt``: each released metapackage -> its direct run dependencies
(``exec_depend``, ``depend``, ``run_depend``), flagged with the distributions releasing it.

``--select ROSDISTRO`` first rewrites the sources list from a ros/rosdistro checkout: the GitHub
source repositories that release two or more packages, one of them named like the repository
(without trailing digits: moveit2 -> moveit), plus ros2/variants; each at the branch of the
newest distribution releasing it, resolved to a commit in its mirror (a repository without one
is left out and named).

Whether a package is a metapackage is read from its folder, never from its name
(:func:`is_metapackage`). Third-party files are read from the mirrors only; just the table and
the sources list enter this repository.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import textwrap
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path, PurePosixPath

from lxml import etree

from pkgtool.knowledge.tables import DATA, DISTROS, read, render, write
from pkgtool.safe_xml import parser as xml_parser

MIRRORS = Path("/work/.mirror")
SOURCES = "metapackage_sources"
EXTRA_REPOSITORIES = ("ros2/variants",)
"""Repositories of metapackages that no distribution lists under a repository of their name."""
RUN_TAGS = frozenset({"exec_depend", "depend", "run_depend"})
IGNORE_MARKERS = frozenset({"COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE"})

_BOOKKEEPING = re.compile(
    r"(package\.xml|CMakeLists\.txt|setup\.py|setup\.cfg|rosdoc2\.yaml|\.[^/]*"
    r"|(CHANGELOG|README|LICENSE|COPYING|CONTRIBUTING)[^/]*|(doc|docs)/.*"
    r"|launch/[^/]+\.(py|xml|yaml|launch))", re.IGNORECASE)
"""Files of a package folder that are no code or data of its own: bookkeeping, and launch files
(which can only start what the package brings in)."""
_CMAKE_COMMAND = re.compile(r"^\s*(\w+)\s*\(", re.MULTILINE)
_CMAKE_NO_INSTALL = frozenset({
    "cmake_minimum_required", "project", "find_package", "ament_package", "if", "elseif",
    "else", "endif", "set", "message", "ament_lint_auto_find_test_dependencies",
    "ament_export_dependencies"})
"""CMake commands that build and install nothing (a metapackage's whole CMakeLists.txt), with
``ament_package()`` called without ``CONFIG_EXTRAS``."""


def run_dependencies(manifest: bytes) -> tuple[list[str], bool]:
    """The run dependencies a package.xml declares, and whether it exports ``<metapackage/>``."""
    root = etree.fromstring(manifest, xml_parser())
    names = [(child.text or "").strip() for child in root
             if isinstance(child.tag, str) and child.tag in RUN_TAGS]
    exported = root.find("export/metapackage") is not None
    return list(dict.fromkeys(n for n in names if n)), exported


def installs_nothing(cmake: str) -> bool:
    """True when a CMakeLists.txt only finds ament_cmake and calls ``ament_package()``."""
    code = "\n".join(line.split("#", 1)[0] for line in cmake.splitlines()).lower()
    return (set(_CMAKE_COMMAND.findall(code)) <= _CMAKE_NO_INSTALL
            and not re.search(r"ament_package\s*\(\s*[^\s)]", code))


def is_metapackage(name: str, own_files: Iterable[str], exported: bool,
                   cmake: str | None) -> bool:
    """True when a package (with run dependencies) only brings in others.

    It exports ``<metapackage/>``; or its folder holds nothing but bookkeeping (package.xml,
    build files, change log, read-me, licence, docs, the ``resource/<name>`` marker) and
    launch files; or it
    has no setup.py and its CMakeLists.txt installs nothing (maintainer scripts beside it are
    never installed). ``own_files`` are relative to the folder, nested packages left out.
    """
    files = list(own_files)
    if exported or all(_BOOKKEEPING.fullmatch(f) or f == f"resource/{name}" for f in files):
        return True
    return cmake is not None and "setup.py" not in files and installs_nothing(cmake)


def package_folders(paths: Iterable[str]) -> dict[str, list[str]]:
    """Folder of each package.xml -> the files under it that belong to no nested package.

    Folders under a ``COLCON_IGNORE`` (or ament's, catkin's marker) hold no package.
    """
    paths = list(paths)
    ignored = {str(PurePosixPath(p).parent) for p in paths if PurePosixPath(p).name
               in IGNORE_MARKERS}
    folders = sorted({str(PurePosixPath(p).parent) for p in paths
                      if PurePosixPath(p).name == "package.xml"}, key=len, reverse=True)
    folders = [f for f in folders if not any(_under(f, i) for i in ignored)]
    owned: dict[str, list[str]] = {f: [] for f in folders}
    for path in paths:
        owner = next((f for f in folders if _under(path, f)), None)
        if owner is not None:
            owned[owner].append(path if owner == "." else path[len(owner) + 1:])
    return owned


def _under(path: str, folder: str) -> bool:
    return folder == "." or path == folder or path.startswith(folder + "/")


def metapackages(paths: Iterable[str], show: Callable[[str], bytes]
                 ) -> Iterator[tuple[str, list[str]]]:
    """(name, run dependencies) of each metapackage in a tree; ``show(path)`` gives a file's
    bytes."""
    for folder, files in package_folders(paths).items():
        prefix = "" if folder == "." else folder + "/"
        try:
            manifest = show(prefix + "package.xml")
            depends, exported = run_dependencies(manifest)
            name = etree.fromstring(manifest, xml_parser()).findtext("name", "").strip()
        except (etree.XMLSyntaxError, ValueError):
            continue
        cmake = (show(prefix + "CMakeLists.txt").decode("utf-8", "replace")
                 if "CMakeLists.txt" in files else None)
        if name and depends and is_metapackage(name, files, exported, cmake):
            yield name, depends


def _git(mirror: Path, *args: str) -> bytes:
    return subprocess.run(["git", "-C", str(mirror), *args], capture_output=True,
                          check=True).stdout


def mirror_of(repository: str, mirrors: Path) -> Path:
    """The local git mirror of GitHub ``owner/name``, its name matched without case (GitHub's
    names are not case-sensitive: rosdistro writes ``flexbe/...`` for ``FlexBE/...``)."""
    folder = repository.replace("/", "+", 1)
    if not (mirrors / folder).exists() and mirrors.is_dir():
        folder = next((f.name for f in mirrors.iterdir() if f.name.lower() == folder.lower()),
                      folder)
    return mirrors / folder / "repo"


def repository_metapackages(repository: str, commit: str, mirrors: Path
                            ) -> list[tuple[str, list[str]]]:
    """The metapackages of ``repository`` at ``commit``, read from its mirror."""
    mirror = mirror_of(repository, mirrors)
    paths = _git(mirror, "ls-tree", "-r", "--name-only", commit).decode().splitlines()
    return list(metapackages(paths, lambda path: _git(mirror, "show", f"{commit}:{path}")))


def _github(url: str) -> str | None:
    found = re.fullmatch(r"https://github\.com/([\w.-]+)/([\w.-]+?)(?:\.git)?/?", url or "")
    return f"{found.group(1)}/{found.group(2)}" if found else None


def selected(distributions: dict[str, dict]) -> dict[str, str]:  # type: ignore[type-arg]
    """GitHub ``owner/name`` -> source branch of each repository that may hold a metapackage:
    two or more released packages, one named like the repository (trailing digits dropped).
    The newest distribution's branch wins."""
    chosen: dict[str, str] = {}
    for distro in DISTROS:
        for name, entry in (distributions[distro].get("repositories") or {}).items():
            release = (entry or {}).get("release") or {}
            packages = release.get("packages") or [name]
            source = (entry or {}).get("source") or {}
            github = _github(source.get("url", ""))
            if (release.get("version") and len(packages) > 1 and github
                    and {name, name.rstrip("0123456789")} & set(packages)):
                chosen[github] = str(source.get("version") or "HEAD")
    for extra in EXTRA_REPOSITORIES:
        chosen.setdefault(extra, "rolling")
    return chosen


def select(rosdistro: Path, mirrors: Path, output: Path) -> None:
    """Write the sources list: each selected repository and its branch's commit."""
    from pkgtool.knowledge.generate_rosdistro import _commit, _load

    distributions = {d: _load(rosdistro / d / "distribution.yaml") for d in DISTROS}
    lines, missing = [], []
    for repository, branch in sorted(selected(distributions).items(), key=lambda r: r[0].lower()):
        mirror = mirror_of(repository, mirrors)
        try:
            commit = next(_git(mirror, "rev-parse", ref).decode().strip()
                          for ref in (f"refs/heads/{branch}", "HEAD")
                          if _resolves(mirror, ref))
        except (StopIteration, subprocess.CalledProcessError, OSError):
            missing.append(repository)
            continue
        lines.append(f"{repository} {commit}")
    left_out = "No mirror (left out): " + (" ".join(missing) or "none")
    title = "\n".join([
        "GitHub repositories read for metapackages, at the commit of the source branch of the "
        "newest\ndistribution releasing them. Written by `python -m "
        "pkgtool.knowledge.generate_metapackages --select`.",
        *textwrap.wrap(left_out, 95, break_on_hyphens=False)])
    write({SOURCES: render(title, f"ros/rosdistro {_commit(rosdistro)}", [("-", lines)])},
          output)


def _resolves(mirror: Path, ref: str) -> bool:
    return subprocess.run(["git", "-C", str(mirror), "rev-parse", "--verify", "--quiet", ref],
                          capture_output=True, check=False).returncode == 0


def table(sources: dict[str, str], mirrors: Path) -> str:
    """The text of ``metapackages.txt`` from each ``owner/name -> commit`` of ``sources``."""
    released = read("ros_packages").flags
    found: dict[str, list[str]] = {}
    for repository, commit in sorted(sources.items()):
        for name, depends in repository_metapackages(repository, commit, mirrors):
            if name in released:
                found.setdefault(name, depends)
    groups: dict[str, list[str]] = {}
    for name in sorted(found):
        groups.setdefault(released[name], []).append(" ".join([name, *found[name]]))
    title = ("Released metapackages -> their direct run dependencies (flags: the distributions "
             "releasing\nthe metapackage). A metapackage exports <metapackage/> or its folder "
             "holds no code or data of\nits own. Generated by `python -m "
             "pkgtool.knowledge.generate_metapackages`; do not edit.")
    return render(title, [f"{r} {c}" for r, c in sorted(sources.items())],
                  sorted(groups.items(), key=lambda item: (-len(item[1]), item[0])))


def main(argv: list[str] | None = None) -> None:
    """Write the sources list (``--select``) or the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mirrors", type=Path, default=MIRRORS,
                        help="folder of the git mirrors (default: %(default)s)")
    parser.add_argument("--select", type=Path, metavar="ROSDISTRO",
                        help="rewrite the sources list from this ros/rosdistro checkout")
    parser.add_argument("--output", type=Path, default=DATA, help="where to write the table")
    args = parser.parse_args(argv)
    if args.select:
        select(args.select, args.mirrors, args.output)
    sources = _sources(args.output if args.select else DATA)
    write({"metapackages": table(sources, args.mirrors)}, args.output)


def _sources(folder: Path) -> dict[str, str]:
    """``owner/name -> commit`` of the sources list in ``folder``."""
    text = (folder / f"{SOURCES}.txt").read_text(encoding="utf-8")
    pairs = (line.split(" ", 1) for line in text.splitlines()
             if line and line[0] not in "#@" and not line.startswith("source "))
    return {name: commit for name, commit in pairs}


if __name__ == "__main__":
    main()
