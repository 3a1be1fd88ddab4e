"""The grading rubric: a TOML file of criteria with points, checked strictly when loaded.

See docs/grading.md for the format; ``pkgtool grade --init-rubric`` writes a commented example.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from pkgtool.compat import tomllib
from pkgtool.grade.limits import Limits
from pkgtool.records import field, fields, record

KINDS = ("build", "executables", "lint", "style", "tests", "hidden")
VISIBILITIES = ("visible", "hidden", "after_due_date", "after_published")
SEVERITIES = ("error", "warning", "info")
DETAILS = ("full", "summary")
_COMMON = {"kind", "name", "points", "visibility", "feedback"}
_KEYS = {
    "build": set(),
    "executables": {"names", "partial"},
    "lint": {"select", "ignore", "per_finding", "min_severity"},
    "style": {"select", "ignore", "per_finding", "min_severity"},
    "tests": {"partial", "min_tests", "exclude", "details"},
    "hidden": {"path", "partial", "details"},
}
_DEFAULT_NAMES = {"build": "Builds with colcon", "executables": "Executables installed",
                  "lint": "Lint", "style": "Style (ament flake8 and pep257)",
                  "tests": "Own tests pass", "hidden": "Instructor tests pass"}
_LIMIT_KEYS = {f.name for f in fields(Limits)} | {"test_timeout"}
_TYPES: dict[str, tuple[type, str]] = {
    "name": (str, "a string"), "feedback": (str, "a string"), "partial": (bool, "true or false"),
    "per_finding": (float, "a number"), "min_tests": (int, "a whole number"),
}


class RubricError(Exception):
    """A rubric that cannot be used; the message says where and what to change."""


@record
class Criterion:
    """One line of the rubric. Kind-specific fields keep their defaults for other kinds."""

    kind: str
    name: str
    points: float
    visibility: str = "visible"
    feedback: str = ""
    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    per_finding: float | None = None
    min_severity: str = "warning"
    names: tuple[str, ...] = ()
    partial: bool = True
    min_tests: int = 1
    exclude: tuple[str, ...] = ()
    path: Path | None = None
    details: str = "full"


@record
class Rubric:
    """A loaded rubric; ``package`` names the graded package in multi-package submissions."""

    title: str
    criteria: tuple[Criterion, ...]
    package: str | None = None
    limits: Limits = field(default_factory=Limits)
    test_timeout: float = 60.0

    @property
    def max_score(self) -> float:
        """The total of every criterion's points."""
        return sum(c.points for c in self.criteria)


def load_rubric(path: Path) -> Rubric:
    """Read and check the rubric at ``path`` (hidden-test folders resolve against its folder)."""
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise RubricError(f"Cannot read the rubric {path}: {error.strerror or error}.") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise RubricError(f"{path} is not valid TOML: {error}. Fix the file.") from None
    return parse_rubric(data, base=path.parent, label=str(path))


def parse_rubric(data: dict[str, Any], *, base: Path, label: str = "rubric") -> Rubric:
    """Check a rubric's parsed TOML; RubricError names the first problem."""
    _only(data, {"title", "package", "limits", "criteria"}, label)
    limits = dict(_table(data.get("limits", {}), f"{label}: [limits]"))
    _only(limits, _LIMIT_KEYS, f"{label}: [limits]")
    for key, value in limits.items():
        if not isinstance(value, (int, float)) or isinstance(value, bool) or value <= 0:
            raise RubricError(f"{label}: [limits] `{key}` must be a positive number.")
    test_timeout = float(limits.pop("test_timeout", 60.0))
    entries = data.get("criteria")
    if not isinstance(entries, list) or not entries:
        raise RubricError(f"{label}: add at least one [[criteria]] table.")
    criteria = tuple(_criterion(_table(e, f"{label}: criteria[{i}]"), base, f"{label}: "
                                f"criteria[{i}]") for i, e in enumerate(entries))
    names = [c.name for c in criteria]
    twice = next((n for n in names if names.count(n) > 1), None)
    if twice:
        raise RubricError(f"{label}: the criterion name `{twice}` is used twice; give each "
                          "criterion its own `name`.")
    package = data.get("package")
    if package is not None and not isinstance(package, str):
        raise RubricError(f"{label}: `package` must be a package name.")
    return Rubric(str(data.get("title", base.name)), criteria, package,
                  Limits(**limits), test_timeout)


