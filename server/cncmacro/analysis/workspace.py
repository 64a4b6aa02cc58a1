"""The analysis of a workspace of program files, kept up to date across edits.

``WorkspaceAnalysis`` is what the command line and the language server use::

    ws = WorkspaceAnalysis(settings=..., dialect="fanuc", search_paths=[...], locale="en",
                           max_blocks=None, severities={"macro-alarm": "error"},
                           workspace_folders=[...])
    ws.set_workspace_folders([...])       # the editor's workspace folders changed
    ws.open(path, text, version)          # editor-owned text wins over the file on disk
    ws.change(path, l0, c0, l1, c1, text, version)   # an editor change (0-based positions)
    ws.close(path); ws.file_changed(path)            # closed; created/changed/deleted on disk
    result = ws.analyze(path, should_cancel)         # None when cancelled

``AnalysisResult`` (``workspace_result.py``) holds ``version`` (of ``path`` when it was
analysed), ``diagnostics`` (file -> list, severities applied: syntax, static checks, and what
the runs found) and ``values`` (file -> 0-based line -> ``[(variable number, value)]``, the
value each assignment on that line left the last time a run executed it; None is vacant).

The parts, each in its own module: the open documents and their edits
(``workspace_documents.py``), which of their programs run on their own
(``open_programs.py``), their callers on disk (``disk_callers.py``), the runs
(``entry_runs.py``, taken back after edits by ``run_rewind.py``), the result
(``workspace_result.py``) and a huge document's first screen (``first_screen.py``). This
module holds them together: the settings, the library, and the order of an analysis.

Which programs run: every O program of the open files (but a repeated O number's later copy,
which the control does not keep: ``ProgramUnit.duplicate``) that no workspace file calls with a
literal target (G65/G66/M98/call codes) runs on its own, with vacant arguments, ``M99`` at
level 0 ending it; a called program is analysed through its callers, with their arguments,
and its findings appear in its own file. A called program that no caller's run entered gets
the static checks only: run on its own, its argument checks (``IF[#20 EQ #0] THEN #3000=..``)
and divisions by arguments would report what no real call does.

Callers on disk: an open program that no open file calls is looked for in the program files of
the workspace folders (``disk_callers.py``; ``file_changed`` brings its index up to date) and,
when a file there calls it, analysed through the programs on disk that reach it. Their runs
are incremental like any other, and report only what they find in open files. Only the
workspace folders and the search paths are ever read. The dialect of a run is its entry file's
(``library/profiles.py``'s ``file_profile``): a ``(cncmacro: dialect=..)`` comment in the first
lines, then the machine file's ``dialect``, then ``dialect`` given here, then ``fanuc``. Files on disk are read through
``files`` (a ``FileCache``, shared by the program library and the call index): the language
server gives its workspace index's, which it tells of changes itself; without one the analysis
keeps its own, which ``file_changed`` tells.

Incremental: parsing is per line (``ParsedDocument``); the per-line static checks are kept
per line (``StaticLines``), so an edit checks only its lines plus the cross-line part. Each
run keeps checkpoints and the step at which each line first ran, and after an edit resumes
from a checkpoint before the first step the edit can change (``run_rewind.py``); the resumed
run takes the rest of the run before the edit over as soon as its state equals that run's
state at one of its checkpoints and the edited lines do not run after it
(``run_convergence.py``), so that an edit near the start of a long program runs only a few
chunks again; whether a file may read the simulated clock, which then has to be equal too, is
counted per open document from its text (``clock_reads.py``). A changed O header, a dialect
comment or a file changed on disk runs everything again.
"""

from __future__ import annotations

import gc
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from ..bilingual import pick
from ..dialects import Dialect
from ..library.dialect_choice import HEADER_LINES, dialect_from_text
from ..library.file_cache import FileCache
from ..library.machine_file import MachineSettings
from ..library.profiles import file_profile
from ..library.programs import FoundProgram, ProgramLibrary
from ..machine import block_roles
from ..syntax.document import ParsedDocument
from ..syntax.nodes import Block
from .checks import static_checks
from .checks.profile_comment import profile_comment_diagnostics
from .checks.profile_suggestion import suggestion
from .checks.static_lines import StaticLines
from .diagnostics import Diagnostic
from .first_screen import FIRST_SCREEN_LINES, first_screen_findings
from .indexes.block_memo import BlockMemo
from .indexes.call_index import CallIndex
from .indexes.disk_callers import DiskCallers, Targets
from .indexes.open_programs import OpenProgram, RunKey, open_programs
from .runs.clock_reads import DiskClockReads
from .runs.entry_runs import EntryRuns
from .runs.run_checks import MAX_RECORDS, MAX_SECONDS, EntryRun
from .runs.unreached import UnreachedRanges
from .severity import check_overrides
from .workspace_documents import WorkspaceDocument
from .workspace_result import AnalysisResult, gather

