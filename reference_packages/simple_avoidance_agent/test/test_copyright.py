# Copyright 2015 Open Source Robotics Foundation, Inc.
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

"""Copyright and license headers, checked by pkgtool (ament_copyright rejects SPDX headers)."""

from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1]


@pytest.mark.copyright
@pytest.mark.linter
def test_copyright():
    """Check every file's copyright notice and SPDX license line."""
    style = pytest.importorskip('pkgtool.style.api', reason='needs pkgtool')
    errors = style.copyright_errors(PACKAGE)
    assert not errors, 'Found header errors:\n' + '\n'.join(errors)
