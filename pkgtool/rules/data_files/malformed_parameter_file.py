"""DAT008: a ROS parameter file whose structure rcl's YAML parameter parser rejects."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Callable, Iterator
from difflib import SequenceMatcher
from typing import TYPE_CHECKING

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.launch_reader import yaml_problem
from pkgtool.model.package import Package, is_test_yaml
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import files_rcl_reads
from pkgtool.rules.registry import rule

if TYPE_CHECKING:  # the rule reads nodes yaml_problem built: PyYAML is imported only then
    import yaml

PARAMS_KEY = "ros__parameters"
RENAME = "Rename `{name}` to `ros__parameters`"
"""The fix text of a misspelled key, which the DAT008 fixer reads back with :func:`renamed`."""
_ALIASES = frozenset({"parameters", "parameter", "params", "param"})
"""Keys that stand for ``ros__parameters`` right under a node name, once a file is known to
hold parameters."""


def renamed(fix: str | None) -> str | None:
    """The misspelled key a DAT008 finding's ``fix`` text asks to rename, else None."""
    found = re.fullmatch(re.escape(RENAME).replace(r"\{name\}", "(.+)"), fix or "")
    return found.group(1) if found else None


def _is(node: object, kind: str) -> bool:
    """True when ``node`` is a YAML node of ``kind`` (``mapping``, ``sequence``, ``scalar``)."""
    return getattr(node, "id", None) == kind


def _normal(key: str) -> str:
    return re.sub(r"[^a-z]", "", key.lower())


def _near_miss(key: str, value: yaml.Node) -> bool:
    """``ros_parameters:``, ``ros__parameter:``, ``ros_params:``... holding a mapping."""
    normal = _normal(key)
    return _is(value, "mapping") and not key.startswith(PARAMS_KEY) and \
        normal.startswith("ros") and SequenceMatcher(None, normal, "rosparameters").ratio() >= 0.75


def _nested_only(node: yaml.Node) -> bool:
    """True when ``node`` is a mapping whose values are all mappings, as every mapping above
    ``ros__parameters`` is (node names and namespaces): a scalar or a list beside them is
    impossible in a parameter file."""
    return _is(node, "mapping") and all(_is(value, "mapping") for _, value in node.value)


def _items(node: yaml.Node, nested: bool = True) -> Iterator[tuple[str, yaml.Node, bool]]:
    """Every (key, value, nested) reachable from ``node`` through mappings alone (each node
    once); ``nested`` is True when ``nested`` was given and every mapping from ``node`` to the
    key's (both included) holds only mappings."""
    seen: set[int] = set()
    stack = [(node, nested)]
    while stack:
        current, above = stack.pop()
        if id(current) in seen or not _is(current, "mapping"):
            continue
        seen.add(id(current))
        here = above and _nested_only(current)
        for key, value in current.value:
            if _is(key, "scalar"):
                yield str(key.value), value, here
            stack.append((value, here))


def _holds_parameters(node: yaml.Node, strict: bool = False, nested: bool = True) -> bool:
    """True when a key reachable through mappings is ``ros__parameters`` or a near miss.

    With ``strict`` (a file no launch file passes to a node), a near miss counts only when
    every mapping on its path holds only mappings, ``nested`` telling whether those above
    ``node`` do: otherwise the YAML is some other data, which a parameter file cannot be.
    """
    return any(k.startswith(PARAMS_KEY) or (_near_miss(k, v) and (here or not strict))
               for k, v, here in _items(node, nested))


def _span(path: str, node: yaml.Node) -> Span:
    return Span(path, node.start_mark.line + 1, node.start_mark.column + 1)


