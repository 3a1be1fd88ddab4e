"""DAT009: a parameter file has a block for a node none of its launch nodes is named."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.node_parameters import file_entries, near, write_meant
from pkgtool.rules.registry import rule


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
                      f"({shown}){near(base, entry.names)}: its parameters reach no node",
                      write_meant(base, entry.names))
