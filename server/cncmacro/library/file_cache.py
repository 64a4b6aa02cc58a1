"""Program files read from disk and parsed, each once until it changes.

``FileCache`` is the one reader of a workspace's program files: the program library's lookups
(``programs.py``), the index of who calls whom (``analysis/indexes/call_index.py``) and the language
server's workspace index (``analysis/indexes/workspace_index.py``) all read through the same one, so a
file is read (``files.read_program``, with its limits) and parsed (``load_text``, with the shared
block cache) once, not once per reader. An entry is kept by the file's (modification time,
size), looked at with one ``stat`` each time it is asked for: a file changed on disk is read
again at the next question, whether or not an event said so; ``forget`` drops it at once (a
file event). A file that could not be read is kept with its error until it changes; a parsed
file keeps its lines, not its text as well. It is used from the editor's thread and the
analysis thread at once: its table is changed under a lock, a file is read outside it.
"""

from __future__ import annotations

import os
import threading
from dataclasses import dataclass
from pathlib import Path

from ..syntax.block_parser import BlockCache, collector_paused, shared_cache
from ..syntax.document import split_lines
from ..syntax.program import Program, build_program
from .dialect_choice import dialect_from_text
from .files import SkippedFileError, read_program


@dataclass(slots=True)
class LoadedFile:
    """A program file, parsed: its path (as given), lines, structure and dialect comment."""

    path: str
    lines: list[str]
    program: Program
    dialect: str | None
    on_control: bool = False  # a program kept on the control (``control_program``), not a file

    @property
    def name(self) -> str:
        return Path(self.path).name


def load_text(path: str, text: str, cache: BlockCache | None = None) -> LoadedFile:
    """Parse a file's text into a ``LoadedFile``."""
    lines = split_lines(text)
    with collector_paused():
        blocks = (cache if cache is not None else shared_cache).get_many(lines)
        program = build_program(blocks)
    return LoadedFile(path, lines, program, dialect_from_text(lines))


Stamp = tuple[int, int]  # (modification time in ns, size)


@dataclass(slots=True)
class _Read:
    """One file as read: its stamp before it was read, and its text or why it has none."""

    stamp: Stamp
    text: str | None  # let go once parsed (``load``) unless it has a lone CR
    error: OSError | SkippedFileError | None
    loaded: LoadedFile | None = None  # parsed at the first ``load``


class FileCache:
    """See the module docstring. ``cache`` parses the files' lines (the shared block cache
    unless another is given)."""

    def __init__(self, cache: BlockCache | None = None) -> None:
        self.cache = cache if cache is not None else shared_cache
        self.reads = 0  # files read from disk (for tests and benchmarks)
        self._read: dict[str, _Read] = {}
        self._lock = threading.Lock()

    def _entry(self, path: str) -> _Read:
        try:
            st = os.stat(path)
            stamp: Stamp | None = (st.st_mtime_ns, st.st_size)
        except (OSError, ValueError):
            stamp = None
        with self._lock:
            got = self._read.get(path)
        if got is not None and got.stamp == stamp:
            return got
        self.reads += 1
        try:
            got = _Read(stamp or (-1, -1), read_program(path).text, None)
        except (OSError, SkippedFileError) as e:
            got = _Read(stamp or (-1, -1), None, e)
        if stamp is not None:  # a file that is not there is looked for again at each question
            with self._lock:
                self._read[path] = got
        return got

    def text(self, path: str) -> str:
        """The text of the program file at ``path`` (``OSError`` and ``SkippedFileError`` as
        ``read_program`` raises them)."""
        got = self._entry(path)
        if got.error is not None:
            raise got.error
        text = got.text
        if text is None:  # parsed, and its text let go: the same lines, joined
            assert got.loaded is not None
            return "\n".join(got.loaded.lines)
        return text

    def load(self, path: str) -> LoadedFile:
        """The program file at ``path``, parsed (raises as ``text`` does)."""
        got = self._entry(path)
        if got.error is not None:
            raise got.error
        loaded = got.loaded
        if loaded is None:
            text = got.text
            if text is None:  # the other thread parsed it just now
                assert got.loaded is not None
                return got.loaded
            loaded = got.loaded = load_text(path, text, self.cache)
            if text.count("\r") == text.count("\r\n"):
                got.text = None  # its lines joined are the same text to a search by line
        return loaded

    def forget(self, path: str) -> None:
        """``path`` changed on disk (a file, or a folder: every file under it): read it again
        at the next question."""
        below = os.path.join(path, "")
        with self._lock:
            for key in [k for k in self._read if k == path or k.startswith(below)]:
                del self._read[key]
