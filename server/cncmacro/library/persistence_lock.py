"""Runs that share a persistent-variable file take turns, as programs on one control do.

A run that will save ``#500–#999`` holds an exclusive advisory lock from before it reads the
file until it has written it back, so two runs that each add 1 to ``#500`` add 2, whether they
start together or not; a debug session holds it from its launch until it ends. The lock is
taken on a sibling file, ``<name>.cncmacro-lock`` beside the (link-resolved) variable file, never
on the variable file itself: a save renames a new file over that one, and a lock on the replaced
file would guard nothing. The lock file holds the process number of the run that has the lock, for
the message of a run that waits for it in vain. A file of that name that holds anything else is
not a lock of ours and is never written, truncated or deleted: the run is refused, saying so
(a ``persistent_file = "yarn"`` must not cost a shop its ``yarn.lock``; the name's own suffix
makes the clash unlikely, the check makes it harmless). A run deletes it while it still holds the lock
(``PersistentLock.remove``) when it is done, saved or not, so that nothing of it is left beside
the programs. A run that was waiting on the deleted file finds, once it has the lock, that the
path no longer names the file it locked, and locks the path anew: two runs never hold locks on
two different files. A lock file left behind by a run that was killed (``kill -9``, a power
cut) blocks nobody: the system lets go of a dead process's locks, so the next run takes it at
once and deletes it when it is done. A run
that only reads (``--no-save``, ``noSave``) takes no lock: the atomic rename already gives it
a whole file.

A run waits ``wait`` seconds at most (``LOCK_WAIT`` by default), then gives up with a
``PersistentLockError`` that says who holds the file. Where the lock file cannot be made
because the folder is not writable, nothing there can be saved either, so the run goes on
without a lock (its save fails with its own message). ``fcntl.flock`` on POSIX,
``msvcrt.locking`` on Windows; on a platform with neither, runs do not take turns.
"""

from __future__ import annotations

import errno
import os
import stat
import time
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import detail
from .persistence import PersistentFileError

try:
    import fcntl
except ImportError:  # Windows
    fcntl = None  # type: ignore[assignment]
try:
    import msvcrt
except ImportError:  # POSIX
    msvcrt = None  # type: ignore[assignment]

LOCK_WAIT = 10.0
LOCK_SUFFIX = ".cncmacro-lock"
_LOCK_TEXT_MAX = 32  # a process number and a newline: a longer file is not a lock of ours
POLL_SECONDS = 0.01
_NOT_WRITABLE = (errno.EACCES, errno.EPERM, errno.EROFS)


class PersistentLockError(PersistentFileError):
    """Another run or debug session kept the file for longer than this run would wait."""


@dataclass(slots=True)
class PersistentLock:
    """The lock a run holds on its persistent-variable file (``fd`` is ``None`` when none
    could be taken)."""

    path: Path
    fd: int | None

    def release(self) -> None:
        """Let the next run have the file (closing the lock file releases the lock)."""
        fd, self.fd = self.fd, None
        if fd is None:
            return
        try:
            if fcntl is None and msvcrt is not None:
                os.lseek(fd, 0, os.SEEK_SET)
                msvcrt.locking(fd, msvcrt.LK_UNLCK, 1)
        except OSError:
            pass
        finally:
            os.close(fd)

    def remove(self) -> None:
        """Delete the lock file while this run still holds it, then release it: the run is over.
        Where the file cannot be deleted (a folder that is not writable; Windows, while another
        run has it open) it stays."""
        if self.fd is not None:
            try:
                os.unlink(self.path)
            except OSError:
                pass
        self.release()


def lock_file_of(path: Path) -> Path:
    """The lock file beside the persistent-variable file ``path``."""
    return path.with_name(path.name + LOCK_SUFFIX)


def lock_persistent(path: Path, wait: float = LOCK_WAIT) -> PersistentLock:
    """Take the lock of the persistent-variable file ``path`` (already link-resolved), waiting
    for it at most ``wait`` seconds; ``PersistentLockError`` when it stays taken."""
    lock_path = lock_file_of(path)
    deadline = time.monotonic() + max(wait, 0.0)
    while True:
        fd = _open_lock(lock_path)
        if fd is None or (fcntl is None and msvcrt is None):
            return PersistentLock(lock_path, fd)
        _wait_for_lock(fd, path, lock_path, wait, deadline)
        if _still_named(fd, lock_path):
            break
        os.close(fd)  # the run that had it deleted the file (it kept nothing): lock the path anew
    _note_holder(fd)
    return PersistentLock(lock_path, fd)


