"""docs/rules.md is generated from the registry and must be current."""

from __future__ import annotations

from pathlib import Path

from pkgtool.docs_gen import DEFAULT_OUTPUT, explain, main, rules_markdown
from pkgtool.rules.registry import FAMILIES, load_all


def test_rules_md_is_current() -> None:
    assert DEFAULT_OUTPUT.read_text(encoding="utf-8") == rules_markdown(load_all()), (
        "docs/rules.md is stale: run `python -m pkgtool.docs_gen`")
    assert main(["--check"]) == 0


def test_every_rule_has_a_section_with_its_facts_and_docstring() -> None:
    text = rules_markdown(load_all())
    for rule in load_all().values():
        section = text.split(f"\n### {rule.code}\n", 1)[1].split("\n### ", 1)[0]
        assert f"`{rule.name}`" in section
        assert f"Severity: {rule.severity.value}" in section
        assert "#### What it does" in section and "#### Use instead" in section


def test_families_are_sections_in_registry_order() -> None:
    text = rules_markdown(load_all())
    present = [f for f in FAMILIES if any(r.family == f for r in load_all().values())]
    positions = [text.index(f"\n## {family}\n") for family in present]
    assert positions == sorted(positions)


def test_check_mode_reports_a_stale_file(tmp_path: Path) -> None:
    stale = tmp_path / "rules.md"
    stale.write_text("old\n")
    assert main(["--check", str(stale)]) == 1
    assert main([str(stale)]) == 0 and main(["--check", str(stale)]) == 0


def test_explain_uses_second_level_headings() -> None:
    text = explain(load_all()["SYN001"])
    assert text.startswith("# SYN001 unparsable-file\n\nSeverity: error.")
    assert "\n## What it does\n" in text
