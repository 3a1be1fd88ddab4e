"""``[tool.pkgtool]`` settings from pyproject.toml files, layered under the command line.

A package's settings come from up to three layers, later ones winning: the nearest
``pyproject.toml`` with a ``[tool.pkgtool]`` table above the package (the workspace), the one
at the package root, and the command line. Rule selection composes like ruff's: a layer's
``select`` replaces the rules chosen so far, then ``extend-select`` adds and ``ignore`` removes.
``strict`` and ``rosdistro`` are taken from the last layer that sets them; ``severity``
entries override one by one; ``per-file-ignores`` of every layer apply, with globs relative
to that file's folder.
"""

from __future__ import annotations

import fnmatch
import os
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

from pkgtool.findings import Severity
from pkgtool.knowledge.tables import DEFAULT_DISTRO, DISTROS
from pkgtool.records import record, replace
from pkgtool.rules.registry import FAMILIES, Rule, index, load, matching

PYPROJECT = "pyproject.toml"
KEYS = ("select", "ignore", "extend-select", "strict", "severity", "per-file-ignores",
        "rosdistro")
ALL = "ALL"


class ConfigError(ValueError):
    """Invalid settings; the message names the file and key and says what to do."""


@record
class Layer:
    """One source of settings: a ``[tool.pkgtool]`` table or the command line.

    ``base`` is the folder ``per_file_ignores`` globs are relative to (None for the CLI).
    """

    source: str
    base: Path | None = None
    select: tuple[str, ...] | None = None
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    strict: bool | None = None
    severity: tuple[tuple[str, Severity], ...] = ()
    per_file_ignores: tuple[tuple[str, frozenset[str]], ...] = ()
    rosdistro: str | None = None


@record
class Settings:
    """What applies to one package: rules to run, severity overrides, strictness, path ignores
    and the target ROS distribution.

    Rules are kept by code so settings pickle cheaply to worker processes.
    """

    codes: tuple[str, ...]
    severities: Mapping[str, Severity]
    strict: bool
    path_ignores: tuple[tuple[Path, str, frozenset[str]], ...] = ()
    rosdistro: str = DEFAULT_DISTRO
    python: tuple[int, int] | None = None
    """The Python the project's pyproject.toml declares (:mod:`pkgtool.model.declared_python`),
    when one at or above the package does: not configuration, a fact about the project."""

    @property
    def rules(self) -> tuple[Rule, ...]:
        """The rules to run, in code order."""
        return tuple(load(self.codes).values())

    def ignores(self, path: Path, code: str) -> bool:
        """True when a per-file-ignores glob silences ``code`` at absolute ``path``."""
        for base, pattern, codes in self.path_ignores:
            if code in codes and _matches(path, base, pattern):
                return True
        return False


def _matches(path: Path, base: Path, pattern: str) -> bool:
    relative = os.path.relpath(path, base).replace(os.sep, "/")
    if relative.startswith("../"):
        return False
    folder = pattern.rstrip("/") + "/*"
    return (fnmatch.fnmatchcase(relative, pattern) or fnmatch.fnmatchcase(relative, folder)
            or ("/" not in pattern and fnmatch.fnmatchcase(relative.rsplit("/", 1)[-1], pattern)))


def expand(selector: str, *, where: str) -> frozenset[str]:
    """Rule codes a selector names: ``ALL``, a family, a code, a code prefix or a rule name."""
    key = selector.strip()
    if key.upper() == ALL:
        return frozenset(index())
    found = frozenset(matching(key)) if key else frozenset()
    if found or key.upper() in FAMILIES:
        return found
    raise ConfigError(f"Unknown rule selector `{selector}` in {where}. "
                      "Run `pkgtool lint --list-rules` to see the rule codes and names.")


