"""What ``pkgtool create`` is asked for, checked before anything is rendered or written.

:func:`validate` turns raw command-line values into a frozen :class:`Plan` or raises
:class:`CreateError` with a message that says what to do; nothing here touches the disk.
"""

from __future__ import annotations

import re
from pathlib import Path

from pkgtool.create import CreateError
from pkgtool.create.license_choice import choose_license
from pkgtool.create.licenses import LICENSES
from pkgtool.create.names import NAME, check_name
from pkgtool.create.nodes import KINDS, NodeSpec, parse_node
from pkgtool.knowledge import rosdep
from pkgtool.knowledge.rosdistro import is_rosdep_key
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

__all__ = ["Plan", "Request", "check_name", "sort_dependencies", "validate"]

_ROSDEP_KEY = lazy_pattern(r"^python3-[a-z0-9][a-z0-9.+-]*$")
_TEST_FILES = frozenset({"conftest", "copyright", "flake8", "pep257"})
_FORMATS = (2, 3)


@record
class Request:
    """The raw values from the command line (``None``: not given, take the default).

    The maintainer and the year have no default here: the CLI fills them with
    :func:`pkgtool.commands.create.defaults` (git config, SOURCE_DATE_EPOCH).
    """

    name: str
    destination: Path
    description: str | None = None
    license: str = "Apache-2.0"
    maintainer_name: str = ""
    maintainer_email: str = ""
    dependencies: tuple[str, ...] = ()
    node_name: str | None = None
    library_name: str | None = None
    package_format: int = 3
    nodes: tuple[str, ...] = ()
    msg: str | None = None
    srv: str | None = None
    action: str | None = None
    launch: bool = False
    config: bool = False
    year: int | None = None
    spdx_header: bool = False


@record
class Plan:
    """A checked request: everything the renderer needs, nothing left to default."""

    name: str
    destination: Path
    description: str
    license: str
    """As package.xml says it: an SPDX expression, or the user's free text."""
    license_expression: str
    """The SPDX expression of the file headers (``LicenseRef-...`` for free text)."""
    maintainer_name: str
    maintainer_email: str
    year: int
    package_format: int
    nodes: tuple[NodeSpec, ...]
    library_name: str | None
    depends: tuple[str, ...]
    exec_depends: tuple[str, ...]
    test_depends: tuple[str, ...]
    launch: bool
    config: bool
    spdx_header: bool = False
    warnings: tuple[str, ...] = ()
    """What the user should know (a license without a shipped text); not a refusal."""

    @property
    def root(self) -> Path:
        """The package folder to create."""
        return self.destination / self.name

    @property
    def license_shipped(self) -> bool:
        """True when the LICENSE text and the ament_copyright header of the license ship."""
        return self.license in LICENSES


def _text(value: str, what: str, limit: int) -> str:
    if any(ord(c) < 32 for c in value) or not value.strip() or len(value) > limit:
        raise CreateError(f"Invalid {what} {value!r}: give one line of 1 to {limit} characters.")
    return value.strip()


def _email(value: str) -> str:
    if not re.fullmatch(r"[^@\s<>\"']+@[^@\s<>\"']+", value):
        raise CreateError(f"Invalid maintainer email {value!r}: give an address like "
                          "`jane@example.com`.")
    return value


def sort_dependencies(values: tuple[str, ...]) -> tuple[set[str], set[str]]:
    """Split ``--dependencies`` into ROS packages (depend) and rosdep keys (exec_depend)."""
    ros: set[str] = set()
    python: set[str] = set()
    for value in values:
        key = rosdep.key_for_python_module(value)
        if key or is_rosdep_key(value) or _ROSDEP_KEY.match(value):
            python.add(key or value)
        elif value in rosdep.stdlib_modules():
            raise CreateError(f"Dependency `{value}` is in Python's standard library: it needs "
                              "no declaration. Drop it from --dependencies.")
        elif rosdep.suggested_key(value):
            raise CreateError(f"Dependency `{value}` is not a ROS package or a known Python "
                              f"module: use the rosdep key `{rosdep.suggested_key(value)}`.")
        elif NAME.match(value):
            ros.add(value)
        else:
            raise CreateError(f"Dependency `{value}` is neither a ROS package name nor a known "
                              "Python module. Give a ROS package (`sensor_msgs`), a Python "
                              "module (`numpy`) or a rosdep key (`python3-numpy`).")
    return ros, python


