"""The JSON contract of lint, test and grade: one schema (docs/), keys pinned here.

Renaming or removing a key is a ``schema_version`` bump, with docs/json.md and
docs/pkgtool-report.schema.json updated; adding a key keeps the version but still changes
the lists below, so no key changes unnoticed.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from pkgtool import __version__
from pkgtool import testresults as results
from pkgtool.grade.report import render as render_grade
from pkgtool.grade.report.package_tests import render as render_tests
from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Criterion, Rubric
from pkgtool.report import PackageLabel, ReportContext, render as render_lint
from pkgtool.model.span import Span
from pkgtool.records import replace
from pkgtool.report.json import SCHEMA_VERSION
from tests.helpers import make_finding

ROOT = Path(__file__).resolve().parent.parent
ENVELOPE = ["schema_version", "tool", "version", "command"]
KEYS: dict[str, dict[str, list[str]]] = {
    "lint": {"": [*ENVELOPE, "findings", "summary"],
             "finding": ["rule", "severity", "package", "path", "line", "column", "message",
                         "fix", "fixable", "related"],
             "summary": ["error", "warning", "info", "packages"]},
    "test": {"": [*ENVELOPE, "ok", "isolation", "packages"],
             "tested_package": ["name", "ok", "built", "limit", "seconds", "counts", "problem",
                                "tests", "output"],
             "test_case": ["name", "outcome", "seconds", "message", "details"]},
    "grade": {"": [*ENVELOPE, "rubric", "max_score", "submissions"],
              "submission": ["label", "path", "score", "max_score", "criteria", "package",
                             "error", "isolation", "seconds", "unchanged"],
              "criterion": ["name", "kind", "score", "max_score", "feedback", "output",
                            "visibility", "passed"]},
}
RUBRIC = Rubric("demo", (Criterion("build", "Builds", 2.0), Criterion("tests", "Tests", 3.0)))


def _lint() -> dict[str, Any]:
    context = ReportContext(packages=(PackageLabel("pkg", "src/pkg"),))
    findings = [make_finding(), make_finding("MAN013", "warning", path="package.xml", line=0,
                                             col=0, fix=None),
                replace(make_finding("MAN004", path="package.xml", line=5),
                        related=(Span("package.xml", 9, 3), Span("setup.py")))]
    return json.loads(render_lint("json", findings, context=context))


def _test() -> dict[str, Any]:
    summary = results.TestSummary((
        results.TestCase("t.test_a", "passed", 0.1),
        results.TestCase("t.test_b", "failed", 0.2, "assert 1 == 2", "details")))
    packages = [results.PackageTests("good", True, summary, "log", None, 3.0),
                results.PackageTests("broken", False, None, "SyntaxError", "timed out", 1.0)]
    return json.loads(render_tests("json", packages, isolation="namespaces"))


def _grade() -> dict[str, Any]:
    graded = SubmissionResult("alice", "/subs/alice", 3.5, 5.0, (
        CriterionResult("Builds", "build", 2.0, 2.0, ("built",)),
        CriterionResult("Tests", "tests", 1.5, 3.0, ("1 passed, 1 failed",), "FAILED t")),
        package="talker_pkg", isolation="namespaces", seconds=4.2)
    refused = SubmissionResult("eve", "/subs/eve.zip", 0.0, 5.0, (), error="unsafe archive")
    return json.loads(render_grade("json", [graded, refused], rubric=RUBRIC))


DOCUMENTS = {"lint": _lint, "test": _test, "grade": _grade}


def _schema() -> dict[str, Any]:
    path = ROOT / "docs" / "pkgtool-report.schema.json"
    return json.loads(path.read_text(encoding="utf-8"))  # type: ignore[no-any-return]


@pytest.mark.parametrize("command", DOCUMENTS)
def test_every_document_is_valid_against_the_documented_schema(command: str) -> None:
    import jsonschema

    schema = _schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    document = DOCUMENTS[command]()
    jsonschema.Draft202012Validator(schema).validate(document)
    assert document["command"] == command and document["tool"] == "pkgtool"
    assert document["version"] == __version__
    assert document["schema_version"] == SCHEMA_VERSION == 1


@pytest.mark.parametrize("command", DOCUMENTS)
def test_keys_are_pinned(command: str) -> None:
    document = DOCUMENTS[command]()
    nested = {"finding": document.get("findings", [{}])[0],
              "summary": document.get("summary", {}),
              "tested_package": document.get("packages", [{}])[0],
              "test_case": (document.get("packages", [{}])[0].get("tests") or [{}])[0],
              "submission": document.get("submissions", [{}])[0],
              "criterion": (document.get("submissions", [{}])[0].get("criteria") or [{}])[0]}
    for part, keys in KEYS[command].items():
        assert list(document if part == "" else nested[part]) == keys, (command, part)
        definition = _schema()["$defs"][part or command]
        assert definition["required"] == keys and list(definition["properties"]) == keys


def test_the_schema_rejects_a_renamed_key() -> None:
    import jsonschema

    document = _lint()
    document["findings"][0]["code"] = document["findings"][0].pop("rule")
    assert not jsonschema.Draft202012Validator(_schema()).is_valid(document)


def test_the_documentation_names_every_key() -> None:
    text = (ROOT / "docs" / "json.md").read_text(encoding="utf-8")
    missing = {key for parts in KEYS.values() for keys in parts.values() for key in keys
               if f"`{key}`" not in text}
    assert not missing
