"""Who calls whom among the program files on disk in the workspace folders.

``CallIndex`` lists the program files under its folders (``library/files.py``'s rules: known
endings or ``O1234`` names, hidden folders skipped, no link leading out of the folder) and
records, per file, the calls with a literal target that it makes (``G65/G66 P``, ``M98 P``
with its count digits, gsk980tdi ``P[NAME]``, the machine settings' call codes), each with
the O program of the file that makes it. A file is read once (through the ``FileCache`` it
shares with the program library) and kept by (modification time, size); its text is first
searched for a call word and parsed (with the shared block cache) only when it has one, and
only its lines with a call word are looked at. ``callers`` answers
which files name a number or a name: candidates only, since which file a call reaches is the
library's lookup (``ProgramLibrary``), decided by the caller of this index.

It is bounded as every search of a workspace folder is (``library/files.py``): at most
``MAX_FILES`` files and ``MAX_FOLDER_ENTRIES`` folder entries (more, and the index says so in
the log and knows no callers, so that the analysis behaves as if it had no workspace), and files
up to ``MAX_FILE_BYTES`` (a larger one is logged and left out). It is built lazily, at the first
question; ``changed(path)`` (a file created, changed or deleted) lists the folders again at the
next question, reading only the files whose time or size changed.
"""

from __future__ import annotations

import logging
import os
import re
from dataclasses import dataclass
from pathlib import Path

from ...bilingual import pick
from ...library.file_cache import FileCache
from ...library.files import (
    MAX_FOLDER_ENTRIES,
    MAX_PROGRAM_BYTES,
    MAX_PROGRAM_FILES,
    FileTooLargeError,
    SkippedFileError,
    o_number,
    search_program_files,
)
from ...library.machine_file import MachineSettings
from ...library.profiles import file_profile
from ...machine.calls import call_word_pattern
from ..checks import static_checks

log = logging.getLogger(__name__)

MAX_FILES = MAX_PROGRAM_FILES
MAX_FILE_BYTES = MAX_PROGRAM_BYTES


@dataclass(frozen=True, slots=True)
class IndexedCall:
    """A call with a literal target: the index of the O program (unit) of the file that makes
    it, and the program number or (gsk980tdi) bracketed name it names."""

    unit: int
    number: int | None
    name: str | None


@dataclass(slots=True)
class _Entry:
    stamp: tuple[int, int]  # (mtime in ns, size)
    calls: tuple[IndexedCall, ...]


