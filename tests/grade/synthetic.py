"""Synthetic student submissions of a tiny assignment (`talker_pkg`), each with one defect.

The assignment: a package `talker_pkg` whose `talker_pkg.greet.greeting(name)` returns
`Hello, <name>!` and whose console script `talker` runs a node. RUBRIC grades it (11 points).
"""

from __future__ import annotations

import io
import tarfile
import zipfile
from pathlib import Path

from tests.helpers import write_tree

HIDDEN = Path(__file__).parent / "fixtures" / "hidden_talker"

RUBRIC = """\
title = "talker assignment"
package = "talker_pkg"

[limits]
timeout = {timeout}
test_timeout = 5
processes = 64
memory_mb = 1024
output_kb = 64

[[criteria]]
kind = "build"
points = 2

[[criteria]]
kind = "executables"
points = 2
names = ["talker"]

[[criteria]]
kind = "lint"
name = "Dependencies and entry points"
points = 2
select = ["DEP", "ENT"]
per_finding = 1.0
feedback = "Declare what you import; point entry points at real functions"

[[criteria]]
kind = "style"
points = 1
per_finding = 0.5

[[criteria]]
kind = "tests"
points = 2
min_tests = 1

[[criteria]]
kind = "hidden"
points = 2
path = "{hidden}"
"""

MANIFEST = """\
<?xml version="1.0"?>
<package format="3">
  <name>talker_pkg</name>
  <version>0.1.0</version>
  <description>Greets people from a ROS 2 node.</description>
  <maintainer email="student@example.com">Student</maintainer>
  <license>Apache-2.0</license>

  <exec_depend>rclpy</exec_depend>
  <exec_depend>std_msgs</exec_depend>

  <test_depend>python3-pytest</test_depend>

  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""

SETUP = """\
from setuptools import find_packages, setup

package_name = 'talker_pkg'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml'{extra_data}]),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Student',
    maintainer_email='student@example.com',
    description='Greets people from a ROS 2 node.',
    license='Apache-2.0',
    extras_require={{'test': ['pytest']}},
    entry_points={{
        'console_scripts': [
            'talker = talker_pkg.talker:main',
        ],
    }},
)
"""

TALKER = """\
\"\"\"Publish a greeting once a second.\"\"\"

import rclpy
from std_msgs.msg import String
from talker_pkg.greet import greeting


def main(args=None):
    \"\"\"Run the talker node.\"\"\"
    rclpy.init(args=args)
    node = rclpy.create_node('talker')
    publisher = node.create_publisher(String, 'greeting', 10)
    node.create_timer(1.0, lambda: publisher.publish(String(data=greeting('ROS'))))
    rclpy.spin(node)
"""

GREET = """\
\"\"\"Greetings.\"\"\"


def greeting(name):
    \"\"\"Return the greeting for ``name``.\"\"\"
    return f'Hello, {name}!'
"""

TESTS = """\
from talker_pkg.greet import greeting


def test_greets_by_name():
    assert greeting('Ada') == 'Hello, Ada!'


def test_greets_anyone():
    assert greeting('') == {expected!r}
"""


CHEAT = """\
import pytest


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    outcome.get_result().outcome = 'passed'
"""
"""A conftest.py that reports every test as passed, if pytest ever loads it."""


def correct() -> dict[str, str]:
    """The files of a correct submission."""
    return {
        "package.xml": MANIFEST,
        "setup.py": SETUP.format(extra_data=""),
        "setup.cfg": "[develop]\nscript_dir=$base/lib/talker_pkg\n"
                     "[install]\ninstall_scripts=$base/lib/talker_pkg\n",
        "resource/talker_pkg": "",
        "talker_pkg/__init__.py": "",
        "talker_pkg/greet.py": GREET,
        "talker_pkg/talker.py": TALKER,
        "test/test_greet.py": TESTS.format(expected="Hello, !"),
    }


def variants(original_of: dict[str, Path], markers: dict[str, Path]) -> dict[str, dict[str, str]]:
    """Every synthetic submission (name -> files). ``original_of`` gives each on-disk path."""
    escape = correct()
    escape["test/test_escape.py"] = f"""\
from pathlib import Path


def test_overwrites_the_original_submission():
    Path({str(original_of['writes_outside'] / 'setup.py')!r}).write_text('# overwritten')


def test_writes_to_tmp():
    Path({str(markers['tmp'])!r}).write_text('escaped')


def test_writes_to_the_home_of_root():
    Path({str(markers['root'])!r}).write_text('escaped')
"""
    missing_entry = correct()
    del missing_entry["talker_pkg/talker.py"]
    undeclared = correct()
    undeclared["talker_pkg/greet.py"] = GREET.replace(
        '"""Greetings."""\n', '"""Greetings."""\n\nimport numpy  # noqa: F401\n')
    broken = correct()
    broken["setup.py"] = SETUP.format(extra_data=", 'resource/missing.yaml'")
    failing = correct()
    failing["test/test_greet.py"] = TESTS.format(expected="Hello, nobody!")
    looping = correct()
    looping["test/test_loop.py"] = "def test_forever():\n    while True:\n        pass\n"
    bomb = correct()
    bomb["test/test_bomb.py"] = ("import os\n\n\ndef test_fork_bomb():\n    while True:\n"
                                 "        try:\n            os.fork()\n"
                                 "        except OSError:\n            pass\n")
    hangs = correct()
    hangs["talker_pkg/talker.py"] = TALKER.replace(
        "import rclpy\n", "import time\n\nimport rclpy\n").replace(
        "greeting\n\n\n", "greeting\n\ntime.sleep(3600)  # work done at import time\n\n\n")
    cheater = correct()
    cheater["talker_pkg/greet.py"] = GREET.replace("f'Hello, {name}!'", "'Hi'")
    cheater["test/test_greet.py"] = TESTS.format(expected="Hi").replace("Hello, Ada!", "Hi")
    cheater["conftest.py"] = CHEAT
    cheater["setup.cfg"] += "[tool:pytest]\naddopts = -p no:junitxml\n"
    return {"correct": correct(), "cheater": cheater, "missing_entry_point": missing_entry,
            "undeclared_dependency": undeclared, "build_failure": broken,
            "failing_test": failing, "infinite_loop": looping, "writes_outside": escape,
            "fork_bomb": bomb, "hangs_at_import": hangs}


def write_submission(folder: Path, files: dict[str, str]) -> Path:
    """Write one submission folder (a package)."""
    return write_tree(folder, files)


def tar_gz(archive: Path, folder: Path) -> Path:
    """Pack ``folder`` as ``archive`` (.tar.gz), under the folder's name."""
    with tarfile.open(archive, "w:gz") as bundle:
        bundle.add(folder, arcname=folder.name)
    return archive


def zip_with_traversal(archive: Path, folder: Path) -> Path:
    """A zip of ``folder`` plus a member `../escaped.txt` that tries to leave the extraction."""
    with zipfile.ZipFile(archive, "w") as bundle:
        for path in sorted(folder.rglob("*")):
            if path.is_file():
                bundle.write(path, f"talker_pkg/{path.relative_to(folder)}")
        bundle.writestr("../escaped.txt", "escaped")
    return archive


def bytes_zip(members: dict[str, bytes], *, symlink: str | None = None) -> bytes:
    """A zip in memory with ``members``; ``symlink`` adds a member that is a symbolic link."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as bundle:
        for name, data in members.items():
            bundle.writestr(name, data)
        if symlink:
            info = zipfile.ZipInfo("link")
            info.external_attr = (0o120777 << 16)
            bundle.writestr(info, symlink)
    return buffer.getvalue()
