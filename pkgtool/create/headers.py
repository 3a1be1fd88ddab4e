"""The comment every generated source file opens with: copyright line and license header.

``test_copyright.py`` runs ament_copyright where it is installed. It takes the first block of
``#`` lines, finds ``Copyright <years> <holder>`` and then wants the header text of one license
it knows, compared word by word with whitespace ignored; an ``SPDX-License-Identifier`` line
alone leaves the license ``<unknown>``. So for the licenses pkgtool ships a text of, the header
is that license's own notice, taken from the vendored SPDX text (:data:`_PASSAGES`), in the words
ament_copyright expects. Any other license gets the SPDX line, which pkgtool's check reads.
"""

from __future__ import annotations

import re
import textwrap

from pkgtool.create.licenses import LICENSES, licenses_dir
from pkgtool.lazy_regex import lazy_pattern

_PASSAGES = {
    "Apache-2.0": ("Licensed under the Apache License", "limitations under the License."),
    "BSL-1.0": ("Boost Software License", "DEALINGS IN THE SOFTWARE."),
    "MIT": ("Permission is hereby granted", "DEALINGS IN THE SOFTWARE."),
    "MIT-0": ("Permission is hereby granted", "DEALINGS IN THE SOFTWARE."),
    "GPL-3.0-only": ("This program is free software", "<https://www.gnu.org/licenses/>."),
    "BSD-3-Clause": ("Redistribution and use", "POSSIBILITY OF SUCH DAMAGE."),
    "BSD-2-Clause": ("Redistribution and use", "POSSIBILITY OF SUCH DAMAGE."),
}
"""SPDX id -> first and last words of its notice in the license text."""
# The LGPL has no notice of its own: it asks for the GPL's, naming the Lesser GPL instead.
_LESSER = ("LGPL-3.0-only", "GPL-3.0-only", "GNU General Public License",
           "GNU Lesser General Public License")
# ament_copyright's header of the 2-clause BSD license opens with these two paragraphs.
_PREAMBLE = {"BSD-2-Clause": ("All rights reserved.",
                              "Software License Agreement (BSD 2-Clause Simplified License)")}
_ITEM = lazy_pattern(r"^\d+\.\s+")
_WIDTH = 77  # text width of a wrapped paragraph, as in ament's own headers
_KEEP = 95  # a paragraph whose lines all fit this stays as the license text breaks it


def notice(spdx_id: str) -> str:
    """The license notice of ``spdx_id`` (one of :data:`LICENSES`) as plain text paragraphs."""
    if spdx_id == _LESSER[0]:
        return notice(_LESSER[1]).replace(_LESSER[2], _LESSER[3])
    if spdx_id not in _PASSAGES:
        raise ValueError(f"no header for license {spdx_id!r}; known: {', '.join(LICENSES)}")
    text = (licenses_dir() / f"{spdx_id}.txt").read_text(encoding="utf-8")
    first, last = _PASSAGES[spdx_id]
    start = text.index(first)
    passage = text[start:text.index(last, start) + len(last)]
    paragraphs = [*_PREAMBLE.get(spdx_id, ()), *re.split(r"\n\s*\n", passage)]
    return "\n\n".join(_layout(p) for p in paragraphs) + "\n"


def _layout(paragraph: str) -> str:
    lines = [line.strip() for line in paragraph.strip().splitlines()]
    if _ITEM.match(lines[0]):  # "1. Redistributions ..." -> " * Redistributions ..."
        return textwrap.fill(_ITEM.sub("", " ".join(lines)), _WIDTH, initial_indent=" * ",
                             subsequent_indent="   ")
    if all(len(line) <= _KEEP for line in lines):
        return "\n".join(lines)
    return textwrap.fill(" ".join(lines), _WIDTH)


def header(*, year: int, holder: str, license_: str, expression: str,
           spdx_line: bool = False) -> str:
    """The ``#`` comment block for a file of a package licensed ``license_``.

    ``expression`` is the license as an SPDX expression (``LicenseRef-Proprietary`` for free
    text). A shipped license gets its notice, preceded by the SPDX line when ``spdx_line``;
    any other gets the SPDX line alone.
    """
    lines = [f"Copyright {year} {holder}"]
    if license_ not in LICENSES or spdx_line:
        lines.append(f"SPDX-License-Identifier: {expression}")
    if license_ in LICENSES:
        lines += ["", *notice(license_).splitlines()]
    return "".join(f"# {line}\n" if line else "#\n" for line in lines)


def license_ref(text: str) -> str:
    """``Proprietary`` -> ``LicenseRef-Proprietary``: free text as an SPDX user-defined id."""
    return "LicenseRef-" + (re.sub(r"[^A-Za-z0-9.]+", "-", text).strip("-") or "Custom")
