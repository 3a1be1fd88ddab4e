"""Repair the ROS wheels' exported CMake files so that rosidl interface packages build.

The wheels were built in a manylinux image, and their exported CMake files name that image's
Python and NumPy include folders. CMake refuses non-existent include paths, so after every
install we point those strings at this interpreter's folders. Idempotent.
"""

from __future__ import annotations

import sys
import sysconfig
from pathlib import Path
from pkgtool.lazy_regex import lazy_pattern

_BUILD_PYTHON_INCLUDE = lazy_pattern(r"/opt/python/cp3\d+-cp3\d+/include/python3\.\d+")
_BUILD_NUMPY_INCLUDE = lazy_pattern(
    r"/opt/python/cp3\d+-cp3\d+/lib/python3\.\d+/site-packages/numpy/(?:_)?core/include"
)


def _numpy_include() -> str | None:
    try:
        import numpy
    except ImportError:
        return None
    return str(numpy.get_include())


def fix_cmake_exports(prefix: Path) -> list[Path]:
    """Rewrite the build machine's include folders in ``prefix/share/*/cmake``; list changes."""
    python_include = sysconfig.get_paths()["include"]
    numpy_include = _numpy_include()
    changed = []
    for cmake_file in sorted(prefix.glob("share/*/cmake/*.cmake")):
        text = cmake_file.read_text(encoding="utf-8", errors="surrogateescape")
        new = _BUILD_PYTHON_INCLUDE.sub(python_include, text)
        if numpy_include:
            new = _BUILD_NUMPY_INCLUDE.sub(numpy_include, new)
        if new != text:
            cmake_file.write_text(new, encoding="utf-8", errors="surrogateescape")
            changed.append(cmake_file)
    return changed


def main(argv: list[str] | None = None) -> int:
    """Fix the CMake exports of the virtual environment given as the only argument."""
    args = sys.argv[1:] if argv is None else argv
    prefix = Path(args[0]) if args else Path(sys.prefix)
    changed = fix_cmake_exports(prefix)
    print(f"wheel_fixups: rewrote include paths in {len(changed)} CMake file(s)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
