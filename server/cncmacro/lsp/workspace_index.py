"""The index of program files across the workspace, kept fresh by file events.

At start every program file under the workspace folders is read and parsed once (through the
program library's ``load_text``, with the shared block cache), as a search of a workspace folder
reads files (``library/files.py``: at most ``MAX_PROGRAM_FILES`` files and ``MAX_FOLDER_ENTRIES``
entries per folder, each file up to ``MAX_PROGRAM_BYTES``, regular files only, ``MAX_INDEX_BYTES``
in all, so that ``initialize`` is answered soon whatever the folder, ``/`` too); what was not read
is kept in ``skipped`` for the server to report. A file changed on disk (an editor's file event,
or ``disk_watch.py``) is read again, or dropped when it is gone; only a regular file is ever
opened (a FIFO named ``O1234.nc`` would wait for a writer). Open documents take the place of
their file on disk, so every question (which programs exist, where ``#100`` is written, who
calls O9100) sees the editor's text. Program lookup for a call goes through
``library.programs.ProgramLibrary``.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import Detail, detail
from ..library.files import (
    MAX_FOLDER_ENTRIES,
    MAX_INDEX_BYTES,
    MAX_PROGRAM_FILES,
    BinaryFileError,
    ReadScope,
    SkippedFileError,
    is_program_file,
    read_program,
    search_program_files,
    shown_text,
)
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
    first: bool  # the file's first program (what a call by the file's name runs)


class WorkspaceIndex:
    """Parsed program files under the workspace folders, with the open documents on top."""

    def __init__(self, documents: Documents) -> None:
        self.documents = documents
        self.roots: list[Path] = []
        self.files: dict[str, LoadedFile] = {}
        self.skipped: list[Detail] = []  # what the last scan did not read, and why

    def scan(self, roots: list[str]) -> int:
        """Read every program file under ``roots``; the number of files indexed."""
        self.roots = [Path(r) for r in roots if r]
        self.files.clear()
        self.skipped = []
        read = 0
        for root in self.roots:
            if not os.path.isdir(root):
                continue
            found = search_program_files(root, MAX_PROGRAM_FILES, MAX_FOLDER_ENTRIES)
            self.skipped += found.skipped
            for k, p in enumerate(found.files):
                if read > MAX_INDEX_BYTES:
                    self.skipped.append(_index_full(root, len(found.files) - k))
                    break
                problem = self.reload(str(p))
                if problem is not None:
                    self.skipped.append(problem)
                elif str(p) in self.files:
                    read += sum(len(line) + 1 for line in self.files[str(p)].lines)
        return len(self.files)

    def reload(self, path: str) -> Detail | None:
        """Read one file again (created, changed or deleted on disk); why it was not read, if it
        was not (a binary file is only logged: it is no program)."""
        if ReadScope.of(self.roots).refusal(path) is not None:
            return None  # only program files under the workspace folders are read
        try:
            os.lstat(path)
        except FileNotFoundError:  # gone (a file that cannot be looked at is said so below)
            self.files.pop(path, None)
            return None
        except OSError:
            pass
        try:
            text = read_program(path).text
        except (OSError, SkippedFileError) as e:
            self.files.pop(path, None)
            if isinstance(e, BinaryFileError):
                log.info("not indexed: %s", e)
                return None
            if isinstance(e, SkippedFileError):
                return e.message
            reason = e.strerror or str(e)
            shown = shown_text(path)
            return detail(f"{shown}: cannot read ({reason})", f"{shown}：无法读取（{reason}）")
        self.files[path] = load_text(path, text)
        return None

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
        """Every program, named as the outline names it (``Program.named_units``)."""
        for f in self.loaded_files():
            units = f.program.named_units()
            for u in units:
                if u.number is None and u.end - u.start <= 0:
                    continue
                name = f"O{u.number:04d}" if u.number is not None else Path(f.path).stem
                yield ProgramEntry(name, u.number, u.title, f.path, u.start, u.end, u is units[0])

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


def _index_full(root: Path, left: int) -> Detail:
    shown = shown_text(str(root))
    return detail(
        f"{shown}: {left:,} program files are not indexed: the index holds {MAX_INDEX_BYTES:,} bytes of text already",
        f"{shown}：{left:,} 个程序文件未编入索引：索引已有 {MAX_INDEX_BYTES:,} 字节的文本",
    )
