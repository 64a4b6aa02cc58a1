"""Which open programs are called from files on disk, and the programs there whose runs reach them.

An open program that no open file calls is looked for in the program files of the workspace
folders (``call_index.py``: an index of literal calls, read lazily and kept per file by time and
size; ``changed`` brings it up to date). When a file there calls it (the library's lookup from
that file reaching it), it is analysed through the programs on disk that reach it, callers of
callers up to a program nothing calls (``caller_entries.py``, at most ``MAX_CALLER_ENTRIES`` of
them), loaded from disk; an open file's text always wins over its file. Their runs report only
what they find in open files: a caller that was not opened is run for its arguments, not
reported.
"""

from __future__ import annotations

import logging
import os
from collections import Counter
from collections.abc import Callable, Mapping
from typing import Any, Generic, TypeVar

from ...library.file_cache import FileCache
from ...library.machine_file import MachineSettings
from ...library.programs import FoundProgram, ProgramLibrary
from .call_index import CallIndex
from .caller_entries import CallerSearch, call_identity
from .open_programs import OpenProgram, RunKey

log = logging.getLogger(__name__)

MAX_CALLER_ENTRIES = 16  # programs on disk run to reach the open ones, at most
_T = TypeVar("_T")
Targets = tuple[set[int], set[str]]  # the program numbers and names a file calls


class DiskCallers:
    """The callers on disk of the open programs: ``entries``, the programs on disk that runs
    start from (None until found, and again when what they depend on changed), and
    ``called_from_disk``, the open programs they reach."""

    def __init__(self, index: CallIndex | None = None) -> None:
        # made at the first question (``find``), unless given: one index shared by workspaces
        # that look at the same folders (``cncmacro check``'s groups of files)
        self.index: CallIndex | None = index
        self.entries: dict[RunKey, FoundProgram] | None = None
        self.called_from_disk: set[RunKey] = set()

    def forget(self) -> None:
        """The folders or the settings changed: the index is made again at the next question."""
        self.index = None
        self.entries = None

    def changed(self, path: str, units: Callable[[], list[OpenProgram]]) -> bool:
        """A file changed on disk: the index reads it again. Whether the callers found may be
        others now (then ``entries`` is None): not when none were looked for yet, nor when the
        file neither called, nor now calls, a program of ``units`` (the open programs) and no
        open program was found called from disk; a file that came or went counts as one that
        may call them."""
        if self.index is None:
            return False
        usable = self.index.usable
        before = self.index.changed(path)
        if self.entries is None:
            return False
        if not usable and os.path.isfile(path):
            return False  # more files than the index takes: one more, or one saved, keeps it so
        if self.called_from_disk or self.entries or before is None:
            self.entries = None
            return True
        numbers: set[int] = set()
        names: set[str] = set()
        for _, found, _ in units():
            n, s = call_identity(found)
            numbers |= n
            names |= s
        after = self.index.calls_of(path)
        if any(c.number in numbers or c.name in names for c in (*before, *after)):
            self.entries = None
            return True
        return False

    def find(self, units: list[OpenProgram], folders: list[str], settings: MachineSettings, dialect: str | None,
             locale: str, files: FileCache, library: ProgramLibrary, targets: Callable[[], Mapping[str, Targets]],
             real_paths: dict[str, str]) -> None:  # fmt: skip
        """Which of ``units`` that no open file calls are called from files on disk in
        ``folders`` (``called_from_disk``), and the programs on disk that runs start from to
        reach them (``entries``): the callers' callers, up to a program nothing calls. A call
        counts when the library's lookup from the calling file reaches the program
        (``caller_entries.py``). ``targets`` gives what each open file calls (asked only when
        a program is left to look for); ``real_paths`` the open files' paths, links resolved."""
        self.entries = {}
        self.called_from_disk = set()
        if not folders or all(called for _, _, called in units):
            return
        if self.index is None:
            self.index = CallIndex(folders, settings, dialect, locale, files=files)
        calls = targets()
        # how many open files call each program number and name: what the files other than a
        # unit's own call is then one look-up away (not a union over every open file per unit)
        number_calls: Counter[int] = Counter()
        name_calls: Counter[str] = Counter()
        for n, s in calls.values():
            number_calls.update(n)
            name_calls.update(s)
        finder = CallerSearch(library, self.index, real_paths)
        for key, found, called in units:
            if called:
                continue
            own_numbers, own_names = calls[key[0]]
            # what the other open files call: their runs reach those programs
            numbers = _CalledElsewhere(number_calls, own_numbers)
            names = _CalledElsewhere(name_calls, own_names)
            roots = finder.roots(found, numbers, names)
            if roots is None:
                continue  # nothing on disk calls it: it runs on its own
            self.called_from_disk.add(key)
            for k, entry in roots.items():
                if k not in self.entries and len(self.entries) >= MAX_CALLER_ENTRIES:
                    log.info("more than %d programs on disk call the open ones: only the first run", MAX_CALLER_ENTRIES)
                    break
                self.entries[k] = entry


class _CalledElsewhere(Generic[_T]):
    """The program numbers (or names) that open files other than one call."""

    __slots__ = ("counts", "own")

    def __init__(self, counts: Counter[_T], own: set[_T]) -> None:
        # looked up with any object, as a Container is: one of another type is simply absent
        self.counts: Mapping[Any, int] = counts
        self.own = own

    def __contains__(self, item: object) -> bool:
        return self.counts.get(item, 0) > (1 if item in self.own else 0)
