"""What LCH002 and DEP011 share: packages a file names (to start, include or read the share
folder of) that package.xml does not declare, or that no package has as its name."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping

from pkgtool.findings import Hit
from pkgtool.knowledge.rosdistro import (close_names, digits_differ, is_released_package,
                                         key_resolves)
from pkgtool.model.context import commented_dependencies
from pkgtool.model.manifest import Dependency
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import (ANY, declaration, declared, dependency_cause,
                                   no_package_named, released_for)
from pkgtool.rules.setup_values import name_cause, setup_alias


def unlisted_packages(package: Package, used: Iterable[tuple[str, Span]],
                      available: Mapping[str, Dependency], user: str,
                      tag: str = "exec_depend") -> Iterator[Hit]:
    """A hit for the first use of each package named in ``used`` (name, where) that is not this
    one nor among the ``available`` keys; ``user`` says what uses it (``a launch file``),
    ``tag`` how to declare it."""
    seen: set[str] = set()
    for name, span in sorted(used, key=lambda u: (u[1].line, u[1].col)):
        if name == package.name or name in available or name in seen or \
                depends_on(package, name):
            continue
        seen.add(name)
        if name == setup_alias(package):
            yield Hit(span, f"`{name}` is used by {user} but package.xml names this package "
                            f"`{package.name}`", cause=name_cause(name), consequence=True)
            continue
        other = declared(package, ANY).get(name)
        missing = (f"declared only as {declaration(name, other)}" if other else
                   "not declared in package.xml")
        fix = f"Add `<{tag}>{name}</{tag}>` to package.xml"
        if not other and name in commented_out(package):
            missing += "; package.xml has it only inside a comment"
            fix = "Declare it, unless it was left out on purpose (a dependency cycle): then " \
                "make its use optional"
        elif not other and name in package.submodules:
            missing += (f"; it is probably the package of the git submodule `{name}`, which is "
                        "not checked out here")
        elif not other and not known_package(package, name):
            meant = [close for close in close_names(
                name, package.context.distro, limit=3,
                extra=frozenset((*package.context.workspace, package.name)))
                if not digits_differ(name, close)]
            missing += f", and {no_package_named(package, name)}"
            missing += f" (did you mean `{meant[0]}`?)" if meant else ""
            elsewhere = released_for(name)
            fix = f"Write `{meant[0]}`" if meant else \
                f"{fix}, and lint with `--rosdistro {elsewhere[-1]}` if the package targets " \
                f"{elsewhere[-1]}" if elsewhere else "Check the name; declare the package if " \
                "a workspace it is built in provides it"
        yield Hit(span, f"`{name}` is used by {user} but {missing}", fix,
                  cause="" if other else dependency_cause(name), consequence=True)


@per_package
def commented_out(package: Package) -> frozenset[str]:
    """The packages package.xml declares inside a comment (``<!-- <exec_depend>x</exec_depend>
    -->``): maybe left out on purpose (MoveIt's resources leave out what would make a cycle
    for the build farm), maybe replaced by another (``gazebo_ros`` by ``ros_gz_sim``) or
    forgotten: their use is still reported, with no fix."""
    return commented_dependencies(package.texts.get("package.xml", ""))


def depends_on(package: Package, name: str) -> bool:
    """True when the workspace package ``name`` depends on ``package`` (itself or through
    other workspace packages): declaring it would make a cycle colcon cannot order, so a
    launch file or module of ``package`` may only look it up (xarm_ros2's launch files)."""
    workspace = package.context.workspace
    seen, todo = {name}, [name]
    while todo:
        other = workspace.get(todo.pop())
        for dependency in other.depends if other is not None else ():
            if dependency == package.name:
                return True
            if dependency not in seen and dependency in workspace:
                seen.add(dependency)
                todo.append(dependency)
    return False


def known_package(package: Package, name: str) -> bool:
    """True when ``name`` is a package of the workspace or a released one (or a rosdep key)
    on the target distribution."""
    distro = package.context.distro
    return name in package.context.workspace or is_released_package(name, distro) or \
        key_resolves(name, distro)
