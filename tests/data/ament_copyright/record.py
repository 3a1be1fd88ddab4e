"""Record what the real ament_copyright says about each file in ``cases/`` (run by hand).

ament_copyright has no PyPI wheel, so CI cannot run it; its verdicts are kept in
``verdicts.json`` and the tests compare pkgtool with them. To re-record, install ament_copyright
from its sources (ament/ament_lint, folder ament_copyright: ``pip install --no-deps
--no-build-isolation <that folder>`` in a venv with setuptools and wheel), then run this file
with that venv's Python. It asks ament_copyright's own parser, exactly as its command line does.
"""

import json
import sys
from importlib import metadata
from pathlib import Path

from ament_copyright.parser import parse_file  # only where ament_copyright is installed

HERE = Path(__file__).resolve().parent


def verdict(path: Path) -> dict[str, str]:
    """ament_copyright's finding for one source file (its `--verbose` line, as data)."""
    found = parse_file(str(path))
    if not found.copyright_identifiers:
        return {"error": "could not find copyright notice"}
    return {"copyright": ", ".join(str(c) for c in found.copyrights),
            "license": found.license_identifier}


def main() -> None:
    cases = sorted((HERE / "cases").glob("*.py"))
    data = {"ament_copyright": metadata.version("ament_copyright"),
            "verdicts": {case.name: verdict(case) for case in cases}}
    (HERE / "verdicts.json").write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    json.dump(data, sys.stdout, indent=1, sort_keys=True)


if __name__ == "__main__":
    main()
