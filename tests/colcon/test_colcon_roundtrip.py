"""A real colcon build + test of a tiny ament_python package written by the test."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from pkgtool.ros.colcon import colcon_build, colcon_env, colcon_test

pytestmark = [pytest.mark.ros, pytest.mark.colcon]

PACKAGE = {
    "package.xml": """<?xml version="1.0"?>
<package format="3">
  <name>tiny_pkg</name>
  <version>0.0.1</version>
  <description>Smallest ament_python package.</description>
  <maintainer email="dev@example.com">Dev</maintainer>
  <license>Apache-2.0</license>
  <exec_depend>rclpy</exec_depend>
  <test_depend>python3-pytest</test_depend>
  <export><build_type>ament_python</build_type></export>
</package>
""",
    "setup.py": """from setuptools import find_packages, setup

package_name = 'tiny_pkg'
setup(
    name=package_name,
    version='0.0.1',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Dev',
    maintainer_email='dev@example.com',
    description='Smallest ament_python package.',
    license='Apache-2.0',
    extras_require={'test': ['pytest']},
    entry_points={'console_scripts': ['hello = tiny_pkg.hello:main']},
)
""",
    "setup.cfg": ("[develop]\nscript_dir=$base/lib/tiny_pkg\n"
                  "[install]\ninstall_scripts=$base/lib/tiny_pkg\n"),
    "resource/tiny_pkg": "",
    "tiny_pkg/__init__.py": "",
    "tiny_pkg/hello.py": """import rclpy


def main():
    rclpy.init()
    node = rclpy.create_node('hello')
    print('hello from', node.get_name())
    node.destroy_node()
    rclpy.shutdown()
""",
    "test/test_math.py": "def test_adds():\n    assert 1 + 1 == 2\n",
}


def _write(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    _write(tmp_path / "src" / "tiny_pkg", PACKAGE)
    return tmp_path


def test_build_installs_a_runnable_console_script(workspace: Path, ros_domain: int) -> None:
    env = colcon_env(workspace, domain_id=ros_domain)
    build = colcon_build(workspace, base_paths=[workspace / "src"], env=env)
    assert build.ok, build.output
    script = workspace / "install" / "tiny_pkg" / "lib" / "tiny_pkg" / "hello"
    assert script.is_file() and os.access(script, os.X_OK)
    run_env = dict(env, PYTHONPATH=str(next((workspace / "install" / "tiny_pkg" / "lib").glob(
        "python3*/site-packages"))))
    done = subprocess.run([str(script)], env=run_env, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "hello from hello" in done.stdout
    assert not list((workspace / "src" / "tiny_pkg").glob("*.egg-info")), "source tree was written"


def test_colcon_test_really_runs_pytest_and_fails_on_a_failing_test(
        workspace: Path, ros_domain: int) -> None:
    env = colcon_env(workspace, domain_id=ros_domain)
    assert colcon_build(workspace, base_paths=[workspace / "src"], env=env).ok
    passing = colcon_test(workspace, base_paths=[workspace / "src"], env=env)
    assert passing.ok, passing.output
    assert "1 passed" in passing.output
    assert (workspace / "build" / "tiny_pkg" / "pytest.xml").is_file()

    _write(workspace / "src" / "tiny_pkg",
           {"test/test_broken.py": "def test_no():\n    assert False\n"})
    failing = colcon_test(workspace, base_paths=[workspace / "src"], env=env)
    assert not failing.ok
    assert "1 failed" in failing.output