def _node_level(path: str, mapping: yaml.MappingNode, names: tuple[str, ...], passed: bool,
                nested: bool = True, depth: int = 0) -> Iterator[Hit]:
    """Hits of a mapping above ``ros__parameters`` (node names and namespaces).

    Unless the file is ``passed`` to a node, a branch without ``ros__parameters`` (or a near
    miss) is other data of a file read by code, and only values beside ``ros__parameters``
    are reported; a misspelled key counts only when ``nested`` (every mapping above this one
    holds only mappings) and this one holds only mappings too.
    """
    if depth > 50:
        return
    nested = nested and _nested_only(mapping)
    keys = [str(k.value) for k, _ in mapping.value if _is(k, "scalar")]
    beside = any(k.startswith(PARAMS_KEY) for k in keys)
    stray_reported = False
    for key, value in mapping.value:
        if not _is(key, "scalar"):
            continue
        name = str(key.value)
        if name.startswith(PARAMS_KEY):
            if not names:
                yield Hit(_span(path, key), "`ros__parameters` has no node name above it",
                          "Put it under the node's name, or `/**:` for every node")
            elif not _is(value, "mapping") and not (_is(value, "sequence") and not value.value):
                yield Hit(_span(path, key), f"`ros__parameters` of `{'/'.join(names)}` is not "
                          "a mapping of parameters", "Write `ros__parameters: {}` or indent "
                          "the parameters under it")
        elif (passed or nested and names) and _misspelled(name, value, names) and \
                not _holds_parameters(value):  # unpassed: a near miss needs a node above
            yield Hit(_span(path, key), f"`{name}` is not `ros__parameters`: ROS 2 reads no "
                      "parameters from it and rejects the file", RENAME.format(name=name))
        elif _is(value, "mapping"):
            if passed or _holds_parameters(value, strict=True, nested=nested):
                yield from _node_level(path, value, (*names, name), passed, nested, depth + 1)
        elif not stray_reported and (passed or beside):
            stray_reported = True
            yield Hit(_span(path, key), _stray(name, names, beside),
                      "Move the parameters under `<node name>: ros__parameters:`")


def _misspelled(key: str, value: yaml.Node, names: tuple[str, ...]) -> bool:
    """A near miss, or ``parameters:``/``params:`` right under a node name."""
    return _near_miss(key, value) or (bool(names) and key.lower() in _ALIASES and
                                      _is(value, "mapping"))


def _stray(name: str, names: tuple[str, ...], beside: bool) -> str:
    """Why a value outside ``ros__parameters`` is wrong, from where it is."""
    if beside:
        return f"`{name}` is beside `ros__parameters`, not inside it"
    if not names:
        return f"`{name}` is a value at the top level, outside any `<node>: ros__parameters:`"
    return f"`{'/'.join(names)}` holds values but no `ros__parameters` key above them"


_MOVEIT_FILES = lazy_pattern(
    r"(kinematics|joint_limits|moveit_controllers|pilz_cartesian_limits|sensors_3d|"
    r"trajectory_execution|\w+_planning)\.ya?ml")
"""The files of a MoveIt configuration package ``MoveItConfigsBuilder`` loads into dicts."""
_LOAD_YAML = lazy_pattern(r"load_yaml\s*\([^)]*?['\"]([^'\"]+\.ya?ml)['\"]")
"""A ``load_yaml(package, 'config/kinematics.yaml')`` call of MoveIt's launch helpers."""


def _code_reads_parameter_keys(package: Package) -> bool:
    """True when a module of the package (not a launch file) names `ros__parameters`: it
    reads parameter-style YAML itself (``cfg.get('ros__parameters', cfg)``), so a file no
    launch file passes to a node may follow that code's format."""
    launch = {f.path for f in package.launch_files}
    return any("ros__parameters" in text for path, text in package.texts.items()
               if path.endswith(".py") and path not in launch and path != "setup.py")


def _read_as_dicts(package: Package) -> Callable[[str], bool]:
    """Whether a launch file reads the YAML file at a path into a dict itself: MoveIt's
    configuration files when a launch file uses ``MoveItConfigsBuilder``, and the files a
    ``load_yaml(...)`` helper is given (by name)."""
    texts = [package.texts.get(f.path, "") for f in package.launch_files]
    moveit = any("MoveItConfigsBuilder" in text for text in texts)
    loaded = {posixpath.basename(m) for text in texts for m in _LOAD_YAML.findall(text)}
    return lambda path: posixpath.basename(path) in loaded or \
        moveit and _MOVEIT_FILES.fullmatch(posixpath.basename(path)) is not None


