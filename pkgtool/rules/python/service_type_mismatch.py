"""PYC067: a client of a service (action) type no server of the package serves under its
name."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.endpoints import type_mismatches
from pkgtool.rules.registry import rule


@rule("PYC067", "service-type-mismatch", Severity.ERROR,
      fix="Use the same service type on both sides, or another service name")
def service_type_mismatch(package: Package) -> Iterator[Hit]:
    """A client calls a service name with another service type than the package's server
    of that name serves (or an action client, an action server's).

    ## What it does
    Pairs the `create_service` and `create_client` calls of the package's installed modules
    by service name, when the name is certain (as for PYC021: a string literal, a name
    bound once to one, or a parameter read whose literal default no parameter or launch file
    of the package may change). Reports a client whose service class (imported by name,
    `pkg.srv.Name`) is none of the classes the package's services of that name use, when all
    of those are known. Private names (`~/x`) are left out, and so are packages with C or
    C++ sources (their native nodes serve too, unseen). The same for rclpy's
    `ActionClient` and `ActionServer` (`pkg.action.Name` classes, by action name).

    ## Why is this bad?
    ROS 2 matches a client to a server only when their types agree: `wait_for_service()`
    never returns True (or times out every time) and every call waits forever. It follows a
    change of the service type on one side only, or an interface imported under the wrong
    name.

    ## Example
    ```python
    self.create_service(AddTwoInts, 'add_two_ints', self.add)   # server.py
    self.client = self.create_client(Trigger, 'add_two_ints')  # client.py
    ```

    ## Use instead
    ```python
    self.create_service(AddTwoInts, 'add_two_ints', self.add)
    self.client = self.create_client(AddTwoInts, 'add_two_ints')
    ```
    """
    for client, services, types in type_mismatches(package, services=True):
        action = "action " if client.kind.startswith("action") else ""
        yield Hit(client.type_span,
                  f"The {action}client of `{client.topic}` uses `{client.type}`, but this "
                  f"package serves {types} under that name: the types differ, so the client "
                  f"never finds the {action}server and every {'goal' if action else 'call'} "
                  "waits forever", related=tuple(s.type_span for s in services))
