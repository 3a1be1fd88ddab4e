"""What ``--license`` may be: a license pkgtool ships, any SPDX expression, or free text.

Like ``ros2 pkg create``, any string is taken; a ``LICENSE`` file is written only for the
licenses whose text ships (:data:`~pkgtool.create.licenses.LICENSES`), and the others come with
a warning. ``--license ?`` lists what ships.
"""

from __future__ import annotations

from pkgtool.create import CreateError
from pkgtool.create.headers import license_ref
from pkgtool.create.licenses import LICENSES
from pkgtool.create.spdx import canonical
from pkgtool.records import record

AMENT_SPELLINGS = {"BSD-2.0": "BSD-3-Clause"}
"""ament_copyright's identifiers that are not SPDX ones -> the SPDX id of the same text.

ament's "BSD License 2.0" (``BSD-2.0``, offered by ``ros2 pkg create``) is the 3-clause text."""
_NAMES = {"Apache-2.0": "Apache License 2.0", "BSL-1.0": "Boost Software License 1.0",
          "BSD-2-Clause": "BSD 2-Clause \"Simplified\" License",
          "BSD-3-Clause": "BSD 3-Clause \"New\" or \"Revised\" License", "MIT": "MIT License",
          "MIT-0": "MIT No Attribution", "GPL-3.0-only": "GNU General Public License v3.0 only",
          "LGPL-3.0-only": "GNU Lesser General Public License v3.0 only"}
_LIMIT = 100


@record
class LicenseChoice:
    """The license as package.xml says it, as the headers' SPDX expression, and warnings."""

    value: str
    expression: str
    warnings: tuple[str, ...] = ()

    @property
    def shipped(self) -> bool:
        """True when pkgtool has the LICENSE text and the ament_copyright header for it."""
        return self.value in LICENSES


def choose_license(text: str) -> LicenseChoice:
    """Read ``--license``; CreateError only for an empty or multi-line value."""
    value = text.strip()
    if not value or len(value) > _LIMIT or any(ord(c) < 32 for c in value):
        raise CreateError(f"Invalid license {text!r}: give an SPDX id or expression "
                          f"(`--license ?` lists those that ship a text), or one line of up to "
                          f"{_LIMIT} characters.")
    shipped = {spdx.lower(): spdx for spdx in LICENSES}
    shipped.update({alias.lower(): spdx for alias, spdx in AMENT_SPELLINGS.items()})
    if value.lower() in shipped:
        spdx = shipped[value.lower()]
        renamed = () if spdx.lower() == value.lower() else (
            f"`{value}` is ament_copyright's name for the `{spdx}` license text; package.xml "
            f"gets the SPDX id `{spdx}`.",)
        return LicenseChoice(spdx, spdx, renamed)
    missing = (f"No LICENSE text ships for `{{}}`: add the license text as `LICENSE` yourself "
               f"(`--license ?` lists the {len(LICENSES)} that ship).")
    expression = canonical(value)
    if expression is not None:
        return LicenseChoice(expression, expression, (missing.format(expression),))
    return LicenseChoice(value, license_ref(value), (
        f"`{value}` is not an SPDX license expression{_guess(value)}: package.xml keeps it as "
        f"written and the file headers say `SPDX-License-Identifier: {license_ref(value)}`. "
        + missing.format(value),))


def _guess(value: str) -> str:
    from pkgtool.knowledge.licenses import spdx_ids_for

    ids = spdx_ids_for(value)
    return f" (did you mean `{'` or `'.join(ids)}`?)" if ids else ""


def listing() -> str:
    """The text of ``--license ?``."""
    width = max(map(len, LICENSES))
    lines = ["Licenses whose LICENSE text and ament_copyright header ship with pkgtool:"]
    lines += [f"  {spdx:<{width}}  {_NAMES[spdx]}" for spdx in LICENSES]
    lines += [f"  {alias:<{width}}  ament_copyright's name for {spdx}"
              for alias, spdx in AMENT_SPELLINGS.items()]
    lines.append("Any other SPDX id or expression (`GPL-2.0-or-later`, `Apache-2.0 OR MIT`) or "
                 "free text (`Proprietary`) is accepted with a warning: add its LICENSE file "
                 "yourself.")
    return "\n".join(lines) + "\n"
