"""DAT009: a parameter file has a block for a node none of its launch nodes is named."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.node_parameters import (FileEntry, file_entries, fully_seen_parameter_files,
                                           key_matches,
                                           near, node_name, write_meant)
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern


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
    module -> the one `Node` subclass's `super().__init__('name')` literal. A block is also
    reported when every node of its name runs in a namespace its key cannot match: the
    launch node's static `namespace=` is not empty and the key's namespace (`talker`: none,
    `/robot1/talker`: `/robot1`) neither equals it (an absolute namespace) nor ends with it (a
    relative one, to which a launch file including this one may prepend more). Keys with
    wildcards match any namespace; other namespaces (pushed by `PushRosNamespace`, or by a
    launch file including this one) are not compared. A block matching no node is left when
    the file is passed to a node of another package and the block is namespaced or named
    after that node: its process may make nodes of its own (Nav2's servers make
    `local_costmap/local_costmap`, its `bt_navigator` makes
    `bt_navigator_navigate_to_pose_rclcpp_node`). Files are skipped when a node's name is
    not known that way, when a launch file gives parameters not read statically to a node
    that is not among the file's users (a launch argument may name the file; a node whose
    argument's default is this file is one of its users), or when the package's Python code
    mentions the file's name; but a block naming none of the file's users nor any node
    given parameters not read statically (`<param from="$(var x)"/>`), when all of those
    have known names, is still reported: no node it may reach is named so. A block named
    by a quoted word of a Python launch file that loads YAML itself (`yaml.safe_load`) is
    left alone: the launch file may read it. Also
    reports, at the launch file, a node given a file none of whose blocks names it, when each
    block names another node the file is passed to (a node renamed for a second copy,
    `name='local_filter'`, given the file of `filter`).

    ## Why is this bad?
    ROS 2 ignores parameters of nodes that do not exist: nothing warns, and the node runs with
    its defaults. A key is matched against the node's fully qualified name, and a key without
    a leading `/` is taken from the root: `talker` is `/talker`, never `/robot1/talker`
    (checked on Jazzy's rclpy), the classic reason parameters vanish once a namespace is added.

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
    entries = list(file_entries(package))
    yield from _nodes_without_a_block(package, entries)
    yield from _blocks_no_possible_user_takes(package)
    for entry in entries:
        if not entry.matched and entry.foreign and _made_by_the_process(entry.key, entry.names):
            continue  # a node another package's process makes (Nav2's local_costmap/...)
        if not entry.matched and entry.key.rpartition("/")[2] in _read_by_launch(package):
            continue  # a block a launch file loads with yaml and reads itself
        if not entry.matched:
            base = entry.key.rpartition("/")[2]
            shown = ", ".join(f"`{n}`" for n in entry.names)
            yield Hit(entry.span, f"`{entry.key}` is none of the nodes this file is passed to "
                      f"({shown}){near(base, entry.names)}: its parameters reach no node",
                      write_meant(base, entry.names))
        elif "*" not in entry.key and not any(_may_match(entry.key, n.namespace)
                                              for n in entry.matched):
            spaces = sorted({n.namespace or "" for n in entry.matched})
            base = entry.key.rpartition("/")[2]
            full = _absolute(entry.key)
            named = f"`{entry.key}`" if full == entry.key else f"`{entry.key}` (`{full}`)"
            yield Hit(entry.span, f"{named} cannot name the node `{base}` the file is passed "
                      f"to: the launch file runs it in the namespace "
                      f"{' and '.join(f'`{s}`' for s in spaces)}, and a key is matched against "
                      f"the node's full name, so its parameters reach no node",
                      f"Write `{spaces[0].rstrip('/')}/{base}`" if len(spaces) == 1 and
                      spaces[0].startswith("/") else f"Write `/**/{base}` (any namespace)")


def _blocks_no_possible_user_takes(package: Package) -> Iterator[Hit]:
    """A hit for each block of a file the launch files pass to their nodes that matches none
    of them nor any node that may be given a file at run time (``<param from="$(var x)"/>``),
    when every such node's name is known: whichever file those nodes get, no node is
    named so."""
    fully = fully_seen_parameter_files(package)
    others = [node_name(package, n) for f in package.launch_files for n in f.nodes
              if n.other_parameters]
    if None in others:
        return
    for entry in file_entries(package, unseen_users=True):
        names = sorted({*entry.names, *(n for n in others if n is not None)})
        base = entry.key.rpartition("/")[2]
        if entry.path in fully or entry.matched or \
                any(key_matches(entry.key, name) for name in names) or \
                entry.foreign and _made_by_the_process(entry.key, names) or \
                base in _read_by_launch(package):
            continue
        shown = ", ".join(f"`{n}`" for n in names)
        yield Hit(entry.span, f"`{entry.key}` is none of the nodes that may be given this file "
                  f"({shown}){near(base, names)}: its parameters reach no node",
                  write_meant(base, names))


def _nodes_without_a_block(package: Package, entries: list[FileEntry]) -> Iterator[Hit]:
    """A hit for each node a file is passed to that none of its blocks names, when every
    block names another node the file is passed to (a renamed copy of a node: the blocks
    reported above are another mistake)."""
    by_path: dict[str, list[FileEntry]] = {}
    for entry in entries:
        by_path.setdefault(entry.path, []).append(entry)
    users = fully_seen_parameter_files(package)
    for path, found in sorted(by_path.items()):
        if not all(entry.matched for entry in found):
            continue
        matched = {id(node) for entry in found for node in entry.matched}
        for node in users.get(path, ()):
            name = node_name(package, node)
            ref = next((r for r in node.parameter_files if r.package == package.name and
                        path.endswith(posixpath.join(*r.parts))), None)
            if id(node) in matched or name is None or ref is None:
                continue
            blocks = ", ".join(f"`{key}`" for key in sorted({e.key for e in found}))
            yield Hit(ref.span, f"The node `{name}` gets nothing from `{path}`: its blocks "
                      f"name other nodes ({blocks}) and none is `{name}` or `/**`",
                      f"Add a `{name}:` block (or `/**:` for every node) to `{path}`")


_YAML_LOADS = lazy_pattern(r"\byaml\.(?:safe_|full_|unsafe_)?load\b")
_QUOTED = lazy_pattern(r"""['"]([\w.-]+)['"]""")


