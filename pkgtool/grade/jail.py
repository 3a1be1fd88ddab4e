"""Linux namespaces around untrusted commands: a machine of their own that shows almost nothing.

The strongest mode this machine allows is probed once per process (:func:`jail_support`):

- ``root`` (as root): new mount, network (loopback only), pid, IPC, UTS and cgroup namespaces;
  a seccomp filter forbids new user namespaces; the command runs as an unprivileged per-job
  uid without capabilities and with ``no_new_privs``.
- ``userns`` (not root, user namespaces allowed): the same namespaces inside a user
  namespace whose ``user.max_user_namespaces`` is 0; no uid change.
- ``none``: the sandbox falls back to resource limits and a process group.

In both jails the command sees a new root: a read-only tmpfs holding read-only binds of the
system folders (:data:`SYSTEM_DIRS`) and of the interpreter and pkgtool, a fresh ``/proc``,
a ``/dev`` of the harmless devices, a private ``/tmp`` and ``/dev/shm``, and the job's
workspace, writable, at its own path. Nothing else of the machine exists in there: not the
rubric, the hidden tests (bound read-only only for the step that runs them), the
submissions, other jobs, ``/run`` or host sockets.
"""

from __future__ import annotations

import functools
import os
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from collections.abc import Sequence
from pathlib import Path

import pkgtool
from pkgtool.records import record

SYSTEM_PATH = "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"
SYSTEM_DIRS = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc")
"""System folders a jailed command sees, read-only (those that exist)."""
DEVICES = ("null", "zero", "full", "random", "urandom")
JAIL_FAILED = 125
"""Exit status of the jail script when it could not set the jail up (the command never ran)."""
_TOOLS = ("unshare", "mount", "umount", "ip", "setpriv", "pivot_root", "mkdir", "ln")

_SCRIPT = r"""
fail() {{ echo "pkgtool-jail: $*" >&2; exit {failed}; }}
root=$1; uid=$2; binds=$3; tmp_mb=$4; userns=$5; shift 5; here=$(pwd)
if [ -n "$userns" ]; then
  echo 0 > /proc/sys/user/max_user_namespaces || fail "cannot forbid user namespaces"
fi
{mount} --make-rprivate / || fail "cannot make the mounts private"
{ip} link set lo up || fail "cannot bring the loopback interface up"
{mount} -t tmpfs -o size=1m,mode=755,nosuid,nodev tmpfs "$root" || fail "cannot mount the root"
{mkdir} -m 1777 "$root/tmp" "$root/dev" "$root/proc" || fail "cannot make the root folders"
{mount} -t tmpfs -o "size=${{tmp_mb}}m,mode=1777,nosuid,nodev" tmpfs "$root/tmp" &&
  {mount} -t tmpfs -o size=1m,mode=755,nosuid tmpfs "$root/dev" &&
  {mkdir} -m 1777 "$root/dev/shm" &&
  {mount} -t tmpfs -o "size=${{tmp_mb}}m,mode=1777,nosuid,nodev" tmpfs "$root/dev/shm" &&
  {mount} -t proc -o nosuid,nodev,noexec proc "$root/proc" || fail "cannot mount /tmp, /dev, /proc"
for device in {devices}; do
  : > "$root/dev/$device" && {mount} --bind "/dev/$device" "$root/dev/$device" ||
    fail "cannot expose /dev/$device"
done
{ln} -s /proc/self/fd "$root/dev/fd" && {ln} -s /proc/self/fd/0 "$root/dev/stdin" &&
  {ln} -s /proc/self/fd/1 "$root/dev/stdout" && {ln} -s /proc/self/fd/2 "$root/dev/stderr" ||
  fail "cannot link /dev/fd"
while IFS='	' read -r path flags; do
  [ -n "$path" ] || continue
  if [ -L "$path" ]; then
    {mkdir} -p "$root${{path%/*}}" && {ln} -s "$(readlink "$path")" "$root$path" ||
      fail "cannot link $path"
    continue
  fi
  if [ -d "$path" ]; then {mkdir} -p "$root$path"; else : > "$root$path"; fi &&
    {mount} --bind "$path" "$root$path" &&
    {mount} -o "remount,bind,$flags" "$root$path" || fail "cannot expose $path"
done <<EOF
$binds
EOF
{mkdir} "$root/.old" && {pivot_root} "$root" "$root/.old" && cd / &&
  {umount} -l /.old && rmdir /.old || fail "cannot enter the new root"
{mount} -o remount,bind,ro,nosuid,nodev / || fail "cannot make the root read-only"
cd "$here" || fail "cannot enter $here"
set -- --inh-caps=-all --bounding-set=-all --no-new-privs -- "$@"
if [ -n "$uid" ]; then set -- --reuid="$uid" --regid="$uid" --clear-groups "$@"; fi
{setpriv} "$@"
exit $?  # not exec: a signal death becomes 128 + its number, which unshare cannot re-raise
"""


@record
class JailSupport:
    """What this machine allows: ``mode`` (root, userns, none) and why nothing stronger."""

    mode: str
    reason: str = ""


@functools.cache
def _tools() -> dict[str, str] | None:
    found = {name: shutil.which(name, path=SYSTEM_PATH) for name in _TOOLS}
    return None if None in found.values() else found  # type: ignore[return-value]


def _script() -> str:
    tools = {k: shlex.quote(v) for k, v in (_tools() or {}).items()}
    return _SCRIPT.format(failed=JAIL_FAILED, devices=" ".join(DEVICES), **tools)


