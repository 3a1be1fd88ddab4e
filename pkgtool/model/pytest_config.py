"""pytest's collection settings for a package, from the configuration file pytest would use.

pytest takes the first of ``pytest.ini``, ``.pytest.ini``, ``pyproject.toml`` (with a
``[tool.pytest.ini_options]`` table), ``tox.ini`` (with ``[pytest]``) and ``setup.cfg`` (with
``[tool:pytest]``) in the folder it runs in; ``colcon test`` runs it in the package folder.
"""

from __future__ import annotations

import configparser

from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.records import field, record

DEFAULTS: dict[str, tuple[str, ...]] = {
    "python_files": ("test_*.py", "*_test.py"),
    "python_functions": ("test",),
    "python_classes": ("Test",),
    "norecursedirs": ("*.egg", ".*", "_darcs", "build", "CVS", "dist", "node_modules", "venv",
                      "{arch}"),
    "testpaths": (),
    "addopts": (),
}
"""The settings the collection depends on, with pytest's defaults."""
CONFIG_FILES = ("pytest.ini", ".pytest.ini", "pyproject.toml", "tox.ini", "setup.cfg")
_SECTIONS = {"pytest.ini": "pytest", ".pytest.ini": "pytest", "tox.ini": "pytest",
             "setup.cfg": "tool:pytest"}


@record
class PytestConfig:
    """The configuration file pytest uses (``""`` for none) and the settings it gives."""

    path: str = ""
    options: dict[str, tuple[str, ...]] = field(default_factory=dict)

    def get(self, key: str) -> tuple[str, ...]:
        """A setting's values: the file's, else pytest's default."""
        return self.options.get(key, DEFAULTS[key])

    def where(self, key: str) -> str:
        """`` (`key` in path)`` when the file sets ``key``, else ``""``: for messages."""
        return f" (`{key}` in {self.path})" if key in self.options else ""


@per_package
def pytest_config(package: Package) -> PytestConfig | None:
    """The package's pytest settings; None when the file pytest uses does not parse."""
    for path in CONFIG_FILES:
        text = package.texts.get(path)
        if text is None:
            continue
        found = _toml(text) if path == "pyproject.toml" else _ini(path, text)
        if found is None:
            return None
        if found is not False:
            return PytestConfig(path, found)
    return PytestConfig()


def _toml(text: str) -> dict[str, tuple[str, ...]] | bool | None:
    from pkgtool.compat import tomllib

    try:
        table = tomllib.loads(text).get("tool", {}).get("pytest", {}).get("ini_options")
    except (tomllib.TOMLDecodeError, AttributeError):
        return None
    if not isinstance(table, dict):
        return False
    options: dict[str, tuple[str, ...]] = {}
    for key in DEFAULTS:
        value = table.get(key)
        if isinstance(value, str):
            options[key] = _words(value)
        elif isinstance(value, list) and all(isinstance(v, str) for v in value):
            options[key] = tuple(value)
        elif value is not None:
            return None
    return options


def _ini(path: str, text: str) -> dict[str, tuple[str, ...]] | bool | None:
    parser = configparser.ConfigParser(interpolation=None, strict=False)
    try:
        parser.read_string(text, source=path)
        section = _SECTIONS[path]
        if not parser.has_section(section):
            return {} if section == "pytest" and path != "tox.ini" else False  # pytest.ini counts
        return {key: _words(parser.get(section, key)) for key in DEFAULTS
                if parser.has_option(section, key)}
    except (configparser.Error, ValueError):
        return None


def _words(value: str) -> tuple[str, ...]:
    """An option's value split as a shell would (as pytest splits ``addopts``)."""
    import shlex  # only here: most packages set no pytest option

    return tuple(shlex.split(value))
