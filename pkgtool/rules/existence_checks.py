"""Whether a module asks if files exist (or makes them): its paths may be missing on
purpose."""

from __future__ import annotations

import ast

from pkgtool.model.launch import EXISTENCE_CHECKS
from pkgtool.rules.syntax_trees import Index

HANDLING_FILES = EXISTENCE_CHECKS | {"makedirs", "mkdir", "load_dotenv"}
"""Those, ``os.makedirs`` and ``Path.mkdir()`` (a module making folders may make the share
path it names too) and ``load_dotenv()``, which returns False for a missing file."""


def checks_files(index: Index, calls: frozenset[str] = HANDLING_FILES) -> bool:
    """True when the module makes one of ``calls`` (by default: asks whether files or folders
    exist, or makes folders): it handles a share file that may be missing (a model it
    downloads when absent, a file the user adds, a folder it creates), so none of its share
    paths is certainly read."""
    return any(isinstance(call.func, ast.Attribute) and call.func.attr in calls or
               isinstance(call.func, ast.Name) and call.func.id == "load_dotenv" and
               "load_dotenv" in calls
               for call in index.calls)
