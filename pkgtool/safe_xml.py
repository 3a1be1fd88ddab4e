"""The one lxml parser configuration for XML pkgtool did not write, and the one XML escaper.

The parser reads package files and test reports: entities are never resolved, no DTD is
loaded, nothing is fetched from the network, and lxml's limits for huge documents stay on.
"""

from __future__ import annotations

from typing import Any


def parser() -> Any:
    """A new lxml ``XMLParser`` with those settings (lxml is imported only when called)."""
    from lxml import etree

    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           huge_tree=False, dtd_validation=False, remove_comments=False)


def xml_text(value: str) -> str:
    """``value`` escaped for XML text or a double-quoted attribute."""
    # not xml.sax.saxutils.escape: importing it pulls in urllib (20 ms of a 0.1 s command)
    return (value.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;"))