def settings_for(layers: Iterable[Layer]) -> Settings:
    """Combine layers (outermost first) into the settings of one package."""
    chosen = {code for code, r in index().items() if r.default_enabled}
    severities: dict[str, Severity] = {}
    strict = False
    rosdistro = DEFAULT_DISTRO
    ignores: list[tuple[Path, str, frozenset[str]]] = []
    for layer in layers:
        rosdistro = layer.rosdistro or rosdistro
        if layer.select is not None:
            chosen = set().union(*(expand(s, where=layer.source) for s in layer.select))
        chosen |= set().union(*(expand(s, where=layer.source) for s in layer.extend_select))
        chosen -= set().union(*(expand(s, where=layer.source) for s in layer.ignore))
        strict = strict if layer.strict is None else layer.strict
        severities.update(layer.severity)
        if layer.base is not None:
            ignores.extend((layer.base, glob, codes) for glob, codes in layer.per_file_ignores)
    return Settings(tuple(sorted(chosen)), severities, strict, tuple(ignores), rosdistro)


def parse_table(table: Mapping[str, object], *, source: str, base: Path) -> Layer:
    """Validate a ``[tool.pkgtool]`` table; unknown keys, codes or values raise ConfigError."""
    for key in table:
        if key not in KEYS:
            close = _close(key.replace("_", "-"), KEYS, n=1)
            hint = f" Did you mean `{close[0]}`?" if close else f" Known keys: {', '.join(KEYS)}."
            raise ConfigError(f"Unknown key `{key}` in [tool.pkgtool] of {source}.{hint}")

    def where(key: str) -> str:
        return f"`{key}` of [tool.pkgtool] in {source}"

    strict = table.get("strict")
    if strict is not None and not isinstance(strict, bool):
        raise ConfigError(f"{where('strict')} must be true or false.")
    select = _selectors(table, "select", where) if "select" in table else None
    rosdistro = table.get("rosdistro")
    if rosdistro is not None:
        check_rosdistro(rosdistro, where("rosdistro"))
    return Layer(source, base, select, _selectors(table, "ignore", where),
                 _selectors(table, "extend-select", where), strict,
                 _severities(table.get("severity", {}), where("severity")),
                 _per_file(table.get("per-file-ignores", {}), where("per-file-ignores")),
                 rosdistro)


def check_rosdistro(value: object, where: str) -> str:
    """``value`` when it names a distribution pkgtool knows, else ConfigError."""
    if isinstance(value, str) and value in DISTROS:
        return value
    close = _close(str(value), DISTROS, n=1)
    hint = f" Did you mean `{close[0]}`?" if close else ""
    raise ConfigError(f"{where} must be one of {', '.join(DISTROS)}, not `{value}`.{hint}")


def _selectors(table: Mapping[str, object], key: str,
               where: Callable[[str], str]) -> tuple[str, ...]:
    value = table.get(key, [])
    label = where(key)
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ConfigError(f"{label} must be a list of rule codes, families or names.")
    for selector in value:
        expand(selector, where=label)
    return tuple(value)


def _severities(value: object, where: str) -> tuple[tuple[str, Severity], ...]:
    if not isinstance(value, dict):
        raise ConfigError(f"{where} must be a table such as `MAN003 = \"warning\"`.")
    catalogue = index()
    by_name = {r.name: r.code for r in catalogue.values()}
    result = []
    for key, level in value.items():
        code = key.upper() if key.upper() in catalogue else by_name.get(key)
        if code is None:
            raise ConfigError(f"Unknown rule `{key}` in {where}. "
                              "Run `pkgtool lint --list-rules` to see the rule codes.")
        if level not in {s.value for s in Severity}:
            raise ConfigError(f"`{key}` in {where} must be \"error\", \"warning\" or \"info\".")
        result.append((code, Severity(level)))
    return tuple(result)


