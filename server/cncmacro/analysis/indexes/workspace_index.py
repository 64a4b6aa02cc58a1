"""The index of program files across the workspace, kept fresh by file events: which programs
exist, where each file's labels and variables are, which program a call names.

At start every program file under the workspace folders is read and parsed once (through its
``FileCache``, ``library/file_cache.py``, the one reader of the workspace's files: the
analysis's program library and call index read through the same one), as a search of a workspace folder
reads files (``library/files.py``: at most ``MAX_PROGRAM_FILES`` files and ``MAX_FOLDER_ENTRIES``
entries per folder, each file up to ``MAX_PROGRAM_BYTES``, regular files only, ``MAX_INDEX_BYTES``
in all, so that ``initialize`` is answered soon whatever the folder, ``/`` too); what was not read
is kept in ``skipped`` for the server to report (a file over the size limit, often a long CAM
program, is named as not read for the programs calls look for: opened in the editor it is read
and checked in full). A file changed on disk (an editor's file event,
or ``disk_watch.py``) is read again, or dropped when it is gone; only a regular file is ever
opened (a FIFO named ``O1234.nc`` would wait for a writer). Open documents take the place of
their file on disk, so every question (which programs exist, where ``#100`` is written, who
calls O9100) sees the editor's text: the index knows them through ``open_files``, a function
giving the open documents (``OpenFile``: path, lines, parsed text, site index), and reads each
one's dialect through ``dialect_for``. Each file on disk gets a site index (``site_index.py``)
at the first search, kept while the file is. Program lookup for a call goes through
``library.programs.ProgramLibrary``, in the folders of the programs read with the calling
file's machine file (``library/callee_folders.py``). It knows nothing of a protocol: the language server makes
one over its documents.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from ...bilingual import Detail, detail
from ...dialects.dialect import Dialect
from ...library.callee_folders import callee_folders
from ...library.file_cache import FileCache
from ...library.files import (
    MAX_FOLDER_ENTRIES,
    MAX_INDEX_BYTES,
    MAX_PROGRAM_FILES,
    BinaryFileError,
    FileTooLargeError,
    ReadScope,
    SkippedFileError,
    is_program_file,
    search_program_files,
    shown_text,
)
from ...library.machine_file import MACHINE_FILE_NAME
from ...library.programs import FoundProgram, Listing, ListingKey, LoadedFile, ProgramLibrary, forget_listings
from ...syntax.document import ParsedDocument
from .block_memo import BlockMemo
from .site_index import FileSites, SiteIndex
from .sites import Calls

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


class OpenFile(Protocol):
    """A document open in an editor, as the index sees it (the language server's
    ``OpenDocument``)."""

    @property
    def path(self) -> str: ...

    @property
    def lines(self) -> list[str]: ...

    @property
    def parsed(self) -> ParsedDocument: ...

    @property
    def sites(self) -> SiteIndex: ...

    def as_loaded(self) -> LoadedFile: ...


class WorkspaceIndex:
    """Parsed program files under the workspace folders, with the open documents on top.
    ``memo`` is the per-line fact cache of the open documents (``block_memo.py``), shared by
    the files on disk; ``files`` reads the files (a cache of its own when none is given);
    ``extensions_for`` gives the machine file's endings of program files for a path, ``machine_of``
    the machine file it is read with."""

    def __init__(self, open_files: Callable[[], Iterable[OpenFile]], dialect_for: Callable[[list[str], str], Dialect],
                 memo: BlockMemo | None = None, files: FileCache | None = None,
                 calls_for: Callable[[str], Calls] = lambda path: None,
                 extensions_for: Callable[[str], frozenset[str]] = lambda path: frozenset(),
                 machine_of: Callable[[str], Path | None] = lambda path: None,
                 reading_rule: Callable[[], object] = lambda: None) -> None:  # fmt: skip
        self.open_files = open_files
        # what ``dialect_for`` and ``calls_for`` answer by besides a file's text (the editor's
        # setting, the machine files): while it is the same, a file's answer is kept with its sites
        self.reading_rule = reading_rule
        self.machine_of = machine_of  # the machine file a path is read with
        self.extensions_for = extensions_for
        self.dialect_for = dialect_for
        self.calls_for = calls_for  # the machine file's call codes for a path (which words are jumps)
        self.memo = memo if memo is not None else BlockMemo()
        self.disk = files if files is not None else FileCache()
        self.roots: list[Path] = []
        self.files: dict[str, LoadedFile] = {}
        self.skipped: list[Detail] = []  # what the last scan did not read, and why
        # the files' site indexes, by path, with the reading rule they were made under
        self._sites: dict[str, tuple[LoadedFile, SiteIndex, object]] = {}
        # per folder, the program numbers no file header there holds: a call to a program outside
        # the index is searched for in its folders' first files once, not at every hover or look-up
        # (``ProgramLibrary.find_number``); a folder's entry goes when a file there changes
        self.absent: dict[Path, set[int]] = {}
        # the program files on disk of the folders the libraries of hovers and look-ups listed
        # (``ProgramLibrary``'s ``listings``): a folder is listed again only when a file comes or goes
        self.listings: dict[ListingKey, Listing] = {}
        # per machine file, the folders of its program files (``callee_folders``), until a file
        # comes into the index or leaves it: not worked out from every indexed file at each hover
        self._callee: dict[Path | None, list[str]] = {}

    def scan(self, roots: list[str]) -> int:
        """Read every program file under ``roots``; the number of files indexed."""
        self.roots = [Path(r) for r in roots if r]
        self.files.clear()
        self.absent.clear()
        self.listings.clear()
        self._callee.clear()
        self.skipped = []
        read = 0
        for root in self.roots:  # what the cache holds of them is read again, all at once
            self.disk.forget(str(root))
        for root in self.roots:
            if not os.path.isdir(root):
                continue
            found = search_program_files(root, MAX_PROGRAM_FILES, MAX_FOLDER_ENTRIES, self.extensions_for(str(root)))
            self.skipped += found.skipped
            for k, p in enumerate(found.files):
                if read > MAX_INDEX_BYTES:
                    self.skipped.append(_index_full(root, len(found.files) - k))
                    break
                problem = self.reload(str(p), scanning=True)
                if problem is not None:
                    self.skipped.append(problem)
                elif str(p) in self.files:
                    read += sum(len(line) + 1 for line in self.files[str(p)].lines)
        return len(self.files)

    def reload(self, path: str, scanning: bool = False) -> Detail | None:
        """Read one file again (created, changed or deleted on disk); why it was not read, if it
        was not (a binary file is only logged: it is no program). The file cache reads it again
        at the next question, wherever it is. ``scanning``: read by ``scan``, which forgot what the
        cache held under its roots at once, so nothing is forgotten file by file (each of which
        looked at every file the cache holds: a scan of thousands of files was quadratic)."""
        held = path in self.files
        try:
            return self._reload(path, scanning)
        finally:
            if (path in self.files) != held or Path(path).name == MACHINE_FILE_NAME:
                self._callee.clear()  # the folders of a machine's programs may be others now

    def _reload(self, path: str, scanning: bool = False) -> Detail | None:
        if not scanning:
            self.disk.forget(path)
            self.absent.pop(Path(path).parent, None)  # it may hold a header searched for in vain
            forget_listings(self.listings, path)
        if path not in self.files and len(self.files) >= MAX_PROGRAM_FILES:
            return None  # the index is full: a file it does not hold is not read for it (a branch switch of 100k files)
        if ReadScope.of(self.roots, extensions=self.extensions_for(path)).refusal(path) is not None:
            return None  # only program files under the workspace folders are read
        try:
            os.lstat(path)
        except FileNotFoundError:  # gone (a file that cannot be looked at is said so below)
            self.files.pop(path, None)
            return None
        except OSError:
            pass
        try:
            loaded = self.disk.load(path)
        except (OSError, SkippedFileError) as e:
            self.files.pop(path, None)
            if isinstance(e, BinaryFileError):
                log.info("not indexed: %s", e)
                return None
            if isinstance(e, FileTooLargeError):  # a long CAM file, or a program a call will miss
                shown = shown_text(path)
                return detail(
                    f"{shown}: {e.size:,} bytes, over the limit of {e.limit:,}: not read for the programs that calls"
                    " look for (opened in the editor, it is checked in full)",
                    f"{shown}：{e.size:,} 字节，超过 {e.limit:,} 字节的上限：调用查找程序时不读取"
                    "（在编辑器中打开则完整检查）",
                )
            if isinstance(e, SkippedFileError):
                return e.message
            reason = e.strerror or str(e)
            shown = shown_text(path)
            return detail(f"{shown}: cannot read ({reason})", f"{shown}：无法读取（{reason}）")
        self.files[path] = loaded
        return None

    def refresh_folder(self, folder: str) -> None:
        """A folder's entries changed: its program files that are new are read, the ones gone
        dropped (the others are read again by their own change)."""
        here = Path(folder)
        self.absent.pop(here, None)
        for key in [k for k in list(self.listings) if k[0] == here]:
            del self.listings[key]
        try:
            names = os.listdir(here)
        except OSError:
            names = []
        extensions = self.extensions_for(folder)
        present = {str(here / n) for n in names if not n.startswith(".") and is_program_file(here / n, extensions)}
        for path in [p for p in self.files if Path(p).parent == here and p not in present]:
            del self.files[path]
            self._callee.clear()
        for path in sorted(present - self.files.keys()):
            self.reload(path)

    # ---- views
    def loaded_files(self) -> Iterator[LoadedFile]:
        """Every program file: open documents as the editor has them, the rest as on disk."""
        open_paths = set()
        for doc in self.open_files():
            open_paths.add(doc.path)
            yield doc.as_loaded()
        for path, loaded in self.files.items():
            if path not in open_paths:
                yield loaded

    def file_sites(self) -> Iterator[FileSites]:
        """Every program file with its site index: open documents as the editor has them (their
        own index), the others as on disk (an index per loaded file, kept while it is)."""
        open_paths = set()
        for doc in self.open_files():
            open_paths.add(doc.path)
            yield FileSites(doc.path, doc.lines, doc.sites)
        files = self.files
        kept = self._sites
        for path in [p for p, (loaded, _, _) in kept.items() if files.get(p) is not loaded]:
            del kept[path]
        rule = self.reading_rule()
        for path, loaded in files.items():
            if path in open_paths:
                continue
            hit = kept.get(path)
            if hit is None or hit[2] != rule:  # the profile and call codes asked once per rule, not per hover
                dialect, calls = self.dialect_for(loaded.lines, path), self.calls_for(path)
                if hit is None or not hit[1].reads_with(dialect, calls):
                    hit = (loaded, SiteIndex(loaded.program.blocks, dialect, calls, self.memo), rule)
                else:
                    hit = (loaded, hit[1], rule)
                kept[path] = hit
            yield FileSites(path, loaded.lines, hit[1])

    def machine_sites(self, path: str, dialect: Dialect) -> Iterator[FileSites]:
        """``file_sites`` of the one machine the file at ``path``, read in ``dialect``, runs on:
        the files read with the same machine file (``machine_of``) in the same profile. A
        control's commons and system variables are one memory for all its programs; a file of
        another control in the same folder (its dialect comment names another profile) or under
        another machine file is another machine, whose ``#100`` is not this one's."""
        machine = self.machine_of(path)
        for f in self.file_sites():
            if f.sites.dialect.name == dialect.name and (f.path == path or self.machine_of(f.path) == machine):
                yield f

    def programs(self) -> Iterator[ProgramEntry]:
        """Every program, named as the outline names it (``Program.named_units``)."""
        for f in self.loaded_files():
            units = f.program.named_units()
            for u in units:
                if u.number is None and u.end - u.start <= 0:
                    continue
                name = f"O{u.number:04d}" if u.number is not None else Path(f.path).stem
                yield ProgramEntry(name, u.number, u.title, f.path, u.start, u.end, u is units[0])

    def callee_folders(self, machine_file: Path | None) -> list[str]:
        """The folders a call in a file read with ``machine_file`` looks in beyond its own: the
        folders of the workspace's program files read with that machine file
        (``library/callee_folders.py``, the rule ``cncmacro check`` follows)."""
        folders = self._callee.get(machine_file)
        if folders is None:
            folders = self._callee[machine_file] = callee_folders(
                (), (p for p in self.files if self.machine_of(p) == machine_file)
            )
        return folders

    def folders_to_list(self) -> ProgramLibrary | None:
        """A library over the folders a call looks in (those of the first workspace folder's
        machine), whose ``list_folders`` lists them into ``listings`` ahead of the first hover or
        look-up on a call, which would otherwise wait for it (100 folders of 1,000 programs take
        over half a second). Made here; listing touches only the disk and ``listings``, so it
        may run on a thread of its own."""
        if not self.roots:
            return None
        where = str(self.roots[0])
        return ProgramLibrary(folders=self.callee_folders(self.machine_of(where)), files=self.disk,
                              extensions=self.extensions_for(where), listings=self.listings)  # fmt: skip

    def library(self, near: OpenFile | None) -> ProgramLibrary:
        """A program library over the folders of the machine's programs (``near``'s machine,
        else the first workspace folder's) with the open documents' text (the files on disk
        read through the index's cache), which finds for a call only the programs read in the
        calling file's profile (``ProgramLibrary.on_machine``)."""
        open_files = list(self.open_files())
        texts = {d.path: d.parsed.text for d in open_files if near is None or d is not near}
        for d in open_files:  # an open document's text may hold a header by now
            self.absent.pop(Path(d.path).parent, None)
        where = near.path if near is not None else str(self.roots[0]) if self.roots else ""
        folders = self.callee_folders(self.machine_of(where)) if where else list(map(str, self.roots))
        extensions = self.extensions_for(where)
        return ProgramLibrary(folders=folders, texts=texts, files=self.disk, extensions=extensions,
                              absent=self.absent, listings=self.listings, profile_of=self._profile_name)  # fmt: skip

    def _profile_name(self, lines: list[str], path: str) -> str:
        """The name of the profile the file at ``path`` is read in (``dialect_for``): a call finds
        only the programs of its own file's profile, as ``machine_sites`` shares variables."""
        return self.dialect_for(lines, path).name

    def find_program(self, doc: OpenFile, number: int | None, name: str | None) -> FoundProgram | None:
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
        f"{shown}：{left:,} 个程序文件未编入索引：已编入的文本已达 {MAX_INDEX_BYTES:,} 字节",
    )
