"""Rule modules: one rule per file; shared analysis in helper modules, never in another rule.

A family folder (``pkgtool/rules/manifest/``) holds rule modules and the family's own helper
modules; helpers that several families use sit at ``pkgtool/rules/`` beside the registry.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from pkgtool.rules.registry import load_all
from tests.test_layers import ROOT, imported_files

RULES = ROOT / "pkgtool" / "rules"


def _rule_files() -> Counter[Path]:
    """How many rules each module registers."""
    return Counter(ROOT.joinpath(*rule.check.__module__.split(".")).with_suffix(".py")
                   for rule in load_all().values())


def test_every_rule_module_registers_exactly_one_rule_in_a_family_folder() -> None:
    counts = _rule_files()
    assert {p.relative_to(ROOT).as_posix(): n for p, n in counts.items() if n != 1} == {}
    assert all(p.parent.parent == RULES for p in counts), "rules live in family folders"


def test_rules_import_helpers_only_never_other_rules_or_other_families_helpers() -> None:
    rule_files = set(_rule_files())
    wrong = []
    for path in sorted(RULES.rglob("*.py")):
        for target in imported_files(path):
            if target.is_relative_to(RULES) and target != path and (
                    target in rule_files
                    or (target.parent != RULES and target.parent != path.parent)):
                wrong.append(f"{path.relative_to(ROOT)} imports {target.relative_to(ROOT)}")
    assert not wrong, "\n".join(wrong)


def test_a_code_or_a_name_taken_twice_fails_at_registration(monkeypatch) -> None:
    import pytest

    from pkgtool.findings import Severity
    from pkgtool.rules import registry

    monkeypatch.setattr(registry, "_RULES", {})
    monkeypatch.setattr(registry, "_CODES_BY_NAME", {})
    doc = "Demo.\n\n" + "\n\n".join(f"{section}\nText." for section in registry.DOC_SECTIONS)

    def check(package):  # noqa: ANN001, ANN202 - a stand-in rule
        return []

    def other(package):  # noqa: ANN001, ANN202 - another stand-in rule
        return []

    check.__doc__ = other.__doc__ = doc
    registry.rule("SYN901", "demo-rule", Severity.ERROR, fix="Mend")(check)
    registry.rule("SYN901", "demo-rule", Severity.ERROR, fix="Mend")(check)  # the same again
    with pytest.raises(ValueError, match="clashes"):
        registry.rule("SYN901", "another-rule", Severity.ERROR, fix="Mend")(other)
    with pytest.raises(ValueError, match="clashes"):
        registry.rule("SYN902", "demo-rule", Severity.ERROR, fix="Mend")(other)
    registry.rule("SYN902", "another-rule", Severity.ERROR, fix="Mend")(other)
    assert sorted(registry._RULES) == ["SYN901", "SYN902"]