def _open_lock(lock_path: Path) -> int | None:
    """The lock file's descriptor; None where the folder is not writable (no lock is taken)."""
    try:
        return _open(lock_path)
    except OSError as e:
        if e.errno in _NOT_WRITABLE or isinstance(e, FileNotFoundError):
            return None
        raise PersistentFileError(detail(f"{lock_path}: cannot lock the persistent variables ({e.strerror or e})",
                                         f"{lock_path}：无法锁定断电保持变量（{e.strerror or e}）")) from e  # fmt: skip


def _still_named(fd: int, lock_path: Path) -> bool:
    """Whether ``lock_path`` still names the file open as ``fd`` (a run may have deleted it)."""
    try:
        named = os.stat(lock_path, follow_symlinks=False)
    except OSError:
        return False
    st = os.fstat(fd)
    return (named.st_dev, named.st_ino) == (st.st_dev, st.st_ino)


def _wait_for_lock(fd: int, path: Path, lock_path: Path, wait: float, deadline: float) -> None:
    """Take the lock on ``fd`` by ``deadline``, or close ``fd`` and raise ``PersistentLockError``."""
    while not _try_lock(fd, lock_path):
        if time.monotonic() >= deadline:
            holder = _holder(fd)
            os.close(fd)
            who = detail(f" (process {holder})", f"（进程 {holder}）") if holder else detail("", "")
            raise PersistentLockError(detail(
                f"{path}: the persistent variables are in use by another run or debug session{who}; "
                f"waited {wait:g} s. Run again when it has ended, or run without saving them "
                "('--no-save', or 'noSave' in a launch configuration)",
                f"{path}：断电保持变量正被另一次运行或调试会话使用{who.zh}，已等待 {wait:g} 秒。"
                "请在其结束后再运行，或不保存这些变量运行（'--no-save'，或启动配置中的 'noSave'）"))  # fmt: skip
        time.sleep(POLL_SECONDS)


def _open(lock_path: Path) -> int:
    """The lock file, made when missing; read-only when another user's and not writable (a
    lock can be taken through either). Never through a link, never anything but a file."""
    lock_path.parent.mkdir(parents=True, exist_ok=True)
    flags = os.O_CREAT | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(lock_path, os.O_RDWR | flags, 0o666)
    except PermissionError:
        fd = os.open(lock_path, os.O_RDONLY | (flags & ~os.O_CREAT))
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise OSError(errno.EINVAL, "the lock file is not a regular file")
    if not _holds_a_lock(fd):
        os.close(fd)
        raise PersistentFileError(detail(
            f"{lock_path}: this file is not a lock of cncmacro's (it holds something else), so it is "
            "left as it is and the persistent variables are not used; move it, or name another "
            "'persistent_file' in the machine file",
            f"{lock_path}：该文件不是 cncmacro 的锁文件（其中有别的内容），因此保持原样，不使用断电保持变量；"
            "请移走该文件，或在机床设置文件中另指定 'persistent_file'"))  # fmt: skip
    return fd


def _holds_a_lock(fd: int) -> bool:
    """Whether the open file is empty or holds only a process number (a lock of ours, maybe left
    by a run that was killed). Where another run's lock keeps it from being read (Windows locks
    the byte it holds), it is one."""
    try:
        if os.fstat(fd).st_size > _LOCK_TEXT_MAX:
            return False
        os.lseek(fd, 0, os.SEEK_SET)
        text = os.read(fd, _LOCK_TEXT_MAX + 1)
    except OSError:
        return True
    return text.strip().isdigit() or not text.strip()


def _try_lock(fd: int, lock_path: Path) -> bool:
    """Whether the lock was free and is now this run's; ``PersistentFileError`` when the file
    system cannot lock at all (an NFS mount without its lock service)."""
    try:
        if fcntl is not None:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        else:
            os.lseek(fd, 0, os.SEEK_SET)
            msvcrt.locking(fd, msvcrt.LK_NBLCK, 1)
    except OSError as e:
        if e.errno in (errno.EAGAIN, errno.EACCES, errno.EWOULDBLOCK, errno.EDEADLK):
            return False
        os.close(fd)
        raise PersistentFileError(detail(f"{lock_path}: cannot lock the persistent variables ({e.strerror or e})",
                                         f"{lock_path}：无法锁定断电保持变量（{e.strerror or e}）")) from e  # fmt: skip
    return True


def _note_holder(fd: int) -> None:
    """Write this process's number into the lock file (when it is writable)."""
    try:
        os.lseek(fd, 0, os.SEEK_SET)
        os.write(fd, f"{os.getpid()}\n".encode())
        os.ftruncate(fd, os.lseek(fd, 0, os.SEEK_CUR))
    except OSError:
        pass


def _holder(fd: int) -> int | None:
    try:
        os.lseek(fd, 0, os.SEEK_SET)
        text = os.read(fd, 32).decode("ascii", "replace").strip()
    except OSError:
        return None
    return int(text) if text.isdigit() else None