class CallIndex:
    """See the module docstring."""

    def __init__(self, folders: list[str], settings: MachineSettings, dialect: str | None, locale: str = "en",
                 max_files: int = MAX_FILES, max_bytes: int = MAX_FILE_BYTES,
                 files: FileCache | None = None, known: frozenset[str] = frozenset()) -> None:  # fmt: skip
        """``known``: files under ``folders`` that are not read, their callers known otherwise: a
        check's own files, each checked beside every file that calls it (cli/call_groups.py)."""
        self.folders = [Path(f) for f in dict.fromkeys(str(f) for f in folders)]
        self.known = known
        self.settings = settings
        self.dialect = dialect
        self.locale = locale
        self.max_files = max_files
        self.max_bytes = max_bytes
        self.disk = files if files is not None else FileCache()  # shared with the program library
        self.usable = True  # False when there were more files than ``max_files``
        self.files_read = 0  # files read since the index was made (for tests and benchmarks)
        self.files_parsed = 0
        self._entries: dict[str, _Entry] = {}
        self._listed = False
        self._numbers: dict[int, set[str]] = {}
        self._names: dict[str, set[str]] = {}
        self._word = re.compile(call_word_pattern(settings.calls))  # a local call (M97) names no program

    # ---------------------------------------------------------------- keeping up to date
    def changed(self, path: str) -> tuple[IndexedCall, ...] | None:
        """A file was created, changed or deleted. A file the index holds that is still a file is
        read again at once (the other files are not looked at: a shop's folders change one file
        at a time); anything else, a file that came or went or a folder, makes the index look at
        the folders again when next asked. Returns the calls the file made before, or None
        when the index did not hold it."""
        entry = self._entries.get(path) if self._listed else None
        if entry is None or not os.path.isfile(path):
            self._listed = False
            return entry.calls if entry is not None else None
        try:
            st = os.stat(path)
        except OSError:
            self._listed = False
            return entry.calls
        self._forget_calls(path, entry.calls)
        fresh = _Entry((st.st_mtime_ns, st.st_size), () if st.st_size > self.max_bytes else self._read(path))
        self._entries[path] = fresh
        self._index_calls(path, fresh.calls)
        return entry.calls

    def _index_calls(self, path: str, calls: tuple[IndexedCall, ...]) -> None:
        for c in calls:
            if c.number is not None:
                self._numbers.setdefault(c.number, set()).add(path)
            if c.name is not None:
                self._names.setdefault(c.name, set()).add(path)
                number = o_number(c.name)
                if number is not None:
                    self._numbers.setdefault(number, set()).add(path)

    def _forget_calls(self, path: str, calls: tuple[IndexedCall, ...]) -> None:
        for c in calls:
            numbers = [c.number, o_number(c.name) if c.name is not None else None]
            for n in numbers:
                if n is not None and n in self._numbers:
                    self._numbers[n].discard(path)
            if c.name is not None and c.name in self._names:
                self._names[c.name].discard(path)

    @property
    def size(self) -> int:
        """How many files the index holds."""
        self._ensure()
        return len(self._entries)

    def _ensure(self) -> None:
        if self._listed:
            return
        self._listed = True
        paths = self._list()
        if paths is None:
            self.usable = False
            self._entries.clear()
            self._numbers.clear()
            self._names.clear()
            return
        self.usable = True
        old = self._entries
        self._entries = {}
        known = self.known
        for path in paths:
            if path in known:
                continue
            try:
                st = os.stat(path)
            except OSError:
                continue
            stamp = (st.st_mtime_ns, st.st_size)
            entry = old.get(path)
            if entry is None or entry.stamp != stamp:
                if st.st_size > self.max_bytes:
                    log.info("%s: %d bytes, larger than %d: its calls are not indexed", path, st.st_size,
                             self.max_bytes)  # fmt: skip
                    entry = _Entry(stamp, ())
                else:
                    entry = _Entry(stamp, self._read(path))
            self._entries[path] = entry
        self._numbers = {}
        self._names = {}
        for path, entry in self._entries.items():
            self._index_calls(path, entry.calls)

    def _list(self) -> list[str] | None:
        """The program files under the folders, or None when there are more than allowed."""
        seen: dict[str, None] = {}
        for folder in self.folders:
            left = self.max_files - len(seen)
            found = search_program_files(folder, left, MAX_FOLDER_ENTRIES, self.settings.extensions)
            seen.update((str(p), None) for p in found.files)
            for problem in found.skipped:
                log.info("%s", pick(self.locale, str(problem), problem.zh))
            if not found.complete or len(seen) > self.max_files:
                where = ", ".join(str(f) for f in self.folders)
                en = f"more than {self.max_files} program files under {where}: callers on disk are not looked for"
                zh = f"{where} 下的程序文件超过 {self.max_files} 个：不查找磁盘上调用它们的程序"
                log.warning("%s", pick(self.locale, en, zh))
                return None
        return sorted(seen)

    def _read(self, path: str) -> tuple[IndexedCall, ...]:
        """The literal calls that the file at ``path`` makes."""
        try:
            text = self.disk.text(path)  # its size was looked at by ``_ensure``
        except FileTooLargeError as e:
            log.info("%s: its calls are not indexed", e)
            return ()
        except (OSError, SkippedFileError):
            return ()
        self.files_read += 1
        word = self._word.search
        if word(text) is None:
            return ()
        self.files_parsed += 1
        try:
            loaded = self.disk.load(path)
        except (OSError, SkippedFileError):  # changed again since
            return ()
        ctx = static_checks.line_context(
            file_profile(loaded.lines, self.settings, self.dialect),
            self.settings,
            self.locale,
        )
        program = loaded.program
        blocks = program.blocks
        out: list[IndexedCall] = []
        for line, text_line in enumerate(loaded.lines):
            if line >= len(blocks) or word(text_line) is None:
                continue
            facts = static_checks.line_facts(blocks[line], ctx)
            if facts is None or not facts.calls:
                continue
            unit = program.units.index(program.unit_at(line))
            for c in facts.calls:
                if c.number is not None or c.name is not None:
                    name = c.name.strip().lower() if c.name is not None else None
                    out.append(IndexedCall(unit, c.number, name))
        return tuple(dict.fromkeys(out))

    # ---------------------------------------------------------------- questions
    def callers(self, number: int | None, name: str | None) -> list[str]:
        """The files on disk that name program ``number`` or the bracketed ``name`` (lower
        case) in a call, sorted: candidates, each to be confirmed by the library's lookup."""
        self._ensure()
        found: set[str] = set()
        if number is not None:
            found |= self._numbers.get(number, set())
        if name is not None:
            found |= self._names.get(name, set())
        return sorted(found)

    def calls_of(self, path: str) -> tuple[IndexedCall, ...]:
        """The literal calls the indexed file ``path`` makes (none for a file not indexed)."""
        self._ensure()
        entry = self._entries.get(path)
        return entry.calls if entry is not None else ()

    def holds(self, path: str) -> bool:
        self._ensure()
        return path in self._entries
