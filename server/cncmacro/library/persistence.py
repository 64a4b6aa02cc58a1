"""Keeping the persistent commons (``#500–#999``, and e.g. the 30i's ``#98000–#98499``) between runs:
a small JSON file, written atomically. Which numbers persist is the machine's to say
(``Machine.persistent_values``, ``Machine.load_persistent``); this module only keeps them.
Runs that share the file take turns (``persistence_lock``).

The file is written to a temporary file in the same folder, flushed and fsynced, then renamed
over the old one, so that a run killed at any moment leaves either the old file or the new
one, never a torn one. The new file keeps the old one's permission bits and, where the owner
may set it, its group (a group-shared ``0664`` file stays ``0664``); a first file gets the
mode every new file gets (``0666`` less the umask). A file that is a symbolic link is read
and written through the link: ``persistent_target`` names the file it leads to, and the
temporary file is made in that file's folder, so the link stays and the state is never split
in two; a link to nothing is refused rather than followed to create a file somewhere.

Only a regular file is read, opened without blocking (a FIFO or a device is refused at once)
and at most ``MAX_BYTES`` of it. A missing file means every persistent variable is vacant; a
damaged one is refused with a message that says what is wrong, never half-read: not JSON,
nested too deeply, or a value that no variable of a control can hold (``NaN``, ``Infinity``,
a number beyond a double, named by its variable). A run killed while writing leaves its
temporary file behind; the next save removes those older than ``STALE_SECONDS`` (a younger
one may belong to a run still writing).
"""

from __future__ import annotations

import glob
import json
import math
import os
import stat
import time
from pathlib import Path

from ..bilingual import Detail, detail
from ..dialects.alarms import MAX_VALUE
from .files import FileTooLargeError, NotAFileError, read_bytes

STALE_SECONDS = 60.0
MAX_BYTES = 1 << 20  # a full file of 1,000 variables is about 30 kB


class PersistentFileError(ValueError):
    """The file exists but does not hold persistent variables (its argument is a ``Detail``)."""


def led_outside(path: Path, folder: Path) -> Path | None:
    """Where ``path`` leads once its links (of its folders and of itself) are followed, when
    that is outside ``folder`` (links followed too); None when it stays inside. The one rule of
    where a persistent-variable file, and so its lock, may be: a run never writes outside the
    folder the file is named in."""
    target = Path(os.path.realpath(path))
    return None if target.is_relative_to(Path(os.path.realpath(folder))) else target


def persistent_target(path: Path, saving: bool = True, folder: Path | None = None) -> Path:
    """The file that ``path`` names once its symbolic links are followed (``path`` itself
    when it is none). ``PersistentFileError`` for a link that leads to no file, when ``saving``
    would make one there (a run that only reads finds every variable vacant), and for one that
    leads outside ``folder`` when it is given (``led_outside``), before anything there is read,
    locked or written."""
    if folder is not None:
        outside = led_outside(path, folder)
        if outside is not None:
            raise PersistentFileError(detail(
                f"{path}: the persistent-variable file is a link to {outside}, outside the folder {folder}; "
                "nothing is read or written there. Remove the link, or name the file with 'persistent_file' "
                "in a machine file",
                f"{path}：断电保持变量文件是指向 {outside} 的链接，在文件夹 {folder} 之外；"
                "不会在那里读写任何内容。请删除该链接，或在机床设置文件中用 'persistent_file' 指定文件"))  # fmt: skip
    target = Path(os.path.realpath(path))
    if saving and os.path.islink(path) and not target.exists():
        raise PersistentFileError(detail(
            f"{path}: the persistent-variable file is a link to {target}, which does not exist",
            f"{path}：断电保持变量文件是指向 {target} 的链接，而该文件不存在"))  # fmt: skip
    return target


