"""Fixers of setup() keywords: metadata package.xml decides, the script group and the module
of a console script, the test extra."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.edit.core import Edit, Fix
from pkgtool.edit.setup_cfg import rename_option
from pkgtool.edit.setup_py import SetupDoc
from pkgtool.findings import Finding
from pkgtool.fix.common import cfg_source, offer, python_nodes, renames, setup_doc
from pkgtool.fix.registry import Refusal, fixer
from pkgtool.model.package import Package
from pkgtool.rules.entry_points.misspelled_script_group import misspelt
from pkgtool.rules.manifest.template_placeholder import is_placeholder, is_placeholder_email
from pkgtool.rules.setup.tests_require import TEST_EXTRAS

ENTRY_POINTS = "options.entry_points"


def _from_manifest(package: Package, keyword: str, wanted: str | None
                   ) -> Iterator[Fix | Refusal]:
    """Write package.xml's ``wanted`` over the string literal setup() takes ``keyword`` from;
    refused when ``wanted`` is a template's placeholder (``TODO: License declaration``): then
    setup.py holds the real value, and MAN017's fixer writes it into package.xml."""
    doc = setup_doc(package)
    if doc is None or wanted is None:
        return
    if is_placeholder(wanted) or is_placeholder_email(wanted):
        yield Refusal(f"package.xml's {keyword} `{wanted}` is a placeholder (MAN017): write "
                      f"the real one into package.xml, not the placeholder into setup.py")
        return

    def build() -> list[Edit]:
        value = doc.value(keyword, f"`{keyword}`")
        return [doc.replace_value(value, doc.doc.string(wanted), f"`{keyword}`")]

    yield from offer(f"Write `{keyword}={wanted!r}` from package.xml", build)


