"""setup.py read with ``ast`` and an allow-list evaluator: nothing is imported or executed.

The evaluator understands string literals and concatenation, f-strings, module-level names,
``os.path.join``, ``glob``/``glob.glob``, pathlib globbing, list comprehensions over those, and
``find_packages``/``find_namespace_packages`` (simulated over the package's file list). Anything
else is recorded as :class:`Unresolved` with its line, and rules must not report from it.
"""

from __future__ import annotations

from pkgtool.model.span import ParseProblem, Span, Unresolved
from pkgtool.records import record


@record
class Value:
    """A keyword argument of ``setup()`` that evaluated statically (str, tuple, dict, ...)."""

    value: object
    span: Span


@record
class EntryPoint:
    """One ``name = module:attr`` line of an entry-point group (``valid`` False when malformed)."""

    group: str
    name: str
    module: str
    attr: str | None
    spec: str
    span: Span
    valid: bool


@record
class DataSource:
    """One source of a data_files entry: a path or glob pattern and the files it matches.

    ``matches`` are package-relative POSIX paths; for a plain path it is the path itself when
    the file exists, else empty.
    """

    pattern: str
    is_glob: bool
    matches: tuple[str, ...]
    span: Span


@record
class DataFile:
    """One ``(destination, [sources])`` entry of data_files."""

    destination: str
    sources: tuple[DataSource, ...]
    span: Span
    sources_is_text: bool = False
    """True when the sources were one string, which setuptools reads character by character."""


PACKAGE_DATA = ("package_data", "include_package_data")
"""setup() keywords that install other files into a Python package's folder."""


@record
class PackagesSpec:
    """How ``packages=`` was given and what it resolves to.

    ``kind`` is ``list``, ``find_packages`` or ``find_namespace_packages``; ``names`` are the
    resolved dotted package names, ``where``/``include``/``exclude`` the finder's arguments.
    """

    kind: str
    names: tuple[str, ...]
    span: Span
    where: str = "."
    include: tuple[str, ...] = ()
    exclude: tuple[str, ...] = ()


@record
class SetupPy:
    """What ``setup(...)`` in setup.py declares, as far as it evaluates statically.

    Each optional field is None when the keyword is absent; a keyword present but not
    evaluable is listed in ``unresolved`` (keyed by keyword) and its field stays None
    (``data_files_in_part`` keeps what could be read of ``data_files``).
    """

    path: str
    setup_span: Span | None
    keywords: tuple[str, ...]
    name: Value | None
    version: Value | None
    description: Value | None
    license: Value | None
    maintainer: Value | None
    maintainer_email: Value | None
    packages: PackagesSpec | None
    package_dir: dict[str, str] | None
    py_modules: tuple[str, ...] | None
    data_files: tuple[DataFile, ...] | None
    entry_points: tuple[EntryPoint, ...] | None
    tests_require: Value | None
    extras_require: Value | None
    install_requires: Value | None
    unresolved: tuple[tuple[str, Unresolved], ...] = ()
    scripts: tuple[str, ...] | None = None
    data_files_in_part: tuple[DataFile, ...] = ()
    """When ``data_files`` is a list not every item of which evaluates, the entries that do
    (each entry's own checks hold for them; what the package installs is still unknown)."""
    commands: tuple[str, ...] | None = None
    """The setuptools commands ``cmdclass`` replaces when it is a dict display (``build_py``
    for ``{'build_py': BuildPy}``); None without one, or when it is another expression."""
    acting_commands: tuple[str, ...] = ()
    """Those of :attr:`commands` whose replacement may run programs or write files (a class
    setup.py does not define, or one calling ``subprocess``, ``open``, ``shutil``, ...)."""

    def is_unresolved(self, keyword: str) -> bool:
        """True when ``keyword`` was given but could not be evaluated."""
        return any(key == keyword for key, _ in self.unresolved)

    @property
    def data_file_entries(self) -> tuple[DataFile, ...]:
        """The ``data_files`` entries known, each on its own: all of them, or those
        :attr:`data_files_in_part` keeps."""
        return self.data_files if self.data_files is not None else self.data_files_in_part

    @property
    def console_scripts(self) -> tuple[EntryPoint, ...]:
        """Entry points of the ``console_scripts`` group."""
        return tuple(e for e in self.entry_points or () if e.group == "console_scripts")


def parse_setup_py(path: str, text: str, files: tuple[str, ...] | None
                   ) -> SetupPy | ParseProblem:
    """Read setup.py ``text``; ``files`` (the package's file list) resolves globs and finders
    (None: they are not evaluated, see :func:`~pkgtool.model.setup_eval.evaluate`)."""
    from pkgtool.model.setup_eval import read_setup

    return read_setup(path, text, files)