def load_persistent(path: Path) -> dict[int, float]:
    """The stored values (vacant ones are absent). ``PersistentFileError`` if damaged."""
    text = _read_regular_file(path)
    if text is None:
        return {}

    def damaged(why: Detail) -> PersistentFileError:
        return PersistentFileError(detail(f"{path}: not a persistent-variable file ({why})",
                                          f"{path}：不是断电保持变量文件（{why.zh}）"))  # fmt: skip

    try:
        data = json.loads(text)
    except ValueError as e:
        raise damaged(detail(f"{e}", f"{e}")) from None
    except RecursionError:
        raise damaged(detail("nested too deeply", "嵌套层数过多")) from None
    values = data["variables"] if isinstance(data, dict) and "variables" in data else data
    if not isinstance(values, dict):
        raise damaged(detail("it holds no '{\"variables\": {\"500\": 1.5, ...}}'",
                             "其中没有 '{\"variables\": {\"500\": 1.5, ...}}'"))  # fmt: skip
    out: dict[int, float] = {}
    for k, v in values.items():
        try:
            number = int(k)
            value = None if v is None else float(v)
        except (ValueError, TypeError, OverflowError):
            shown = f"#{str(k)[:20]} = {repr(v)[:40]}"
            why = detail(f"{shown} is not a variable number and a value", f"{shown} 不是变量号和数值")
            raise damaged(why) from None
        if value is None:
            continue
        if not math.isfinite(value) or abs(value) > MAX_VALUE:
            raise PersistentFileError(detail(
                f"{path}: #{number} holds {v!r}, which no variable of a control can hold: "
                "write a number, or 'null' for vacant",
                f"{path}：#{number} 的值为 {v!r}，数控系统的变量不能取该值：请写数值，空值写 'null'"))  # fmt: skip
        out[number] = value
    return out


def _read_regular_file(path: Path) -> str | None:
    """The text of ``path`` (``None`` when there is no such file), read as every file is read
    (``files.read_bytes``: a regular file only, never waited on) and at most ``MAX_BYTES``."""
    try:
        data = read_bytes(path, MAX_BYTES)
    except FileNotFoundError:
        return None
    except NotAFileError:
        raise PersistentFileError(detail(
            f"{path}: the persistent-variable file is not a regular file (a folder, a FIFO or a device)",
            f"{path}：断电保持变量文件不是普通文件（而是文件夹、FIFO 或设备）")) from None  # fmt: skip
    except FileTooLargeError as e:
        raise PersistentFileError(detail(
            f"{path}: too large ({e.size} bytes) to be a persistent-variable file",
            f"{path}：文件过大（{e.size} 字节），不是断电保持变量文件")) from None  # fmt: skip
    except OSError as e:
        raise _unreadable(path, e.strerror or str(e)) from e
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise PersistentFileError(detail(f"{path}: not a persistent-variable file (not UTF-8 text)",
                                         f"{path}：不是断电保持变量文件（不是 UTF-8 文本）")) from None  # fmt: skip


def _unreadable(path: Path, why: str) -> PersistentFileError:
    return PersistentFileError(detail(f"{path}: cannot read the persistent variables ({why})",
                                      f"{path}：无法读取断电保持变量（{why}）"))  # fmt: skip


def save_persistent(path: Path, values: dict[int, float]) -> None:
    """Write the values atomically (temporary file, fsync, rename) to ``path``'s target,
    keeping the old file's mode and group."""
    path = Path(os.path.realpath(path))
    payload = {"variables": {str(k): values[k] for k in sorted(values)}}
    text = json.dumps(payload, indent=1, allow_nan=False) + "\n"
    folder = path.parent
    folder.mkdir(parents=True, exist_ok=True)
    try:
        old: os.stat_result | None = os.stat(path)
    except OSError:
        old = None
    tmp = folder / f".{path.name}.{os.urandom(4).hex()}.tmp"
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0), 0o666)
    try:
        with os.fdopen(fd, "wb") as f:
            if old is not None and stat.S_ISREG(old.st_mode):
                _keep_owner_and_mode(f.fileno(), old)
            f.write(text.encode("utf-8"))
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    _remove_stale_temporaries(path)
    try:  # make the rename itself durable
        dir_fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(dir_fd)
    except OSError:
        pass
    finally:
        os.close(dir_fd)


def _keep_owner_and_mode(fd: int, old: os.stat_result) -> None:
    """Give the new file the old one's group (where this user may) and permission bits."""
    if hasattr(os, "fchown") and old.st_gid != os.fstat(fd).st_gid:
        try:
            os.fchown(fd, -1, old.st_gid)
        except OSError:
            pass  # not a member of that group: the permission bits still let the group in or not
    if hasattr(os, "fchmod"):
        os.fchmod(fd, stat.S_IMODE(old.st_mode))


def _remove_stale_temporaries(path: Path) -> None:
    """Delete the temporary files that killed runs left beside ``path``."""
    now = time.time()
    for tmp in path.parent.glob(f".{glob.escape(path.name)}.*.tmp"):
        try:
            if now - tmp.stat().st_mtime > STALE_SECONDS:
                tmp.unlink()
        except OSError:
            pass