def check_node_name(name: str) -> str:
    """``name`` if a node (module, executable and test file) may be called so, else CreateError."""
    check_name(name, "node name")
    if name in _TEST_FILES:
        raise CreateError(f"Invalid node name `{name}`: it is taken by a generated test file "
                          "(conftest.py or an ament linter test). Rename it.")
    return name


def node_dependencies(nodes: tuple[NodeSpec, ...]) -> tuple[set[str], set[str]]:
    """(run-time ROS packages, test keys) that the generated modules and tests of ``nodes`` use."""
    if not nodes:
        return set(), set()
    ros = {"rclpy"} | {n.interface.package for n in nodes if n.interface}
    actions = any(n.kind.interface == "action" for n in nodes)
    tests = {"python3-pytest"} | ({"action_msgs"} if actions else set())
    return ros, tests


def _check_interface_options(request: Request) -> None:
    """--msg/--srv/--action must reach a node: one of that family given without its own TYPE."""
    taking = set()
    for text in request.nodes:
        kind, _, own_type = text.partition(":")[2].partition(":")
        if not own_type:
            taking.add(KINDS[kind].interface)
    for family, given in (("msg", request.msg), ("srv", request.srv), ("action", request.action)):
        if given and family not in taking:
            kinds = [kind.name for kind in KINDS.values() if kind.interface == family]
            raise CreateError(f"--{family} `{given}` is for {' or '.join(kinds)} nodes, and no "
                              f"such node takes it: add `--node NAME:{kinds[0]}`, or drop "
                              f"--{family}.")


def _nodes(request: Request) -> tuple[NodeSpec, ...]:
    specs = [parse_node(text, msg=request.msg, srv=request.srv, action=request.action)
             for text in request.nodes]
    _check_interface_options(request)
    if request.node_name:
        specs.insert(0, parse_node(f"{request.node_name}:timer"))
    seen: set[str] = set()
    for spec in specs:
        check_node_name(spec.name)
        if spec.name in seen or spec.name == request.library_name:
            raise CreateError(f"Node name `{spec.name}` is used twice: give each node and the "
                              "library its own name.")
        seen.add(spec.name)
    return tuple(specs)


def validate(request: Request) -> Plan:
    """Check every value of ``request``; return the :class:`Plan` or raise CreateError."""
    name = check_name(request.name, "package name")
    if request.year is None or not 1000 <= request.year <= 9999:
        raise CreateError(f"Invalid copyright year {request.year}: give four digits.")
    license_ = choose_license(request.license)
    if request.package_format not in _FORMATS:
        raise CreateError(f"Unsupported package format {request.package_format}: use 3 "
                          "(the default) or 2.")
    if request.library_name:
        check_name(request.library_name, "library name")
    nodes = _nodes(request)
    if (request.launch or request.config) and not nodes:
        raise CreateError("--launch and --config need at least one node: add `--node "
                          "NAME:KIND`.")
    ros, python = sort_dependencies(request.dependencies)
    node_ros, node_tests = node_dependencies(nodes)
    ros |= node_ros
    tests = {"ament_flake8", "ament_pep257", "python3-pytest"} | node_tests
    if license_.shipped:  # test_copyright.py uses ament_copyright only for a license it knows
        tests.add("ament_copyright")
    execs = python | ({"launch", "launch_ros"} if request.launch else set())
    description = request.description or f"The {name} ROS 2 Python package."
    return Plan(
        name=name, destination=request.destination,
        description=_text(description, "description", 1000),
        license=license_.value, license_expression=license_.expression,
        maintainer_name=_text(request.maintainer_name, "maintainer name", 80),
        maintainer_email=_email(request.maintainer_email),
        year=request.year, package_format=request.package_format, nodes=nodes,
        library_name=request.library_name, depends=tuple(sorted(ros)),
        exec_depends=tuple(sorted(execs - ros)), test_depends=tuple(sorted(tests - ros)),
        launch=request.launch, config=request.config, spdx_header=request.spdx_header,
        warnings=license_.warnings)
