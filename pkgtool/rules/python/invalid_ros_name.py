"""PYC008: a node, topic or service name literal that rcl rejects."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.endpoints import endpoints, service_endpoints
from pkgtool.rules.node_api import (PARAMETERS, argument, name_argument,
                                    node_api_calls, node_constructions)
from pkgtool.rules.registry import rule
from pkgtool.rules.ros_name_checks import node_name_problem, topic_name_problem
from pkgtool.rules.syntax_trees import installed_trees


@rule("PYC008", "invalid-ros-name", Severity.ERROR,
      fix="Use only letters, digits and underscores (and `/` between parts of topic names)")
def invalid_ros_name(package: Package) -> Iterator[Hit]:
    """A node, topic or service name written in the code is one ROS 2 rejects.

    ## What it does
    Checks string literals given as node names (`super().__init__('name')` in a `Node`
    subclass, `rclpy.create_node('name')`) against `rmw_validate_node_name`, the `namespace=`
    given with them against the rules for namespaces, and as topic or
    service names (`create_publisher`, `create_subscription`, `create_service`,
    `create_client`) against `rcl_validate_topic_name`: no dashes, spaces or dots, no part
    starting with a digit, no empty part; also the topic of a publisher or subscription, and
    the name of a service, client or action server or client, given through a name bound once
    to a string or through a parameter whose literal default no parameter or launch file of
    the package changes (but an empty default, a placeholder for the value a parameter file
    gives). Names with `{substitutions}` are not checked.

    ## Why is this bad?
    ROS 1 and other middleware accept names such as `cmd-vel` or `my node`; rclpy raises
    `InvalidNodeNameException` or `InvalidTopicNameException` when the node starts.

    ## Example
    ```python
    super().__init__('obstacle-detector')
    self.create_publisher(Twist, 'cmd-vel', 10)
    ```

    ## Use instead
    ```python
    super().__init__('obstacle_detector')
    self.create_publisher(Twist, 'cmd_vel', 10)
    ```
    """
    for module, _, index in installed_trees(package):
        for call in node_constructions(index):
            expr = name_argument(call)
            problem = node_name_problem(expr.value) if isinstance(expr, ast.Constant) and \
                isinstance(expr.value, str) else None
            if problem:
                assert expr is not None
                yield Hit(Span(module.path, expr.lineno, expr.col_offset + 1),
                          f"`{expr.value}` is not a valid node name: {problem}")
            space = next((k.value for k in call.keywords if k.arg == "namespace"), None)
            problem = topic_name_problem(space.value) if isinstance(space, ast.Constant) and \
                isinstance(space.value, str) and space.value not in ("", "/") else None
            if problem:
                assert space is not None
                yield Hit(Span(module.path, space.lineno, space.col_offset + 1),
                          f"`{space.value}` is not a valid namespace: {problem}")
    for endpoint in (*endpoints(package), *service_endpoints(package)):
        problem = None if endpoint.literal or not endpoint.topic else \
            topic_name_problem(endpoint.topic)  # '': a placeholder a parameter file sets
        if problem:
            what = "topic" if endpoint.kind in ("publisher", "subscription") else \
                "action name" if endpoint.kind.startswith("action") else "service name"
            yield Hit(endpoint.topic_span,
                      f"`{endpoint.topic}`, the {what} this {endpoint.kind} is given (through a "
                      f"name or a parameter's default), is not a valid {what.split()[0]} name: "
                      f"{problem}")
    for module, call, method, _ in node_api_calls(package):
        parameters = PARAMETERS[method]
        expr = argument(call, parameters, parameters[1])
        if isinstance(expr, ast.Constant) and isinstance(expr.value, str):
            problem = topic_name_problem(expr.value)
            kind = "service" if "srv_name" in parameters else "topic"
            if problem:
                yield Hit(Span(module.path, expr.lineno, expr.col_offset + 1),
                          f"`{expr.value}` is not a valid {kind} name: {problem}")
