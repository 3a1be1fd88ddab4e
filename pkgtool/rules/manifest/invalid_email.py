"""MAN007: a maintainer without an email, or a maintainer or author email that is not valid."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.manifest.schema import EMAIL, token
from pkgtool.rules.registry import rule


def _check(element: XmlElement) -> Hit | None:
    who = f"{element.tag} `{element.text}`" if element.text else element.tag
    email = element.attribute("email")
    if email is None:
        if element.tag == "maintainer":
            return Hit(element.span, f"{who[0].upper()}{who[1:]} has no `email` attribute",
                       'Add `email="you@example.com"` to `<maintainer>`')
        return None
    if EMAIL.fullmatch(email):
        return None
    if EMAIL.fullmatch(token(email)):
        return Hit(element.span, f"Email `{email}` of {who} has spaces around it",
                   f'Write `email="{token(email)}"`')
    return Hit(element.span, f"Email `{email}` of {who} is not a valid address")


@rule("MAN007", "invalid-email", Severity.ERROR,
      fix="Give a real address such as `name@example.com`")
def invalid_email(package: Package) -> Iterator[Hit]:
    """A ``<maintainer>`` has no email, or a maintainer or author email is malformed.

    ## What it does
    Requires ``email`` on every ``<maintainer>`` and checks every maintainer and author email
    against the schema's pattern (``local@domain.tld``, ASCII, a top-level domain of two or
    more letters). Spaces around the address are reported too: the XSD trims them but catkin_pkg
    does not.

    ## Why is this bad?
    The schema and catkin_pkg reject the manifest, so colcon does not see a ROS package, and
    users and build farms have no one to contact.

    ## Example
    ```xml
    <maintainer>Ada</maintainer>
    <author email="ada at example dot com">Ada</author>
    ```

    ## Use instead
    ```xml
    <maintainer email="ada@example.com">Ada</maintainer>
    <author email="ada@example.com">Ada</author>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in found.named("maintainer", "author"):
        hit = _check(element)
        if hit:
            yield hit
