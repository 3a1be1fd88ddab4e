"""MAN008: a ``<url>`` with a ``type`` the schema does not define, or a malformed URL."""

from __future__ import annotations

import difflib
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.manifest.schema import URL_TYPES, token, valid_any_uri
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern


_SCP_LIKE = lazy_pattern(r"[\w.-]+@(?P<host>[\w.-]+):(?P<path>[^/].*)")
"""git's scp-like address ``git@host:owner/repo.git``, which is not a URI."""
_SYNONYMS = {
    **dict.fromkeys(("source", "code", "git", "github", "repo", "vcs", "scm"), "repository"),
    **dict.fromkeys(("issues", "issue", "bugs", "bug", "tracker", "issue_tracker"), "bugtracker"),
    **dict.fromkeys(("homepage", "home", "docs", "documentation", "wiki", "web"), "website"),
}


def _suggested_type(kind: str) -> str | None:
    key = token(kind).lower()
    close = difflib.get_close_matches(key, URL_TYPES, n=1, cutoff=0.6)
    return _SYNONYMS.get(key) or (close[0] if close else None)


def _url_fix(url: str) -> str:
    scp = _SCP_LIKE.fullmatch(url)
    if scp:
        return f"Write `https://{scp['host']}/{scp['path']}` or `ssh://{url.replace(':', '/', 1)}`"
    return "Write an absolute URL such as `https://github.com/owner/repo`; escape `%` as `%25`"


@rule("MAN008", "invalid-url", Severity.ERROR,
      fix="Use `type=\"website\"`, `type=\"bugtracker\"` or `type=\"repository\"`")
def invalid_url(package: Package) -> Iterator[Hit]:
    """A ``<url>`` has a ``type`` the schema does not know, or is not a valid URI.

    ## What it does
    Checks ``type`` against the three values of the schema (it defaults to ``website``) and the
    URL against RFC 3986, as XSD validation of ``xs:anyURI`` does (bad ``%`` escapes, a colon
    in the first segment of a relative reference, as in git's ``git@host:owner/repo``, two
    ``#``...).

    ## Why is this bad?
    The schema rejects the manifest; index.ros.org and rosdistro use ``type`` to link the
    repository and the issue tracker, and ignore other values.

    ## Example
    ```xml
    <url type="source">https://github.com/ada/my_pkg</url>
    <url type="issues">https://github.com/ada/my_pkg/issues</url>
    ```

    ## Use instead
    ```xml
    <url type="repository">https://github.com/ada/my_pkg</url>
    <url type="bugtracker">https://github.com/ada/my_pkg/issues</url>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in found.named("url"):
        kind = element.attribute("type")
        if kind is not None and token(kind) not in URL_TYPES:
            suggestion = _suggested_type(kind)
            known = ", ".join(f"`{t}`" for t in URL_TYPES)
            yield Hit(element.span, f"URL type `{kind}` is not one of {known}",
                      f'Write `type="{suggestion}"`' if suggestion else None)
        if not element.children and not valid_any_uri(element.text):
            yield Hit(element.span, f"`{element.text}` is not a valid URL", _url_fix(element.text))
