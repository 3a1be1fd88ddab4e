"""Domain leases are exclusive across processes and come back when the holder ends."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.ros import domains

HOLD = """
import sys, time
from pkgtool.ros import domains
domains.LOCK_DIR = domains.Path(sys.argv[1])
print(domains.lease_domain(), flush=True)
sys.stdin.read()
"""


@pytest.fixture
def lock_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setattr(domains, "LOCK_DIR", tmp_path / "locks")
    # This worker's own leases (its session domain) live in _held: start from none of them.
    monkeypatch.setattr(domains, "_held", {})
    return tmp_path / "locks"


def _holder(lock_dir: Path) -> tuple[subprocess.Popen[str], int]:
    holder = subprocess.Popen([sys.executable, "-c", HOLD, str(lock_dir)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True)
    assert holder.stdout is not None
    return holder, int(holder.stdout.readline())


def test_leases_in_one_process_differ_and_are_released(lock_dir: Path) -> None:
    with domains.leased_domain() as first, domains.leased_domain() as second:
        assert first != second
        assert domains.FIRST_ID <= first <= domains.LAST_ID
    again = domains.lease_domain()
    assert again in (first, second)  # both were given back
    domains.release_domain(again)


def test_a_domain_held_by_another_process_is_never_given(lock_dir: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    holder, taken = _holder(lock_dir)
    try:
        monkeypatch.setattr(domains, "FIRST_ID", taken)
        monkeypatch.setattr(domains, "LAST_ID", taken + 1)
        with domains.leased_domain() as mine:
            assert mine == taken + 1
            with pytest.raises(RuntimeError, match="leased by another process"):
                domains.lease_domain()
    finally:
        holder.communicate("")
    with domains.leased_domain() as after_exit:  # the dead holder's lock is gone
        assert after_exit in (taken, taken + 1)
