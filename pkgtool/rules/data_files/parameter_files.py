"""DAT009-DAT011: parameter files whose nodes, names or value types do not fit the code."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.node_parameters import (
    BUILT_IN, analysed_classes, file_entries, flat_parameters, mixed_list, span_of, yaml_type)
from pkgtool.rules.registry import rule


def near(word: str, choices: list[str] | tuple[str, ...]) -> str:
    """`` (did you mean `x`?)`` for a close match of ``word``, else ''."""
    found = get_close_matches(word, sorted(set(choices)), n=1)
    return f" (did you mean `{found[0]}`?)" if found else ""


@rule("DAT009", "parameter-file-unknown-node", Severity.WARNING,
      fix="Name the block after a node the file is passed to, or `/**` for all of them")
def parameter_file_unknown_node(package: Package) -> Iterator[Hit]:
    """A parameter file has a block for a node that none of its launch nodes is named.

    ## What it does
    For YAML files that the package's launch files pass to nodes (`parameters=[...]`,
    `<param from=...>`), checks that the node name of every `<node>: ros__parameters:` block
    (the last part of `/ns/node`, `ns: {node: ...}`; wildcards `/**`, `*` match any name)
    is the name of a node the file is passed to. A node's name is its static `name=` (or a
    `__node:=` remapping), else the name its executable's code gives: console script ->
    module -> the one `Node` subclass's `super().__init__('name')` literal. Namespaces are
    not compared (a launch file may be included under any namespace). Files are skipped when
    a node's name is not known that way, when a launch file gives some node parameters not
    read statically (a launch argument may name the file), or when the package's Python code
    mentions the file's name.

    ## Why is this bad?
    ROS 2 ignores parameters of nodes that do not exist: nothing warns, and the node runs with
    its defaults.

    ## Example
    ```yaml
    talkr:  # the node is `talker`
      ros__parameters:
        period: 1.0
    ```

    ## Use instead
    ```yaml
    talker:
      ros__parameters:
        period: 1.0
    ```
    """
    for entry in file_entries(package):
        if not entry.matched:
            base = entry.key.rpartition("/")[2]
            shown = ", ".join(f"`{n}`" for n in entry.names)
            yield Hit(entry.span, f"`{entry.key}` is none of the nodes this file is passed to "
                      f"({shown}){near(base, entry.names)}: its parameters reach no node")


@rule("DAT010", "unknown-parameter-in-file", Severity.WARNING,
      fix="Use the name the node declares, or declare the parameter in the node")
def unknown_parameter_in_file(package: Package) -> Iterator[Hit]:
    """A parameter file sets a parameter that the node's code never declares.

    ## What it does
    For the blocks of parameter files checked by DAT009, when every node a block applies to
    runs an executable of this package whose `Node` subclass is known (as for DAT009),
    checks each parameter under `ros__parameters` (nested mappings are dotted names:
    `pid: {p: 1}` is `pid.p`) against the names the class's module declares with
    `declare_parameter('name', ...)` and `declare_parameters('ns', [('name', ...)])`.
    Skipped when the module uses `allow_undeclared_parameters` or
    `automatically_declare_parameters_from_overrides`, declares a name that is not a literal,
    when the class derives from another class besides `Node`, or hands `self` to other code.
    `use_sim_time` and `qos_overrides.*` are never reported.

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
    for entry in file_entries(package):
        classes = analysed_classes(package, entry.matched)
        if classes is None:
            continue
        declared = [d.name for c in classes for d in c.declared]
        for name, key, _ in flat_parameters(entry.parameters):
            if name not in declared and name not in BUILT_IN and \
                    not name.startswith("qos_overrides."):
                yield Hit(span_of(entry.path, key), f"`{entry.key}` declares no parameter "
                          f"`{name}`{near(name, declared)}: the value is ignored")


@rule("DAT011", "parameter-type-mismatch", Severity.ERROR,
      fix="Write the value with the declared type (`1.0`, not `1`, for a double)")
def parameter_type_mismatch(package: Package) -> Iterator[Hit]:
    """A parameter file gives a value of another type than the node declares.

    ## What it does
    For the parameters DAT010 checks, compares the type rcl's YAML parser gives the value
    (quoted: string; `true`/`yes`/`on`...: bool; an integer literal: integer; else a
    number: double; else string; a list: an array of its items' type) with the type of the
    literal default of `declare_parameter`. Declarations whose default is not a literal, that
    pass a `ParameterDescriptor` with `dynamic_typing=True` (or a descriptor not written
    in the call) or `ignore_override=True` are not checked. A list mixing types is reported
    in any block of those files: rcl rejects the whole file.

    ## Why is this bad?
    The node dies at start-up: `declare_parameter` raises `InvalidParameterTypeException`.
    `1` is an integer, and an integer is not accepted for a double parameter.

    ## Example
    ```python
    self.declare_parameter('period', 0.5)
    ```
    ```yaml
    talker:
      ros__parameters:
        period: 1
    ```

    ## Use instead
    ```yaml
    talker:
      ros__parameters:
        period: 1.0
    ```
    """
    for entry in file_entries(package):
        classes = analysed_classes(package, entry.matched) or []
        for name, _, value in flat_parameters(entry.parameters):
            if mixed_list(value):
                yield Hit(span_of(entry.path, value), f"`{name}` mixes value types in one "
                          "list: rcl rejects the file")
                continue
            found = yaml_type(value)
            wanted = {d.type for c in classes for d in c.declared if d.name == name} - {None}
            if found is not None and wanted and found not in wanted:
                yield Hit(span_of(entry.path, value), f"`{name}` is declared "
                          f"{' or '.join(sorted(wanted))} but the file gives {found}: the node "
                          "raises InvalidParameterTypeException")
