# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""The lesson's package creation used keys that do not work here."""

import ast
from pathlib import Path
import xml.etree.ElementTree as ElementTree

MANIFEST = Path(__file__).resolve().parents[1] / 'package.xml'
ROOT = MANIFEST.parent


def _declared() -> set[str]:
    root = ElementTree.parse(MANIFEST).getroot()
    tags = ('depend', 'exec_depend', 'build_depend', 'test_depend')
    return {element.text.strip() for tag in tags for element in root.iter(tag)}


def test_seed_mistake_opencv_uses_its_rosdep_key():
    # `ros2 pkg create ... python-opencv` is not a rosdep key; python3-opencv is.
    declared = _declared()
    assert 'python3-opencv' in declared and 'python3-numpy' in declared
    assert 'python-opencv' not in declared


def test_seed_mistake_no_cv_bridge_dependency():
    # PyPI's cv_bridge fails under NumPy 2: the package converts images itself.
    assert 'cv_bridge' not in _declared()
    imported = set()
    for path in (ROOT / 'simple_vision_agent').glob('*.py'):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Import):
                imported.update(alias.name.split('.')[0] for alias in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module:
                imported.add(node.module.split('.')[0])
    assert 'cv2' in imported and 'cv_bridge' not in imported
