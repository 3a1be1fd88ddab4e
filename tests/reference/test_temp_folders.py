"""The reference packages' test set-up leaves nothing in the system temp folder.

Each ``test/conftest.py`` gives rcl a log folder when ``ROS_LOG_DIR`` is unset (a bare
``pytest`` or ``colcon test`` run) and must neither create one when it is set (pkgtool's colcon
runs) nor leave one behind when the process ends.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.resources import resource_dir

CONFTESTS = sorted(resource_dir("reference_packages").glob("*/test/conftest.py"))
_LOAD_ALL = """
import os, runpy, sys
given = os.environ.get('ROS_LOG_DIR')
for path in sys.argv[1:]:
    os.environ.pop('ROS_LOG_DIR', None)
    if given:
        os.environ['ROS_LOG_DIR'] = given
    runpy.run_path(path, run_name='conftest')
    print(os.path.isdir(os.environ['ROS_LOG_DIR']))  # a log folder while the tests run
"""


@pytest.mark.parametrize("log_dir_given", [True, False])
def test_conftests_leave_the_temp_folder_as_they_found_it(tmp_path: Path, log_dir_given: bool,
                                                          ros_domain: int) -> None:
    assert len(CONFTESTS) >= 9
    temp = tmp_path / "temp"
    temp.mkdir()
    env = dict(os.environ, TMPDIR=str(temp), ROS_DOMAIN_ID=str(ros_domain),
               ROS_LOG_DIR=str(tmp_path) if log_dir_given else "")
    done = subprocess.run([sys.executable, "-c", _LOAD_ALL, *map(str, CONFTESTS)], env=env,
                          capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["True"] * len(CONFTESTS)
    assert sorted(p.name for p in temp.iterdir()) == []
