"""Fixers of Python code: a standard module never imported, a called callback, a misspelt
logger method, an int for a float field, rclpy's Time for a message, a ``Parameter`` for its
value, a path missing its ``/``, a method used without ``()``, ``=+`` for ``+=``, a lone
comparison, a string without its ``f`` prefix, a ``Parameter`` whose type and value disagree."""

from __future__ import annotations

import ast
import importlib
import io
import re
import tokenize
from collections.abc import Iterator

from pkgtool.edit.core import Edit, Fix
from pkgtool.edit.pysource import PyDoc
from pkgtool.findings import Finding
from pkgtool.fix.common import WRITE_NAME, python_nodes, renames
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package, is_test_material
from pkgtool.rules.python.field_value_type import TO_MSG, float_fix
from pkgtool.rules.python._loggers import logged_message
from pkgtool.rules.python.invalid_logger_call import ATTRIBUTES, meant_level
from pkgtool.rules.python.parameter_object_as_value import truth_tests
from pkgtool.rules.python.path_without_separator import joins
from pkgtool.rules.syntax_trees import index_of
from pkgtool.lazy_regex import lazy_pattern

_DECIMAL = lazy_pattern(r"[0-9][0-9_]*")
_MODULES = frozenset("""argparse copy glob json math os random re shutil signal socket
                     struct subprocess sys threading time""".split())
"""Standard library modules code uses by their name (``math.pi``) and forgets to import."""
_OPENING = lazy_pattern(r"[rRbBuUfF]*(\"\"\"|'''|\"|')")
"""A string literal's prefix and opening quotes."""


def _insert(doc: PyDoc, at: int, text: str) -> Edit:
    return Edit(doc.source.path, at, at, text)


@fixer("PYC001", "Import the standard library module the code uses")
def stdlib_import(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Add ``import math`` (in the import order the file follows) when ``math`` is undefined,
    nothing in the module binds it, every use reads an attribute of it and the module has
    each (``math.sqrt``). Safe: those lines raised NameError. Other undefined names (a
    typo, a third-party module whose import name is a guess) need the user."""
    done: set[tuple[str, str]] = set()
    for doc, finding, _ in python_nodes(package, findings):
        name = finding.message.removeprefix("Undefined name `").removesuffix("`")
        if name in _MODULES and (doc.source.path, name) not in done and \
                _used_as_module(doc.tree, name):
            done.add((doc.source.path, name))
            yield Fix(f"Import `{name}`", tuple(doc.add_imports([(name, None)])))


def _used_as_module(tree: ast.Module, name: str) -> bool:
    """True when ``name`` is bound nowhere in ``tree`` and each use reads an attribute of the
    standard module ``name`` that it has."""
    module = importlib.import_module(name)
    uses = [n for n in ast.walk(tree) if isinstance(n, ast.Name) and n.id == name]
    taken = [n.attr for n in ast.walk(tree) if isinstance(n, ast.Attribute) and
             isinstance(n.value, ast.Name) and n.value.id == name]
    bound = any(isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and
                n.name == name or isinstance(n, ast.arg) and n.arg == name or
                isinstance(n, ast.alias) and (n.asname or n.name).split(".")[0] == name
                for n in ast.walk(tree))
    return not bound and all(isinstance(n.ctx, ast.Load) for n in uses) and \
        len(uses) == len(taken) and all(hasattr(module, attr) for attr in taken)


@fixer("PYC013", "Pass the callback without calling it")
def callback_called(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the empty ``()`` after the callback PYC013 reports (``self.tick()`` becomes
    ``self.tick``). Safe: the called function returns None, so rclpy got None; calls with
    arguments are left to the user."""
    for doc, _, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call)), None)
        if call is not None and isinstance(call.func, (ast.Name, ast.Attribute)) and \
                not call.args and not call.keywords:
            name = ast.unparse(call.func)
            yield Fix(f"Pass `{name}` instead of `{name}()`",
                      (Edit(doc.source.path, doc.end(call.func), doc.end(call), ""),))


@fixer("PYC016", "Call the logging method the misspelt one is close to; log a value that is "
                 "no string as `str(value)`")
