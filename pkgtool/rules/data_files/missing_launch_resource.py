"""DAT012: a launch file reads a file of its package's share folder that the package lacks."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import nodes_of_class, opens_to_write
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.submodules import ignored, under
from pkgtool.rules.data_files.common import (installed_descriptions, sibling_share_misses,
                                             uninstalled_launch_resources)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees, launch_trees


@rule("DAT012", "missing-launch-resource", Severity.ERROR,
      fix="Fix the path in the launch file, or add the file to the package and install it")
def missing_launch_resource(package: Package) -> Iterator[Hit]:
    """An installed launch file or module uses a share file of the package that does not exist.

    ## What it does
    For each launch file data_files installs, and each installed module that imports
    `ament_index_python`, looks at the paths it builds from this package's share folder
    (`get_package_share_directory('<pkg>')`, `FindPackageShare`, `$(find-pkg-share <pkg>)`
    joined with static parts, also as a word of an XML node's `args`) and reports those
    that data_files does not install and that are no file or folder of the package either:
    a misspelt name (`param.yaml` for `params.yaml`), a wrong folder, a file never committed.
    It suggests the closest path the package installs or has. A file the package has but
    does not install is DAT006's. In a launch file that sets a simulator's search path
    (`GZ_SIM_RESOURCE_PATH`, `GAZEBO_MODEL_PATH`, ...), folders (a last part with no
    suffix) are left alone, by both rules: they are entries of the path, which skips a
    missing one, not files read. Nor is a file whose name a `.gitignore` of the package or
    of the folders above it lists (a calibration or a map the user makes, kept out of git
    on purpose). Paths that are glob patterns (`config/*.yaml`) count when installed files
    match them, and a module that asks whether files or folders exist (`os.path.exists`,
    `os.path.isdir`, `Path.exists()`: it handles a missing one, as a model it downloads),
    and a module or Python launch file that makes folders (`os.makedirs`) or loads an
    optional `.env` file (`load_dotenv`) is left alone; a launch file asking whether a path
    exists is left alone for that path and those below it (for all when it asks of a path
    pkgtool cannot work out); so is a name with no suffix for which the package has a file
    with one (`worlds/arena` for `worlds/arena.sdf`), but not as a node's parameter file:
    code adds suffixes in ways not read statically (`'%s.urdf' % base`), and launch files
    pass world names on to ones that add the suffix; and so is a folder
    data_files installs into (setuptools makes it, files or not), and a file in a folder
    setup.py installs only when it exists (`glob('maps/*') if os.path.exists('maps') else
    []`: the user makes it).
    A path the code builds but never uses (the value of a local name never read, read only
    by nodes it never starts, or replaced before any use; of a module-level name nothing
    reads or imports; or stored in `self.x` that the module never reads) is not read
    either, nor is a file it opens to write (`open(path, 'w')`, `'a'`, `'x'`): the code
    makes it; nor a file of the name another installed module of the package opens to
    write (one node writes the state file another reads). A launch file included from the
    share folder of another ament_python package of the workspace, or a robot description,
    world or RViz file read from there (`.urdf`, `.xacro`, `.sdf`, `.srdf`, `.world`,
    `.rviz`: files installed as written, never made at run time as a map or a calibration
    may be), is reported when that package's setup.py installs no file of its name into its
    folder (its globs are matched by name: `launch/*.launch.py` never installs
    `launch/robot.launch.xml`).

    ## Why is this bad?
    Nothing can install a file the package does not have: `ros2 launch` fails on the missing
    parameter file, URDF or RViz configuration on every machine, or a node silently runs with
    its default parameters.

    ## Example
    ```python
    params = PathJoinSubstitution([FindPackageShare('my_pkg'), 'config', 'param.yaml'])
    # the package has config/params.yaml
    ```

    ## Use instead
    ```python
    params = PathJoinSubstitution([FindPackageShare('my_pkg'), 'config', 'params.yaml'])
    ```
    """
    share = f"share/{package.name}/"
    written = _written_names(package)
    for reader, ref, relative, installed in uninstalled_launch_resources(package):
        if package.has_file(relative) or package.has_folder(relative) or \
                under(relative, package.unfetched) or ignored(relative, package.ignores) or \
                _installed_when_present(package, relative) or \
                relative.rpartition("/")[2] in written:
            continue  # a file git ignores is the user's to make (a calibration, a map)
        known = {target[len(share):] for target in installed if target.startswith(share)}
        known.update(package.files)
        if _shell_word(package, reader, relative) in known:
            continue  # `cmd=['gz sim ', path_to('world.sdf '), ...], shell=True`: the shell
            # splits the joined line, and the space is no part of the name
        if _suffix_added(relative, known) and \
                (ref.package, ref.parts) not in _parameter_files(package, reader):
            continue  # a name the reader or the launch file it includes adds `.sdf` to
        close = get_close_matches(relative, sorted(known), n=1)
        hint = f" (did you mean `{close[0]}`?)" if close else ""
        yield Hit(ref.span, f"`{relative}` is no file of `{package.name}`: `{reader}` "
                            f"reads it from the share folder, where nothing installs it{hint}",
                  f"Write `{close[0]}`" if close else None)
    for reader, ref, relative in sibling_share_misses(package):
        if relative.rpartition("/")[2] in written:
            continue  # the package makes it there (a URDF expanded from a xacro file)
        sibling = package.context.workspace[ref.package or ""]
        present = relative in sibling.description_files  # the file is there, not installed
        close = [] if present else get_close_matches(
            relative, installed_descriptions(package, ref.package or ""), n=1)
        hint = f" (did you mean `{close[0]}`?)" if close else \
            f" (`{ref.package}` has the file)" if present else ""
        yield Hit(ref.span, f"`{relative}` is not installed by `{ref.package}`, a package of "
                            f"the workspace: `{reader}` reads it from its share folder, where "
                            f"its setup.py's data_files put no file of that name{hint}",
                  f"Write `{close[0]}`" if close else
                  f"Install `{relative}` with data_files in `{ref.package}`'s setup.py"
                  if present else
                  f"Fix the path, or install the file in `{ref.package}`'s setup.py")


def _shell_word(package: Package, reader: str, relative: str) -> str | None:
    """``relative`` without the spaces around its parts, when the reader runs commands
    through a shell (``shell=True``) and they hold spaces; else None."""
    stripped = "/".join(part.strip() for part in relative.split("/"))
    return stripped if stripped != relative and \
        "shell=True" in (package.texts.get(reader) or "") else None


def _suffix_added(relative: str, known: set[str]) -> bool:
    """True when ``relative`` has no suffix and a file of that name with one is known
    (``worlds/arena`` for ``worlds/arena.sdf``): code appends the suffix in ways not read
    statically (``[PathJoinSubstitution([...]), '.yaml']``, ``'%s.urdf' % base``), or the
    launch file it is passed to does (``[LaunchConfiguration('world'), '.sdf']``)."""
    return "." not in relative.rpartition("/")[2] and \
        any(k.startswith(relative + ".") and "/" not in k[len(relative):] for k in known)


def _parameter_files(package: Package, reader: str) -> set[tuple[str | None, tuple[str, ...]]]:
    """The share files (package, parts) the launch file ``reader`` gives a node as its
    parameters: paths rcl opens as they are."""
    return {(ref.package, ref.parts) for launch in package.launch_files if launch.path == reader
            for node in launch.nodes for ref in node.parameter_files}


@per_package
def _written_names(package: Package) -> frozenset[str]:
    """The file names the package's installed modules and Python launch files open to write
    (``open(share + '/state.ini', 'w')``; the last part of each text in the path given, or in
    what the name given is bound to in the module): one module may make the file another
    reads, a launch file the URDF it expands from a xacro file."""
    found: set[str] = set()
    trees = [tree for _, tree, _ in installed_trees(package)]
    for tree in [*trees, *(tree for _, tree, _ in launch_trees(package))]:
        values = {t.id: n.value for n in nodes_of_class(tree, ast.Assign) for t in n.targets
                  if isinstance(t, ast.Name)}
        for call in nodes_of_class(tree, ast.Call):
            if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and \
                    call.func.id == "open" and call.args and opens_to_write(call):
                path = call.args[0]
                path = values.get(path.id, path) if isinstance(path, ast.Name) else path
                found.update(n.value.rstrip("/").rpartition("/")[2] for n in ast.walk(path)
                             if isinstance(n, ast.Constant) and isinstance(n.value, str))
    return frozenset(found)


_EXISTENCE = lazy_pattern(r"\b(?:exists|isdir|is_dir)\(")


def _installed_when_present(package: Package, relative: str) -> bool:
    """True when a line of setup.py asks whether the top folder of ``relative`` exists
    (``glob('maps/*') if os.path.exists('maps') else []``): the folder is the user's to
    make (a map saved after a mapping run), installed when there."""
    folder = relative.split("/")[0]
    quoted = (f"'{folder}'", f'"{folder}"', f"'{folder}/", f'"{folder}/')
    return "/" in relative and any(
        _EXISTENCE.search(line) and any(q in line for q in quoted)
        for line in package.texts.get("setup.py", "").splitlines())