def _criterion(entry: dict[str, Any], base: Path, where: str) -> Criterion:
    kind = entry.get("kind")
    if kind not in KINDS:
        raise RubricError(f"{where}: `kind` must be one of {', '.join(KINDS)}, not {kind!r}.")
    where = f"{where} ({kind})"
    _only(entry, _COMMON | _KEYS[kind], where)
    points = entry.get("points")
    if not isinstance(points, (int, float)) or isinstance(points, bool) or points < 0:
        raise RubricError(f"{where}: `points` must be a number of at least 0.")
    if entry.get("visibility", "visible") not in VISIBILITIES:
        raise RubricError(f"{where}: `visibility` must be one of {', '.join(VISIBILITIES)}.")
    values = {k: v for k, v in entry.items() if k not in ("kind", "points")}
    for key, (wanted, words) in _TYPES.items():
        value = values.get(key, wanted())
        accepted = (int, float) if wanted is float else (wanted,)
        if isinstance(value, bool) != (wanted is bool) or not isinstance(value, accepted):
            raise RubricError(f"{where}: `{key}` must be {words}.")
    for key, floor, words in (("per_finding", 0, "more than 0"), ("min_tests", -1, "at least 0")):
        if values.get(key, floor + 1) <= floor:
            raise RubricError(f"{where}: `{key}` must be {words}.")
    for key in ("select", "ignore", "names", "exclude"):
        if key in values:
            values[key] = _strings(values[key], f"{where}: `{key}`")
    if values.get("min_severity", "warning") not in SEVERITIES:
        raise RubricError(f"{where}: `min_severity` must be one of {', '.join(SEVERITIES)}.")
    if values.get("details", "full") not in DETAILS:
        raise RubricError(f"{where}: `details` must be one of {', '.join(DETAILS)}.")
    if values.get("feedback") in DETAILS:
        raise RubricError(f"{where}: `feedback` is the text shown to students; to choose how "
                          f"much of the test output they see, write `details = "
                          f"\"{values['feedback']}\"`.")
    if kind == "style":
        values.setdefault("select", ("STY",))
    if kind in ("lint", "style"):
        _check_selectors(values.get("select", ()), values.get("ignore", ()), where)
    if kind == "executables" and not values.get("names"):
        raise RubricError(f"{where}: list the required console scripts in `names`.")
    if kind == "hidden":
        values["path"] = _hidden_folder(values.get("path"), base, where)
    values.setdefault("name", _DEFAULT_NAMES[kind])
    return Criterion(kind=kind, points=float(points), **values)


def _check_selectors(select: tuple[str, ...], ignore: tuple[str, ...], where: str) -> None:
    from pkgtool.rules.registry import FAMILIES, matching

    if not select:
        raise RubricError(f"{where}: list rule codes, families or names in `select`.")
    for selector in select + ignore:
        if not matching(selector):
            raise RubricError(f"{where}: `{selector}` matches no lint rule (families: "
                              f"{', '.join(FAMILIES)}).")


def _hidden_folder(value: object, base: Path, where: str) -> Path:
    if not isinstance(value, str) or not value:
        raise RubricError(f"{where}: set `path` to the folder of instructor tests.")
    folder = (base / value).resolve()
    if not folder.is_dir():
        raise RubricError(f"{where}: the hidden-test folder {folder} does not exist.")
    return folder


def _table(value: object, where: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise RubricError(f"{where} must be a table.")
    return value


def _strings(value: object, where: str) -> tuple[str, ...]:
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
        raise RubricError(f"{where} must be a list of strings.")
    return tuple(value)


def _only(table: dict[str, Any], allowed: set[str], where: str) -> None:
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise RubricError(f"{where}: unknown key `{unknown[0]}` (expected one of "
                          f"{', '.join(sorted(allowed))}).")
