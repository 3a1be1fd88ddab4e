"""Generate ``data/rclpy_names.txt``: the modules of rclpy and the names each defines.

Run ``python -m pkgtool.knowledge.generate_rclpy_names --rclpy-git DIR`` in pkgtool's locked
environment (``.venv``, with the ROS 2 Jazzy wheels), ``DIR`` a clone of ros2/rclpy (a bare
one will do). Jazzy's rclpy is the installed wheel's source; Humble's and Rolling's are read
from the clone's ``humble`` and ``rolling`` branches (``git show``, nothing is checked out).
Nothing is imported: each module's top-level bindings are read from its syntax tree (defs,
classes, assignments, imports, also under top-level ``if``/``try``/``with``/``for``, and the
public names of a ``from rclpy... import *``), with its submodules. A module whose names cannot
be read this way (a compiled extension, a module ``__getattr__``, a star import from outside
rclpy) is an entry without names: anything may come from it.

Each entry is ``<module> <name>...`` flagged with the distributions whose rclpy has the module
with exactly those names (``h`` Humble, ``j`` Jazzy, ``r`` Rolling); a module whose names
differ between them has one entry per variant, the later ones keyed ``<module>@<flags>``.
"""

from __future__ import annotations

import argparse
import ast
import importlib.metadata
import importlib.util
import subprocess
from collections.abc import Callable, Iterator
from pathlib import Path

from pkgtool.knowledge.tables import DATA, render, write

Reader = Callable[[str], str]
"""Reads one file of an rclpy source tree (``rclpy/node.py``) as text."""
OPEN = "*"
"""The names of a module that may define anything."""
BRANCHES = {"h": "humble", "r": "rolling"}
"""Distribution flag -> ros2/rclpy branch read from the clone."""


def _blocks(node: ast.stmt) -> tuple[str, ...]:
    """The blocks of a top-level statement that run on import (not a def's or a class's body,
    nor the body of ``if TYPE_CHECKING:``)."""
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return ()
    if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
        return ("orelse",)
    return ("body", "orelse", "finalbody")


def _bound(body: list[ast.stmt]) -> Iterator[str]:
    """Names a module body binds at top level (``*<module>`` for a star import)."""
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            yield node.name
        elif isinstance(node, ast.Import):
            yield from ((a.asname or a.name.split(".")[0]) for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            for alias in node.names:
                yield (f"*{'.' * node.level}{node.module or ''}" if alias.name == "*"
                       else alias.asname or alias.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign, ast.For, ast.With)):
            targets = node.targets if isinstance(node, ast.Assign) else \
                [item.optional_vars for item in node.items if item.optional_vars] \
                if isinstance(node, ast.With) else [node.target]
            yield from (n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name))
        for block in _blocks(node):
            yield from _bound(getattr(node, block, []))
        for handler in getattr(node, "handlers", []):
            yield from _bound(handler.body)


def _modules(files: list[str], read: Reader) -> dict[str, set[str]]:
    """Module -> the names it defines, from the ``rclpy/...`` file paths of one source tree."""
    found: dict[str, set[str]] = {}
    for path in files:
        parts = path.removesuffix(".py").split(".")[0].split("/")
        is_package = parts[-1] == "__init__"
        module = ".".join(parts[:-1] if is_package else parts)
        # a compiled extension (rclpy._rclpy_pybind11) may define anything
        names = set(_bound(ast.parse(read(path)).body)) if path.endswith(".py") else {OPEN}
        if "__getattr__" in names:
            names.add(OPEN)
        found.setdefault(module, set()).update(names)
        parent, _, leaf = module.rpartition(".")
        if parent:  # a submodule is an attribute of its package (once imported)
            found.setdefault(parent, set()).add(leaf)
    return {module: _expand(module, found) for module in found}


def _expand(module: str, found: dict[str, set[str]]) -> set[str]:
    """The names of ``module`` with each star import replaced by what it brings."""
    names = set()
    for name in found[module]:
        if not name.startswith("*") or name == OPEN:
            names.add(name)
            continue
        source = name[1:]
        if source.startswith("."):
            package = module if module in found and any(
                m.startswith(module + ".") for m in found) else module.rpartition(".")[0]
            source = package + ("." + source.lstrip(".") if source.strip(".") else "")
        given = found.get(source)
        names |= {OPEN} if given is None else {n for n in given if not n.startswith("_")}
    return names


def installed() -> dict[str, set[str]]:
    """The modules of the installed rclpy (Jazzy's in pkgtool's environment)."""
    spec = importlib.util.find_spec("rclpy")
    assert spec and spec.submodule_search_locations, "rclpy is not installed"
    root = Path(spec.submodule_search_locations[0]).parent
    files = [p.relative_to(root).as_posix() for p in (root / "rclpy").rglob("*")
             if p.suffix in (".py", ".so") and "__pycache__" not in p.parts]
    return _modules(sorted(files), lambda path: (root / path).read_text(encoding="utf-8"))


def git_text(git: Path, *args: str) -> str:
    """The output of ``git --git-dir=GIT ARGS`` (generators read pinned commits this way)."""
    return subprocess.run(["git", f"--git-dir={git}", *args], check=True, capture_output=True,
                          text=True).stdout


def from_branch(git: Path, branch: str) -> dict[str, set[str]]:
    """The modules of rclpy on ``branch`` of a ros2/rclpy clone."""
    listed = git_text(git, "ls-tree", "-r", "--name-only", branch, "rclpy/rclpy/").split()
    files = [p[len("rclpy/"):] for p in listed if p.endswith(".py")]
    files.append("rclpy/_rclpy_pybind11.so")  # built from C++ on every branch
    return _modules(sorted(files), lambda path: git_text(git, "show", f"{branch}:rclpy/{path}"))


def table(git: Path) -> str:
    """The text of ``rclpy_names.txt``."""
    trees = {"j": installed()}
    trees.update((flag, from_branch(git, branch)) for flag, branch in BRANCHES.items())
    variants: dict[tuple[str, str], str] = {}  # (module, names) -> flags
    for flag in "hjr":
        for module, names in trees[flag].items():
            key = (module, " ".join(sorted(names)))
            variants[key] = variants.get(key, "") + flag
    groups: dict[str, list[str]] = {}
    seen: set[str] = set()
    for (module, names), flags in sorted(variants.items(), key=lambda kv: (kv[0][0], kv[1])):
        entry = module if module not in seen else f"{module}@{flags}"
        seen.add(module)
        groups.setdefault(flags, []).append(f"{entry} {names}")
    heads = {branch: git_text(git, "rev-parse", "--short", branch).strip()
             for branch in BRANCHES.values()}
    sources = [f"ros-jazzy-rclpy=={importlib.metadata.version('ros-jazzy-rclpy')}",
               *(f"ros2/rclpy@{branch}:{head}" for branch, head in heads.items())]
    return render("The modules of rclpy and the names each defines at top level (submodules "
                  "included; `*`: anything),\nper distribution (h Humble, j Jazzy, r Rolling).\n"
                  "Generated by `python -m pkgtool.knowledge.generate_rclpy_names`; do not "
                  "edit.", sources, sorted(groups.items()))


def main(argv: list[str] | None = None) -> None:
    """Write the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rclpy-git", type=Path, required=True,
                        help="the git directory of a ros2/rclpy clone")
    parser.add_argument("--output", type=Path, default=DATA, help="where to write the table")
    args = parser.parse_args(argv)
    write({"rclpy_names": table(args.rclpy_git)}, args.output)


if __name__ == "__main__":
    main()
