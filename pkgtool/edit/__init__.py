"""Source-preserving edits of package files, and the atomic writer that applies them.

An edit replaces one span of one file's text; every byte outside the spans stays as it was.
Editors (:mod:`.manifest`, :mod:`.setup_py`, :mod:`.setup_cfg`, :mod:`.launch`, :mod:`.params`)
compute edits from a file's text without touching the disk; :mod:`.changes` turns edits into
whole-file changes (a diff, or an all-or-nothing atomic write).
"""

from pkgtool.edit.core import Edit, EditError, Fix, apply_edits, conflicts, select_fixes

__all__ = ["Edit", "EditError", "Fix", "apply_edits", "conflicts", "select_fixes"]
