"""The package an ``add`` works on: its model, an edit session, and what it is called."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from pkgtool.create import CreateError
from pkgtool.create.license_choice import choose_license
from pkgtool.create.options import Plan
from pkgtool.create.pysource import copyright_year
from pkgtool.edit.changes import Session
from pkgtool.edit.core import Edit, EditError
from pkgtool.model.package import Package, load_package


@dataclass
class Target:
    """An ament_python package being edited; ``notes`` collect what the user should know."""

    root: Path
    package: Package
    session: Session
    notes: list[str]

    @property
    def name(self) -> str:
        """The package name (package.xml's)."""
        return self.package.name

    def source_text(self, path: str) -> str | None:
        """The file's text as edited so far, or None."""
        source = self.session.source(path)
        return None if source is None else source.text

    def exists(self, path: str) -> bool:
        """True when ``path`` exists on disk or was created in this session."""
        return self.session.source(path) is not None

    def files(self) -> tuple[str, ...]:
        """The package's files, with those created in this session."""
        created = {p for p, s in self.session.current.items() if s is not None}
        return tuple(sorted(set(self.package.files) | created))

    def setup(self):  # type: ignore[no-untyped-def]
        """setup.py as edited so far, ready for the next edit."""
        from pkgtool.edit.setup_py import SetupDoc

        source = self.session.source("setup.py")
        assert source is not None
        return SetupDoc(source, self.files())

    def create(self, path: str, text: str) -> bool:
        """Add the file unless it exists (then it is kept, untouched); True when added."""
        if self.exists(path):
            self.notes.append(f"`{path}` exists: kept as it is.")
            return False
        self.session.apply([Edit(path, 0, 0, text, create=True)])
        return True

    def plan(self, *, year: int | None = None, **values: object) -> Plan:
        """A create :class:`Plan` carrying this package's name, license and maintainer."""
        manifest = self.package.manifest
        assert manifest is not None
        person = manifest.maintainers[0] if manifest.maintainers else None
        try:
            license_ = choose_license(manifest.licenses[0].value if manifest.licenses else "")
        except CreateError:  # none, or not one line: the headers say TODO
            license_ = choose_license("TODO")
        fields: dict[str, object] = dict(
            name=self.name, destination=self.root.parent, description="",
            license=license_.value, license_expression=license_.expression,
            maintainer_name=person.name if person else "", maintainer_email="",
            year=year or copyright_year(), package_format=manifest.format or 3, nodes=(),
            library_name=None, depends=(), exec_depends=(), test_depends=(), launch=False,
            config=False)
        fields.update(values)
        return Plan(**fields)  # type: ignore[arg-type]


def open_target(path: Path) -> Target:
    """Load the package at ``path``; EditError when it is not an ament_python package to edit."""
    from pkgtool.model.installed import is_ament_python

    if not path.is_dir():
        raise EditError(f"`{path}` is not a folder: give the package folder (default: the "
                        "current one).")
    if not (path / "package.xml").is_file() or not (path / "setup.py").is_file():
        raise EditError(f"`{path}` has no package.xml and setup.py: give the folder of an "
                        "ament_python package, or start one with `pkgtool create`.")
    package = load_package(path)
    broken = [p for p in package.problems if p.span.path in ("package.xml", "setup.py")]
    if broken or package.manifest is None or package.setup_py is None:
        where = f" ({broken[0].span.path}:{broken[0].span.line}: {broken[0].detail})" \
            if broken else ""
        raise EditError(f"package.xml or setup.py of `{path}` does not parse{where}: fix it "
                        "first (`pkgtool lint` says where).")
    if not is_ament_python(package):
        raise EditError(f"`{path}` is not an ament_python package: pkgtool adds to "
                        "ament_python packages only.")
    return Target(path, package, Session(path), [])
