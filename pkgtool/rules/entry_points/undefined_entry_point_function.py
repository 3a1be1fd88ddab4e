"""ENT003: a console script whose function the module does not define."""

from __future__ import annotations

import ast
from difflib import get_close_matches
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.installed import installed_modules
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.imports import absolute_module, python_package_of
from pkgtool.rules.node_api import node_subclasses
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, installed_trees


def _star_names(package: Package, module: PythonModule) -> frozenset[str] | None:
    """The names ``module``'s ``from x import *`` imports bind, when each ``x`` is a module
    the package installs without star imports of its own (absolute, relative, or named from
    the module's Python package: ``from services.callbacks import *`` in ``my_pkg/server.py``
    is ``my_pkg.services.callbacks``); None when one is not known."""
    installed = installed_modules(package) or {}
    owner = python_package_of(package, module)
    found: set[str] = set()
    for imported in module.imports:
        if "*" not in imported.names:
            continue
        dotted = absolute_module(imported.module, imported.level, owner) if owner \
            else imported.module or ""  # a module outside any package: its dots lead nowhere
        path = installed.get(dotted) or (installed.get(f"{owner}.{dotted}")
                                         if owner and not imported.level else None)
        source = package.module(path) if path else None
        if source is None or source.syntax_error or \
                any("*" in i.names for i in source.imports) or \
                "__getattr__" in source.top_level_names:
            return None
        found |= source.top_level_names
    return frozenset(found)


def _top_function(package: Package, path: str, name: str
                  ) -> ast.FunctionDef | ast.AsyncFunctionDef | None:
    """The function ``name`` when the installed module ``path`` binds it once at its top
    level, with a ``def``; else None."""
    for module, tree, _ in installed_trees(package):
        if module.path == path:
            bindings = [s for s in tree.body if name in _bound_at_top(s)]
            found = bindings[0] if len(bindings) == 1 else None
            return found if isinstance(found, FUNCTIONS) else None
    return None


def _required_parameters(package: Package, path: str, name: str) -> list[str]:
    """The parameters without a default of the undecorated function ``name`` the installed
    module ``path`` defines once at its top level (empty for anything else)."""
    function = _top_function(package, path, name)
    if function is None or function.decorator_list:
        return []
    arguments = function.args
    positional = [*arguments.posonlyargs, *arguments.args]
    required = positional[:len(positional) - len(arguments.defaults)]
    return [a.arg for a in required] + [
        a.arg for a, default in zip(arguments.kwonlyargs, arguments.kw_defaults)
        if default is None]


def _bound_at_top(statement: ast.stmt) -> set[str]:
    """The names a top-level statement binds (definitions, imports, assignment targets)."""
    if isinstance(statement, (*FUNCTIONS, ast.ClassDef)):
        return {statement.name}
    if isinstance(statement, (ast.Import, ast.ImportFrom)):
        return {(a.asname or a.name).split(".")[0] for a in statement.names}
    return {n.id for n in ast.walk(statement) if isinstance(n, ast.Name)
            and not isinstance(n.ctx, ast.Load)}


def _uninitialised_node(package: Package, path: str, name: str) -> bool:
    """True when ``name`` is a Node subclass of the installed module ``path`` and neither it
    nor the module's top-level code calls ``rclpy.init``."""
    for module, tree, index in installed_trees(package):
        if module.path != path:
            continue
        node = next((c for c in node_subclasses(index) if c.name == name), None)
        if node is None:
            return False
        top = [s for s in tree.body if not isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef,
                                                          ast.ClassDef))]
        parts = {id(part) for part in (node, *top)}
        return not any(index.qualified(call.func) == "rclpy.init" and index.inside(call, parts)
                       for call in index.calls)
    return False


@rule("ENT003", "undefined-entry-point-function", Severity.ERROR,
      fix="Define the function at the module's top level, or point the entry at the right one")
def undefined_entry_point_function(package: Package) -> Iterator[Hit]:
    """A console script names a function its module does not define at top level.

    ## What it does
    For console scripts whose module is installed and parses, checks that the first part of
    `:function` is defined at the module's top level (a `def`, a class, an assignment or an
    import). Modules with a module-level `__getattr__` are skipped, and so are those with
    `from x import *` unless `x` is a module of the package (its names then count).
    Also reports an entry naming a `Node` subclass of the module instead of a function
    (`talker = my_pkg.talker:Talker`) when neither the class nor the module's top-level code
    calls `rclpy.init()`, a function with a parameter that has no default (`def main(node):`:
    the script calls it with no arguments), and an entry reading an attribute off a plain function
    (`talker = my_pkg.talker:main.py`: `getattr(main, 'py')` fails).

    ## Why is this bad?
    The build succeeds, but running the command fails with `AttributeError` (or `ImportError`
    in the generated wrapper), often only after deployment.

    ## Example
    ```python
    # setup.py: 'talker = my_pkg.talker:main'
    def run():          # my_pkg/talker.py defines run, not main
        ...
    ```

    ## Use instead
    ```python
    def main():
        ...
    ```
    """
    entries, modules = scripts_and_modules(package)
    for entry in entries:
        if entry.module not in modules:
            continue
        module = package.module(modules[entry.module])
        if module is None or module.syntax_error or "__getattr__" in module.top_level_names:
            continue
        starred = _star_names(package, module)
        if starred is None:
            continue  # `from x import *` of a module whose names are unknown
        names = module.top_level_names | starred
        function = (entry.attr or "").split(".")[0]
        if function not in names:
            close = get_close_matches(function, sorted(module.top_level_names), n=1)
            meant = typo_of(function, module.top_level_names)
            yield Hit(entry.span, f"`{entry.module}` does not define `{function}` at its top "
                                  f"level (`{modules[entry.module]}`"
                                  f"{f'; did you mean `{close[0]}`?' if close else ''})",
                      f"Write `{meant}`" if meant else None)
        elif entry.attr != function and \
                _top_function(package, module.path, function) is not None:
            assert entry.attr is not None
            rest = entry.attr.split(".", 1)[1]
            yield Hit(entry.span, f"`{entry.attr}` reads `{rest}` off the function "
                      f"`{function}`, which has no such attribute: running the script raises "
                      "AttributeError", f"Write `{entry.module}:{function}`")
        elif entry.attr == function and \
                (needed := _required_parameters(package, module.path, function)):
            shown = [f"`{name}`" for name in needed]
            names = " and ".join([", ".join(shown[:-1]), shown[-1]] if len(shown) > 1 else shown)
            yield Hit(entry.span, f"`{function}` needs {names}, but the console script calls "
                      f"`{function}()` with no arguments: running it raises TypeError",
                      f"Give {names} a default (`def {function}(args=None):`), or point the "
                      "entry at a function that takes none")
        elif entry.attr == function and _uninitialised_node(package, module.path, function):
            yield Hit(entry.span, f"`{function}` is a Node class, not a function: the script "
                      "constructs it before anything calls rclpy.init(), which raises, and "
                      "nothing would spin it", "Point the entry at the module's `main`")
