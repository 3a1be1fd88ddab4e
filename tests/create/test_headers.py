"""Generated headers are the ones stock ament_copyright accepts; pkgtool's check agrees with it.

The verdicts in ``tests/data/ament_copyright`` were recorded from the real ament_copyright
(see its README.md): CI cannot install it, so these tests compare against that record.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pkgtool.create.headers import header
from pkgtool.create.licenses import LICENSES
from pkgtool.ament.copyright import read_header

DATA = Path(__file__).resolve().parents[1] / "data" / "ament_copyright"
VERDICTS = json.loads((DATA / "verdicts.json").read_text())["verdicts"]
AMENT_NAMES = {"apache2": "Apache-2.0", "boost1": "BSL-1.0", "bsd_2clause": "BSD-2-Clause",
               "bsd_3clause": "BSD-3-Clause", "mit": "MIT", "mit0": "MIT-0",
               "gplv3": "GPL-3.0-only", "lgplv3": "LGPL-3.0-only"}
"""ament_copyright's license names -> SPDX ids (its licenses.py gives each an SPDX id)."""
BODY = '\n"""A module."""\n'
LENIENT = {
    "apache_first_sentence_only.py": "pkgtool knows a license by its key phrases",
    "mit_paragraphs_swapped.py": "pkgtool does not check the order of the paragraphs",
}
"""Where pkgtool accepts what ament_copyright rejects: it wants the whole text, in order. The
reverse, pkgtool rejecting a header ament accepts, would be a false error: never listed here."""


def _case(spdx_id: str, spdx_line: bool) -> str:
    stem = spdx_id.lower().replace("-", "_").replace(".", "_")
    return stem + ("_spdx_line" if spdx_line else "") + ".py"


@pytest.mark.parametrize("spdx_line", [False, True])
@pytest.mark.parametrize("spdx_id", LICENSES)
def test_every_generated_header_is_a_case_ament_copyright_accepted(spdx_id: str,
                                                                   spdx_line: bool) -> None:
    name = _case(spdx_id, spdx_line)
    written = header(year=2026, holder="Jane Doe", license_=spdx_id, expression=spdx_id,
                     spdx_line=spdx_line)
    assert written + BODY == (DATA / "cases" / name).read_text(), (
        "the header changed: re-record tests/data/ament_copyright with the real ament_copyright")
    assert VERDICTS[name] == {"copyright": "Jane Doe (2026)",
                              "license": next(k for k, v in AMENT_NAMES.items() if v == spdx_id)}


@pytest.mark.parametrize("case", sorted(VERDICTS))
def test_pkgtool_check_agrees_with_ament_copyright(case: str) -> None:
    """Same notice and license where ament accepts; pkgtool differs only by reading SPDX lines."""
    text = (DATA / "cases" / case).read_text()
    found, verdict = read_header(text), VERDICTS[case]
    assert (found.copyright_line is not None) == ("copyright" in verdict)
    if verdict.get("license", "<unknown>") != "<unknown>":
        assert found.license == AMENT_NAMES[verdict["license"]]
    elif "SPDX-License-Identifier" in text:
        assert found.license is not None  # pkgtool's deliberate extra: it reads the SPDX line
    else:
        assert (found.license is None) != (case in LENIENT), LENIENT.get(case, case)


def test_other_licenses_get_the_spdx_line_alone() -> None:
    assert header(year=2026, holder="Jane Doe", license_="Proprietary",
                  expression="LicenseRef-Proprietary") == (
        "# Copyright 2026 Jane Doe\n# SPDX-License-Identifier: LicenseRef-Proprietary\n")
