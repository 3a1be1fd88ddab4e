"""DAT025: a parameter name a typo away from ``use_sim_time``."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package, is_test_material
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import (SIM_TIME, flat_parameters, node_classes,
                                           parameter_blocks, sim_time_typo, span_of)
from pkgtool.rules.registry import rule


@rule("DAT025", "misspelled-use-sim-time", Severity.WARNING, fix=f"Write `{SIM_TIME}`")
def misspelled_use_sim_time(package: Package) -> Iterator[Hit]:
    """A node is given a parameter whose name is a typo of `use_sim_time`.

    ## What it does
    Reads the parameter names the package's launch files give nodes of any package
    (`parameters=[{...}]` dicts, `-p name:=value` arguments, XML `<param name=...>`, YAML
    `param:` entries) and the keys under `ros__parameters` of its YAML files (not tests),
    and reports a name one edit
    (a letter added, dropped or replaced, two neighbours swapped) away from `use_sim_time`
    (`use_sim_tme`, `use_sime_time`, `use_sim_tile`), unless a node of the package declares
    it; a nested name is judged by its last part.

    ## Why is this bad?
    Every node declares `use_sim_time`; a misspelt name sets a parameter nobody reads (or
    one the node rejects), so the node keeps the wall clock while the simulator publishes
    `/clock`: TF lookups fail with extrapolation errors, and timers and maps drift.

    ## Example
    ```python
    Node(package='slam_toolbox', executable='async_slam_toolbox_node',
         parameters=[{'use_sim_tme': True}])
    ```

    ## Use instead
    ```python
    Node(package='slam_toolbox', executable='async_slam_toolbox_node',
         parameters=[{'use_sim_time': True}])
    ```
    """
    declared = {d.name for c in node_classes(package) for d in c.declared}
    for launch in package.launch_files:
        for node in launch.nodes:
            for name, span, _ in node.inline_parameters:
                yield from _misspelt(name, span, declared)
    yield from _parameter_files(package, declared)


def _parameter_files(package: Package, declared: set[str]) -> Iterator[Hit]:
    from pkgtool.model.launch_reader import yaml_problem

    for path, text in sorted(package.texts.items()):
        if not path.endswith((".yaml", ".yml")) or is_test_material(path) or \
                "ros__parameters" not in text:
            continue
        documents = yaml_problem(path, text)
        for document in documents if isinstance(documents, list) else ():
            for _, _, parameters in parameter_blocks(path, document):
                for name, key, _ in flat_parameters(parameters):
                    yield from _misspelt(name, span_of(path, key), declared)


def _misspelt(name: str, span: Span, declared: set[str]) -> Iterator[Hit]:
    if sim_time_typo(name) and name not in declared:
        yield Hit(span, f"`{name.rpartition('.')[2]}` is a typo of `{SIM_TIME}`: the node "
                        f"never gets `{SIM_TIME}` and keeps the wall clock while a simulator "
                        "publishes `/clock`")
