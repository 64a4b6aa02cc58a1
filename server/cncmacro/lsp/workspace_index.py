"""The index of program files across the workspace, kept fresh by file events.

At start every program file under the workspace folders is read and parsed once (through the
program library's ``load_text``, with the shared block cache). A file changed on disk (an
editor's file event, or ``disk_watch.py``) is read again, or dropped when it is gone; only a
regular file is ever opened (a FIFO named ``O1234.nc`` would wait for a writer). Open
documents take the place of their file on disk, so every question (which programs exist,
where ``#100`` is written, who calls O9100) sees the editor's text. Program lookup for a call
goes through ``library.programs.ProgramLibrary``.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from ..library.files import BinaryFileError, ReadScope, find_program_files, is_program_file
from ..library.programs import FoundProgram, LoadedFile, ProgramLibrary, load_text
from .documents import Documents, OpenDocument

log = logging.getLogger(__name__)


@dataclass(frozen=True, slots=True)
class ProgramEntry:
    """One O program of the workspace (or a file without a header, named by its file)."""

    name: str  # O9100, or the file's stem
    number: int | None
    title: str | None
    path: str
    line: int
    end: int


class WorkspaceIndex:
    """Parsed program files under the workspace folders, with the open documents on top."""

    def __init__(self, documents: Documents) -> None:
        self.documents = documents
        self.roots: list[Path] = []
        self.files: dict[str, LoadedFile] = {}

    def scan(self, roots: list[str]) -> int:
        """Read every program file under ``roots``; the number of files indexed."""
        self.roots = [Path(r) for r in roots if r]
        self.files.clear()
        for root in self.roots:
            if not root.is_dir():
                continue
            for p in find_program_files(root):
                self.reload(str(p))
        return len(self.files)

    def reload(self, path: str) -> None:
        """Read one file again (created, changed or deleted on disk)."""
        if not Path(path).is_file():  # gone, or not a regular file: never opened
            self.files.pop(path, None)
            return
        try:
            text = ReadScope.of(self.roots).read(path).text  # program files under the workspace folders only
        except (OSError, BinaryFileError) as e:
            log.info("not indexed: %s", e)
            self.files.pop(path, None)
            return
        self.files[path] = load_text(path, text)

    def refresh_folder(self, folder: str) -> None:
        """A folder's entries changed: its program files that are new are read, the ones gone
        dropped (the others are read again by their own change)."""
        here = Path(folder)
        try:
            names = os.listdir(here)
        except OSError:
            names = []
        present = {str(here / n) for n in names if not n.startswith(".") and is_program_file(here / n)}
        for path in [p for p in self.files if Path(p).parent == here and p not in present]:
            del self.files[path]
        for path in sorted(present - self.files.keys()):
            self.reload(path)

    # ---- views
    def loaded_files(self) -> Iterator[LoadedFile]:
        """Every program file: open documents as the editor has them, the rest as on disk."""
        open_paths = set()
        for doc in self.documents.by_uri.values():
            open_paths.add(doc.path)
            yield doc.as_loaded()
        for path, loaded in self.files.items():
            if path not in open_paths:
                yield loaded

    def programs(self) -> Iterator[ProgramEntry]:
        for f in self.loaded_files():
            for u in f.program.units:
                if u.number is None and u.end - u.start <= 0:
                    continue
                name = f"O{u.number:04d}" if u.number is not None else Path(f.path).stem
                yield ProgramEntry(name, u.number, u.title, f.path, u.start, u.end)

    def library(self, near: OpenDocument | None) -> ProgramLibrary:
        """A program library over the workspace folders with the open documents' text."""
        texts = {d.path: d.parsed.text for d in self.documents.by_uri.values() if near is None or d is not near}
        return ProgramLibrary(folders=list(self.roots), texts=texts)

    def find_program(self, doc: OpenDocument, number: int | None, name: str | None) -> FoundProgram | None:
        """The program a call in ``doc`` names, found as the program library finds it."""
        lib = self.library(doc)
        near = doc.as_loaded()
        if name is not None:
            return lib.find_name(name, near)
        if number is not None:
            return lib.find_number(number, near)
        return None
