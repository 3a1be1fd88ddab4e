"""Pillow names that Pillow 10.0 (July 2023) removed, and what to write instead.

From Pillow's 10.0.0 release notes ("Removed features"): the resampling constants
``Image.ANTIALIAS``, ``Image.LINEAR`` and ``Image.CUBIC`` (deprecated since 9.1; the
``Image.Resampling`` members and the plain ``Image.LANCZOS``, ``Image.BILINEAR`` and
``Image.BICUBIC`` stay), ``ImageDraw.textsize()`` and ``multiline_textsize()``, and the
fonts' ``getsize()``, ``getsize_multiline()`` and ``getoffset()``. Ubuntu 22.04 (Humble)
ships Pillow 9.0.1, Ubuntu 24.04 (Jazzy, Kilted, and Rolling as
:mod:`pkgtool.knowledge.numpy_removed` has it) 10.2.
"""

from __future__ import annotations

REMOVED_CONSTANTS = {"ANTIALIAS": "Image.LANCZOS", "LINEAR": "Image.BILINEAR",
                     "CUBIC": "Image.BICUBIC"}
"""Constants of ``PIL.Image`` -> the name to use."""
REMOVED_DRAW_METHODS = {"textsize": "`draw.textbbox((0, 0), text, font=font)` (right - left, "
                                    "bottom - top) or `draw.textlength(text, font=font)`",
                        "multiline_textsize": "`draw.multiline_textbbox((0, 0), text, "
                                              "font=font)`"}
"""Methods of an ``ImageDraw.Draw`` -> what to call."""
REMOVED_FONT_METHODS = {"getsize": "`font.getbbox(text)` or `font.getlength(text)`",
                        "getsize_multiline": "`ImageDraw.Draw(image).multiline_textbbox((0, 0), "
                                             "text, font=font)`",
                        "getoffset": "`font.getbbox(text)[:2]`"}
"""Methods of a font (``ImageFont.truetype()``, ``load_default()``) -> what to call."""
FONT_MAKERS = frozenset({"PIL.ImageFont.truetype", "PIL.ImageFont.load_default",
                         "PIL.ImageFont.load", "PIL.ImageFont.FreeTypeFont",
                         "PIL.ImageFont.TransposedFont"})
DRAW_MAKERS = frozenset({"PIL.ImageDraw.Draw", "PIL.ImageDraw2.Draw"})
"""Calls that make a drawing context."""
"""Calls that make a font."""
SYSTEM_PILLOW = {"humble": "9.0", "jazzy": "10.2", "kilted": "10.2", "rolling": "10.2"}
"""The Pillow (python3-pil) of the Ubuntu release each ROS 2 distribution targets."""
