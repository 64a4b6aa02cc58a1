"""The work of ``cncmacro check`` on one machine's files, in pieces a process can be sent.

``MachineWork`` holds what checking one machine's files needs (its settings, the folders a call
looks in, the language, the block budget) and nothing that cannot be sent to another process:
each process makes its own workspaces from it (``workspace``: one ``FileCache`` and one
``CallIndex`` of the callers on disk per process). Its two steps are ``keys`` (what the files
name and call, ``call_groups.file_keys``, and ``names`` when their exact O numbers are needed)
and ``check`` (a batch of call groups, each analysed in one workspace). They run in the checking
process itself with ``--jobs 1`` and in worker processes otherwise (``check_jobs.py``), and
give the same answers either way: what a group's check would say on standard error (a file that
could no longer be read) comes back with its findings as text, and so do the warnings logged
meanwhile (``logged``), for the checking process to write in the order of the groups.
"""

from __future__ import annotations

import gc
import logging
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path

from ..analysis import Diagnostic
from ..analysis.faults import FILE, internal_error
from ..analysis.indexes.call_index import CallIndex
from ..analysis.workspace import WorkspaceAnalysis
from ..bilingual import is_chinese, pick
from ..library.file_cache import FileCache
from ..library.files import MAX_PROGRAM_BYTES, SkippedFileError, read_program, shown_text
from ..library.machine_file import MachineSettings
from ..syntax.document import ParsedDocument
from .call_groups import FileKeys, Key, exact_names, file_keys

log = logging.getLogger(__name__)

Found = tuple[Path, bool]  # a program file, and whether it was found by searching a folder


@dataclass(slots=True)
class GroupResult:
    """What checking one call group gives: its findings, and the lines the check would have
    written on standard error meanwhile (files not read), then the warnings it logged."""

    findings: list[Diagnostic]
    said: list[str]
    logged: list[logging.LogRecord]


@dataclass
class MachineWork:
    """See the module docstring. ``folders`` are the workspace folders (the checked files'
    folders, then the search paths), ``callees`` the folders a call looks in."""

    settings: MachineSettings
    dialect: str | None
    folders: list[str]
    callees: list[str]
    locale: str
    max_blocks: int | None
    # the files checked with these settings: the index of callers on disk does not read them, for
    # a file that calls one of them is in its group, open beside it (``call_groups.join_groups``)
    checked: frozenset[str] = frozenset()
    _fresh: Callable[[], WorkspaceAnalysis] | None = field(default=None, repr=False, compare=False)

    def __getstate__(self) -> dict[str, object]:
        state = {name: getattr(self, name) for name in self.__dataclass_fields__}
        state["_fresh"] = None  # each process makes its own workspaces
        return state

    def __setstate__(self, state: dict[str, object]) -> None:
        for name, value in state.items():
            object.__setattr__(self, name, value)

    def workspace(self) -> WorkspaceAnalysis:
        """A fresh workspace for one group; they share this process's reading of the files on
        disk and its index of their callers."""
        if self._fresh is None:
            disk = FileCache()
            index = CallIndex(self.folders, self.settings, self.dialect, self.locale, files=disk, known=self.checked)
            self._fresh = partial(WorkspaceAnalysis, settings=self.settings, dialect=self.dialect,
                                  search_paths=self.callees, locale=self.locale, max_blocks=self.max_blocks,
                                  severities=self.settings.severity, workspace_folders=self.folders, files=disk,
                                  call_index=index)  # fmt: skip
        return self._fresh()

    def keys(self, files: list[Found]) -> list[FileKeys | str]:
        """``call_groups.file_keys`` of each of ``files``, or what to say of one that could not be read."""
        answers: list[FileKeys | str] = []
        for found in files:
            said: list[str] = []
            text = self._text(found, said)
            answers.append(file_keys(found[0], text, self.settings, self.dialect) if text is not None else said[0])
        return answers

    def names(self, files: list[Found]) -> list[frozenset[Key] | None]:
        """``call_groups.exact_names`` of each of ``files`` (None: it could not be read)."""
        said: list[str] = []
        return [None if (text := self._text(f, said)) is None else exact_names(f[0], text) for f in files]

    def check(self, groups: list[list[Found]]) -> list[GroupResult]:
        """The findings of each of ``groups``, each group analysed in a workspace of its own."""
        results = []
        for group in groups:
            said: list[str] = []
            with logged() as records:
                texts = [(f[0], text) for f in group if (text := self._text(f, said)) is not None]
                collect_left_behind()  # before this group's parse freezes what is alive (``analyse_files``)
                found = analyse_files(texts, self.workspace, self.locale) if texts else []
                _left.behind = True
            results.append(GroupResult(found, said, records))
        return results

    def _text(self, found: Found, said: list[str]) -> str | None:
        """The text of a program file (one found by searching a folder up to
        ``MAX_PROGRAM_BYTES``), or None when it is not read, which is added to ``said``."""
        return read_text(found, self.locale, said)