def logger_method(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a method rclpy's logger does not have when exactly one of its logging methods
    is spelled like it (``err`` becomes ``error``; ``warn`` and ``warning`` count as one), and
    wrap a message that is certainly no string (a number, a message, a caught exception) in
    ``str()``. Safe: the call raised AttributeError or TypeError; ``str()`` logs the value's
    text. Calls with several arguments, or methods close to none or to several, are left to
    the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call)), None)
        func = call.func if call is not None else None
        if not isinstance(func, ast.Attribute):
            continue
        if _NOT_TEXT.search(finding.message):
            assert call is not None
            message = logged_message(call)
            if message is not None and not isinstance(message, ast.Starred):
                yield Fix(f"Log `str({ast.unparse(message)})`",
                          (_insert(doc, doc.start(message), "str("),
                           _insert(doc, doc.end(message), ")")))
            continue
        if func.attr in ATTRIBUTES:
            continue
        meant, end = meant_level(func.attr), doc.end(func)
        if meant and doc.text[end - len(func.attr):end] == func.attr:
            yield Fix(f"Call `{meant}` instead of `{func.attr}`",
                      (Edit(doc.source.path, end - len(func.attr), end, meant),))


_NOT_TEXT = lazy_pattern(r"(is given .*, not a string|takes a string): rclpy raises `TypeError`")
"""PYC016's message for a logging call given a value that is certainly no string."""