def exposed_paths() -> tuple[str, ...]:
    """Read-only paths of the jail: system folders, the interpreter's folders and pkgtool's."""
    needed = {sys.prefix, sys.base_prefix, os.path.dirname(os.path.realpath(sys.executable)),
              *sysconfig.get_paths().values(), str(Path(pkgtool.__file__).parent)}
    folders = sorted({os.path.realpath(p) for p in needed if p and os.path.isdir(p)})
    kept = [p for p in folders if not any(p.startswith(k + "/") for k in folders)]
    return tuple(p for p in SYSTEM_DIRS if os.path.lexists(p)) + tuple(
        p for p in kept if not any(p == s or p.startswith(s + "/") for s in SYSTEM_DIRS))


def mount_flags(path: str) -> str:
    """The per-mount flags (``nosuid``, ``noexec``, ...) of the mount holding ``path``.

    A bind keeps them when it is made read-only (in a user namespace they are locked).
    """
    best, flags = "", ""
    with open("/proc/self/mountinfo", encoding="utf-8", errors="replace") as table:
        for line in table:
            fields = line.split()
            point = fields[4].encode().decode("unicode_escape")
            if (path == point or path.startswith(point.rstrip("/") + "/")) and \
                    len(point) >= len(best):
                best, flags = point, fields[5]
    return ",".join(f for f in flags.split(",") if f not in ("rw", "ro"))


def jail_command(command: Sequence[str], *, root: Path, workspace: Path, uid: int | None,
                 mode: str, tmp_mb: int, extra: Sequence[Path] = ()) -> list[str]:
    """``command`` wrapped to run in the jail of ``mode``.

    ``root`` is an empty folder to build the new root on, ``workspace`` the writable folder,
    ``extra`` read-only folders for this command only (the hidden tests).
    """
    lines = [(p, "ro,nosuid,nodev") for p in exposed_paths()]
    lines += [(str(p), "ro,nosuid,nodev") for p in extra]
    lines.append((str(workspace), "nosuid,nodev"))
    binds = "\n".join(f"{path}\t{_flags(path, wanted)}" for path, wanted in lines)
    tools = _tools() or {}
    user = ["--user", "--map-root-user"] if mode == "userns" else []
    return [tools.get("unshare", "unshare"), *user, "--mount", "--net", "--pid", "--ipc",
            "--uts", "--cgroup", "--fork", "--kill-child", "sh", "-c", _script(),
            "pkgtool-jail", str(root), "" if uid is None else str(uid), binds, str(tmp_mb),
            "1" if mode == "userns" else "", *command]


def _flags(path: str, wanted: str) -> str:
    kept = [f for f in mount_flags(os.path.realpath(path)).split(",") if f]
    return ",".join(dict.fromkeys([*wanted.split(","), *kept]))


MODES = ("root", "userns", "none")


@functools.cache
def mode_problem(mode: str) -> str:
    """Why the jail ``mode`` cannot be used here ("" when it can; ``none`` always can)."""
    if mode == "none":
        return ""
    if mode not in MODES:
        return f"unknown mode (one of {', '.join(MODES)})"
    if mode == "root" and os.geteuid() != 0:
        return "it needs root"
    if not sys.platform.startswith("linux") or _tools() is None:
        return jail_support().reason or "namespaces are not available"
    return _probe(mode)


def mode_error(mode: str | None) -> str | None:
    """The usage error for a requested sandbox ``mode`` this machine cannot provide."""
    if not mode or not mode_problem(mode):
        return None
    return (f"The sandbox mode `{mode}` is not available here ({mode_problem(mode)}). "
            "Choose another --sandbox mode (auto picks the strongest available).")


@functools.cache
def jail_support() -> JailSupport:
    """The strongest jail mode that works here (probed by really running one)."""
    if not sys.platform.startswith("linux"):
        return JailSupport("none", "namespaces need Linux")
    if _tools() is None:
        return JailSupport("none", f"one of {', '.join(_TOOLS)} is missing")
    modes = ["root", "userns"] if os.geteuid() == 0 else ["userns"]
    errors = []
    for mode in modes:
        problem = _probe(mode)
        if not problem:
            return JailSupport(mode)
        errors.append(f"{mode}: {problem}")
    return JailSupport("none", "; ".join(errors))


def _probe(mode: str) -> str:
    """"" when a jail of ``mode`` starts and holds, else its last error line."""
    from pkgtool.grade.seccomp import forbid_user_namespaces

    with tempfile.TemporaryDirectory(prefix="pkgtool-jail-probe-") as probe:
        uid = 65534 if mode == "root" else None
        (Path(probe) / "root").mkdir()
        workspace = Path(probe) / "ws"
        workspace.mkdir()
        os.chmod(probe, 0o755)
        if uid is not None:
            os.chown(workspace, uid, uid)
        command = jail_command(["sh", "-c", "touch ./ok && ! touch /ok 2>/dev/null"],
                               root=Path(probe) / "root", workspace=workspace, uid=uid,
                               mode=mode, tmp_mb=1)
        done = subprocess.run(command, cwd=workspace, capture_output=True, text=True,
                              timeout=30, check=False, env={"PATH": SYSTEM_PATH},
                              preexec_fn=forbid_user_namespaces if mode == "root" else None)
    return "" if done.returncode == 0 else \
        (done.stderr.strip().splitlines() or ["failed"])[-1]
