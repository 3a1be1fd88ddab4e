"""PYC rules on code built in memory: name resolution, scopes, and hostile input."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import MINIMAL_MANIFEST, codes, findings, make_package

PYC = ("PYC001", "PYC002", "PYC003", "PYC004", "PYC005")


def _lines(tmp_path: Path, source: str, *rules: str) -> list[tuple[str, int]]:
    package = make_package(tmp_path / "demo", {
        "package.xml": MINIMAL_MANIFEST.format(name="demo"), "demo/__init__.py": "",
        "demo/node.py": source})
    return [(f.code, f.span.line) for f in findings(package, *(rules or PYC))]


def test_names_bound_to_numpy_and_something_else_are_not_resolved(tmp_path: Path) -> None:
    source = "import numpy as np\n\n\ndef f(np):\n    return np.int0\n\n\nx = np.float\n"
    assert _lines(tmp_path, source, "PYC002") == []


def test_submodule_import_resolves_through_the_package(tmp_path: Path) -> None:
    source = ("import rclpy.action\nimport numpy.linalg\n\n"
              "A = rclpy.action.ActionClient.GoalStatus\nB = numpy.product\n")
    assert _lines(tmp_path, source) == [("PYC004", 4), ("PYC002", 5)]


def test_other_modules_with_the_same_attribute_names_are_fine(tmp_path: Path) -> None:
    source = ("import torch\nfrom rclpy.action import ActionServer\n\n"
              "A = torch.float\nB = ActionServer.register_goal_callback\n")
    assert _lines(tmp_path, source) == []


def test_parameters_and_module_level_try_are_not_unbound_errors(tmp_path: Path) -> None:
    source = """
def main(node=None):
    try:
        node = make()
    finally:
        node.destroy_node()


try:
    handle = open('x')
finally:
    handle.close()
"""
    assert _lines(tmp_path, source, "PYC003") == []


def test_names_used_only_in_the_try_body_are_fine(tmp_path: Path) -> None:
    source = """
def main():
    try:
        node = make()
        node.spin()
    except Exception:
        print('failed')
    finally:
        cleanup()
"""
    assert _lines(tmp_path, source, "PYC003") == []


def test_spin_on_a_stored_request_future_in_another_method(tmp_path: Path) -> None:
    source = """
import rclpy


class Client:
    def send(self):
        self.future = self.client.call_async(self.request)

    def wait(self):
        rclpy.spin_until_future_complete(self, self.future)

    def other(self, future):
        rclpy.spin_until_future_complete(self, future)
"""
    assert _lines(tmp_path, source, "PYC005") == [("PYC005", 9)]


@pytest.mark.parametrize("source", [
    "def broken(:\n",
    "x = " + "+".join(["1"] * 900) + "\n",
    "\x00\x01binary",
])
def test_hostile_modules_give_no_pyc_finding_and_no_crash(tmp_path: Path, source: str) -> None:
    package = make_package(tmp_path / "demo", {
        "package.xml": MINIMAL_MANIFEST.format(name="demo"), "demo/__init__.py": "",
        "demo/node.py": source})
    assert codes(package, *PYC) == []