@fixer("PYC025", "Give a float field a float; convert rclpy's Time to a message")
def field_value(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Append ``.0`` to a decimal int literal a float field is given (``x = 1`` becomes ``x =
    1.0``), convert an int name or attribute with ``float()`` (``x = float(turns)``), and
    append ``.to_msg()`` to rclpy's ``Time`` or ``Duration`` given to a message field. Safe:
    the assignment raised, or published garbage. Other values need the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        value = nodes[0] if nodes else None
        if not isinstance(value, ast.expr) or finding.fix is None:
            continue
        number = value.operand if isinstance(value, ast.UnaryOp) else value
        start, end = doc.start(value), doc.end(value)
        if finding.fix == float_fix(value, None) and _DECIMAL.fullmatch(doc.segment(number)):
            yield Fix(f"Write `{ast.unparse(value)}.0`", (_insert(doc, doc.end(number), ".0"),))
        elif finding.fix == float_fix(value, "int") and \
                isinstance(value, (ast.Name, ast.Attribute)):
            yield Fix(f"Write `float({ast.unparse(value)})`",
                      (_insert(doc, start, "float("), _insert(doc, end, ")")))
        elif finding.fix == TO_MSG and isinstance(value, (ast.Call, ast.Name, ast.Attribute)):
            yield Fix(f"Convert `{ast.unparse(value)}` with `.to_msg()`",
                      (_insert(doc, doc.end(value), ".to_msg()"),))


@fixer("PYC031", "Take the parameter's value with `.value`")
def parameter_value(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Append ``.value`` to the ``Parameter`` object used as a value
    (``self.get_parameter('period')`` becomes ``self.get_parameter('period').value``), or taken
    as text (``str(self.get_parameter('topic'))`` becomes
    ``str(self.get_parameter('topic').value)``; a name holding such a text is left to the
    user). Safe where it raised TypeError (arithmetic, ``create_timer``, ``float()``) or the
    text was refused; a comparison, which was always false, then compares the value: that fix
    is unsafe."""
    for doc, finding, nodes in python_nodes(package, findings):
        value = next((n for n in nodes if isinstance(n, (ast.Call, ast.Name, ast.Attribute))
                      and finding.message.startswith(f"`{ast.unparse(n)}` ")), None)
        if value is not None and "` is the text of the `Parameter`" in finding.message:
            value = value.args[0] if isinstance(value, ast.Call) and len(value.args) == 1 \
                and isinstance(value.args[0], ast.Call) else None
        if value is None:
            continue
        compared = any(isinstance(n, ast.Compare) and (n.left is value or value in n.comparators)
                       for n in ast.walk(doc.tree)) or \
            any(test is value for test in truth_tests(doc.tree))
        yield Fix(f"Take `{ast.unparse(value)}.value`",
                  (_insert(doc, doc.end(value), ".value"),), safe=not compared)


@fixer("PYC032", "Put the missing `/` after the package's folder")
def path_separator(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Insert ``/`` at the start of the relative path joined to the folder
    (``share + 'config/a.yaml'`` becomes ``share + '/config/a.yaml'``, ``f'{share}config'``
    becomes ``f'{share}/config'``). Safe: the path named no file before."""
    for doc, _, nodes in python_nodes(package, findings):
        ids = {id(n) for n in nodes}
        for node, left, _, text in joins(doc.tree, index_of(doc.tree)):
            at = _after_folder(doc, node, left) if id(node) in ids else None
            if at is not None and doc.text.startswith(text[:1], at):
                yield Fix(f"Write `/{text}`", (_insert(doc, at, "/"),))


def _after_folder(doc: PyDoc, node: ast.expr, left: ast.expr) -> int | None:
    """Where the relative path joined to ``left`` starts: after the opening quote of the
    right operand of ``+``, or after the ``}`` closing ``left``'s field of an f-string."""
    if isinstance(node, ast.BinOp):
        opening = _OPENING.match(doc.text, doc.start(node.right))
        return opening.end() if opening else None
    closing = doc.text.find("}", doc.end(left))
    return closing + 1 if closing >= 0 else None


@fixer("PYC046", "Call the method used without `()`")
def method_call(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Append ``()`` to the method PYC046 reports (``future.result`` becomes
    ``future.result()``). Safe where the code raised AttributeError (``future.result.sum``);
    where the method was tested (always true), kept as a value or named alone (the statement
    did nothing), calling it changes what runs: unsafe. A method of the package's own class
    may need arguments: the user calls it."""
    for doc, finding, nodes in python_nodes(package, findings):
        if "is a method of `" in finding.message:
            continue
        method = next((n for n in nodes if isinstance(n, (ast.Attribute, ast.Name)) and
                       finding.message.startswith(f"`{ast.unparse(n)}` ")), None)
        if method is not None:
            raised = "raises AttributeError" in finding.message
            yield Fix(f"Call `{ast.unparse(method)}()`",
                      (_insert(doc, doc.end(method), "()"),), safe=raised)


@fixer("PYC033", "Pass a timeout given in the executor's place as `timeout_sec=`")
def timeout_keyword(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``timeout_sec=`` before the timeout PYC033 finds in the place of
    ``rclpy.spin_until_future_complete()``'s executor. Safe: the call failed before. The
    other PYC033 findings (too many arguments) need the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        value = next((n for n in nodes if isinstance(n, ast.expr) and finding.message.startswith(
            f"`{ast.unparse(n)}` is given in the place of")), None)
        if value is not None:
            yield Fix(f"Pass `timeout_sec={ast.unparse(value)}`",
                      (_insert(doc, doc.start(value), "timeout_sec="),))


@fixer("PYC047", "Write the augmented assignment `=+` stands for", safe=False)
def augmented_assignment(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Swap ``=+`` to ``+=`` (``=-`` to ``-=``) in the assignment PYC047 reports. Unsafe:
    the value was assigned before, it is added now (and a name first bound there raises)."""
    for doc, _, nodes in python_nodes(package, findings):
        assign = next((n for n in nodes if isinstance(n, ast.Assign)), None)
        at = doc.start(assign.value) - 1 if assign is not None else -1
        if assign is not None and doc.text[at:at + 2] in ("=+", "=-"):
            sign = doc.text[at + 1]
            yield Fix(f"Write `{sign}=`", (Edit(doc.source.path, at, at + 2, f"{sign}="),),
                      safe=False)


@fixer("PYC050", "Assign, or assert in a test, what a lone comparison compares", safe=False)
def lone_comparison(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``=`` for the ``==`` of a comparison standing alone (``msg.data == 'hi'`` becomes
    ``msg.data = 'hi'``), or put ``assert`` before it in a test. Unsafe: the statement did
    nothing before; now it assigns, or the test can fail."""
    for doc, _, nodes in python_nodes(package, findings):
        compare = next((n for n in nodes if isinstance(n, ast.Compare)), None)
        if compare is None:
            continue
        if is_test_material(doc.source.path):
            yield Fix("Assert the comparison", (_insert(doc, doc.start(compare), "assert "),),
                      safe=False)
            continue
        between = doc.text[doc.end(compare.left):doc.start(compare.comparators[0])]
        at = doc.end(compare.left) + between.find("==")
        if between.count("==") == 1 and "#" not in between and \
                isinstance(compare.left, (ast.Name, ast.Attribute, ast.Subscript)):
            yield Fix("Assign with `=`", (Edit(doc.source.path, at, at + 2, "="),), safe=False)


@fixer("PYC019", "Write the field the misspelt one is close to", safe=False)
def message_field(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a field a message does not have (set, read or given as a keyword) to the one
    field spelled like it. Unsafe: it guesses which field was meant; the code raised
    AttributeError (or the constructor ignored the keyword) before."""
    yield from renames(package, findings, re.compile(r"has no field `(\w+)`"), WRITE_NAME)


@fixer("PYC063", "Write the standard library name the misspelt one is close to", safe=False)
def stdlib_name(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a name a standard library module lacks to the one name it has spelled like it
    (``signal.SIGNT`` to ``signal.SIGINT``). Unsafe: it guesses which name was meant; the
    line raised AttributeError or ImportError before."""
    yield from renames(package, findings, re.compile(r"has no `(\w+)` on Python"), WRITE_NAME)


@fixer("PYC076", "Write the NumPy name the misspelt one is close to", safe=False)
def numpy_name(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a name no NumPy release defines to the one name it is a typo of (``np.uit8`` to
    ``np.uint8``). Unsafe: it guesses which name was meant; the line raised AttributeError or
    ImportError before."""
    yield from renames(package, findings, re.compile(r"has no `(\w+)` in any release"),
                       WRITE_NAME)


@fixer("PYC078", "Write the method of the builtin type the misspelt one is close to",
       safe=False)
def builtin_attribute(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename an attribute a list, dict, str or number lacks to the one it has spelled like it
    (``items.apend`` to ``items.append``). Unsafe: it guesses which one was meant; the line
    raised AttributeError before."""
    yield from renames(package, findings, re.compile(r"which has no `(\w+)`"), WRITE_NAME)


@fixer("PYC064", "Read the attribute of the package's class the misspelt one is close to",
       safe=False)
def instance_attribute(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename an attribute an instance of a package class lacks to the one name its class
    defines spelled like it (``detect_edge`` to ``detect_edges``). Unsafe: it guesses which
    attribute was meant; the read raised AttributeError before."""
    yield from renames(package, findings, re.compile(r"has no attribute `(\w+)`"), WRITE_NAME)


@fixer("PYC029", "Write the keyword rclpy's function takes that the misspelt one is close to",
       safe=False)
def rclpy_keyword(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a keyword no rclpy distribution takes to the parameter a typo away
    (``callback_grup=`` to ``callback_group=``); a near name that is no typo (``timeout=``
    for ``timeout_sec=``) is left to the user. Unsafe: it guesses which parameter was meant;
    the call raised TypeError before."""
    yield from renames(package, findings, re.compile(r"has no `(\w+)` argument"),
                       re.compile(r"Write `(\w+)=`"))


@fixer("PYC079", "Write the keyword the standard library call takes that the misspelt one "
       "is close to", safe=False)
def stdlib_keyword(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a keyword no Python 3.10-3.13 gives the call to the one a typo away
    (``reversed=`` to ``reverse=``). Unsafe: it guesses which keyword was meant; the call
    raised TypeError before."""
    yield from renames(package, findings, re.compile(r"has no `(\w+)` argument on Python"),
                       re.compile(r"Write `(\w+)=`"))


@fixer("PYC080", "Read the field a point, vector or quaternion holds at that position",
       safe=False)
def message_position(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Replace a literal index of a point, vector or quaternion message by its field
    (``position[0]`` becomes ``position.x``). Unsafe: it takes the `[x, y, z(, w)]` order
    other APIs use; the line raised TypeError before."""
    for doc, finding, nodes in python_nodes(package, findings):
        meant = _FIELD_AT.fullmatch(finding.fix or "")
        subscript = next((n for n in nodes if isinstance(n, ast.Subscript) and meant and
                          ast.unparse(n.value) == meant[1]), None)
        if meant is not None and subscript is not None:
            yield Fix(f"Write `{meant[1]}.{meant[2]}`", (
                Edit(doc.source.path, doc.end(subscript.value), doc.end(subscript),
                     f".{meant[2]}"),))


_FIELD_AT = re.compile(r"Write `(.+)\.([xyzw])`")
"""The help of a PYC080 finding that names the field meant."""


@fixer("PYC014", "Read the declared parameter the misspelt name is close to", safe=False)
def parameter_read(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a parameter read but never declared to the one declared parameter spelled like
    it (``perod`` to ``period``). Unsafe: it guesses which parameter was meant; the read
    raised ParameterNotDeclaredException before."""
    yield from renames(package, findings, re.compile(r"reads parameter `([^`]+)` but never"),
                       WRITE_NAME)


@fixer("PYC058", "Add the `f` prefix the string's fields need", safe=False)
def f_prefix(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Put ``f`` before the string PYC058 reports (``'Count: {count}'`` becomes
    ``f'Count: {count}'``; ``r'...'`` becomes ``fr'...'``), when it is one literal, not
    several joined. Unsafe: the fields are evaluated now, and one may raise where the line
    logged its text before."""
    for doc, _, nodes in python_nodes(package, findings):
        literal = next((n for n in nodes if isinstance(n, ast.Constant) and
                        isinstance(n.value, str)), None)
        text = doc.segment(literal) if literal is not None else ""
        opening = _OPENING.match(text)
        if literal is None or opening is None or opening.group(0)[:-len(opening.group(1))] \
                not in ("", "r", "R") or not _one_literal(text):
            continue
        shown = f"Write `f{text}`" if len(text) <= 40 else "Add the `f` prefix"
        yield Fix(shown, (_insert(doc, doc.start(literal), "f"),), safe=False)


def _one_literal(text: str) -> bool:
    """True when ``text`` is a single string literal token (not ``'a' 'b'`` joined)."""
    try:
        tokens = [t for t in tokenize.generate_tokens(io.StringIO(text).readline)
                  if t.type not in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER)]
    except (tokenize.TokenError, SyntaxError):
        return False
    return len(tokens) == 1 and tokens[0].type == tokenize.STRING


@fixer("PYC062", "Name the misspelt constructor `__init__`", safe=False)
def constructor_name(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the method to ``__init__``. Unsafe: the method now runs whenever the object is
    made, which is what its ``super().__init__()`` call or its name says was meant, and the
    base class's constructor no longer runs in its place."""
    for doc, _, nodes in python_nodes(package, findings):
        method = next((n for n in nodes if isinstance(n, ast.FunctionDef)), None)
        if method is None:
            continue  # an async method would make an async __init__: the user's to rewrite
        start = doc.source.offset_of_utf8(method.lineno, method.col_offset)
        found = re.compile(rf"def\s+({re.escape(method.name)})\b").search(doc.source.text, start)
        if found:
            yield Fix(f"Rename `{method.name}` to `__init__`",
                      (Edit(doc.source.path, found.start(1), found.end(1), "__init__"),), False)


@fixer("PYC065", "Write the pytest name the misspelt one is close to", safe=False)
def pytest_name(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a pytest name or mark pytest lacks to the one it has spelled like it
    (``fixure`` to ``fixture``, ``paramtrize`` to ``parametrize``). Unsafe: it guesses which
    name was meant; the test module or the test did not run as written before."""
    yield from renames(package, findings,
                       re.compile(r"(?:^`pytest\.mark\.|^`pytest` has no `)(\w+)`"), WRITE_NAME)


@fixer("PYC066", "Name the test function's parameter the misspelt one is close to",
       safe=False)
def parametrize_name(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a name of ``parametrize`` to the parameter of the test function spelled like
    it (``sped`` to ``speed``). Unsafe: it guesses which parameter was meant; pytest refused
    the test before."""
    yield from renames(package, findings, re.compile(r"^`parametrize` names `(\w+)`"),
                       WRITE_NAME)


@fixer("PYC026", "Return the response a service callback fills in", safe=False)
def service_response(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """In a service callback (``def on_request(self, request, response)``): append ``return
    response`` to a callback that never returns it or falls off its end (safe: rclpy raised
    TypeError there, and the callback filled that response in), and write ``return
    response`` for a ``return`` of something else (``return response.sum``, a bare
    ``return``): unsafe, that path may not have filled the response in. Action and
    set-parameters callbacks need the user (a ``Result()`` or ``SetParametersResult``)."""
    for doc, finding, nodes in python_nodes(package, findings):
        if not finding.message.startswith("The service callback "):
            continue
        index = index_of(doc.tree)
        node = nodes[0] if nodes else None
        function = node if isinstance(node, ast.FunctionDef) else \
            index.enclosing_function(node, through_lambdas=False) if node is not None else None
        skip = 1 if isinstance(index.parents.get(id(function)), ast.ClassDef) else 0
        parameters = [*function.args.posonlyargs, *function.args.args] if function else []
        if function is None or len(parameters) < skip + 2:
            continue
        response = parameters[skip + 1].arg
        if isinstance(node, ast.Return) or node is not None and \
                isinstance(index.parents.get(id(node)), ast.Return):
            statement = node if isinstance(node, ast.Return) else index.parents[id(node)]
            yield Fix(f"Return `{response}`", (Edit(doc.source.path, doc.start(statement),
                                                    doc.end(statement),
                                                    f"return {response}"),), safe=False)
        elif node is function or node is function.body[-1]:
            last = function.body[-1]
            line_end = doc.text.find("\n", doc.end(last))
            at = len(doc.text) if line_end < 0 else line_end
            indent = " " * function.body[0].col_offset
            yield Fix(f"End the callback with `return {response}`",
                      (_insert(doc, at, f"\n{indent}return {response}"),), safe=True)


@fixer("PYC068", "Compare `__name__` with `'__main__'`", safe=False)
def main_guard(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``'__main__'`` over the misspelt string (``'__man__'``). Unsafe: the block now
    runs when the file is run as a script, which it never did."""
    for doc, _, nodes in python_nodes(package, findings):
        text = next((n for n in nodes if isinstance(n, ast.Constant)), None)
        if text is not None and isinstance(text.value, str):
            yield Fix("Write `'__main__'`", (Edit(doc.source.path, doc.start(text),
                                                  doc.end(text), doc.string("__main__")),),
                      safe=False)


@fixer("PYC081", "Name the exception class an `except` clause calls")
def exception_class(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``KeyboardInterrupt`` for the ``KeyboardInterrupt()`` an ``except`` clause names.
    Safe: the handler raised TypeError whenever an exception reached it; a call with
    arguments needs the user."""
    for doc, _, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call)), None)
        if call is not None and not call.args and not call.keywords:
            name = ast.unparse(call.func)
            edit = Edit(doc.source.path, doc.start(call), doc.end(call), name)
            yield Fix(f"Write `{name}`", (edit,))


@fixer("PYC041", "Call `super()` before its `__init__`")
def super_call(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``super()`` for the ``super`` of ``super.__init__(...)``. Safe: the line raised
    TypeError; a constructor that never calls ``super().__init__`` needs the user (the node
    name is theirs)."""
    for doc, _, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call)), None)
        func = call.func if call is not None else None
        if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) and \
                func.value.id == "super":
            yield Fix("Write `super()`", (_insert(doc, doc.end(func.value), "()"),))


@fixer("PYC070", "Give an rclpy Parameter a float for a double, a Parameter.Type for a message "
                 "constant, a value given as its type by name")
def parameter_type(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Append ``.0`` to a decimal int given with ``Parameter.Type.DOUBLE`` (``2`` becomes
    ``2.0``), write ``Parameter.Type.STRING`` for ``ParameterType.PARAMETER_STRING``, and
    ``value=10.0`` for a value given in the place of the type. Safe: the call raised. Other
    values (a list, a string for a bool, no value at all) need the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        value = nodes[0] if nodes else None
        match = _WRITE.fullmatch(finding.fix or "")
        if not isinstance(value, ast.expr) or match is None:
            continue
        number = value.operand if isinstance(value, ast.UnaryOp) else value
        if match.group(1) == f"{ast.unparse(value)}.0" and \
                _DECIMAL.fullmatch(doc.segment(number)):
            yield Fix(f"Write `{match.group(1)}`", (_insert(doc, doc.end(number), ".0"),))
        elif match.group(1) == f"value={ast.unparse(value)}":
            yield Fix(f"Write `{match.group(1)}`", (_insert(doc, doc.start(value), "value="),))
        elif match.group(2) and _parameter_name(doc.tree, value):
            written = f"{_parameter_name(doc.tree, value)}.Type.{match.group(2)}"
            yield Fix(f"Write `{written}`",
                      (Edit(doc.source.path, doc.start(value), doc.end(value), written),))


_WRITE = lazy_pattern(r"Write `(.+)`|Use `Parameter\.Type\.([A-Z_]+)`")
"""PYC070's helps that name one replacement."""


def _parameter_name(tree: ast.Module, value: ast.AST) -> str | None:
    """How the ``Parameter`` call holding ``value`` names rclpy's ``Parameter`` class."""
    for call in ast.walk(tree):
        if isinstance(call, ast.Call) and any(a is value for a in call.args) and \
                isinstance(call.func, (ast.Name, ast.Attribute)):
            return ast.unparse(call.func)
    return None


_FIELD_MEANT = lazy_pattern(r"Compare the field: `[^`]*\.([A-Za-z_]\w*)`")
"""The help of a PYC082 finding naming the one field meant."""


@fixer("PYC082", "Compare the field of a message compared with a plain value", safe=False)
def compared_field(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``msg.data`` for the ``msg`` compared with ``'stop'``, when one field of the
    message holds such values (the finding's help names it). Unsafe: the comparison was
    always False (or True); now the branch runs when the field matches."""
    for doc, finding, nodes in python_nodes(package, findings):
        meant = _FIELD_MEANT.fullmatch(finding.fix or "")
        ref = next((n for n in reversed(nodes) if isinstance(n, (ast.Name, ast.Attribute)) and
                    finding.message.startswith(f"`{ast.unparse(n)}` is a ")), None)
        if meant is not None and ref is not None:
            yield Fix(f"Compare `{ast.unparse(ref)}.{meant.group(1)}`",
                      (_insert(doc, doc.end(ref), f".{meant.group(1)}"),), safe=False)


_READ_NAMES = lazy_pattern(r"reads ((?:`\w+`(?:, )?)+), which the enclosing loop")


@fixer("PYC094", "Bind the loop's values as the lambda's defaults", safe=False)
def loop_values_bound(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Give a lambda made in a loop each name the loop rebinds as a defaulted parameter
    (``lambda msg: f(robot)`` becomes ``lambda msg, robot=robot: f(robot)``), when it takes
    no ``*args``, ``**kwargs`` or keyword-only parameters and the statement making it does not
    assign the name (``timer = create_timer(1, lambda: timer.cancel())``: a default would
    read it before it is bound); a function defined in the loop needs the user. rclpy
    passes a subscription, service or timer callback only the arguments a parameter without
    a default takes. Unsafe: each callback then sees its own turn's value, where all saw the
    last one."""
    for doc, finding, nodes in python_nodes(package, findings):
        function = next((n for n in nodes if isinstance(n, ast.Lambda)), None)
        names = _READ_NAMES.search(finding.message)
        if function is None or names is None or function.args.vararg or \
                function.args.kwarg or function.args.kwonlyargs:
            continue
        read = re.findall(r"`(\w+)`", names.group(1))
        if set(read) & _assigned_by_statement(doc.tree, function):
            continue  # `timer = create_timer(1, lambda: timer.cancel())`: not bound yet
        bound = ", ".join(f"{n}={n}" for n in read)
        given = [*function.args.posonlyargs, *function.args.args, *function.args.defaults]
        at = max(doc.end(n) for n in given) if given else doc.start(function) + len("lambda")
        text = f", {bound}" if given else f" {bound}"
        yield Fix(f"Bind {names.group(1)} as defaults", (_insert(doc, at, text),), safe=False)


@fixer("PYC095", "Parse the command line without ROS's arguments")
def ros_arguments_removed(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Give the ``parse_args()`` PYC095 reports the command line without ROS's arguments:
    ``parse_args(remove_ros_args(sys.argv)[1:])``, importing ``sys`` and rclpy's
    ``remove_ros_args`` as needed. Safe: the node exited at launch before; the arguments
    it declares are read as they were."""
    for doc, _, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call) and not n.args and
                     isinstance(n.func, ast.Attribute) and n.func.attr == "parse_args"), None)
        if call is None or doc.text[doc.end(call) - 2:doc.end(call)] != "()":
            continue
        at = doc.end(call) - 1
        yield Fix("Parse `remove_ros_args(sys.argv)[1:]`", (
            _insert(doc, at, "remove_ros_args(sys.argv)[1:]"),
            *doc.add_imports([("sys", None), ("rclpy.utilities", "remove_ros_args")])))


def _assigned_by_statement(tree: ast.Module, node: ast.AST) -> set[str]:
    """The names the statement holding ``node`` assigns (its value is made first)."""
    for statement in ast.walk(tree):
        if isinstance(statement, (ast.Assign, ast.AnnAssign)) and statement.value is not None \
                and any(child is node for child in ast.walk(statement.value)):
            targets = statement.targets if isinstance(statement, ast.Assign) else \
                [statement.target]
            return {n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}
    return set()
