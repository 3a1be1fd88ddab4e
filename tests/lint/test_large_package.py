"""A package of many modules is linted in time linear in its size: every file is parsed once
and every tree's facts stay while the package is checked (bounded caches once made each rule
that looks at every module parse and walk them all again)."""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

import pytest

from tests.helpers import correct_package_files, findings, make_package

MODULES = 530
"""More modules than the largest bounded cache of trees held (512)."""


def _module(number: int) -> str:
    return f'''
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String


        class Relay{number}(Node):

            def __init__(self):
                super().__init__('relay_{number}')
                self.count = 0
                self.pub = self.create_publisher(String, 'out_{number}', 10)
                self.timer = self.create_timer(0.5, self.tick)

            def tick(self):
                msg = String()
                msg.data = f'{{self.count}}'
                self.count += 1
                self.pub.publish(msg)


        def main():
            rclpy.init()
            rclpy.spin(Relay{number}())
        '''


def test_every_module_of_a_large_package_is_parsed_once(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    files = correct_package_files()
    files.update({f"demo/relays/relay_{n}.py": _module(n) for n in range(MODULES)})
    files["demo/relays/__init__.py"] = ""
    parsed: Counter[str] = Counter()
    parse = ast.parse

    def counting_parse(source, filename="<unknown>", *args, **kwargs):  # type: ignore
        parsed[str(filename)] += 1
        return parse(source, filename, *args, **kwargs)

    monkeypatch.setattr(ast, "parse", counting_parse)
    package = make_package(tmp_path / "demo", files)
    found = findings(package)
    relays = [name for name in parsed if "relay_" in name]
    assert len(relays) == MODULES
    assert max(parsed[name] for name in relays) == 1
    assert not [f for f in found if "relay_" in f.span.path and f.code.startswith("PYC")], found
