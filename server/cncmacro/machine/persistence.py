"""Keeping the persistent commons (``#500–#999``, and e.g. the 30i's ``#98000–#98499``) between runs:
a small JSON file, written atomically. Which numbers persist is the machine's to say
(``Machine.persistent_values``, ``Machine.load_persistent``); this module only keeps them.

The file is written to a temporary file in the same folder, flushed and fsynced, then renamed
over the old one, so that a run killed at any moment leaves either the old file or the new
one, never a torn one. A missing or unreadable file means every persistent variable is
vacant; a damaged one is reported and ignored, never half-read. A run killed while writing
leaves its temporary file behind; the next save removes those older than ``STALE_SECONDS``
(a younger one may belong to a run still writing).
"""

from __future__ import annotations

import glob
import json
import os
import tempfile
import time
from pathlib import Path

from ..library.files import SkippedFileError, read_bytes

STALE_SECONDS = 60.0
MAX_PERSISTENT_BYTES = 10_000_000  # 500 variables take some 15 KB


class PersistentFileError(ValueError):
    """The file exists but does not hold persistent variables."""


def load_persistent(path: Path) -> dict[int, float]:
    """The stored values (vacant ones are absent). ``PersistentFileError`` if damaged."""
    try:
        text = read_bytes(path, MAX_PERSISTENT_BYTES).decode("utf-8")  # a regular file only: a FIFO never blocks
    except FileNotFoundError:
        return {}
    except OSError as e:
        raise PersistentFileError(f"{path}: cannot read the persistent variables ({e.strerror or e})") from e
    except (SkippedFileError, UnicodeDecodeError) as e:
        raise PersistentFileError(f"{path}: not a persistent-variable file ({e})") from e
    try:
        data = json.loads(text)
        values = data["variables"] if isinstance(data, dict) and "variables" in data else data
        out = {int(k): float(v) for k, v in values.items() if v is not None}
    except (ValueError, TypeError, AttributeError, KeyError, RecursionError) as e:
        raise PersistentFileError(f"{path}: not a persistent-variable file ({e})") from e
    return out


def save_persistent(path: Path, values: dict[int, float]) -> None:
    """Write the values atomically (temporary file, fsync, rename)."""
    payload = {"variables": {str(k): values[k] for k in sorted(values)}}
    text = json.dumps(payload, indent=1) + "\n"
    folder = path.parent
    folder.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
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


def _remove_stale_temporaries(path: Path) -> None:
    """Delete the temporary files that killed runs left beside ``path``."""
    now = time.time()
    for tmp in path.parent.glob(f".{glob.escape(path.name)}.*.tmp"):
        try:
            if now - tmp.stat().st_mtime > STALE_SECONDS:
                tmp.unlink()
        except OSError:
            pass