@fixer("SET003", "Write package.xml's name into setup.py")
def name(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """package.xml wins: the string literal the name comes from (usually ``package_name =
    '...'``) gets package.xml's name, so data_files paths built from it follow. Safe: ROS tools
    know the package by package.xml's name only; a name computed by code is refused, and so is
    one that is also the Python package ``packages=`` installs (``packages=[package_name]``
    with the code in ``<old name>/``): the code would no longer be installed, and so is a
    package whose folder is named as setup.py says (package.xml may hold the typo)."""
    manifest = package.manifest
    wanted = manifest.name.value if manifest and manifest.name else None
    setup = package.setup_py
    old = setup.name.value if setup and setup.name else None
    installs = setup.packages.names if setup and setup.packages and \
        setup.packages.kind == "list" else ()
    if isinstance(old, str) and wanted and old in installs and package.has_folder(old) and \
            not package.has_folder(wanted):
        yield Refusal(f"`{old}` is also the Python package setup.py installs (the folder "
                      f"`{old}/`): rename the folder to `{wanted}` first, or write the names "
                      "by hand")
        return
    if isinstance(old, str) and wanted and old != wanted and package.root.name == old:
        yield Refusal(f"The folder is `{old}` too: package.xml's `<name>{wanted}</name>` may be "
                      f"the one misspelt; correct the name where it is wrong by hand")
        return
    yield from _from_manifest(package, "name", wanted)


@fixer("SET004", "Write package.xml's version into setup.py")
def version(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """package.xml wins (bloom releases its version). Safe: only metadata changes."""
    manifest = package.manifest
    yield from _from_manifest(package, "version", manifest.version.value if manifest and
                              manifest.version else None)


@fixer("SET005", "Write package.xml's license into setup.py")
def license_(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """package.xml wins; several ``<license>`` tags are joined with ``, `` as catkin_pkg's
    ``generate_distutils_setup`` does (no OR or AND is claimed). Safe: only metadata changes."""
    licenses = package.manifest.licenses if package.manifest else ()
    if licenses:
        yield from _from_manifest(package, "license", ", ".join(x.value for x in licenses))


@fixer("SET006", "Write package.xml's maintainer into setup.py")
def maintainer(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """``maintainer`` gets the name and ``maintainer_email`` the email of package.xml's one
    ``<maintainer>``. Safe: only metadata changes. With several maintainers the user chooses
    (a Refusal); a keyword that matches already is left as it is."""
    setup, people = package.setup_py, package.manifest.maintainers if package.manifest else ()
    if setup is None:
        return
    at = {(f.span.line, f.span.col) for f in findings if f.span.path == "setup.py"}
    for keyword in ("maintainer", "maintainer_email"):
        given = getattr(setup, keyword)
        if given is None or (given.span.line, given.span.col) not in at:
            continue
        if len(people) != 1:
            yield Refusal(f"package.xml has {len(people)} maintainers: write the one that "
                          f"answers for the package into `{keyword}` by hand.")
            continue
        wanted = people[0].name if keyword == "maintainer" else people[0].email
        if wanted:
            yield from _from_manifest(package, keyword, wanted)


@fixer("ENT002", "Write the installed module the console script means")
def script_module(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rewrite the module of a console script that names an installed module without its
    package (``talker = talker:main`` for ``my_pkg.talker``), when the rule found exactly
    that module (its help says `Write `my_pkg.talker:main``). Safe: the script could not
    start. Modules that are not written, not installed or misspelt need the user, and so
    do scripts in setup.cfg."""
    for doc, finding, nodes in python_nodes(package, findings):
        literal = next((n for n in nodes if isinstance(n, ast.Constant)), None)
        meant = finding.fix[7:-1].rpartition(":")[0] if finding.fix and \
            finding.fix.startswith("Write `") else ""
        written = finding.message.split("`")[1]
        if literal is None or not meant or \
                finding.message != f"`{written}` is not installed: the module is `{meant}`":
            continue
        text, start = doc.segment(literal), doc.start(literal)
        found = list(re.finditer(rf"(?<==)(\s*){re.escape(written)}(?=\s*:)", text))
        if len(found) == 1:
            at = start + found[0].end(1)
            yield Fix(f"Write `{meant}`", (Edit(doc.source.path, at, at + len(written),
                                                meant),))


@fixer("ENT003", "Point the console script at the function its misspelt one is close to",
       safe=False)
def script_function(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the function of a console script (``talker:mian``) to the one top-level name
    of its module spelled like it. Unsafe: it guesses which function was meant; the script
    raised ImportError before."""
    yield from renames(package, findings, re.compile(r"^`[\w.]+` does not define `(\w+)`"),
                       re.compile(r"Write `(\w+)`"), ":")


@fixer("ENT005", "Name the entry point group `console_scripts`")
def script_group(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Rename the misspelt group key (setup.py's dict literal or setup.cfg's option). Safe:
    the executables the author listed get installed. A group that exists already as well
    would need merging, and an INI string in setup.py is not edited: both are refused."""
    lines = {f.span.line for f in findings if f.span.path == "setup.cfg"}
    cfg, source = package.setup_cfg, cfg_source(package)
    for option in cfg.options if cfg and source and lines else ():
        wanted = misspelt(option.key) if option.section == ENTRY_POINTS else None
        if wanted and option.span.line in lines:
            if cfg.get(ENTRY_POINTS, wanted) is not None:
                yield Refusal(f"setup.cfg has both `{option.key}` and `{wanted}`: merge them "
                              "by hand.")
            else:
                yield Fix(f"Rename `{option.key}` to `{wanted}`",
                          tuple(rename_option(source, ENTRY_POINTS, option.key, wanted)))
    setup, doc = package.setup_py, setup_doc(package)
    at = {(f.span.line, f.span.col) for f in findings if f.span.path == "setup.py"}
    groups = {e.group for e in setup.entry_points or () if (e.span.line, e.span.col) in at} \
        if setup and doc else set()
    for group in sorted(groups):
        yield from offer(f"Rename the group `{group}` to `{misspelt(group)}`",
                         lambda group=group: _rename_group(doc, group))


def _rename_group(doc: SetupDoc, group: str) -> list[Edit]:
    groups = doc.value("entry_points", "the entry points")
    wanted = misspelt(group)
    if not isinstance(groups, dict) or wanted is None:
        return doc.refuse("gives entry_points as a string, which pkgtool does not edit")
    if wanted in groups:
        return doc.refuse(f"has both `{group}` and `{wanted}` groups: merge them by hand")
    key = next(k for k in groups if k == group)
    return [doc.replace_value(key, doc.doc.string(wanted), "the entry point group")]


@fixer("SET007", "Replace `tests_require` by the `test` extra")
def tests_require(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """``tests_require=X`` becomes ``extras_require={'test': X}`` (or joins the extras given).
    Safe: colcon reads pytest from either, and setuptools 72+ only knows the extra."""
    doc = setup_doc(package)
    if doc is not None:
        yield from offer("Move `tests_require` into `extras_require['test']`",
                         lambda: _test_extra(doc))


def _test_extra(doc: SetupDoc) -> list[Edit]:
    found = doc.keyword("tests_require")
    if found is None:
        return []
    value = doc.doc.segment(found.value)
    item = f"{doc.doc.string('test')}: {value}"
    extras = doc.value("extras_require", "extras_require")
    if extras is None:
        return [doc.replace_keyword("tests_require", "extras_require={" + item + "}")]
    if isinstance(extras, dict) and any(key in extras for key in TEST_EXTRAS):
        return []
    return doc.add_to_dict(extras, item, "extras_require") + [doc.remove_keyword("tests_require")]


@fixer("SET016", "Write the setup() or find_packages() keyword meant")
def setup_keyword(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Rename the misspelt keyword to the one a typo away. Safe: setuptools dropped the
    misspelt one, so the package now gets what its author wrote (the keyword meant is
    never given as well)."""
    yield from renames(package, findings, re.compile(r"^`\w+\(\)` has no keyword `(\w+)`"))
