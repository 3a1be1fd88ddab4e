"""Oracle: lint's workspace discovery finds the same packages as `colcon list` on one tree.

The tree holds every case discovery decides: ignore markers (colcon's own and colcon-ros'),
the folders colcon creates (with the COLCON_IGNORE it writes into them), a folder merely named
``build``, hidden folders, an old catkin install space, packages nested in packages, and
setup.py-only packages. colcon runs no package code here: packages with a package.xml are
identified from it, and the setup.py-only ones are given a setup.cfg name.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from pkgtool.ros.colcon import colcon_env, colcon_executable
from pkgtool.workspace import discover

pytestmark = [pytest.mark.ros, pytest.mark.colcon]


def _manifest(name: str) -> str:
    return (f'<?xml version="1.0"?>\n<package format="3"><name>{name}</name>'
            '<version>0.0.1</version><description>d</description>'
            '<maintainer email="d@example.com">d</maintainer><license>MIT</license>'
            '<export><build_type>ament_python</build_type></export></package>\n')


def _python_only(name: str) -> dict[str, str]:
    return {"setup.py": "from setuptools import setup\nsetup()\n",
            "setup.cfg": f"[metadata]\nname = {name}\n"}


TREE: dict[str, str] = {
    "src/alpha/package.xml": _manifest("alpha"),
    "src/alpha/nested/package.xml": _manifest("nested"),
    "src/group/beta/package.xml": _manifest("beta"),
    "src/build/zeta/package.xml": _manifest("zeta"),
    "src/install_notes/theta/package.xml": _manifest("theta"),
    "src/ignored/COLCON_IGNORE": "",
    "src/ignored/gamma/package.xml": _manifest("gamma"),
    "src/ament_ignored/AMENT_IGNORE": "",
    "src/ament_ignored/package.xml": _manifest("ament_ignored"),
    "src/catkin_ignored/CATKIN_IGNORE": "",
    "src/catkin_ignored/iota/package.xml": _manifest("iota"),
    "src/.hidden/delta/package.xml": _manifest("delta"),
    "build/COLCON_IGNORE": "",
    "build/alpha/package.xml": _manifest("alpha_build"),
    "install/COLCON_IGNORE": "",
    "install/alpha/share/alpha/package.xml": _manifest("alpha_install"),
    "log/COLCON_IGNORE": "",
    "log/latest/package.xml": _manifest("log_pkg"),
    "old_install/_setup_util.py": "",
    "old_install/share/eta/package.xml": _manifest("eta"),
    **{f"src/pure/{name}": text for name, text in _python_only("pure").items()},
    **{f"tools/build/kappa/{name}": text for name, text in _python_only("kappa").items()},
}


@pytest.fixture(scope="module")
def tree(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("discovery")
    for relative, text in TREE.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def _colcon_list(root: Path, scratch: Path, domain_id: int) -> set[str]:
    env = colcon_env(scratch, domain_id=domain_id)
    done = subprocess.run([colcon_executable(), "--log-base", os.devnull, "list", "--paths-only",
                           "--base-paths", str(root)], cwd=scratch, env=env,
                          capture_output=True, text=True, timeout=300, check=True)
    return {Path(line).resolve().relative_to(root).as_posix()
            for line in done.stdout.split() if line}


def test_discovery_matches_colcon_list(tree: Path, tmp_path: Path, ros_domain: int) -> None:
    ours = {p.relative_to(tree).as_posix() for p in discover(["."], cwd=tree).packages}
    assert ours == _colcon_list(tree, tmp_path, ros_domain)
    assert "src/build/zeta" in ours and "tools/build/kappa" in ours  # the oracle saw them too
