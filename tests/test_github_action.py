"""The GitHub Action: action.yml's wiring, and its script run here as the action runs it.

The script is scripts/github-action.sh with the INPUT_* variables the composite step sets;
``INPUT_INSTALL=false`` uses this checkout's pkgtool (the action installs its own otherwise).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import yaml

from tests.helpers import run_cli

ROOT = Path(__file__).resolve().parent.parent
ACTION = yaml.safe_load((ROOT / "action.yml").read_text(encoding="utf-8"))
SCRIPT = ROOT / "scripts" / "github-action.sh"


def test_the_action_is_composite_and_every_input_it_uses_is_declared() -> None:
    assert ACTION["runs"]["using"] == "composite"
    text = (ROOT / "action.yml").read_text(encoding="utf-8")
    used = set(re.findall(r"inputs\.([a-z-]+)", text))
    assert used == set(ACTION["inputs"]), used ^ set(ACTION["inputs"])
    lint = next(step for step in ACTION["runs"]["steps"] if step.get("id") == "lint")
    assert "scripts/github-action.sh" in lint["run"]
    script = SCRIPT.read_text(encoding="utf-8")
    for name in lint["env"]:
        assert name in script, f"{name} is set by action.yml but the script never reads it"
    assert {name[len("INPUT_"):].lower().replace("_", "-") for name in lint["env"]} <= set(
        ACTION["inputs"])


def _package(root: Path, *, broken: bool) -> Path:
    assert run_cli("create", "gh_demo", "--node", "talker:publisher", cwd=root).exit_code == 0
    if broken:
        module = root / "gh_demo" / "gh_demo" / "talker.py"
        module.write_text(module.read_text(encoding="utf-8") + "\nimport numpy  # noqa\n",
                          encoding="utf-8")
    return root / "gh_demo"


def _run(tmp_path: Path, **inputs: str) -> tuple[dict[str, str], str]:
    output = tmp_path / "github_output"
    output.write_text("")
    env = {**os.environ, "GITHUB_OUTPUT": str(output), "INPUT_INSTALL": "false",
           "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
           **{f"INPUT_{key.upper()}": value for key, value in inputs.items()}}
    done = subprocess.run(["bash", str(SCRIPT)], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr  # the job fails in the last step, after the upload
    outputs = dict(line.split("=", 1) for line in output.read_text().splitlines())
    return outputs, done.stdout


def test_a_clean_package_passes_and_gets_an_empty_sarif_report(tmp_path: Path) -> None:
    _package(tmp_path, broken=False)
    outputs, stdout = _run(tmp_path, paths="gh_demo", sarif_file="out.sarif")
    assert outputs == {"exit-code": "0"}
    assert "::error" not in stdout
    sarif = json.loads((tmp_path / "out.sarif").read_text())
    assert sarif["version"] == "2.1.0" and sarif["runs"][0]["results"] == []


def test_findings_fail_with_annotations_and_sarif_results(tmp_path: Path) -> None:
    _package(tmp_path, broken=True)
    outputs, stdout = _run(tmp_path, paths="gh_demo\n", sarif_file="out.sarif")
    assert outputs == {"exit-code": "1"}
    assert "::error file=gh_demo/gh_demo/talker.py," in stdout and "title=DEP001::" in stdout
    results = json.loads((tmp_path / "out.sarif").read_text())["runs"][0]["results"]
    assert [r["ruleId"] for r in results] == ["DEP001"]


def test_ignore_and_select_reach_pkgtool(tmp_path: Path) -> None:
    _package(tmp_path, broken=True)
    assert _run(tmp_path, paths="gh_demo", ignore="DEP001")[0] == {"exit-code": "0"}
    assert _run(tmp_path, paths="gh_demo", select="MAN")[0] == {"exit-code": "0"}
    assert _run(tmp_path, paths="gh_demo", select="DEP001,MAN")[0] == {"exit-code": "1"}


def test_strict_makes_warnings_fail(tmp_path: Path) -> None:
    package = _package(tmp_path, broken=False)
    test = package / "test" / "test_talker.py"
    test.write_text(test.read_text(encoding="utf-8") + "\nimport numpy  # noqa\n",
                    encoding="utf-8")  # DEP003, a warning: an undeclared test import
    assert _run(tmp_path, paths="gh_demo")[0] == {"exit-code": "0"}
    assert _run(tmp_path, paths="gh_demo", strict="true")[0] == {"exit-code": "1"}


def test_fix_check_fails_on_pending_fixes_and_passes_a_clean_package(tmp_path: Path) -> None:
    _package(tmp_path, broken=False)
    assert _run(tmp_path, paths="gh_demo", fix_check="true")[0] == {"exit-code": "0"}
    (tmp_path / "broken").mkdir()
    _package(tmp_path / "broken", broken=True)
    outputs, stdout = _run(tmp_path / "broken", paths="gh_demo", fix_check="true")
    assert outputs == {"exit-code": "1"}
    assert "would change files" in stdout
    assert "+  <exec_depend>python3-numpy</exec_depend>" in stdout
