# Copyright 2017 Open Source Robotics Foundation, Inc.
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""Code style with ament's flake8 settings: ament_flake8, or pkgtool where ament is absent."""

from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1]


@pytest.mark.flake8
@pytest.mark.linter
def test_flake8():
    """Check the code style with ament's flake8 settings."""
    try:
        from ament_flake8.main import main_with_errors
    except ImportError:
        style = pytest.importorskip('pkgtool.style.api', reason='needs ament_flake8 or pkgtool')
        errors = style.flake8_errors(PACKAGE)
    else:
        errors = main_with_errors(argv=[str(PACKAGE)])[1]
    assert not errors, \
        'Found %d code style errors / warnings:\n' % len(errors) + '\n'.join(errors)
