"""Read setup.py statically: ``ast.parse`` plus an allow-list evaluator, never executing it.

:func:`read_setup` runs the module's statements over plain data (string operations,
``os.path``, ``glob`` and ``pathlib`` answered from the package's file list, setuptools'
package finders simulated) until it reaches ``setup(...)``. Whatever it cannot compute is
recorded as :class:`~pkgtool.model.span.Unresolved` under the keyword it would feed.
"""

from __future__ import annotations

import ast
from typing import Any

from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.setup_eval.commands import acting
from pkgtool.model.setup_eval.entries import Malformed, data_files, entry_points
from pkgtool.model.setup_eval.evaluator import SetupCall
from pkgtool.model.setup_eval.executor import CONTROL_FLOW, Runner
from pkgtool.model.setup_eval.scope import Scope
from pkgtool.model.setup_eval.tree import BlindTree, Tree, normalize
from pkgtool.model.setup_eval.values import Found, NotStatic, plain
from pkgtool.model.setup_py import DataFile, PackagesSpec, SetupPy, Value
from pkgtool.model.span import ParseProblem, Span, Unresolved
from pkgtool.records import record

_VALUE_FIELDS = ("name", "version", "description", "license", "maintainer", "maintainer_email",
                 "tests_require", "extras_require", "install_requires")


@record
class Evaluation:
    """One run of setup.py: its ``ast``, the module scope at the end, the setup() call."""

    module: ast.Module
    scope: Scope
    call: SetupCall | None
    tree: Tree


def evaluate(path: str, text: str, files: tuple[str, ...] | None
             ) -> Evaluation | ParseProblem:
    """Run setup.py ``text`` over evaluated data; a syntax error gives a ParseProblem.

    ``files`` is the package's file list; None evaluates without one: globs and package
    finders are refused, so what is evaluated does not depend on the files (a
    :class:`~pkgtool.model.setup_eval.tree.BlindTree`).
    """
    module = parse_tree(path, text)  # the parse PYC001 and PYC006 share
    if isinstance(module, ParseProblem):
        return module
    runner = Runner(path, text, files or ())
    if files is None:
        runner.tree = BlindTree(runner.budget)
    scope = Scope()
    try:
        runner.run_block(module.body, scope)
    except CONTROL_FLOW:
        pass
    call = runner.setup_calls[0] if runner.setup_calls else _unreached_call(runner, module)
    return Evaluation(module, scope, call, runner.tree)


def read_setup(path: str, text: str, files: tuple[str, ...] | None) -> SetupPy | ParseProblem:
    """Evaluate setup.py ``text`` statically (``files``: see :func:`evaluate`); a syntax
    error gives a ParseProblem."""
    found = evaluate(path, text, files)
    if isinstance(found, ParseProblem):
        return found
    return _setup_py(path, found.call, found.tree, found.module)


def _unreached_call(runner: Runner, module: ast.Module) -> SetupCall | None:
    """A setup() call the run did not reach (in an uncalled function): nothing is known."""
    for node in ast.walk(module):
        if isinstance(node, ast.Call) and getattr(node.func, "id",
                                                  getattr(node.func, "attr", None)) == "setup":
            call = SetupCall(runner.span(node))
            call.unresolved.append(("**", runner.unresolved(node)))
            return call
    return None


_FIELDS = (*_VALUE_FIELDS, "packages", "package_dir", "py_modules", "data_files", "entry_points",
           "scripts")


def _setup_py(path: str, call: SetupCall | None, tree: Tree, module: ast.Module) -> SetupPy:
    if call is None:
        return SetupPy(path=path, setup_span=None, keywords=(),
                       **dict.fromkeys(_FIELDS))  # type: ignore[arg-type]
    fields: dict[str, Any] = {}
    unresolved = list(call.unresolved)
    for key, value in call.values.items():
        try:
            fields[key] = _field(key, value, call.spans[key], tree, call.sources[key])
        except (NotStatic, Malformed):
            unresolved.append((key, call.sources[key]))
            fields.pop(key, None)
    keywords = tuple(dict.fromkeys([*call.values, *(k for k, _ in unresolved if k != "**")]))
    known = {name: fields.get(name) for name in _FIELDS}
    return SetupPy(path=path, setup_span=call.span, keywords=keywords,
                   unresolved=tuple(unresolved), data_files_in_part=_in_part(call, tree),
                   commands=None if call.commands is None else tuple(
                       command for command, _ in call.commands),
                   acting_commands=acting(call.commands or (), module),
                   **known)


def _in_part(call: SetupCall, tree: Tree) -> tuple[DataFile, ...]:
    """The entries of a ``data_files`` list display that evaluate, when the whole does not."""
    items = call.in_part.get("data_files")
    if not items:
        return ()
    found: list[DataFile] = []
    for item in items:
        try:
            found.extend(data_files([item], tree, call.span))
        except Malformed:
            continue
    return tuple(found)


def _field(key: str, value: Any, span: Span, tree: Tree, source: Unresolved) -> Any:
    if key in _VALUE_FIELDS:
        return Value(plain(value, source), span)
    if key == "packages":
        return _packages(value, span)
    if key == "package_dir":
        return _package_dir(value)
    if key in ("py_modules", "scripts"):
        if not isinstance(value, (list, tuple)) or not all(isinstance(m, str) for m in value):
            raise Malformed(key)
        return tuple(str(m) for m in value)
    if key == "data_files":
        return data_files(value, tree, span)
    if key == "entry_points":
        return entry_points(value, span)
    return None


def _packages(value: Any, span: Span) -> PackagesSpec:
    if not isinstance(value, (list, tuple)) or not all(isinstance(n, str) for n in value):
        raise Malformed("packages")
    names = tuple(str(n) for n in value)
    if isinstance(value, Found):
        return PackagesSpec(value.kind, names, span, value.where, value.include, value.exclude)
    return PackagesSpec("list", names, span)


def _package_dir(value: Any) -> dict[str, str]:
    if not isinstance(value, dict):
        raise Malformed("package_dir")
    result = {}
    for package, folder in value.items():
        normal = normalize(str(folder)) if isinstance(folder, str) else None
        if not isinstance(package, str) or normal is None:
            raise Malformed("package_dir")
        result[str(package)] = normal
    return result
