"""MAN017: ``ros2 pkg create`` placeholders left in package.xml."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern

_TODO = lazy_pattern(r"TODO(?::|$)")
"""``TODO: Package description`` (ros2 pkg create) and a bare ``TODO`` (catkin_create_pkg)."""
_PLACEHOLDER_DOMAIN = "@todo.todo"
"""``ros2 pkg create`` writes ``<user>@todo.todo`` when git has no ``user.email``."""
_FIXES = {"description": "Describe in one sentence what the package does",
          "license": "Name the license with its SPDX identifier, e.g. `Apache-2.0`"}


@rule("MAN017", "template-placeholder", Severity.WARNING,
      fix="Replace the placeholder with the real value")
def template_placeholder(package: Package) -> Iterator[Hit]:
    """package.xml still holds the placeholders ``ros2 pkg create`` wrote.

    ## What it does
    Reports a ``<description>`` or ``<license>`` that is ``TODO`` or starts with ``TODO:``
    (``ros2 pkg create`` writes "TODO: Package description" and "TODO: License declaration"),
    and maintainer or author emails at ``todo.todo``, the address it invents from the login
    name when git has no ``user.email``.

    ## Why is this bad?
    The package ships without a usable description, license or contact: rosdistro and bloom
    reviews reject it, and license checks cannot classify it.

    ## Example
    ```xml
    <description>TODO: Package description</description>
    <maintainer email="user@todo.todo">user</maintainer>
    <license>TODO: License declaration</license>
    ```

    ## Use instead
    ```xml
    <description>Obstacle avoidance for a differential-drive robot</description>
    <maintainer email="ada@example.com">Ada Lovelace</maintainer>
    <license>Apache-2.0</license>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in found.named("description", "license"):
        if is_placeholder(element.text):
            yield Hit(element.span, f"`<{element.tag}>` is the placeholder `{element.text}`",
                      _FIXES[element.tag])
    for element in found.named("maintainer", "author"):
        email = (element.attribute("email") or "").strip()
        if is_placeholder_email(email):
            yield Hit(element.span, f"{element.tag.capitalize()} `{element.text}` has the "
                      f"placeholder email `{email}`",
                      "Write your real name and email address")


def is_placeholder_email(email: str) -> bool:
    """True for the email address ``ros2 pkg create`` writes when git has none."""
    return email.lower().endswith(_PLACEHOLDER_DOMAIN)


def is_placeholder(text: str) -> bool:
    """True for the description and license texts the package templates write."""
    return bool(_TODO.match(text))
