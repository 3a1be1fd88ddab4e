"""Copyright notice and license header recognition (ament_copyright's rules plus SPDX)."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.knowledge.licenses import spdx_ids_for
from pkgtool.style.api import copyright_errors
from pkgtool.ament.copyright import read_header
from tests.helpers import MINIMAL_MANIFEST, write_tree

APACHE = """# Copyright 2015 Open Source Robotics Foundation, Inc.
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
"""
BSD3 = """# Copyright (c) 2020, 2021-2023 Someone
# Redistribution and use in source and binary forms, with or without
# modification, are permitted provided that the following conditions are met:
# * Neither the name of the copyright holder nor the names of its contributors
"""
BSD2 = """# Copyright 2020 Someone
# Redistribution and use in source and binary forms, with or without
# modification, are permitted provided that the following conditions are met:
"""
MIT = """# Copyright 2024 Someone
# Permission is hereby granted, free of charge, to any person obtaining a copy
# The above copyright notice and this permission notice shall be included in all
"""


@pytest.mark.parametrize(("text", "license_"), [
    (APACHE, "Apache-2.0"), (BSD3, "BSD-3-Clause"), (BSD2, "BSD-2-Clause"), (MIT, "MIT"),
    ("#!/usr/bin/env python3\n# Copyright 2026 Ada\n# SPDX-License-Identifier: BSL-1.0\n",
     "BSL-1.0"),
    ("# Copyright 2026 Ada\n# This program is free software: GNU General Public License,\n"
     "# either version 3 of the License\n", "GPL-3.0-only"),
    ("# Copyright 2026 Ada\n# GNU Lesser General Public License version 3\n", "LGPL-3.0-only"),
])
def test_license_is_recognised(text: str, license_: str) -> None:
    header = read_header(text + "x = 1\n")
    assert header.copyright_line is not None
    assert header.license == license_


def test_no_notice_and_notice_without_license() -> None:
    assert read_header("x = 1\n# copyright is nice\n").copyright_line is None
    header = read_header("# Copyright 2026 Ada\nx = 1\n")
    assert header.copyright_line == 1 and header.license is None


@pytest.mark.parametrize(("value", "ids"), [
    ("Apache License 2.0", ("Apache-2.0",)), ("Apache-2.0", ("Apache-2.0",)),
    ("BSD", ("BSD-2-Clause", "BSD-3-Clause")), ("GPLv3", ("GPL-3.0-only",)),
    ("Proprietary", ()),
])
def test_package_xml_license_spellings(value: str, ids: tuple[str, ...]) -> None:
    assert spdx_ids_for(value) == ids


def test_api_reports_headers_in_a_package(tmp_path: Path) -> None:
    write_tree(tmp_path, {
        "package.xml": MINIMAL_MANIFEST.format(name="demo"),
        "setup.py": "from setuptools import setup\nsetup(name='demo')\n",
        "demo/__init__.py": "",
        "demo/good.py": "# Copyright 2026 Dev\n# SPDX-License-Identifier: Apache-2.0\nx = 1\n",
        "demo/bare.py": "x = 1\n",
        "demo/mit.py": "# Copyright 2026 Dev\n# SPDX-License-Identifier: MIT\nx = 1\n",
        "_private/skipped.py": "x = 1\n",
    })
    errors = copyright_errors(tmp_path)
    assert [e.split(":")[0] for e in errors] == ["demo/bare.py", "demo/mit.py"]
    assert "CPY001" in errors[0] and "CPY003" in errors[1]
