"""The one lxml parser configuration for XML pkgtool did not write (package files, test reports).

Entities are never resolved, no DTD is loaded, nothing is fetched from the network, and lxml's
limits for huge documents stay on.
"""

from __future__ import annotations

from typing import Any


def parser() -> Any:
    """A new lxml ``XMLParser`` with those settings (lxml is imported only when called)."""
    from lxml import etree

    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           huge_tree=False, dtd_validation=False, remove_comments=False)
