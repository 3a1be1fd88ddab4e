"""A seccomp filter that forbids new user namespaces, and the other ``prctl`` calls of the jail.

Inside the jail no process may create a user namespace: in one it would hold every
capability over new mount and network namespaces of its own (mount a tmpfs the disk cap
does not see, hide from the grader's view). The filter (classic BPF, installed before the
jail starts, inherited by every descendant) answers ``EPERM`` to ``unshare`` and ``clone``
with ``CLONE_NEWUSER``, ``ENOSYS`` to ``clone3`` (whose flags a filter cannot read; the C
library then falls back to ``clone``), and ``EPERM`` to any call of another architecture's
ABI (x32, i386). Only x86-64 and AArch64 are known; elsewhere there is no filter and the
sandbox says so.
"""

from __future__ import annotations

import ctypes
import errno
import functools
import platform
import struct

_PR_SET_PDEATHSIG = 1
_PR_SET_DUMPABLE = 4
_PR_SET_SECCOMP = 22
_PR_SET_NO_NEW_PRIVS = 38
_SECCOMP_MODE_FILTER = 2
_CLONE_NEWUSER = 0x10000000
_ALLOW = 0x7FFF0000
_ERRNO = 0x00050000
# machine -> (AUDIT_ARCH, clone, unshare, clone3)
_ARCHES = {"x86_64": (0xC000003E, 56, 272, 435), "aarch64": (0xC00000B7, 220, 97, 435)}


def _ins(code: int, k: int, jt: int = 0, jf: int = 0) -> bytes:
    return struct.pack("HBBI", code, jt, jf, k)


@functools.cache
def _program() -> bytes | None:
    known = _ARCHES.get(platform.machine())
    if known is None:
        return None
    arch, clone, unshare, clone3 = known
    load, jeq, jge, jset, ret = 0x20, 0x15, 0x35, 0x45, 0x06
    return b"".join([
        _ins(load, 4),                                 # 0: architecture
        _ins(jeq, arch, 0, 9),                         # 1: another ABI -> 11 (deny)
        _ins(load, 0),                                 # 2: system call number
        _ins(jge, 0x40000000, 7, 0),                   # 3: x32 numbers -> 11 (deny)
        _ins(jeq, clone3, 7, 0),                       # 4: clone3 -> 12 (ENOSYS)
        _ins(jeq, unshare, 2, 0),                      # 5: unshare -> 8
        _ins(jeq, clone, 1, 0),                        # 6: clone -> 8
        _ins(ret, _ALLOW),                             # 7
        _ins(load, 16),                                # 8: first argument (flags), low half
        _ins(jset, _CLONE_NEWUSER, 1, 0),              # 9: CLONE_NEWUSER -> 11
        _ins(ret, _ALLOW),                             # 10
        _ins(ret, _ERRNO | errno.EPERM),               # 11
        _ins(ret, _ERRNO | errno.ENOSYS),              # 12
    ])


def available() -> bool:
    """True when this machine's architecture has a filter."""
    return _program() is not None


def _prctl(*args: int) -> None:
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(*(ctypes.c_ulong(a) for a in args)) != 0:
        number = ctypes.get_errno()
        raise OSError(number, f"prctl{args[:2]}: {errno.errorcode.get(number, number)}")


def no_new_privs() -> None:
    """No later exec of this process or its children may gain privileges (setuid, caps)."""
    _prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)


def forbid_user_namespaces() -> None:
    """Install the filter in this process (root, or after :func:`no_new_privs`)."""
    program = _program()
    if program is None:
        return
    buffer = ctypes.create_string_buffer(program, len(program))
    fprog = struct.pack("HxxxxxxP", len(program) // 8, ctypes.addressof(buffer))
    holder = ctypes.create_string_buffer(fprog, len(fprog))
    _prctl(_PR_SET_SECCOMP, _SECCOMP_MODE_FILTER, ctypes.addressof(holder))


def die_with_parent() -> None:
    """SIGKILL this process when the thread that started it ends (even by SIGKILL)."""
    _prctl(_PR_SET_PDEATHSIG, 9)


def not_dumpable() -> None:
    """Make this process non-dumpable: same-uid processes can no longer open its
    ``/proc/<pid>/fd``, ``mem`` or attach to it with ptrace."""
    _prctl(_PR_SET_DUMPABLE, 0)
