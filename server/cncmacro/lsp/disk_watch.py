"""Files changed on disk: the file watchers the server asks the editor for, and, where no
editor event can come, the files the analysis read, looked at by time and size.

An editor that can register watchers at run time (``workspace.didChangeWatchedFiles.
dynamicRegistration``) is asked for one on every program file (the endings of
``library.files.PROGRAM_SUFFIXES`` in any case, and ``O1234`` names) and on the machine file,
``.cncmacro.toml``; its events then say what changed under the workspace folders.

Every other change is found by ``DiskStamps``: it keeps (file type, modification time, size) of
each file the analysis read from disk and each folder it listed, plus the places a machine
file is looked for (above the first workspace folder and above each document opened), and
``changed`` names those that differ. That is a handful of ``stat`` calls
(the programs the open ones call, not the workspace), made when an analysis starts and now and
then while documents are open. With the editor's watcher in force, only the paths its patterns
do not cover are looked at: those outside the workspace folders, the folders, and the programs
known by their text or by a machine file's ``extensions`` (``1234.txt`` that starts with
``O1234``), which no fixed pattern names (``watched``).
"""

from __future__ import annotations

import fnmatch
import os
import stat
import time
import weakref
from collections.abc import Iterable
from pathlib import Path

from lsprotocol import types

from ..library.files import PROGRAM_SUFFIXES, stays_inside
from ..library.machine_file import MACHINE_FILE_NAME

REGISTRATION_ID = "cncmacro-program-files"
Stamp = tuple[int, int, int]  # (file type bits, modification time in ns, size)
_UNKNOWN: Stamp = (-1, -1, -1)  # changed while it was read: read again at the next check


def _any_case(text: str) -> str:
    return "".join(f"[{c.lower()}{c.upper()}]" if c.isalpha() else c for c in text)


def watch_globs() -> list[str]:
    """The glob patterns of the program files and the machine file, in any case."""
    endings = [f"**/*{_any_case(suffix)}" for suffix in sorted(PROGRAM_SUFFIXES)]
    return [*endings, "**/[oO][0-9]*", f"**/{MACHINE_FILE_NAME}"]


def watched(path: str) -> bool:
    """Whether a file at ``path`` under a workspace folder is one the editor's watcher reports
    (its name matches one of ``watch_globs``)."""
    name = os.path.basename(path)
    return any(fnmatch.fnmatchcase(name, glob.removeprefix("**/")) for glob in watch_globs())


def watch_registration() -> types.RegistrationParams:
    """The ``client/registerCapability`` request for the editor's file watcher."""
    watchers = [types.FileSystemWatcher(glob_pattern=g) for g in watch_globs()]
    return types.RegistrationParams(
        registrations=[
            types.Registration(
                id=REGISTRATION_ID,
                method=types.WORKSPACE_DID_CHANGE_WATCHED_FILES,
                register_options=types.DidChangeWatchedFilesRegistrationOptions(watchers=watchers),
            )
        ]
    )


def stamp_of(path: str) -> Stamp | None:
    """The path's file type, time and size (its links followed); None when it is not there."""
    try:
        st = os.stat(path)
    except (OSError, ValueError):
        return None
    return (stat.S_IFMT(st.st_mode), st.st_mtime_ns, st.st_size)


class DiskStamps:
    """See the module docstring. ``record`` and ``changed`` run on the analysis thread."""

    def __init__(self) -> None:
        self.evented = False  # the editor's watcher reports the files under the workspace folders
        self._roots: list[Path] = []
        self._fixed: dict[str, Stamp | None] = {}  # where the machine file is looked for
        self._stamps: dict[str, Stamp | None] = {}
        self._inside: dict[str, bool] = {}
        self._sources: list[weakref.ref[object]] = []  # the libraries that read the files

    def set_roots(self, roots: list[str]) -> None:
        """The workspace folders: a machine file is looked for in the first and above it."""
        self._roots = [Path(r) for r in roots if r]
        self._inside.clear()
        self._fixed = {}
        if self._roots:
            self.watch_machine_files(str(self._roots[0]), folder=True)

    def watch_machine_files(self, start: str, folder: bool = False) -> None:
        """Look also at the places a machine file of ``start`` (a document's path, or a
        ``folder``) is looked for: its folder and those above it (``find_machine_file``)."""
        if not os.path.isabs(start):  # an unsaved document: the first folder's are watched
            return
        try:
            p = Path(start).resolve()
        except (OSError, RuntimeError, ValueError):
            return
        first = p if folder or os.path.isdir(p) else p.parent
        places = [str(f / MACHINE_FILE_NAME) for f in (first, *first.parents)]
        if all(place in self._fixed for place in places):
            return
        fixed = dict(self._fixed)  # a new dictionary: the analysis thread may be looking at the old one
        for place in places:
            if place not in fixed:
                fixed[place] = stamp_of(place)
        self._fixed = fixed

    def record(self, sources: list[object], paths: Iterable[str], started_ns: int) -> None:
        """After an analysis that started at ``started_ns``: ``paths`` are what ``sources`` (the
        analyses' program libraries) have read from disk. A path met before keeps its stamp
        while the same libraries hold it; a new one is stamped now, as unknown when it was
        changed since the analysis started (it may have been read before that change)."""
        fresh = len(sources) != len(self._sources) or any(
            r() is not s for r, s in zip(self._sources, sources, strict=True)
        )
        self._sources = [weakref.ref(s) for s in sources]
        ended = time.time_ns()
        old = {} if fresh else self._stamps
        stamps: dict[str, Stamp | None] = {}
        for path in paths:
            if path in old:
                stamps[path] = old[path]
                continue
            now = stamp_of(path)
            stamps[path] = _UNKNOWN if now is not None and started_ns <= now[1] <= ended else now
        self._stamps = stamps
        self._inside = {p: v for p, v in self._inside.items() if p in stamps or p in self._fixed}

    def seen(self, paths: list[str]) -> None:
        """``paths`` are about to be read again (an editor's event named them): their stamps
        are taken now, so that the next look does not find the same change again."""
        for kept in (self._fixed, self._stamps):
            for path in paths:
                if path in kept:
                    kept[path] = stamp_of(path)

    def changed(self) -> list[str]:
        """The paths whose stamp differs from the one kept (their new stamps kept now)."""
        out = []
        for kept in (self._fixed, self._stamps):
            for path, before in kept.items():
                if self.evented and self._reported(path):
                    continue
                now = stamp_of(path)
                if now != before:
                    kept[path] = now
                    out.append(path)
        return out

    def _reported(self, path: str) -> bool:
        """Whether the editor's watcher reports changes of ``path``: a file its patterns name
        under a workspace folder (a folder's new files it reports only by their names)."""
        reported = self._inside.get(path)
        if reported is None:
            under = any(stays_inside(Path(path), r) for r in self._roots)
            reported = self._inside[path] = under and not os.path.isdir(path) and watched(path)
        return reported
