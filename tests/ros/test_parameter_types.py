"""DAT011's type table agrees with real rclpy: a file value is rejected exactly when the rule
says its type differs from the declared default's."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from pkgtool.rules.node_parameters import python_type, yaml_type

pytestmark = pytest.mark.ros

DEFAULTS = [0.5, 3, "x", True, [1.0], [1], ["a"], [True]]
VALUES = ["1", "1.5", "'fast'", "fast", "true", "on", "No", "0x10", "010", "1e3", ".inf", "nan",
          "'1'", "null", "[1, 2]", "[1.0, 2.0]", "[a, b]", "[true]"]
PROBE = """
import json, sys
import rclpy
from rclpy.context import Context
from rclpy.exceptions import InvalidParameterTypeException
from rclpy.node import Node

results = []
for default, path in json.load(sys.stdin):
    context = Context()
    rclpy.init(context=context, args=['--ros-args', '--params-file', path])
    node = Node('probe', context=context)
    try:
        node.declare_parameter('p', default)
        results.append(False)
    except InvalidParameterTypeException:
        results.append(True)
    node.destroy_node()
    rclpy.shutdown(context=context)
print(json.dumps(results))
"""


def test_type_table_matches_rclpy(ros_env: dict[str, str], tmp_path: Path) -> None:
    assert os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "OFF"
    cases, predicted = [], []
    for number, text in enumerate(VALUES):
        path = tmp_path / f"p{number}.yaml"
        path.write_text(f"probe:\n  ros__parameters:\n    p: {text}\n", encoding="utf-8")
        found = yaml_type(yaml.compose(text))
        for default in DEFAULTS:
            if found is not None:
                cases.append((default, str(path)))
                predicted.append((default, text, found != python_type(default)))
    run = subprocess.run([sys.executable, "-c", PROBE], input=json.dumps(cases), text=True,
                         capture_output=True, timeout=120, env=dict(os.environ), check=True)
    rejected = json.loads(run.stdout.strip().splitlines()[-1])
    assert [(d, t, r) for (d, t, _), r in zip(predicted, rejected)] == predicted
    assert ("0.5", "1", True) in [(str(d), t, r) for d, t, r in predicted]  # int for double
