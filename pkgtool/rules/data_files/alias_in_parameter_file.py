"""DAT026: a YAML alias in a parameter file that rcl's parser reads."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import files_rcl_reads
from pkgtool.rules.registry import rule


def _aliases(text: str) -> Iterator[tuple[int, int, str]]:
    """(line, column, anchor) of every alias (``*name``) of ``text``, which parses."""
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    try:
        for event in yaml.parse(text, Loader=loader):
            if isinstance(event, yaml.AliasEvent):
                mark = event.start_mark
                yield mark.line + 1, mark.column + 1, str(event.anchor)
    except yaml.YAMLError:
        return  # SYN001 reports the file


@rule("DAT026", "alias-in-parameter-file", Severity.ERROR,
      fix="Write the value out where the alias stands: rcl reads no YAML aliases or `<<` merges")
def alias_in_parameter_file(package: Package) -> Iterator[Hit]:
    """A parameter file passed to a node uses a YAML alias (`*name`, `<<: *name`).

    ## What it does
    Reads the YAML files a launch file of the package passes to a node as parameters
    (`parameters=[path]`, `<param from=...>`, the path written statically) and reports each
    alias: `*name`, alone or in a `<<: *name` merge. Files passed only to components are left
    alone (launch_ros reads those itself, with a YAML library that resolves aliases), and so
    are files the launch files do not pass (code may read them with PyYAML).

    ## Why is this bad?
    A node gets such a file as `--params-file`, read by `rcl_yaml_param_parser`, which stops
    at the first alias with "Will not support aliasing at line N": the node exits before it
    starts. Anchors are plain YAML and PyYAML reads the file without complaint, so the mistake
    shows only when the launch runs.

    ## Example
    ```yaml
    common: &common
      rate: 10.0
    talker:
      ros__parameters:
        <<: *common
    ```

    ## Use instead
    ```yaml
    talker:
      ros__parameters:
        rate: 10.0
    ```
    """
    for path in sorted(files_rcl_reads(package)):
        text = package.texts.get(path)
        if text is None or "*" not in text:
            continue
        for line, col, anchor in _aliases(text):
            yield Hit(Span(path, line, col), f"`*{anchor}` is a YAML alias: rcl's parameter "
                      "parser rejects it (\"Will not support aliasing\") and the node given "
                      "this file does not start")
