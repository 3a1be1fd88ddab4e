"""YAML merge keys in parameter blocks resolve as PyYAML (YAML 1.1) resolves them."""

import yaml

from pkgtool.rules.node_parameters import flat_parameters

BLOCK = """\
a: &a {x: 1, y: 2}
b: &b {y: 3, z: 4}
t:
  ros__parameters:
    <<: [*a, *b]
    x: 10
    n: {<<: *a, y: 5}
"""


def _parameters(text: str) -> dict[str, str]:
    document = yaml.compose(text)
    block = {k.value: v for k, v in document.value}["t"]
    parameters = {k.value: v for k, v in block.value}["ros__parameters"]
    return {name: value.value for name, _, value in flat_parameters(parameters)}


def test_written_keys_win_over_merged_ones_and_the_first_merged_mapping_over_later_ones():
    loaded = yaml.safe_load(BLOCK)["t"]["ros__parameters"]
    expected = {"x": 10, "y": 2, "z": 4, "n.x": 1, "n.y": 5}
    assert {k: int(v) for k, v in _parameters(BLOCK).items()} == expected
    assert {**{k: v for k, v in loaded.items() if k != "n"},
            **{f"n.{k}": v for k, v in loaded["n"].items()}} == expected


def test_a_mapping_merging_itself_ends():
    text = "t:\n  ros__parameters: &p\n    x: 1\n    n:\n      <<: *p\n"
    assert _parameters(text)["x"] == "1"
