"""Linux namespaces around untrusted commands: no network, own pids, read-only machine, no root.

The strongest mode this machine allows is probed once per process:

- ``root``: as root, ``unshare`` gives new mount, network (loopback only) and pid namespaces,
  every mount except the job's workspace is remounted read-only, and the command runs as an
  unprivileged per-job uid with no capabilities (so RLIMIT_NPROC is enforced).
- ``userns``: the same namespaces inside a user namespace, for a non-root user.
- ``none``: neither works; the sandbox falls back to resource limits and a process group.
"""

from __future__ import annotations

import functools
import os
import shlex
import shutil
import stat
import subprocess
import sys
import sysconfig
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

SYSTEM_PATH = "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"
JAIL_FAILED = 125
"""Exit status of the jail script when it could not set the jail up (the command never ran)."""

_SCRIPT = r"""
fail() {{ echo "pkgtool-jail: $*" >&2; exit {failed}; }}
ws=$1; uid=$2; expose=$3; shift 3; here=$(pwd)
{mount} --make-rprivate / || fail "cannot make the mounts private"
{ip} link set lo up || fail "cannot bring the loopback interface up"
{mount} -t tmpfs -o size=256m,mode=1777,nosuid,nodev tmpfs /dev/shm || fail "cannot mount /dev/shm"
{mount} --bind "$ws" "$ws" || fail "cannot bind the workspace"
i=0
while IFS=: read -r hide keep; do  # bind every kept folder aside before hiding any ancestor
  [ -n "$keep" ] || continue
  i=$((i + 1)); mkdir "/dev/shm/.jail$i" && {mount} --rbind "$keep" "/dev/shm/.jail$i" ||
    fail "cannot expose $keep"
done <<EOF
$expose
EOF
hidden=" "; i=0
while IFS=: read -r hide keep; do
  [ -n "$keep" ] || continue
  case "$hidden" in *" $hide "*) ;; *) hidden="$hidden$hide "
    {mount} -t tmpfs -o size=1m,mode=755 tmpfs "$hide" || fail "cannot hide $hide";; esac
  i=$((i + 1)); mkdir -p "$keep" && {mount} --move "/dev/shm/.jail$i" "$keep" &&
    rmdir "/dev/shm/.jail$i" || fail "cannot expose $keep"
done <<EOF
$expose
EOF
awk '{{n = split($6, o, ","); f = ""; for (i = 1; i <= n; i++) if (o[i] != "rw") f = f "," o[i];
      print $5, f}}' /proc/self/mountinfo | while read -r point flags; do
  case "$point" in "$ws"|/dev|/dev/*|/proc|/proc/*) continue;; esac
  case "$flags," in *,ro,*) continue;; esac
  {mount} -o "remount,bind,ro$flags" "$point" || fail "cannot make $point read-only"
done || exit {failed}
cd "$here" || fail "cannot enter $here"  # again: through the writable bind
set -- --inh-caps=-all --bounding-set=-all --no-new-privs -- "$@"
if [ -n "$uid" ]; then set -- --reuid="$uid" --regid="$uid" --clear-groups "$@"; fi
{setpriv} "$@"
exit $?  # not exec: a signal death becomes 128 + its number, which unshare cannot re-raise
"""


@dataclass(frozen=True, slots=True)
class JailSupport:
    """What this machine allows: ``mode`` (root, userns, none) and why nothing stronger."""

    mode: str
    reason: str = ""

    @property
    def drops_uid(self) -> bool:
        """True when commands run as an unprivileged per-job uid."""
        return self.mode == "root"


@functools.cache
def _tools() -> dict[str, str] | None:
    found = {name: shutil.which(name, path=SYSTEM_PATH) for name in
             ("unshare", "mount", "ip", "setpriv", "awk", "mktemp")}
    return None if None in found.values() else found  # type: ignore[return-value]


def _prefix(mode: str) -> list[str]:
    tools = _tools() or {}
    user = ["--user", "--map-root-user"] if mode == "userns" else []
    return [tools.get("unshare", "unshare"), *user, "--mount", "--net", "--pid", "--fork",
            "--kill-child", "--mount-proc"]


def _script() -> str:
    tools = _tools() or {}
    return _SCRIPT.format(failed=JAIL_FAILED, **{k: shlex.quote(v) for k, v in tools.items()})


def exposed_paths() -> tuple[tuple[str, str], ...]:
    """``(hidden, kept)`` pairs: interpreter folders an unprivileged uid cannot reach.

    For each, the jail mounts an empty tmpfs on the unreachable ancestor ``hidden`` (e.g.
    ``/root``) and binds ``kept`` back into it, read-only, so nothing else there is visible.
    """
    needed = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.executable,
                                            *sysconfig.get_paths().values()) if p}
    pairs: list[tuple[str, str]] = []
    for path in sorted(p if os.path.isdir(p) else os.path.dirname(p) for p in needed):
        if any(path == k or path.startswith(k + "/") for _, k in pairs):
            continue
        blocked = next((str(a) for a in reversed(Path(path).parents)
                        if str(a) != "/" and not os.stat(a).st_mode & stat.S_IXOTH), None)
        if blocked is not None:
            pairs.append((blocked, path))
    return tuple(pairs)


def jail_command(command: Sequence[str], *, workspace: Path, uid: int | None,
                 mode: str) -> list[str]:
    """``command`` wrapped to run in the jail of ``mode`` with ``workspace`` writable."""
    expose = "\n".join(f"{h}:{k}" for h, k in exposed_paths()) if uid is not None else ""
    return [*_prefix(mode), "sh", "-c", _script(), "pkgtool-jail", str(workspace),
            "" if uid is None else str(uid), expose, *command]


@functools.cache
def jail_support() -> JailSupport:
    """The strongest jail mode that works here (probed by really running one)."""
    if not sys.platform.startswith("linux"):
        return JailSupport("none", "namespaces need Linux")
    if _tools() is None:
        return JailSupport("none", "unshare, mount, ip or setpriv is missing")
    modes = ["root", "userns"] if os.geteuid() == 0 else ["userns"]
    errors = []
    for mode in modes:
        with tempfile.TemporaryDirectory(prefix="pkgtool-jail-probe-") as probe:
            uid = 65534 if mode == "root" else None
            os.chmod(probe, 0o755)
            command = jail_command(["sh", "-c", "touch ./ok && ! touch /ok 2>/dev/null"],
                                   workspace=Path(probe), uid=uid, mode=mode)
            if uid is not None:
                os.chown(probe, uid, uid)
            done = subprocess.run(command, cwd=probe, capture_output=True, text=True,
                                  timeout=30, check=False, env={"PATH": SYSTEM_PATH})
            if done.returncode == 0:
                return JailSupport(mode)
            errors.append(f"{mode}: {(done.stderr.strip().splitlines() or ['failed'])[-1]}")
    return JailSupport("none", "; ".join(errors))
