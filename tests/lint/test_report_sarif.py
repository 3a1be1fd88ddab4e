"""SARIF 2.1.0: rule metadata from the registry, one result per finding."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pkgtool.findings import Finding
from pkgtool.report import ReportContext, render
from pkgtool.rules.registry import load_all
from tests.helpers import make_finding


def _run(*findings: Finding) -> dict[str, Any]:
    document = json.loads(render("sarif", list(findings), context=ReportContext(rules=load_all())))
    assert document["version"] == "2.1.0"
    assert document["$schema"].endswith("sarif-2.1.0.json")
    (run,) = document["runs"]
    return run


def test_driver_lists_every_rule_with_metadata() -> None:
    driver = _run()["tool"]["driver"]
    assert driver["name"] == "pkgtool" and driver["version"]
    assert [r["id"] for r in driver["rules"]] == list(load_all())
    syn001 = next(r for r in driver["rules"] if r["id"] == "SYN001")
    assert syn001["name"] == "unparsable-file"
    assert syn001["shortDescription"]["text"] == load_all()["SYN001"].summary
    assert syn001["fullDescription"]["text"].startswith("Reports XML that is not well-formed")
    assert "## Why is this bad?" in syn001["help"]["markdown"]
    assert syn001["defaultConfiguration"]["level"] == "error"


def test_results_locations_and_levels() -> None:
    run = _run(make_finding(), make_finding("SYN002", "info", path="", line=0, col=0),
               make_finding(root="/abs/my pkg", path="package.xml", line=2, col=0))
    third, second, first = run["results"]  # report order: by path
    assert first["ruleId"] == "SYN001" and first["level"] == "error"
    assert first["ruleIndex"] == list(load_all()).index("SYN001")
    assert first["message"]["text"].startswith("Python syntax error: invalid syntax. Fix: ")
    location = first["locations"][0]["physicalLocation"]
    assert location == {
        "artifactLocation": {"uri": "src/pkg/pkg/node.py", "uriBaseId": "%SRCROOT%"},
        "region": {"startLine": 3, "startColumn": 5}}
    assert second["level"] == "note"
    assert "region" not in second["locations"][0]["physicalLocation"]
    assert third["locations"][0]["physicalLocation"] == {
        "artifactLocation": {"uri": "file:///abs/my%20pkg/package.xml"},
        "region": {"startLine": 2}}


def test_the_document_is_valid_against_the_official_sarif_schema() -> None:
    """tests/data holds the OASIS schema (see its NOTICE); nothing is fetched."""
    import jsonschema

    schema = json.loads((Path(__file__).parent.parent / "data" / "sarif-schema-2.1.0.json")
                        .read_text(encoding="utf-8"))
    validator = jsonschema.validators.validator_for(schema)(schema)
    findings = [make_finding(), make_finding("SYN002", "info", path="", line=0, col=0),
                make_finding("MAN013", "warning", root="/abs/my pkg", path="package.xml",
                             line=2, col=0, fix=None),
                make_finding(message="bad\x00text\x1b[2J\nPASS", path="odd\nname.py")]
    document = json.loads(render("sarif", findings, context=ReportContext(rules=load_all())))
    errors = sorted(validator.iter_errors(document), key=str)
    assert not errors, "\n".join(f"{list(e.absolute_path)}: {e.message}" for e in errors[:5])
    broken = {**document, "runs": [{**document["runs"][0], "results": [{"level": "fatal"}]}]}
    assert not validator.is_valid(broken)  # the validator does reject what the schema forbids


def test_related_places_are_related_locations() -> None:
    from pkgtool.records import replace

    from pkgtool.model.span import Span

    finding = replace(make_finding("MAN004", path="package.xml", line=5),
                      related=(Span("package.xml", 9, 3), Span("setup.py")))
    (result,) = _run(finding)["results"]
    assert result["locations"][0]["physicalLocation"]["region"]["startLine"] == 5
    assert [(r["id"], r["physicalLocation"]["artifactLocation"]["uri"],
             r["physicalLocation"].get("region")) for r in result["relatedLocations"]] == [
        (1, "src/pkg/package.xml", {"startLine": 9, "startColumn": 3}),
        (2, "src/pkg/setup.py", None)]
    assert "relatedLocations" not in _run(make_finding())["results"][0]
