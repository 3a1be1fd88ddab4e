"""SET016: a misspelt keyword of ``setup()``, or a keyword ``find_packages()`` does not take."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import setup_tree
from pkgtool.rules.syntax_trees import index_of

SETUP_KEYWORDS = frozenset({
    # distutils
    "name", "version", "author", "author_email", "maintainer", "maintainer_email", "url",
    "license", "description", "long_description", "keywords", "platforms", "classifiers",
    "download_url", "provides", "requires", "obsoletes", "packages", "package_dir",
    "package_data", "py_modules", "scripts", "ext_modules", "ext_package", "libraries",
    "headers", "data_files", "cmdclass", "distclass", "script_name", "script_args", "options",
    "password", "command_options",
    # setuptools
    "license_file", "license_files", "long_description_content_type", "project_urls",
    "python_requires", "zip_safe", "install_requires", "entry_points", "extras_require",
    "setup_requires", "dependency_links", "namespace_packages", "test_suite", "tests_require",
    "test_loader", "eager_resources", "include_package_data", "exclude_package_data",
    "use_2to3", "convert_2to3_doctests", "use_2to3_fixers", "use_2to3_exclude_fixers",
    "py_limited_api", "src_root",
})
"""The keywords ``setup()`` of distutils and setuptools knows (plugins add others: a keyword
that is a typo away from none of these is left alone)."""
_HABITS = {"test_requires": "tests_require", "extra_requires": "extras_require",
           "install_require": "install_requires", "entry_point": "entry_points"}
"""Misspellings more than one edit away that people write."""
FINDERS = {"find_packages": ("where", "exclude", "include"),
           "find_namespace_packages": ("where", "exclude", "include")}
"""setuptools' package finders and the keywords they take."""


def _setup_keywords(tree: ast.Module) -> Iterator[ast.keyword]:
    """The named keywords of every ``setup(...)`` / ``<module>.setup(...)`` call."""
    for node in nodes_of_class(tree, ast.Call):
        assert isinstance(node, ast.Call)
        if "setup" in (getattr(node.func, "id", None), getattr(node.func, "attr", None)):
            yield from (k for k in node.keywords if k.arg is not None)


def _finder_calls(tree: ast.Module) -> Iterator[tuple[str, ast.Call]]:
    """Calls of setuptools' package finders (``find_packages(...)`` imported from setuptools,
    ``setuptools.find_packages(...)``)."""
    index = index_of(tree)
    for call in index.calls:
        named = index.qualified(call.func) if isinstance(call.func, (ast.Name, ast.Attribute)) \
            else None
        finder = named.removeprefix("setuptools.") if named else ""
        if finder in FINDERS and named == f"setuptools.{finder}":
            yield finder, call


@rule("SET016", "misspelled-setup-keyword", Severity.ERROR,
      fix="Write the keyword setuptools knows (see the message)")
def misspelled_setup_keyword(package: Package) -> Iterator[Hit]:
    """A keyword of `setup()` is misspelt, or `find_packages()` is given one it does not take.

    ## What it does
    Reports a keyword of `setup()` in setup.py that setuptools does not know and that is a
    typo away from exactly one keyword it knows (`packges=`, `nae=`, `install_require=`,
    `test_requires=`), when that keyword is not given as well; keywords of plugins
    (`use_scm_version=`, `cffi_modules=`), a typo away from none, are left alone. Also
    reports any keyword other than `where`, `include` and `exclude` given to setuptools'
    `find_packages()` or `find_namespace_packages()` (`excude=`).

    ## Why is this bad?
    setuptools only warns "Unknown distribution option" and drops the keyword: the build
    succeeds without it. A misspelt `packages` installs no Python code (every console script
    then fails with ModuleNotFoundError), `name` gives an `UNKNOWN` distribution, and
    `install_requires` or `entry_points` vanish. A keyword `find_packages()` does not take
    is a TypeError, and the build fails.

    ## Example
    ```python
    setup(name=package_name, packges=find_packages(excude=['test']), ...)
    ```

    ## Use instead
    ```python
    setup(name=package_name, packages=find_packages(exclude=['test']), ...)
    ```
    """
    tree = setup_tree(package)
    if tree is None:
        return
    keywords = list(_setup_keywords(tree))
    given = {k.arg for k in keywords}
    for keyword in keywords:
        assert keyword.arg is not None
        if keyword.arg in SETUP_KEYWORDS:
            continue
        meant = _HABITS.get(keyword.arg) or typo_of(keyword.arg, SETUP_KEYWORDS)
        if meant and meant not in given:
            yield Hit(Span("setup.py", keyword.lineno, keyword.col_offset + 1),
                      f"`setup()` has no keyword `{keyword.arg}`: setuptools ignores it with a "
                      f"warning, so the package is built without `{meant}`", f"Write `{meant}`")
    for finder, call in _finder_calls(tree):
        for keyword in call.keywords:
            if keyword.arg is not None and keyword.arg not in FINDERS[finder]:
                meant = typo_of(keyword.arg, FINDERS[finder])
                yield Hit(Span("setup.py", keyword.lineno, keyword.col_offset + 1),
                          f"`{finder}()` has no keyword `{keyword.arg}`: TypeError, the "
                          "build fails", f"Write `{meant}`" if meant else
                          "Use `where`, `include` or `exclude`")
