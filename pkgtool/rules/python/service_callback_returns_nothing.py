"""PYC026: a service callback that never returns the response."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._message_instances import callback_function
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import returns_none


@rule("PYC026", "service-callback-returns-nothing", Severity.ERROR,
      fix="End the callback with `return response`")
def service_callback_returns_nothing(package: Package) -> Iterator[Hit]:
    """A service callback never returns the response.

    ## What it does
    Reports the callback given to `create_service` when it is a plain method of the
    registering class (`self.on_request`) or a plain function bound once in the module, and
    certainly returns `None`: no `return <value>` anywhere, no `yield`, not `async`, no
    decorator, not a placeholder body (only `pass`, `...`, a docstring or `raise`).

    ## Why is this bad?
    rclpy sends what the callback returns as the response: `None` makes
    `Service.send_response` raise `TypeError` in the executor on the first request, the
    node dies and the client waits forever. Filling in the `response` argument is not
    enough: it must be returned.

    ## Example
    ```python
    def on_request(self, request, response):
        response.success = True
    ```

    ## Use instead
    ```python
    def on_request(self, request, response):
        response.success = True
        return response
    ```
    """
    for path, value, api, _, index, tree in callback_arguments(package):
        found = callback_function(value, tree, index) if api == "create_service()" else None
        if found is not None and returns_none(found[0]):
            yield Hit(Span(path, found[0].lineno, found[0].col_offset + 1),
                      f"The service callback `{ast.unparse(value)}` never returns the response: "
                      "rclpy's send_response() raises TypeError on the first request",
                      related=(Span(path, value.lineno, value.col_offset + 1),))
