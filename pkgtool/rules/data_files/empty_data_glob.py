"""DAT002: a data_files glob that matches nothing."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.setup_eval.tree import normalize
from pkgtool.model.submodules import ignored, under
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("DAT002", "empty-data-glob", Severity.WARNING,
      fix="Fix the pattern (relative to setup.py) or add the files it should match")
def empty_data_glob(package: Package) -> Iterator[Hit]:
    """A glob in data_files matches no file.

    ## What it does
    Evaluates `glob(...)`, `glob.glob(...)` and `Path(...).glob/rglob(...)` used in data_files
    against the package's files and reports patterns that match nothing, unless git ignores
    what they would match (a `.gitignore` of the package or above it lists those files or
    their folder: models or maps a script downloads are left out of git on purpose).

    ## Why is this bad?
    The build succeeds and installs nothing for that entry: a launch or config folder that
    "should" be installed is silently missing, and `ros2 launch` or the node fails later.
    Common causes are a wrong folder name, `*.launch.py` for files named `*_launch.py`, or
    `.yml` versus `.yaml`.

    ## Example
    ```python
    (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py'))
    # the folder holds launch/robot_launch.py
    ```

    ## Use instead
    ```python
    (os.path.join('share', package_name, 'launch'), glob('launch/*launch.*'))
    ```
    """
    setup = checked_setup(package)
    for entry in setup.data_file_entries if setup else ():
        for source in entry.sources:
            written = normalize(source.pattern) or ""
            if source.is_glob and not source.matches and \
                    not under(written, package.unfetched) and \
                    not ignored(written, package.ignores):  # files git leaves out on purpose
                yield Hit(source.span, f"The glob `{source.pattern}` matches no file: nothing "
                                       f"is installed to `{entry.destination}` from it")
