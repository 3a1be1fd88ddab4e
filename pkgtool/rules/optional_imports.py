"""Own modules that a package imports only under a guard: optional back-ends.

rqt_py_console imports its ``spyder_console_widget`` module inside ``try/except ImportError``;
that module imports ``spyder`` unguarded, yet spyder is optional for the package as a whole.
The imports of such a module count as guarded.
"""

from __future__ import annotations

import posixpath

from pkgtool.model.installed import installed_modules
from pkgtool.model.memo import per_package
from pkgtool.model.modules import Import
from pkgtool.model.package import Package
from pkgtool.rules.test_modules import test_files


def _targets(name: str, path: str, imported: Import, own: dict[str, str]) -> set[str]:
    """Files of the package's own modules that ``imported`` (in module ``name``) loads."""
    if imported.level:
        parent = name if posixpath.basename(path) == "__init__.py" else name.rpartition(".")[0]
        for _ in range(imported.level - 1):
            parent = parent.rpartition(".")[0]
        base = ".".join(p for p in (parent, imported.module) if p)
    else:
        base = imported.module
    names = [base, *(f"{base}.{leaf}" for leaf in imported.names)]
    parts = base.split(".")  # importing a.b.c runs a/__init__.py and a/b/__init__.py too
    names += [".".join(parts[:depth]) for depth in range(1, len(parts))]
    return {own[n] for n in names if n in own}


def _fallback(imports: tuple[Import, ...], imported: Import, target: str) -> bool:
    """True when another guarded import of the module names the same file by its bare name
    (``try: from target_types import X`` / ``except ImportError: from
    my_pkg.target_types import X``): one of the two always runs, so the module is needed."""
    stem = posixpath.basename(target).removesuffix(".py")
    return any(other is not imported and other.guarded and not other.level and
               other.module == stem for other in imports)


@per_package
def optional_modules(package: Package) -> frozenset[str]:
    """Paths of own modules imported only guarded, by installed code, and never an entry point.

    Empty when setup.py's modules are not known statically.
    """
    own = installed_modules(package)
    setup = package.setup_py
    if not own or setup is None or setup.is_unresolved("entry_points"):
        return frozenset()
    names = {path: name for name, path in own.items()}
    entries = {e.module for e in setup.entry_points or () if e.valid}
    tests = test_files(package)
    sites: dict[str, set[bool]] = {}
    for module in package.modules:
        if module.path not in names or module.path in tests:
            continue
        for imported in module.imports:
            for target in _targets(names[module.path], module.path, imported, own):
                if target != module.path:
                    sites.setdefault(target, set()).add(
                        imported.guarded and not _fallback(module.imports, imported, target))
    return frozenset(path for path, guards in sites.items()
                     if guards == {True} and names[path] not in entries)