def _candidates(package: Package) -> Iterator[str]:
    launch = {f.path for f in package.launch_files}
    for path, text in package.texts.items():
        if path.endswith((".yaml", ".yml")) and path not in launch and \
                not is_test_yaml(path) and "{%" not in text:
            yield path


@rule("DAT008", "malformed-parameter-file", Severity.ERROR,
      fix="Write the file as `<node name>: ros__parameters: {...}`")
def malformed_parameter_file(package: Package) -> Iterator[Hit]:
    """A ROS parameter file has a structure that ROS 2's parameter parser rejects.

    ## What it does
    Checks YAML parameter files the way `rcl_yaml_param_parser` reads them: above
    `ros__parameters` every key is a node name or namespace (`node:`, `/ns/node:`, `/**:`,
    nested `ns: {node: ...}`), holding mappings only; `ros__parameters` needs a node name
    above it and holds a mapping (or an empty list, which rcl reads as no parameters: a
    placeholder file). It reports a misspelled `ros__parameters` (`ros_parameters`,
    `ros__parameter`, `ros_params`, or `parameters` right under a node name), values outside
    `ros__parameters` (beside it, at the top level, or under a node without it), and a file
    passed to a node whose top level is a list.

    A YAML file is checked in full when a launch file of the package passes it to a node
    (`parameters=[...]`, `<param from=...>`, the path written statically). Otherwise only
    the blocks holding `ros__parameters` or a near miss of it are checked, and the rest is
    taken for data the code reads itself (files mixing both exist); YAML without any such key
    (maps, RViz or bridge configurations, waypoints), files under `test/` and launch files
    are not checked, nor is any file no launch file passes when the package's own code
    names `ros__parameters` (it reads those files itself: `yaml.safe_load(f).get(
    'ros__parameters', {})`, the path given as a program option), nor a file a launch file
    reads into a dict itself: MoveIt's configuration files (`kinematics.yaml`,
    `joint_limits.yaml`, `*_planning.yaml`...) where a launch file uses
    `MoveItConfigsBuilder`, and files given to a `load_yaml(...)` helper. In a checked file a near
    miss (or `parameters:` under a node name) counts only when every mapping above it, the
    top level included, holds only mappings, as node names and namespaces do: beside a
    scalar or a list (`serial_number: a200`, `urdf: null`) it is a key of some other YAML,
    such as a robot description read by code.
    A file passed only to components (`ComposableNode`, `<composable_node>`) is checked as one
    no launch file passes: launch_ros reads it itself and takes a file without
    `ros__parameters` as the component's parameters (`image_transport: raw` at the top level).
    YAML that does not parse is SYN001.

    ## Why is this bad?
    The node does not start: rcl stops with "Cannot have a value before ros__parameters" or
    "There are no node names before ros__parameters", and a misspelled key means the same.

    ## Example
    ```yaml
    talker:
      ros_parameters:
        rate: 10.0
    ```

    ## Use instead
    ```yaml
    talker:
      ros__parameters:
        rate: 10.0
    ```
    """
    passed = files_rcl_reads(package)
    own_reader = _code_reads_parameter_keys(package)
    as_dicts = _read_as_dicts(package)
    for path in _candidates(package):
        if (own_reader or as_dicts(path)) and path not in passed:
            continue  # the package's code reads such files itself: its own format
        documents = yaml_problem(path, package.texts[path])
        if not isinstance(documents, list):
            continue  # SYN001
        for root in documents:
            if _is(root, "mapping") and (path in passed or _holds_parameters(root, strict=True)):
                yield from _node_level(path, root, (), path in passed)
            elif _is(root, "sequence") and path in passed:
                yield Hit(_span(path, root), "A file passed to a node as parameters is a list, "
                          "not a mapping of node names")
