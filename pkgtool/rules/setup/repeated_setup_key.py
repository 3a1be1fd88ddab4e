"""SET017: a dict written in setup.py repeats a key, so Python keeps only its last value."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import setup_tree


@rule("SET017", "repeated-setup-key", Severity.ERROR,
      fix="Write the key once, with every value in it")
def repeated_setup_key(package: Package) -> Iterator[Hit]:
    """A dict in setup.py repeats a key with another value, so the first value is lost.

    ## What it does
    Reports a key written a second time in a dict display of an ament_python package's
    setup.py (`entry_points={'console_scripts': [...], 'console_scripts': [...]}`,
    `package_data`, `package_dir`) when the two values differ.

    ## Why is this bad?
    Python keeps only the last value of a repeated key, silently: the console scripts of
    the first `console_scripts` list are never installed (`ros2 run` says "No executable
    found"), the files of the first `package_data` entry never ship.

    ## Example
    ```python
    entry_points={
        'console_scripts': ['talker = demo.talker:main'],
        'console_scripts': ['listener = demo.listener:main'],
    },
    ```

    ## Use instead
    ```python
    entry_points={
        'console_scripts': [
            'talker = demo.talker:main',
            'listener = demo.listener:main',
        ],
    },
    ```
    """
    tree = setup_tree(package)
    if tree is None:
        return
    for node in nodes_of_class(tree, ast.Dict):
        first: dict[object, tuple[ast.Constant, ast.expr]] = {}
        for key, value in zip(node.keys, node.values):  # type: ignore[attr-defined]
            if not isinstance(key, ast.Constant) or not isinstance(key.value, (str, int)):
                continue
            earlier, old = first.setdefault(key.value, (key, value))
            if earlier is not key and ast.dump(old) != ast.dump(value):
                yield Hit(Span("setup.py", key.lineno, key.col_offset + 1),
                          f"the key {key.value!r} is written again (first on line "
                          f"{earlier.lineno}): Python keeps only this value, and the first is "
                          "lost")
