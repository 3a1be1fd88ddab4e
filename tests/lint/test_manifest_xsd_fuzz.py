"""Random documents and URLs: pkgtool's schema rules and the official XSDs agree.

Seeded, so failures reproduce. The documents start valid for a random format and get zero to
two edits (drop, duplicate, move, or insert an element of another format or with a bad value).
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from lxml import etree

from pkgtool.rules.manifest.schema import valid_any_uri
from tests.lint.test_manifest_xsd_oracle import EXPORT, doc, pkgtool_accepts, xsd_accepts

pytestmark = pytest.mark.oracle

_CANONICAL = [
    "<name>demo_pkg</name>", "<version>1.2.3</version>", "<description>d</description>",
    '<maintainer email="ada@example.com">Ada</maintainer>',
    '<maintainer email="bo@example.com">Bo</maintainer>', "<license>MIT</license>",
    "<license>BSD-3-Clause</license>", '<url type="repository">https://github.com/a/b</url>',
    "<url>https://example.com</url>", "<author>Grace</author>", "<author>Alan</author>",
    "<buildtool_depend>ament_cmake</buildtool_depend>", "<build_depend>std_msgs</build_depend>",
    "<DEPEND>rclpy</DEPEND>", "<test_depend>python3-pytest</test_depend>",
    "<conflict>old_pkg</conflict>", "<GROUPS>", EXPORT,
]
_FOREIGN = [
    "<run_depend>rospy</run_depend>", "<exec_depend>numpy_msgs</exec_depend>",
    '<exec_depend condition="$ROS_VERSION == 2">nav_msgs</exec_depend>',
    "<group_depend>plugins</group_depend>", "<member_of_group>tools</member_of_group>",
    '<license file="L">BSD-3-Clause</license>', "<unknown_tag/>",
    '<depend version_gte="1.0">rclpy</depend>', '<url type="home">https://x.org</url>',
]


def _mutant(rng: random.Random) -> str:
    """A valid document of a random format, then zero to two random edits."""
    fmt = rng.choice([None, "1", "2", "3", "3"])
    depend = "run_depend" if fmt in (None, "1") else "exec_depend"
    groups = ["<group_depend>plugins</group_depend>",
              "<member_of_group>tools</member_of_group>"] if fmt == "3" else []
    elements = []
    for element in _CANONICAL:
        elements += groups if element == "<GROUPS>" else [element.replace("DEPEND", depend)]
    for _ in range(rng.choice([0, 0, 1, 1, 2])):
        operation, index = rng.random(), rng.randrange(len(elements))
        if operation < 0.25:
            elements.pop(index)
        elif operation < 0.45:
            elements.insert(rng.randrange(len(elements) + 1), elements[index])
        elif operation < 0.75:
            elements.insert(rng.randrange(len(elements) + 1), elements.pop(index))
        else:
            elements.insert(rng.randrange(len(elements) + 1), rng.choice(_FOREIGN))
    return doc("\n  ".join(elements), fmt=fmt, head="")


def test_random_documents_agree_with_xsd(tmp_path: Path) -> None:
    rng = random.Random(149)
    disagreements = []
    for number in range(400):
        xml = _mutant(rng)
        if xsd_accepts(xml) != pkgtool_accepts(tmp_path / str(number), xml):
            disagreements.append(xml)
    assert disagreements == []


def test_url_checks_agree_with_xsd_any_uri() -> None:
    schema = etree.XMLSchema(etree.XML(
        b'<xs:schema xmlns:xs="http://www.w3.org/2001/XMLSchema">'
        b'<xs:element name="u" type="xs:anyURI"/></xs:schema>'))
    rng = random.Random(3986)
    alphabet = "ab1:/?#[]@%2F.-_~!$&'()*+,; = \u00e9\\{"
    starts = ["", "http:", "http://", "//", "x://u@", "http://[", "git@h:"]
    for _ in range(3000):
        url = rng.choice(starts) + "".join(rng.choice(alphabet)
                                           for _ in range(rng.randint(0, 12)))
        element = etree.Element("u")
        element.text = url
        assert valid_any_uri(url) is schema.validate(element), url
