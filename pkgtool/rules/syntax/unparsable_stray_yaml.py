"""SYN008: a YAML file nothing installs or names does not parse."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax._problems import problem_hits, stray_yaml


@rule("SYN008", "unparsable-stray-yaml", Severity.WARNING,
      fix="Fix the syntax, or delete the file (or rename it) if it is no YAML")
def unparsable_stray_yaml(package: Package) -> Iterator[Hit]:
    """A YAML file that data_files does not install and no file of the package names does
    not parse.

    ## What it does
    Reports the YAML syntax errors SYN001 leaves to it: in an ament_python package whose
    data_files is known, a `.yaml` or `.yml` file (not a launch file, not test material) that
    data_files does not install and whose name no other file of the package mentions.

    ## Why is this bad?
    Nothing builds, installs or reads the file today, so the package works; but it is either
    a parameter file someone passes by its source path (`--params-file
    src/my_pkg/old_params.yaml`), which then fails, or no YAML at all (a log or a numpy dump
    saved with a `.yaml` suffix) that editors, linters and `yamllint` stumble on.

    ## Example
    ```yaml
    # scratch/old_params.yaml, installed by nothing
    planner:
      ros__parameters:
        frames: [map, odom
    ```

    ## Use instead
    ```yaml
    planner:
      ros__parameters:
        frames: [map, odom]
    ```
    """
    yield from problem_hits(package, {"yaml-syntax": "YAML syntax error"},
                            lambda problem: stray_yaml(package, problem))
