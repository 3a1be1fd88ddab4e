"""The rule catalogue: the ``@rule`` decorator, stable codes, lookup by code, family or name."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Iterable
from functools import cache
from typing import TYPE_CHECKING, NamedTuple, TypeAlias

from pkgtool.findings import Hit, Severity
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

if TYPE_CHECKING:
    from pkgtool.model.package import Package

Check: TypeAlias = "Callable[[Package], Iterable[Hit]]"

CODE_PATTERN = lazy_pattern(r"^[A-Z]{3}\d{3}$")
NAME_PATTERN = lazy_pattern(r"^[a-z][a-z0-9]*(-[a-z0-9]+)*$")
DOC_SECTIONS = ("## What it does", "## Why is this bad?", "## Example", "## Use instead")

FAMILIES = {
    "SYN": "files that cannot be read or parsed",
    "MAN": "package.xml",
    "SET": "setup.py and setup.cfg",
    "ENT": "console_scripts entry points",
    "DAT": "data_files: installed resources",
    "DEP": "imports versus package.xml dependencies",
    "LCH": "launch files",
    "IFC": "interface definitions: .msg, .srv and .action files",
    "PYC": "Python code",
    "STY": "style: flake8 and pydocstyle with ament's settings",
    "CPY": "copyright and license headers",
}
"""Code prefixes and what each family checks. Codes are never reused or renumbered."""


@record
class Rule:
    """A registered rule: identity, default severity, documentation and the check itself."""

    code: str
    name: str
    severity: Severity
    fix: str
    check: Check
    default_enabled: bool = True

    @property
    def doc(self) -> str:
        """The check's docstring, dedented (worked out when asked: a lint run never asks)."""
        import inspect

        return inspect.cleandoc(self.check.__doc__ or "")

    @property
    def family(self) -> str:
        """The code's three-letter prefix, e.g. ``MAN``."""
        return self.code[:3]

    @property
    def summary(self) -> str:
        """The first line of the rule's documentation."""
        return self.doc.strip().splitlines()[0] if self.doc.strip() else self.name


class RuleInfo(NamedTuple):
    """What selecting a rule needs, known without importing it (see :func:`index`)."""

    code: str
    name: str
    severity: Severity
    default_enabled: bool
    module: str
    """The module defining the rule, relative to :mod:`pkgtool.rules`."""


_RULES: dict[str, Rule] = {}
_CODES_BY_NAME: dict[str, str] = {}
"""The code of each registered rule name (a name or code taken twice fails at import)."""
_loaded = False


def rule(
    code: str,
    name: str,
    severity: Severity,
    *,
    fix: str,
    default_enabled: bool = True,
) -> Callable[[Check], Check]:
    """Register ``check`` under a stable ``code`` and kebab-case ``name``.

    ``fix`` is the generic imperative fix shown when a hit carries none of its own. Rules whose
    docstring lacks the required sections, or whose code or name is taken, fail at import.
    """
    if not CODE_PATTERN.match(code) or code[:3] not in FAMILIES:
        raise ValueError(f"rule code {code!r} must be a known family prefix and three digits")
    if not NAME_PATTERN.match(name):
        raise ValueError(f"rule name {name!r} must be kebab-case")

    def register(check: Check) -> Check:
        doc = check.__doc__ or ""
        missing = [s for s in DOC_SECTIONS if s not in doc]
        if missing and sys.flags.optimize < 2:  # ``python -OO`` strips every docstring
            raise ValueError(f"rule {code} docstring lacks {', '.join(missing)}")
        for other in (_RULES.get(code), _RULES.get(_CODES_BY_NAME.get(name, ""))):
            if other is not None and other.check is not check:
                raise ValueError(f"rule {code} {name} clashes with {other.code} {other.name}")
        _RULES[code] = Rule(code, name, severity, fix, check, default_enabled)
        _CODES_BY_NAME[name] = code
        return check

    return register


def load_all() -> dict[str, Rule]:
    """Import every rule module once and return the catalogue keyed by code."""
    global _loaded
    if not _loaded:
        import pkgutil  # only here: a lint run imports the rules it selects, by the index

        import pkgtool.rules as package

        for info in pkgutil.walk_packages(package.__path__, package.__name__ + "."):
            importlib.import_module(info.name)
        _loaded = True
    return dict(sorted(_RULES.items()))


@cache
def index() -> dict[str, RuleInfo]:
    """Every rule's code, name, severity and module, in code order, from the generated
    :mod:`pkgtool.rules._index` (``python -m pkgtool.docs_gen``): selecting rules imports none.
    Shared: do not change the result."""
    from pkgtool.rules._index import RULES

    return {code: RuleInfo(code, name, Severity(severity), default, module)
            for code, (name, severity, default, module) in RULES.items()}


def load(codes: Iterable[str]) -> dict[str, Rule]:
    """The rules of ``codes``, importing only their modules."""
    wanted = sorted(set(codes))
    if not _loaded:
        _import(tuple(wanted))
    return {code: _RULES[code] for code in wanted}


@cache
def _import(codes: tuple[str, ...]) -> None:
    """Import the modules of the rules ``codes``, once per selection (a lint run asks for the
    rules of each package)."""
    catalogue = index()
    for module in sorted({catalogue[code].module for code in codes if code in catalogue}):
        importlib.import_module(f"pkgtool.rules.{module}")


def matching(selector: str) -> list[str]:
    """Codes matching a code (``MAN003``), a family (``MAN``), a code prefix or a rule name,
    read from the index (nothing imported)."""
    rules = index()
    key = selector.strip()
    if key.upper() in rules:
        return [key.upper()]
    by_name = [r.code for r in rules.values() if r.name == key.lower()]
    if by_name:
        return by_name
    return [code for code in rules if code.startswith(key.upper())] if key else []


def resolve(selector: str) -> list[Rule]:
    """The rules :func:`matching` ``selector``, in code order."""
    return list(load(matching(selector)).values())
