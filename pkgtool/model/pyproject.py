"""What a package's pyproject.toml adds to what setuptools installs."""

from __future__ import annotations


def pyproject_may_add_scripts(text: str | None) -> bool:
    """True when a pyproject.toml's text may declare executables setuptools installs: a
    ``[project]`` table with ``scripts``, ``gui-scripts`` or ``entry-points`` (or naming them
    ``dynamic``), or a file that does not parse. A file of tool settings only
    (``[tool.pyright]``, ``[tool.black]``) adds none."""
    if text is None:
        return False
    from pkgtool.compat import tomllib

    try:
        project = tomllib.loads(text).get("project")
    except tomllib.TOMLDecodeError:
        return True
    if not isinstance(project, dict):
        return project is not None
    dynamic = project.get("dynamic") or []
    return any(key in project or isinstance(dynamic, list) and key in dynamic
               for key in ("scripts", "gui-scripts", "entry-points"))
