"""DAT010: a parameter file sets a parameter its node never declares."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.node_parameters import (
    BUILT_IN, analysed_classes, file_entries, flat_parameters, fully_seen_parameter_files,
    makes_a_declaring_node, near, sim_time_typo, span_of)
from pkgtool.rules.registry import rule


@rule("DAT010", "unknown-parameter-in-file", Severity.WARNING,
      fix="Use the name the node declares, or declare the parameter in the node")
def unknown_parameter_in_file(package: Package) -> Iterator[Hit]:
    """A parameter file or launch file sets a parameter that the node's code never declares.

    ## What it does
    For the blocks of parameter files checked by DAT009, and those of the files the launch
    files give the nodes they name when another node gets a file chosen at run time (a
    launch argument: its default, say) but a block for any node (`/**`), which that node may
    read too, when every node a block applies to
    runs an executable of this package whose `Node` subclass is known (as for DAT009),
    checks each parameter under `ros__parameters` (nested mappings are dotted names:
    `pid: {p: 1}` is `pid.p`) against the names the class's module declares with
    `declare_parameter('name', ...)` and `declare_parameters('ns', [('name', ...)])`.
    Skipped when the module uses `allow_undeclared_parameters` or
    `automatically_declare_parameters_from_overrides` (as keywords, or keys of a dict passed
    with `**`), declares a name that is not a literal, in a package whose modules make a
    `MoveItPy` (its own node takes every parameter the process is given),
    when the class derives from another class besides `Node`, or hands `self` to other code
    (rclpy's and tf2_ros's helpers that declare nothing aside: `ActionClient(self, ...)`,
    `TransformListener(buffer, self)`, and built-ins that only look at it: `hasattr(self,
    'timer')`, `super(MyNode, self)`).
    `use_sim_time` and `qos_overrides.*` are never reported. The parameters a Python launch
    file gives a node of this package as a dict (`parameters=[{'period': 1.0}]`, literal
    keys) or as `-p name:=value` arguments (`ros_arguments=['-p', 'period:=1.0']`, or in
    `arguments=` after `--ros-args`) are checked the same way against the class its
    executable runs, and so are the `<param name=...>` of an XML launch file's node and the
    `param:` entries (`name:` and `value:`) of a YAML one.

    ## Why is this bad?
    rclpy ignores values of undeclared parameters: a misspelled name leaves the node on its
    default without a word.

    ## Example
    ```yaml
    talker:
      ros__parameters:
        perod: 1.0  # the node declares `period`
    ```

    ## Use instead
    ```yaml
    talker:
      ros__parameters:
        period: 1.0
    ```
    """
    if makes_a_declaring_node(package):
        return  # a MoveItPy node in one of its processes may take any parameter given
    fully_seen = fully_seen_parameter_files(package)
    for entry in file_entries(package, unseen_users=True):
        if entry.path not in fully_seen and "*" in entry.key.rpartition("/")[2]:
            continue  # a node given a file chosen at run time may read this block too
        classes = analysed_classes(package, entry.matched)
        if classes is None:
            continue
        declared = [d.name for c in classes for d in c.declared]
        for name, key, _ in flat_parameters(entry.parameters):
            if _unknown(name, declared):
                yield Hit(span_of(entry.path, key), f"`{entry.key}` declares no parameter "
                          f"`{name}`{near(name, declared)}: the value is ignored")
    for launch in package.launch_files:
        for node in launch.nodes:
            classes = analysed_classes(package, (node,)) if node.inline_parameters else None
            declared = [d.name for c in classes or () for d in c.declared]
            for name, span, _ in node.inline_parameters if classes else ():
                if _unknown(name, declared):
                    yield Hit(span, f"The node `{node.executable}` declares no parameter "
                              f"`{name}`{near(name, declared)}: the value is ignored")


def _unknown(name: str, declared: list[str]) -> bool:
    """True when a parameter set for a node is none the node declares (nor built in)."""
    return name not in declared and name not in BUILT_IN and not name.startswith(
        "qos_overrides.") and not sim_time_typo(name)