STATIC_SHARE = 0.5  # of a first analysis's progress, the share of the per-line checks (the runs take the rest)


@dataclass(frozen=True, slots=True)
class Progress:
    """How far an analysis got: what it does now (in the user's language) and the fraction done
    (an estimate: the per-line checks, then each run)."""

    what: str
    done: float


class WorkspaceAnalysis:
    """See the module docstring."""

    def __init__(
        self,
        *,
        settings: MachineSettings | None = None,
        dialect: str | None = None,
        search_paths: Sequence[str] = (),
        locale: str = "en",
        max_blocks: int | None = None,
        severities: dict[str, str] | None = None,
        workspace_folders: Sequence[str] = (),
        files: FileCache | None = None,
        memo: BlockMemo | None = None,
        call_index: CallIndex | None = None,
    ) -> None:
        self.settings = settings or MachineSettings()
        self.memo = memo if memo is not None else BlockMemo()  # what each block says by itself
        self.dialect_setting = dialect
        self.search_paths = [str(p) for p in search_paths]
        self.locale = locale
        self.max_blocks = max_blocks if max_blocks is not None else self.settings.max_blocks
        self.max_seconds = MAX_SECONDS  # each run's wall-clock limit and record cap (run_checks.py)
        self.max_records = MAX_RECORDS
        self.progress = Progress("", 0.0)  # how far the analysis got (read from another thread)
        self.severities = check_overrides(dict(severities or {}))
        self.docs: dict[str, WorkspaceDocument] = {}
        self._disk_clock = DiskClockReads()  # files not open: can they read the clock?
        self.stale = True  # every run starts again
        # reads the files on disk, each once; a cache given here is told of changes by its owner
        self._own_files = files is None
        self.files = files if files is not None else FileCache()
        self._library = ProgramLibrary(
            self.search_paths, files=self.files, extensions=self.settings.extensions, profile_of=self._profile_name
        )
        self._library_due = False  # the library is made again when next used (``_reload``)
        self.workspace_folders = [str(p) for p in workspace_folders]
        # the open programs' callers on disk, and the runs that start there; ``call_index``, when
        # given, is an index of those folders shared with other workspaces (reading the same files)
        self.callers = DiskCallers(call_index)
        # the not-executed ranges, kept across edits
        self._unreached = UnreachedRanges(lambda b: block_roles.passed_over(b, self.settings.block_delete))
        self._runs = EntryRuns(self._unreached, self._start_run)

    @property
    def runs(self) -> dict[RunKey, EntryRun]:
        """The runs, by the program each starts from."""
        return self._runs.runs

    def set_search_paths(self, folders: list[str]) -> None:
        """The folders a call looks in beyond its file's own (``library/callee_folders.py``)
        changed: the library looks again."""
        folders = [str(p) for p in folders]
        if folders != self.search_paths:
            self.search_paths = folders
            self._reload()

    def set_workspace_folders(self, folders: list[str]) -> None:
        """The folders whose program files may call the open ones (the editor's workspace
        folders; for the command line the checked files' folders and the search paths)."""
        folders = [str(p) for p in folders]
        if folders != self.workspace_folders:
            self.workspace_folders = folders
            self.callers.forget()

    # ---------------------------------------------------------------- documents
    @staticmethod
    def _key(path: str) -> str:
        return str(Path(path))

    def open(self, path: str, text: str | ParsedDocument, version: int | None = None) -> None:
        """Open a document with its text, or with its text parsed already (in full)."""
        key = self._key(path)
        doc = text if isinstance(text, ParsedDocument) else ParsedDocument(text)
        assert not doc.partial
        loaded = self.library.add_parsed(key, doc.lines, doc.program)  # it sees the document as it is edited
        self.docs[key] = WorkspaceDocument(key, doc, loaded, version, real=os.path.realpath(key))
        self.stale = True

    def first_screen(
        self, path: str, lines: list[str], extra: Sequence[int] = (), head: bool = True
    ) -> list[Diagnostic]:
        """What the first lines of a huge document, and each line of ``extra``, earn by
        themselves (``first_screen.py``); ``head``: False for the lines of ``extra`` alone."""
        ctx = static_checks.line_context(self.dialect_of(lines[:FIRST_SCREEN_LINES]), self.settings, self.locale)
        return first_screen_findings(path, lines, extra, head, ctx, self.memo, self.locale, self.severities)

    def change(self, path: str, start_line: int, start_col: int, end_line: int, end_col: int, text: str,
               version: int) -> None:  # fmt: skip
        """An editor change of an open document (0-based positions)."""
        d = self.docs[self._key(path)]
        if d.edit(start_line, start_col, end_line, end_col, text, version, lambda b: self._calls_in(b, d)):
            self.stale = True

    def close(self, path: str) -> None:
        self.docs.pop(self._key(path), None)
        self._reload()

    def file_changed(self, path: str) -> None:
        """A file (or a folder) was created, changed or deleted on disk. The runs start again
        only when what they rest on may have changed (``ProgramLibrary.sees``, ``DiskCallers.changed``):
        in a folder of thousands of programs, saving one that no open program calls, and that
        calls none, leaves the analysis as it is."""
        key = self._key(path)
        if self._own_files:
            self.files.forget(key)
        callers_moved = self.callers.changed(key, self._units)
        if callers_moved or self._library_due or self._library.sees(key):
            self._reload()

    def _reload(self) -> None:
        """A fresh library (disk files looked at again), the open documents still in it, made
        when it is next used: closing 2,000 documents one after the other makes it once, not
        2,000 times over the documents still open."""
        self._library_due = True
        self.callers.entries = None
        self.stale = True

    @property
    def library(self) -> ProgramLibrary:
        """The programs a run may call: the open documents, then the files on disk."""
        if self._library_due:
            self._library_due = False
            self._library = ProgramLibrary(
                self.search_paths, files=self.files, extensions=self.settings.extensions, profile_of=self._profile_name
            )
            for d in self.docs.values():
                d.loaded = self._library.add_parsed(d.path, d.doc.lines, d.doc.program)
                d.targets = None
                d.own = None
        return self._library

    def document(self, path: str) -> ParsedDocument | None:
        d = self.docs.get(self._key(path))
        return d.doc if d is not None else None

    def configure(self, *, settings: MachineSettings | None = None, dialect: str | None = None,
                  max_blocks: int | None = None, severities: dict[str, str] | None = None) -> None:  # fmt: skip
        """New settings (the editor's changed, or the machine file): the severities apply to
        the next result; another machine file, dialect or budget runs everything again."""
        severities = check_overrides(dict(severities or {}))
        settings = settings or MachineSettings()
        budget = max_blocks if max_blocks is not None else settings.max_blocks
        if settings != self.settings or dialect != self.dialect_setting or budget != self.max_blocks:
            profiles_changed = settings != self.settings or dialect != self.dialect_setting
            self.settings, self.dialect_setting, self.max_blocks = settings, dialect, budget
            if profiles_changed:
                self._reload()  # other files are programs now, or of another profile
            for d in self.docs.values():
                d.own = d.static = d.targets = None
            self._unreached.forget()
            self.callers.forget()
            self.stale = True
        self.severities = severities

    # ---------------------------------------------------------------- dialects and calls
    def dialect_of(self, lines: list[str]) -> Dialect:
        """The profile a file with these lines is read in (``file_profile``)."""
        return file_profile(lines, self.settings, self.dialect_setting)

    def _profile_name(self, lines: list[str], path: str) -> str:
        """The name of ``dialect_of``: the program library finds a call's program only among the
        files read in the calling file's profile (``ProgramLibrary.on_machine``)."""
        return self.dialect_of(lines).name

    def _calls_in(self, block: Block, d: WorkspaceDocument) -> bool:
        ctx = static_checks.line_context(self.dialect_of(d.doc.lines), self.settings, self.locale)
        facts = self.memo.facts(block, ctx)
        return facts is not None and bool(facts.calls)

    def _targets(self, d: WorkspaceDocument) -> Targets:
        if d.targets is None:
            d.targets = self._static(d).call_targets(d.doc.program.read_end)
        return d.targets

    def _static(self, d: WorkspaceDocument) -> StaticLines:
        """The per-line part of ``d``'s static checks, every line looked at."""
        static = self._static_part(d)
        static.fill(d.doc.blocks)
        return static

    def _static_part(self, d: WorkspaceDocument) -> StaticLines:
        """The per-line part of ``d``'s static checks, as far as it got (``StaticLines.fill``)."""
        ctx = static_checks.line_context(self.dialect_of(d.doc.lines), self.settings, self.locale)
        if d.static is None or d.static.ctx is not ctx:

            def looked(done: int, total: int) -> None:
                self.progress = Progress(pick(self.locale, "checking lines", "检查各行"), done / total * STATIC_SHARE)

            d.static = StaticLines(d.doc.blocks, ctx, self.memo, looked, fill=False)
        return d.static

    def _own(self, d: WorkspaceDocument) -> list[Diagnostic]:
        """``d``'s syntax and static findings, with a hint of a profile that fits it better."""
        if d.own is None:
            static = self._static(d)
            d.own = static.diagnostics(d.doc.program, d.path, static.ctx.dialect, self.library, self.locale)
            head = d.doc.lines[:HEADER_LINES]
            wrong_name = profile_comment_diagnostics(head, d.path, static.ctx.dialect.name, self.locale)
            d.own.extend(wrong_name)
            # a file that names its profile is not asked, nor one whose comment names none (it says so)
            chosen = dialect_from_text(head) or wrong_name
            hint = None if chosen else suggestion(d.own, static.facts, d.doc.program, d.path,
                                                  static.ctx.dialect, self.settings, self.locale)  # fmt: skip
            if hint is not None:
                d.own.append(hint)
        return d.own

    def _units(self) -> list[OpenProgram]:
        """Every runnable O program of the open files (``open_programs.py``)."""
        return open_programs(self.docs, lambda d: self._static(d).call_sites(d.doc.program.read_end),
                             self.settings.block_delete)  # fmt: skip

    # ---------------------------------------------------------------- analysing
    def analyze(self, path: str, should_cancel: Callable[[], bool] | None = None,
                slice_seconds: float | None = None) -> AnalysisResult | None:  # fmt: skip
        """See the module docstring. Python's cycle collector is paused meanwhile, as during a
        machine run: the analysis makes no garbage cycles, and a collection walking the
        compiled blocks and records of a large file cost more than an edit's whole analysis.
        With ``slice_seconds`` each run goes on for at most that long (``EntryRuns.advance``):
        the result's ``unfinished`` names the files whose findings wait for the runs that did
        not end, which the next call takes further."""
        was_enabled = gc.isenabled()
        gc.disable()
        try:
            return self._analyze(path, should_cancel, slice_seconds)
        finally:
            if was_enabled:
                gc.enable()

    def _analyze(self, path: str, should_cancel: Callable[[], bool] | None,
                 slice_seconds: float | None) -> AnalysisResult | None:  # fmt: skip
        key = self._key(path)
        version = self.docs[key].version if key in self.docs else None
        _ = self.library  # made again first, when documents closed or files changed meanwhile
        for d in self.docs.values():  # the long part of a first analysis: it stops between chunks
            if not self._static_part(d).fill(d.doc.blocks, should_cancel):
                return None
        callers = self.callers
        if self.stale or any(d.targets is None for d in self.docs.values()):
            callers.entries = None
        units = self._units()
        if callers.entries is None:
            callers.find(units, self.workspace_folders, self.settings, self.dialect_setting, self.locale, self.files,
                         self.library, lambda: {path: self._targets(d) for path, d in self.docs.items()},
                         {path: d.real for path, d in self.docs.items()})  # fmt: skip
        assert callers.entries is not None
        if self.stale:
            self._runs.discard()
            self.stale = False
        else:
            self._runs.take_back(self.docs, self.settings.block_delete)
        for d in self.docs.values():
            for e in d.edits:
                self._unreached.edited(d.path, e.start, e.count, e.shifted or e.structural)
            d.edits.clear()
        primary = {k: found for k, found, called in units if not called and k not in callers.called_from_disk}
        primary.update(callers.entries)
        self._runs.keep_only(primary)

        def running(n: int, found: FoundProgram) -> None:
            self.progress = Progress(pick(self.locale, f"running {found.label}", f"运行 {found.label}"),
                                     STATIC_SHARE + (1 - STATIC_SHARE) * n / len(primary))  # fmt: skip

        if not self._runs.advance(primary, self.max_blocks, should_cancel, running, self.locale, self.max_seconds,
                                  slice_seconds):  # fmt: skip
            return None
        return self._result(version)

    def _start_run(self, found: FoundProgram, budget: int) -> EntryRun:
        """The run of ``found``, in its file's profile, within ``budget`` blocks."""
        run = EntryRun(found, self.dialect_of(found.file.lines), self.settings, self.library, budget,
                       self.max_seconds, self.max_records)  # fmt: skip
        run.reads_clock = self._reads_clock
        return run

    def _reads_clock(self, path: str) -> bool:
        """Whether a program of ``path`` may read the simulated clock (``clock_reads.py``)."""
        d = self.docs.get(path)
        if d is not None:
            return d.reads_clock()
        loaded = self.library.load(path)
        return True if loaded is None else self._disk_clock.reads(path, loaded)

    def _result(self, version: int | None) -> AnalysisResult:
        own = {path: list(self._own(d)) for path, d in self.docs.items()}
        return gather(version, own, self.docs, self.library, self._runs, self.callers.entries or {},
                      self._unreached, self.max_blocks, self.locale, self.severities, self.max_seconds)  # fmt: skip
