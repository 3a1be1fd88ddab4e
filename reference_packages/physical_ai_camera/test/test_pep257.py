# Copyright 2026 Physical AI Robotics Team
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

"""Docstrings with ament's pydocstyle settings: ament_pep257, or pkgtool where ament is absent."""

from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1]


@pytest.mark.linter
@pytest.mark.pep257
def test_pep257():
    """Check the docstrings with ament's pydocstyle settings."""
    try:
        from ament_pep257.main import main
    except ImportError:
        style = pytest.importorskip('pkgtool.style.api', reason='needs ament_pep257 or pkgtool')
        errors = style.pep257_errors(PACKAGE)
        assert not errors, 'Found docstring errors:\n' + '\n'.join(errors)
    else:
        assert main(argv=[str(PACKAGE)]) == 0, 'Found code style errors / warnings'