@per_package
def _read_by_launch(package: Package) -> frozenset[str]:
    """The quoted words of the Python launch files that load YAML themselves
    (``yaml.safe_load(f).get('viewer')``): blocks of a parameter file they may read."""
    return frozenset(word for launch in package.launch_files if launch.kind == "python"
                     for text in [package.texts.get(launch.path, "")]
                     if _YAML_LOADS.search(text) for word in _QUOTED.findall(text))


def _made_by_the_process(key: str, names: tuple[str, ...] | list[str]) -> bool:
    """True for a block naming a node the process of another package's node may make itself:
    a namespaced one (Nav2's `local_costmap/local_costmap`), or one named after a node the
    file is passed to (`bt_navigator_navigate_to_pose_rclcpp_node` for `bt_navigator`)."""
    base = key.strip("/").rpartition("/")[2]
    return "/" in key.strip("/") or any(base.startswith(f"{name}_") for name in names)


def _absolute(namespace: str) -> str:
    """``namespace`` with one leading ``/`` and no trailing one (``/`` for the root)."""
    return "/" + namespace.strip("/")


def _may_match(key: str, namespace: str | None) -> bool:
    """False when a block ``key`` (no wildcard) certainly misses a node launched with the
    static ``namespace`` (None: unknown), whatever namespace an including launch file pushes:
    the key's namespace must be the node's when absolute, end with it when relative."""
    if namespace is None or not namespace.strip("/"):
        return True
    wanted, written = _absolute(namespace), _absolute(key.rpartition("/")[0])
    if namespace.startswith("/"):
        return written == wanted
    return written == wanted or written.endswith(wanted)
