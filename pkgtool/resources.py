"""Folders of data that ship with pkgtool: ``templates/``, ``reference_packages/``.

In the source tree they sit at the top level of the repository. A built wheel carries them as
``pkgtool/_resources/<name>/`` (copied there by ``setup.py``'s build step), so an installed
pkgtool finds them through :mod:`importlib.resources`; a source checkout or an editable install
falls back to the repository folder.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

RESOURCES = ("templates", "reference_packages")
"""The top-level folders shipped inside the package; ``setup.py`` reads this tuple."""


def resource_dir(name: str) -> Path:
    """The folder of the shipped resource ``name`` (one of :data:`RESOURCES`).

    Raises FileNotFoundError naming both places looked at when neither exists.
    """
    if name not in RESOURCES:
        raise ValueError(f"unknown resource {name!r}; known: {', '.join(RESOURCES)}")
    installed = resources.files("pkgtool") / "_resources" / name
    if isinstance(installed, Path) and installed.is_dir():
        return installed
    checkout = Path(__file__).resolve().parent.parent / name
    if checkout.is_dir():
        return checkout
    raise FileNotFoundError(
        f"pkgtool's {name}/ folder is missing (looked in {installed} and {checkout}). "
        "Reinstall pkgtool, or run it from a complete source checkout.")
