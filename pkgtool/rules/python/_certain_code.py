"""What Python certainly evaluates of a statement when it runs: the parts PYC087 follows
through ``__init__`` and PYC090 through a timer callback."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.ast_nodes import child_nodes
from pkgtool.rules.syntax_trees import FUNCTIONS


def certain_parts(statement: ast.stmt) -> Iterator[ast.AST]:
    """The nodes of ``statement`` Python certainly evaluates when the statement runs (for
    an augmented assignment, its target too: it is read first)."""
    if isinstance(statement, (ast.Try, *FUNCTIONS, ast.ClassDef)) or \
            type(statement).__name__ == "TryStar":
        return
    if isinstance(statement, ast.AugAssign):
        yield statement.target
        yield from certain(statement.value)
    elif isinstance(statement, (ast.If, ast.While)):
        yield from certain(statement.test)
    elif isinstance(statement, (ast.For, ast.AsyncFor)):
        yield from certain(statement.iter)
    elif isinstance(statement, (ast.With, ast.AsyncWith)):
        for item in statement.items:
            yield from certain(item.context_expr)
    elif isinstance(statement, ast.Assert):
        yield from certain(statement.test)
    elif isinstance(statement, ast.Match):
        yield from certain(statement.subject)
    elif isinstance(statement, (ast.Assign, ast.AnnAssign)):
        if statement.value is not None:
            yield from certain(statement.value)
        targets = statement.targets if isinstance(statement, ast.Assign) else [statement.target]
        for target in targets:  # `self.config['k'] = v` reads `self.config`
            if isinstance(target, (ast.Subscript, ast.Attribute)):
                yield from certain(target.value)
            if isinstance(target, ast.Subscript):
                yield from certain(target.slice)
    else:
        for child in child_nodes(statement):
            yield from certain(child)


def certain(node: ast.AST) -> Iterator[ast.AST]:
    """``node`` and the parts of it Python certainly evaluates with it: not the branches
    of a conditional expression, the operands after the first of ``and``/``or``, a lambda's
    body, nor a comprehension's but its first iterable."""
    yield node
    if isinstance(node, ast.Lambda):
        return
    if isinstance(node, ast.IfExp):
        yield from certain(node.test)
    elif isinstance(node, ast.BoolOp):
        yield from certain(node.values[0])
    elif isinstance(node, ast.Compare) and len(node.ops) > 1:  # `a < b < c` may stop at `b`
        yield from certain(node.left)
        yield from certain(node.comparators[0])
    elif isinstance(node, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
        yield from certain(node.generators[0].iter)
    else:
        for child in child_nodes(node):
            yield from certain(child)
