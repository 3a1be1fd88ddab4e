"""What the SET, ENT and DAT rules share: which packages they check, and setup.py's values."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.installed import is_ament_python, keyword_known, package_folder
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.setup_py import SetupPy, Value
from pkgtool.model.span import Span


def name_cause(name: str) -> str:
    """The root cause "the package is called ``name`` here, not its package.xml name": SET003
    states it; SET009, DAT003 and DAT004 hits that use ``name`` are its consequences."""
    return f"package-name:{name}"


def checked_setup(package: Package) -> SetupPy | None:
    """setup.py of an ament_python package with a package.xml, when it calls setup(); also
    when that package.xml does not parse (SYN001 says so) and no CMakeLists.txt says the
    package is built otherwise: its setup.py still has its own mistakes."""
    setup = package.setup_py
    if package.manifest is None and not package.has_file("package.xml") or setup is None or \
            setup.setup_span is None:
        return None
    return setup if is_ament_python(package) else None


def setup_tree(package: Package) -> ast.Module | None:
    """The syntax tree of setup.py when :func:`checked_setup` has one to check."""
    if checked_setup(package) is None or "setup.py" not in package.texts:
        return None
    tree = parse_tree("setup.py", package.texts["setup.py"])
    return tree if isinstance(tree, ast.Module) else None


def text_of(value: Value | None) -> tuple[str, Span] | None:
    """A keyword's value and position when it evaluated to a string."""
    if value is None or not isinstance(value.value, str):
        return None
    return value.value, value.span


def script_folder(value: str) -> str:
    """A setup.cfg script folder (``script_dir``, ``install_scripts``) as compared:
    ``${base}`` written ``$base``, no trailing ``/``."""
    return value.strip().replace("${base}", "$base").rstrip("/")


def same_text(left: str, right: str) -> bool:
    """Equal ignoring case and runs of whitespace."""
    return " ".join(left.split()).casefold() == " ".join(right.split()).casefold()


def beside_manifest(package: Package, key: str) -> tuple[str, Span, str] | None:
    """setup.py's string ``key`` (``name``, ``version``), its position, and package.xml's value.

    None unless setup.py of a checked package gives a string and package.xml has the element.
    """
    setup = checked_setup(package)
    found = text_of(getattr(setup, key)) if setup else None
    element = getattr(package.manifest, key, None)
    if found is None or element is None:
        return None
    return found[0], found[1], element.value


def setup_alias(package: Package) -> str | None:
    """setup.py's name when it is not package.xml's: what SET003 reports (its
    :func:`name_cause`), and the name the package's files use for it then."""
    found = beside_manifest(package, "name")
    return found[0] if found and found[0] != found[2] else None


def listed_packages(package: Package) -> Iterator[tuple[str, str, Span]]:
    """(name, folder, span) for each name of an explicit ``packages=[...]`` list of a checked
    setup.py, the folder mapped through ``package_dir`` as setuptools does."""
    setup = checked_setup(package)
    if setup is None or setup.packages is None or setup.packages.kind != "list" or \
            not keyword_known(package, "package_dir"):
        return
    for name in setup.packages.names:
        yield name, package_folder(name, setup.package_dir or {}), setup.packages.span