def _per_file(value: object, where: str) -> tuple[tuple[str, frozenset[str]], ...]:
    if not isinstance(value, dict):
        raise ConfigError(f"{where} must be a table such as `\"test/*\" = [\"DEP001\"]`.")
    result = []
    for pattern, selectors in value.items():
        if not isinstance(selectors, list) or not all(isinstance(s, str) for s in selectors):
            raise ConfigError(f"`{pattern}` in {where} must be a list of rule codes.")
        codes = frozenset().union(*(expand(s, where=f"`{pattern}` in {where}")
                                    for s in selectors))
        result.append((pattern, codes))
    return tuple(result)


def read_pyproject(path: Path) -> Layer | None:
    """The ``[tool.pkgtool]`` layer of ``path``, or None when the file has no such table."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ConfigError(f"Cannot read {path}: {error}. Fix or remove the file.") from None
    if "pkgtool" not in text:
        return None
    from pkgtool.compat import tomllib

    try:
        table = tomllib.loads(text).get("tool", {}).get("pkgtool")
    except tomllib.TOMLDecodeError as error:
        raise ConfigError(f"{path} is not valid TOML ({error}). Fix the file.") from None
    if table is None:
        return None
    if not isinstance(table, dict):
        raise ConfigError(f"[tool.pkgtool] in {path} must be a table.")
    return parse_table(table, source=str(path), base=path.parent)


class ConfigFinder:
    """Find each package's layers, reading every pyproject.toml once (one per lint run)."""

    def __init__(self, command_line: Layer, *, isolated: bool = False) -> None:
        self._cli = command_line
        self._isolated = isolated
        self._layers: dict[Path, Layer | None] = {}
        self._nearest: dict[Path, Layer | None] = {}
        self._pythons: dict[Path, tuple[int, int] | None] = {}
        self._settings: dict[tuple[tuple[Layer, ...], tuple[int, int] | None], Settings] = {}

    def settings(self, root: Path) -> Settings:
        """The settings of the package at absolute ``root``."""
        found = () if self._isolated else (self._above(root.parent), self._at(root))
        layers = tuple(layer for layer in found if layer is not None) + (self._cli,)
        python = None if self._isolated else self._python(root)
        if (layers, python) not in self._settings:
            chosen = settings_for(layers)
            self._settings[layers, python] = replace(chosen, python=python) if python \
                else chosen
        return self._settings[layers, python]

    def consulted(self) -> list[Path]:
        """Every pyproject.toml path looked at so far, whether it exists or not."""
        return [folder / PYPROJECT for folder in dict.fromkeys((*self._layers, *self._pythons))]

    def _python(self, folder: Path) -> tuple[int, int] | None:
        """The Python the nearest pyproject.toml at or above ``folder`` declaring one does."""
        if folder not in self._pythons:
            file = os.path.join(folder, PYPROJECT)
            here = _declared(file) if os.path.isfile(file) else None
            parent = folder.parent
            self._pythons[folder] = here if here or parent == folder else self._python(parent)
        return self._pythons[folder]

    def _at(self, folder: Path) -> Layer | None:
        if folder not in self._layers:
            file = os.path.join(folder, PYPROJECT)  # os.path: once per package, pathlib costs
            self._layers[folder] = read_pyproject(Path(file)) if os.path.isfile(file) else None
        return self._layers[folder]

    def _above(self, folder: Path) -> Layer | None:
        """The nearest layer at ``folder`` or above it (the workspace configuration)."""
        if folder not in self._nearest:
            here = self._at(folder)
            parent = folder.parent
            self._nearest[folder] = here if here or parent == folder else self._above(parent)
        return self._nearest[folder]


def _declared(file: str) -> tuple[int, int] | None:
    """The Python the pyproject.toml ``file`` declares; None also when it cannot be read."""
    from pkgtool.model.declared_python import declared_python

    try:
        with open(file, encoding="utf-8") as stream:
            return declared_python(stream.read())
    except (OSError, UnicodeDecodeError):
        return None


def _close(word: str, choices: Iterable[str], n: int) -> list[str]:
    """The ``n`` choices closest to a mistyped ``word`` (difflib, imported only for a mistake)."""
    import difflib

    return difflib.get_close_matches(word, choices, n=n)