def read_text(found: Found, locale: str, said: list[str]) -> str | None:
    """The text of the program file ``found`` (one found by searching a folder up to
    ``MAX_PROGRAM_BYTES``), or None when it is not read, which is added to ``said`` in
    ``locale``'s language."""
    path, searched = found
    try:
        return read_program(path, MAX_PROGRAM_BYTES if searched else None).text
    except SkippedFileError as e:
        said.append(f"cncmacro：{e.message.zh}" if is_chinese(locale) else f"cncmacro: {e}")
    except OSError as e:
        why, shown = e.strerror or e, shown_text(str(path))
        said.append(pick(locale, f"cncmacro: {shown}: cannot read: {why}", f"cncmacro：{shown}：无法读取：{why}"))
    return None


@contextmanager
def logged() -> Iterator[list[logging.LogRecord]]:
    """The warnings logged meanwhile, kept (in a worker process) to be logged again by the
    checking process in the order of the groups; in the checking process itself they go out at
    once, as they always did."""
    records: list[logging.LogRecord] = []
    handler = _Keeper(records)
    root = logging.getLogger()
    keep = _in_worker
    if keep:
        root.addHandler(handler)
    try:
        yield records
    finally:
        if keep:
            root.removeHandler(handler)


_in_worker = False  # set in a worker process (``check_jobs.py``)


class _Left:
    """Whether a group checked in this process left its runs and machines, which refer to each
    other, for the cycle collector."""

    behind = False


_left = _Left()


def collect_left_behind() -> None:
    """Collect what the last group checked in this process left, if it has not been: before the
    next group's parse freezes what is alive, and when the check ends in a process that goes on.
    A check that ends its process leaves it (a 1M-line file's, a third of a second)."""
    if _left.behind:
        gc.collect()
        _left.behind = False


def in_worker() -> None:
    """Mark this process as a worker: what it logs is kept and sent back with the findings."""
    global _in_worker
    _in_worker = True
    logging.getLogger().setLevel(logging.WARNING)


class _Keeper(logging.Handler):
    """Keeps each record, its message and traceback made text (a traceback cannot be sent)."""

    def __init__(self, records: list[logging.LogRecord]) -> None:
        super().__init__(logging.WARNING)
        self.records = records
        self.setFormatter(logging.Formatter())  # as Python's last-resort handler writes a record

    def emit(self, record: logging.LogRecord) -> None:
        text = self.format(record)
        kept = logging.makeLogRecord(record.__dict__)
        kept.msg, kept.args, kept.exc_info, kept.exc_text, kept.stack_info = text, None, None, None, None
        self.records.append(kept)


def analyse_files(
    files: list[tuple[Path, str]], workspace: Callable[[], WorkspaceAnalysis], locale: str
) -> list[Diagnostic]:
    """The diagnostics of ``files`` analysed together in a workspace from ``workspace``. Should
    the checker itself fail there (a bug, not a mistake in a program), each file is analysed again
    on its own in a fresh workspace, so that one file that trips the checker costs only its own
    findings: it gets an ``internal-error`` diagnostic, the others are reported as usual.

    The files are parsed before their workspace is made: parsing freezes what is alive for the
    cycle collector (``collector_paused``), and a workspace frozen with its runs in it (which
    refer to each other) would stay in memory after its group is done."""
    try:
        docs = [(str(path), ParsedDocument(text)) for path, text in files]
        ws = workspace()
        for name, doc in docs:
            ws.open(name, doc, 0)
        result = ws.analyze(docs[0][0])
        assert result is not None  # nothing cancels it
        return [d for diags in result.diagnostics.values() for d in diags]
    except Exception:
        log.exception("checking %d files together failed: checking them one by one", len(files))
    found: list[Diagnostic] = []
    for path, text in files:
        try:
            doc = ParsedDocument(text)
            alone = workspace()
            alone.open(str(path), doc, 0)
            result = alone.analyze(str(path))
            assert result is not None
            found += [d for diags in result.diagnostics.values() for d in diags]
        except Exception as e:
            found.append(internal_error(str(path), 0, FILE, e, locale))
    return found
