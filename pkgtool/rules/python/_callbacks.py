"""The callbacks given to rclpy's API (PYC013, PYC024, PYC026, PYC035, PYC037)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.node_api import (ACTION_SERVER_CALLBACKS, ACTION_SERVERS, CALLBACKS,
                                    argument, node_api_calls)
from pkgtool.rules.python._message_instances import Function, callback_function
from pkgtool.rules.syntax_trees import Index, installed_trees


Argument = tuple[str, ast.expr, str, str, Index, ast.Module]
"""A callback argument: path, argument, the API called, the parameter it is given for, the
module's index and tree."""


@per_package
def callback_arguments(package: Package) -> tuple[Argument, ...]:
    """Callback arguments of rclpy calls (worked out once per package: PYC013, PYC024 and
    PYC026 read the same)."""
    return tuple(_arguments(package))


def _arguments(package: Package) -> Iterator[Argument]:
    trees = {module.path: tree for module, tree, _ in installed_trees(package)}
    for module, call, method, index in node_api_calls(package, CALLBACKS):
        parameters, callbacks = CALLBACKS[method]
        for name in callbacks:
            value = argument(call, parameters, name)
            if value is not None:
                yield module.path, value, f"{method}()", name, index, trees[module.path]
    for module, tree, index in installed_trees(package):
        for call in index.calls:
            if index.qualified(call.func) in ACTION_SERVERS:
                for name in ACTION_SERVER_CALLBACKS[1]:
                    value = argument(call, ACTION_SERVER_CALLBACKS[0], name)
                    if value is not None:
                        yield module.path, value, "ActionServer()", name, index, tree


def execute_callbacks(package: Package
                      ) -> Iterator[tuple[str, ast.expr, Function, str, Index]]:
    """The functions certainly given to ``ActionServer`` as execute callbacks (PYC037): path,
    the argument, the function, its goal handle parameter and the index."""
    for path, value, api, name, index, tree in callback_arguments(package):
        found = callback_function(value, tree, index) \
            if api == "ActionServer()" and name == "execute_callback" else None
        if found is None:
            continue
        function, skipped = found
        parameters = [*function.args.posonlyargs, *function.args.args]
        if len(parameters) > skipped:
            yield path, value, function, parameters[skipped].arg, index
