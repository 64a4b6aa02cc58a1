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

``AnalysisResult`` holds ``version`` (of ``path`` when it was analysed), ``diagnostics`` (file
-> list, severities applied: syntax, static checks, and what the runs found) and ``values``
(file -> 0-based line -> ``[(variable number, value)]``, the value each assignment on that
line left the last time a run executed it; None is vacant).

Which programs run: every O program of the open files (but a repeated O number's later copy,
which the control does not keep: ``ProgramUnit.duplicate``) that no workspace file calls with a
literal target (G65/G66/M98/call codes) runs on its own, with vacant arguments, ``M99`` at
level 0 ending it; a called program is analysed through its callers, with their arguments,
and its findings appear in its own file. A called program that no caller's run entered gets
the static checks only: run on its own, its argument checks (``IF[#20 EQ #0] THEN #3000=..``)
and divisions by arguments would report what no real call does.

Callers on disk: an open program that no open file calls is looked for in the program files of
the workspace folders (``call_index.py``: an index of literal calls, read lazily and kept per
file by time and size; ``file_changed`` brings it up to date). When a file there calls it (the
library's lookup from that file reaching it), it is analysed through the programs on disk
that reach it, callers of callers up to a program nothing calls (``caller_entries.py``, at
most ``MAX_CALLER_ENTRIES`` of them), loaded from disk; an open file's text always wins over
its file. Their runs are incremental like any other, and report only what they find in open
files: a caller that was not opened is run for its arguments, not reported. Only the
workspace folders and the search paths are ever read. The dialect of a run is its entry file's:
a ``(cncmacro: dialect=..)`` comment in the first lines, then the machine file's
``dialect``, then ``dialect`` given here, then ``fanuc``. Files on disk are read through
``files`` (a ``FileCache``, shared by the program library and the call index): the language
server gives its workspace index's, which it tells of changes itself; without one the analysis
keeps its own, which ``file_changed`` tells.

Incremental: parsing is per line (``ParsedDocument``); the per-line static checks are kept
per line (``StaticLines``), so an edit checks only its lines plus the cross-line part. Each
run keeps checkpoints and the step at which each line first ran. After an edit that keeps
the number of lines and touches no label, O header or loop marker, a run resumes from its
last checkpoint before the first execution of a changed line (or of the nearest line before
the change, whose compiled form knows which line follows it); a run that never executed them
is kept whole. The resumed run takes the rest of the run before the edit over as soon as its
state equals that run's state at one of its checkpoints and the edited lines do not run after
it (``run_convergence.py``), so that an edit near the start of a long program runs only a few
chunks again; whether a file may read the simulated clock, which then has to be equal too, is
counted per open document from its text. An edit that adds or removes lines (Enter) resumes a run from its last
checkpoint before it first reached the line before the edit or any later line of the file:
nothing it keeps refers to a moved line, and the file is compiled afresh as it runs. An edit
that changes labels, loops or '%' resumes each run from before the first time it entered the
edited file. A changed O header, a dialect comment or a file changed on disk runs everything
again.
"""

from __future__ import annotations

import gc
import logging
import os
import re
from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Generic, TypeVar

from ..bilingual import is_chinese, pick
from ..dialects import DIALECTS, Dialect, get_dialect
from ..library.dialect_choice import HEADER_LINES, dialect_from_text
from ..library.file_cache import FileCache
from ..library.files import o_number
from ..library.machine_file import MachineSettings
from ..library.profiles import file_profile
from ..library.programs import FoundProgram, LoadedFile, ProgramLibrary
from ..machine import block_roles
from ..machine.status import RunStatus
from ..syntax.document import ParsedDocument
from ..syntax.nodes import Block
from . import static_checks
from .block_memo import BlockMemo
from .call_index import CallIndex
from .caller_entries import CallerSearch
from .cycle_lenses import FileTiming, file_timings
from .diagnostics import UNNECESSARY, Diagnostic, diagnostic
from .faults import RUN, internal_error
from .profile_suggestion import suggestion
from .run_checks import FILE_BUDGETS, MAX_RECORDS, MAX_SECONDS, EntryRun, not_run_diagnostic, run_diagnostics
from .severity import apply_severities, check_overrides
from .static_lines import StaticLines, syntax_findings
from .unreached import UnreachedRanges

log = logging.getLogger(__name__)

STATIC_SHARE = 0.5  # of a first analysis's progress, the share of the per-line checks (the runs take the rest)


@dataclass(frozen=True, slots=True)
class Progress:
    """How far an analysis got: what it does now (in the user's language) and the fraction done
    (an estimate: the per-line checks, then each run)."""

    what: str
    done: float


FIRST_SCREEN_LINES = 2_000  # the lines of a huge document checked first, before the whole (``first_screen``)

Value = float | None
MAX_CALLER_ENTRIES = 16  # programs on disk run to reach the open ones, at most
_T = TypeVar("_T")


@dataclass(slots=True)
class AnalysisResult:
    """See the module docstring."""

    version: int | None
    diagnostics: dict[str, list[Diagnostic]]
    values: dict[str, dict[int, list[tuple[int, Value]]]]
    timing: dict[str, FileTiming] = field(default_factory=dict)  # the open files' (cycle_lenses.py)


@dataclass(slots=True)
class _Edit:
    start: int
    count: int  # lines of the new text
    structural: bool  # a label, O header, '%' or loop marker was changed, added or removed
    shifted: bool  # lines were added or removed: the lines after the edit moved


@dataclass(slots=True)
class _Open:
    """An open document and what is cached about it."""

    path: str
    doc: ParsedDocument
    loaded: LoadedFile
    version: int | None
    own: list[Diagnostic] | None = None  # syntax + static, until the next change
    static: StaticLines | None = None  # the per-line part of ``own``, kept across edits
    targets: tuple[set[int], set[str]] | None = None  # literal call targets
    edits: list[_Edit] = field(default_factory=list)
    clock_reads: int | None = None  # how many places may read the clock (``_CLOCK_READ``)
    real: str = ""  # the path with links resolved, found once


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
        self.docs: dict[str, _Open] = {}
        self.runs: dict[tuple[str, int], EntryRun] = {}
        self._disk_clock: dict[str, tuple[LoadedFile, bool]] = {}  # files not open: can they read the clock?
        self.stale = True  # every run starts again
        # reads the files on disk, each once; a cache given here is told of changes by its owner
        self._own_files = files is None
        self.files = files if files is not None else FileCache()
        self.library = ProgramLibrary(self.search_paths, files=self.files)
        self.workspace_folders = [str(p) for p in workspace_folders]
        self.index: CallIndex | None = None  # made at the first question (``_find_disk_entries``)
        self._entries: dict[tuple[str, int], FoundProgram] | None = None  # callers on disk that run
        self._called_from_disk: set[tuple[str, int]] = set()  # open programs that callers on disk reach
        self._unreached = UnreachedRanges(self._unreachable_skips)  # the not-executed ranges, kept across edits
        self._failed: dict[tuple[str, int], Diagnostic] = {}  # runs that failed by a fault of the checker
        self._not_run: dict[tuple[str, int], FoundProgram] = {}  # entries left out: their file's budget was spent

    def set_workspace_folders(self, folders: list[str]) -> None:
        """The folders whose program files may call the open ones (the editor's workspace
        folders; for the command line the checked files' folders and the search paths)."""
        folders = [str(p) for p in folders]
        if folders != self.workspace_folders:
            self.workspace_folders = folders
            self.index = None
            self._entries = None

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
        self.docs[key] = _Open(key, doc, loaded, version, real=os.path.realpath(key))
        self.stale = True

    def first_screen(
        self, path: str, lines: list[str], extra: Sequence[int] = (), head: bool = True
    ) -> list[Diagnostic]:
        """What each of the first ``FIRST_SCREEN_LINES`` of ``lines``, and each line of
        ``extra``, earns by itself (syntax and the per-line static findings, the user's
        severities applied): what a huge document shows at once, before it is parsed in full
        and analysed, and at each edit until then. The checks that connect lines (labels,
        loops, calls) and the runs need the whole document and come with its analysis, which
        finds these again: nothing shown here is taken back by it. ``head``: False for the lines
        of ``extra`` alone."""
        top = ParsedDocument("\n".join(lines[:FIRST_SCREEN_LINES]) if head else "")
        ctx = static_checks.line_context(self.dialect_of(lines[:FIRST_SCREEN_LINES]), self.settings, self.locale)
        found: list[Diagnostic] = []
        if head:
            static = StaticLines(top.blocks, ctx, self.memo)
            found, _ = static.line_diagnostics(min(top.program.read_end, len(top.lines)), path, self.locale)
        chinese = is_chinese(self.locale)
        for line in extra:
            block = top.cache.get(lines[line])
            found.extend(syntax_findings(block.problems, line, path, chinese))
            facts = self.memo.facts(block, ctx)
            if facts is not None:
                found.extend(static_checks.findings_of(facts, line, path))
        return apply_severities(found, self.severities)

    def change(self, path: str, start_line: int, start_col: int, end_line: int, end_col: int, text: str,
               version: int) -> None:  # fmt: skip
        d = self.docs[self._key(path)]
        doc = d.doc
        n = len(doc.lines)
        sl = min(max(start_line, 0), n - 1)
        el = min(max(end_line, sl), n - 1)
        old = doc.blocks[sl : el + 1]
        before = _clock_reads(doc.lines[sl : el + 1]) if d.clock_reads is not None else 0
        doc.apply_change(start_line, start_col, end_line, end_col, text)
        delta = len(doc.lines) - n
        new = doc.blocks[sl : el + 1 + delta]
        if d.clock_reads is not None:
            d.clock_reads += _clock_reads(doc.lines[sl : el + 1 + delta]) - before
        d.version = version
        d.own = None
        structural = _changes_structure(old, new)
        if d.static is not None:
            d.static.replace(doc.blocks, sl, el + 1 - sl, el + 1 - sl + delta, structural)
        both = old + new
        if any(b.program is not None for b in both) or (
            sl < HEADER_LINES and dialect_from_text(doc.lines) != d.loaded.dialect
        ):
            d.loaded.dialect = dialect_from_text(doc.lines)
            self.stale = True
        if d.targets is not None and any(self._calls_in(b, d) for b in both):
            d.targets = None
        d.edits.append(_Edit(sl, len(new), structural, delta != 0))

    def close(self, path: str) -> None:
        self.docs.pop(self._key(path), None)
        self._reload()

    def file_changed(self, path: str) -> None:
        if self._own_files:
            self.files.forget(self._key(path))
        if self.index is not None:
            self.index.changed(self._key(path))
        self._reload()

    def _reload(self) -> None:
        """A fresh library (disk files looked at again), the open documents still in it."""
        self.library = ProgramLibrary(self.search_paths, files=self.files)
        self._entries = None
        for d in self.docs.values():
            d.loaded = self.library.add_parsed(d.path, d.doc.lines, d.doc.program)
            d.targets = None
            d.own = None
        self.stale = True

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
            self.settings, self.dialect_setting, self.max_blocks = settings, dialect, budget
            for d in self.docs.values():
                d.own = d.static = d.targets = None
            self._unreached.forget()
            self.index = None
            self._entries = None
            self.stale = True
        self.severities = severities

    # ---------------------------------------------------------------- dialects and calls
    def dialect_of(self, lines: list[str]) -> Dialect:
        """The profile a file with these lines is read in (``file_profile``)."""
        return file_profile(lines, self.settings, self.dialect_setting)

    def _calls_in(self, block: Block, d: _Open) -> bool:
        ctx = static_checks.line_context(self.dialect_of(d.doc.lines), self.settings, self.locale)
        facts = self.memo.facts(block, ctx)
        return facts is not None and bool(facts.calls)

    def _targets(self, d: _Open) -> tuple[set[int], set[str]]:
        if d.targets is None:
            d.targets = self._static(d).call_targets(d.doc.program.read_end)
        return d.targets

    def _static(self, d: _Open) -> StaticLines:
        """The per-line part of ``d``'s static checks, every line looked at."""
        static = self._static_part(d)
        static.fill(d.doc.blocks)
        return static

    def _static_part(self, d: _Open) -> StaticLines:
        """The per-line part of ``d``'s static checks, as far as it got (``StaticLines.fill``)."""
        ctx = static_checks.line_context(self.dialect_of(d.doc.lines), self.settings, self.locale)
        if d.static is None or d.static.ctx is not ctx:

            def looked(done: int, total: int) -> None:
                self.progress = Progress(pick(self.locale, "checking lines", "检查各行"), done / total * STATIC_SHARE)

            d.static = StaticLines(d.doc.blocks, ctx, self.memo, looked, fill=False)
        return d.static

    def _units(self) -> list[tuple[tuple[str, int], FoundProgram, bool]]:
        """Every runnable O program of the open files: (key, program, whether another
        program calls it; a program that only calls itself still runs on its own)."""
        by_number: dict[int, list[tuple[str, int]]] = {}
        by_name: dict[str, list[tuple[str, int]]] = {}
        for path, d in self.docs.items():
            ignored = [u for u in d.doc.program.units if u.duplicate]
            for line, number, name in self._static(d).call_sites(d.doc.program.read_end):
                if ignored and any(line in u for u in ignored):
                    continue  # a copy the control does not keep calls nothing
                if number is not None:
                    by_number.setdefault(number, []).append((path, line))
                elif name is not None:
                    by_name.setdefault(name, []).append((path, line))
        out = []
        for path in sorted(self.docs):
            d = self.docs[path]
            program = d.doc.program
            stem = Path(path).stem
            named = o_number(stem, bare=True)  # the number a call finds this file by
            first = program.named_units()[0]  # what a call by the file's name runs
            for k, unit in enumerate(program.units):
                if unit.duplicate or not block_roles.runnable(program, unit, self.settings.block_delete):
                    continue
                sites = list(by_number.get(unit.number, ())) if unit.number is not None else []
                if unit.number is None and k == 0:
                    sites = list(by_number.get(named, ())) if named is not None else []
                if unit is first:
                    sites += by_name.get(stem.lower(), ())
                called = any(p != path or not unit.start <= line < unit.end for p, line in sites)
                out.append(((path, k), FoundProgram(d.loaded, unit), called))
        return out

    # ---------------------------------------------------------------- callers on disk
    def _find_disk_entries(self, units: list[tuple[tuple[str, int], FoundProgram, bool]]) -> None:
        """Which open programs that no open file calls are called from files on disk in the
        workspace folders (``_called_from_disk``), and the programs on disk that runs start
        from to reach them (``_entries``): the callers' callers, up to a program nothing
        calls. A call counts when the library's lookup from the calling file reaches the
        program (``caller_entries.py``)."""
        self._entries = {}
        self._called_from_disk = set()
        if not self.workspace_folders or all(called for _, _, called in units):
            return
        if self.index is None:
            self.index = CallIndex(self.workspace_folders, self.settings, self.dialect_setting, self.locale,
                                   files=self.files)  # fmt: skip
        targets = {path: self._targets(d) for path, d in self.docs.items()}
        # how many open files call each program number and name: what the files other than a
        # unit's own call is then one look-up away (not a union over every open file per unit)
        number_calls: Counter[int] = Counter()
        name_calls: Counter[str] = Counter()
        for n, s in targets.values():
            number_calls.update(n)
            name_calls.update(s)
        finder = CallerSearch(self.library, self.index, {path: d.real for path, d in self.docs.items()})
        for key, found, called in units:
            if called:
                continue
            own_numbers, own_names = targets[key[0]]
            # what the other open files call: their runs reach those programs
            numbers = _CalledElsewhere(number_calls, own_numbers)
            names = _CalledElsewhere(name_calls, own_names)
            roots = finder.roots(found, numbers, names)
            if roots is None:
                continue  # nothing on disk calls it: it runs on its own
            self._called_from_disk.add(key)
            for k, entry in roots.items():
                if k not in self._entries and len(self._entries) >= MAX_CALLER_ENTRIES:
                    log.info("more than %d programs on disk call the open ones: only the first run", MAX_CALLER_ENTRIES)
                    break
                self._entries[k] = entry

    # ---------------------------------------------------------------- analysing
    def analyze(self, path: str, should_cancel: Callable[[], bool] | None = None) -> AnalysisResult | None:
        """See the module docstring. Python's cycle collector is paused meanwhile, as during a
        machine run: the analysis makes no garbage cycles, and a collection walking the
        compiled blocks and records of a large file cost more than an edit's whole analysis."""
        was_enabled = gc.isenabled()
        gc.disable()
        try:
            return self._analyze(path, should_cancel)
        finally:
            if was_enabled:
                gc.enable()

    def _analyze(self, path: str, should_cancel: Callable[[], bool] | None) -> AnalysisResult | None:
        key = self._key(path)
        version = self.docs[key].version if key in self.docs else None
        for d in self.docs.values():  # the long part of a first analysis: it stops between chunks
            if not self._static_part(d).fill(d.doc.blocks, should_cancel):
                return None
        if self.stale or any(d.targets is None for d in self.docs.values()):
            self._entries = None
        units = self._units()
        if self._entries is None:
            self._find_disk_entries(units)
        assert self._entries is not None
        if self.stale:
            for run in self.runs.values():
                run.discard()
            self.runs.clear()
            self.stale = False
        else:
            for d in self.docs.values():
                if d.edits:
                    for k, run in list(self.runs.items()):
                        try:
                            self._rewind(run, d)
                        except Exception:  # a bug: run that program again from its start
                            log.exception("taking an analysis run back failed")
                            self._drop(k)
        for d in self.docs.values():
            for e in d.edits:
                self._unreached.edited(d.path, e.start, e.count, e.shifted or e.structural)
            d.edits.clear()
        primary = {k: found for k, found, called in units if not called and k not in self._called_from_disk}
        primary.update(self._entries)
        for k in [k for k in self.runs if k not in primary]:
            self._drop(k)  # a called program is analysed only through its callers
        self._failed = {}
        self._not_run = {}
        file_budget = FILE_BUDGETS * self.max_blocks
        spent: dict[str, int] = {}  # blocks run by the runs from each file so far
        for n, (k, found) in enumerate(primary.items()):
            self.progress = Progress(pick(self.locale, f"running {found.label}", f"运行 {found.label}"),
                                     STATIC_SHARE + (1 - STATIC_SHARE) * n / len(primary))  # fmt: skip
            file = found.file.path
            left = file_budget - spent.get(file, 0)
            if left <= 0:  # the runs before it used up the file's share: it is not run
                self._drop(k)
                self._not_run[k] = found
                continue
            try:
                if not self._advance(k, found, should_cancel, min(self.max_blocks, left), file_budget):
                    return None
                spent[file] = spent.get(file, 0) + self.runs[k].machine.blocks
            except Exception as e:  # a bug in one run must not cost the others and the static findings
                self._drop(k)
                self._failed[k] = internal_error(found.file.path, found.unit.start, RUN, e, self.locale)
        return self._result(version)

    def _drop(self, k: tuple[str, int]) -> None:
        run = self.runs.pop(k, None)
        if run is not None:
            run.discard()

    def _advance(self, k: tuple[str, int], found: FoundProgram, should_cancel: Callable[[], bool] | None,
                 budget: int, file_budget: int) -> bool:  # fmt: skip
        run = self.runs.get(k)
        if run is None:
            dialect = self.dialect_of(found.file.lines)
            run = self.runs[k] = EntryRun(found, dialect, self.settings, self.library, budget,
                                          self.max_seconds, self.max_records)  # fmt: skip
            run.reads_clock = self._reads_clock
        elif run.entry.unit is not found.unit:
            run.entry = found
            run.max_blocks = budget
            run.restart()
            self._unreached.rewound(run)
        elif run.max_blocks != budget:  # the runs before it in its file now run more or fewer blocks
            m = run.machine
            grown = budget > run.max_blocks and m.status == RunStatus.LIMIT and run.stopped_by is None
            run.max_blocks = budget
            if m.blocks > budget or grown:
                run.back_to(min(m.blocks, budget) - 1)
                self._unreached.rewound(run)
        run.file_budget = file_budget if budget < self.max_blocks else None
        return run.advance(should_cancel)

    def _rewind(self, run: EntryRun, d: _Open) -> None:
        """Take ``run`` back to before the first step the edits of ``d`` can change."""
        path = d.path
        if run.first_step(path) is None:
            run.reset_file(path)
            return
        blocks = d.doc.blocks
        program = d.doc.program
        structural = any(e.structural for e in d.edits)
        if not structural and any(e.shifted for e in d.edits):
            structural = not self._rewind_shifted(run, d)
            if not structural:
                return
        lines: list[int] = []
        if not structural:
            end_do = {p.end_line: p.do_line for p in program.loops}
            for e in d.edits:
                lines.extend(range(e.start, e.start + e.count))
                p = e.start - 1
                while p >= 0 and block_roles.skipped(blocks[p], self.settings.block_delete):
                    p -= 1
                unit = program.unit_at(e.start)
                if p < unit.start or (p == unit.start and blocks[p].program is not None):
                    structural = True  # where the program starts running may have moved
                    break
                lines.append(p)
                if p in end_do:
                    lines.append(end_do[p])
        if structural:
            step = run.first_step(path)
            assert step is not None
            run.rewind(step, avoid_file=path)
            self._unreached.rewound(run)
            run.reset_file(path)
            return
        step = run.first_step(path, lines)
        if step is not None or run.earlier is not None:
            run.edited(path, lines)
        if step is not None:
            run.rewind(step)
            self._unreached.rewound(run)
        run.forget_lines(path, lines)

    def _rewind_shifted(self, run: EntryRun, d: _Open) -> bool:
        """Lines were added or removed (no structure changed): take ``run`` back to before the
        first step at which it reached the line before the first edit or any line after it,
        so that nothing it keeps refers to a line that moved. False when that cannot be told
        (the edit is at a program's start, or the run stopped at its budget without reaching
        the edit, its stopping place perhaps moved)."""
        path = d.path
        blocks = d.doc.blocks
        start = min(e.start for e in d.edits)
        p = start - 1
        while p >= 0 and block_roles.skipped(blocks[p], self.settings.block_delete):
            p -= 1
        unit = d.doc.program.unit_at(start)
        if p < unit.start or (p == unit.start and blocks[p].program is not None):
            return False
        step = run.first_reaching(path, p)
        if step is None:
            if run.machine.status == RunStatus.LIMIT or not run.finished:
                return False
        else:
            run.rewind(step, avoid_file=path)
            self._unreached.rewound(run)
        run.reset_file(path)
        return True

    def _reads_clock(self, path: str) -> bool:
        """Whether a program of ``path`` may read the simulated clock (a timer, the date or
        time, or any variable through indirection); a comment mentioning one counts too."""
        d = self.docs.get(path)
        if d is not None:
            if d.clock_reads is None:
                d.clock_reads = _clock_reads(d.doc.lines)
            return d.clock_reads > 0
        loaded = self.library.load(path)
        if loaded is None:
            return True
        cached = self._disk_clock.get(path)
        if cached is None or cached[0] is not loaded:
            cached = self._disk_clock[path] = (loaded, _clock_reads(loaded.lines) > 0)
        return cached[1]

    # ---------------------------------------------------------------- results
    def _line_text(self, file: str, line: int) -> str:
        d = self.docs.get(file)
        lines = d.doc.lines if d is not None else None
        if lines is None:
            loaded = self.library.load(file)
            lines = loaded.lines if loaded is not None else []
        return lines[line] if 0 <= line < len(lines) else ""

    def _own(self, d: _Open) -> list[Diagnostic]:
        if d.own is None:
            static = self._static(d)
            d.own = static.diagnostics(d.doc.program, d.path, static.ctx.dialect, self.library, self.locale)
            chosen = dialect_from_text(d.doc.lines[:HEADER_LINES])  # a file that names its profile is not asked
            hint = None if chosen else suggestion(d.own, static.facts, d.doc.program, d.path,
                                                  static.ctx.dialect, self.settings, self.locale)  # fmt: skip
            if hint is not None:
                d.own.append(hint)
        return d.own

    def _result(self, version: int | None) -> AnalysisResult:
        by_file: dict[str, list[Diagnostic]] = {path: list(self._own(d)) for path, d in self.docs.items()}
        seen: set[tuple[str, int, str]] = set()
        errors: set[tuple[str, int]] = set()
        for path, diags in by_file.items():
            for x in diags:
                seen.add((path, x.line, x.code))
                if x.severity == "error":
                    errors.add((path, x.line))
        entries = self._entries or {}
        for k, x in self._failed.items():
            if k not in entries or x.file in self.docs:
                by_file.setdefault(x.file, []).append(x)
        for found_entry in self._not_run.values():
            if found_entry.file.path in self.docs:
                by_file.setdefault(found_entry.file.path, []).append(
                    not_run_diagnostic(found_entry, FILE_BUDGETS * self.max_blocks, self.locale)
                )
        for k, run in self.runs.items():
            shown = self.docs if k in entries else None  # a caller on disk: findings in open files only
            try:
                found = run_diagnostics(run, self._line_text, self.locale, errors)
            except Exception as e:  # a bug: say so where the run started
                found = [internal_error(run.entry.file.path, run.entry.unit.start, RUN, e, self.locale)]
            for x in found:
                if shown is not None and x.file not in shown:
                    continue
                key = (x.file, x.line, x.code)
                if key in seen:
                    continue
                seen.add(key)
                by_file.setdefault(x.file, []).append(x)
        try:
            unreached = self._not_executed()
        except Exception:  # only hints are lost
            log.exception("finding the blocks no run reached failed")
            unreached = []
        for x in unreached:
            by_file.setdefault(x.file, []).append(x)
        values: dict[str, dict[int, list[tuple[int, Value]]]] = {}
        for k, run in self.runs.items():
            for file, lines in run.state.written.items():
                if k in entries and file not in self.docs:
                    continue
                per = values.setdefault(file, {})
                for line, h in lines.items():
                    _, n, v = h[-1]
                    per[line] = [(n, v)]
        out = {}
        for path, diags in by_file.items():
            diags.sort(key=Diagnostic.sort_key)
            out[path] = apply_severities(diags, self.severities)
        timing = file_timings(((run, k not in entries) for k, run in self.runs.items()), self.docs)
        return AnalysisResult(version, out, values, timing)

    def _not_executed(self) -> list[Diagnostic]:
        """Ranges of blocks that no run reached, in the programs that some run entered, in the
        open files and the files that runs from open files enter (``unreached.py`` keeps them
        up to date across edits)."""
        shown = set(self.docs)
        entries = self._entries or {}
        for k, run in self.runs.items():
            if k not in entries:
                shown.update(run.state.first)
        out: list[Diagnostic] = []
        found = self._unreached.ranges(self.runs, self._loaded, sorted(shown))
        for file, ranges in found.items():
            loaded = self._loaded(file)
            if loaded is None:  # ``ranges`` found it loaded: only a file gone since then
                continue
            out += [self._unreached_diagnostic(file, loaded.lines, first, last) for first, last in ranges]
        return out

    def _loaded(self, file: str) -> LoadedFile | None:
        return self.docs[file].loaded if file in self.docs else self.library.load(file)

    def _unreachable_skips(self, b: Block) -> bool:
        """Whether a block neither starts nor ends a not-executed range."""
        return block_roles.passed_over(b, self.settings.block_delete)

    def _unreached_diagnostic(self, file: str, lines: list[str], first: int, last: int) -> Diagnostic:
        n = last - first + 1
        en = "no analysis run reaches this block" if first == last else f"no analysis run reaches these {n} lines"
        zh = "分析运行从未执行到此程序段" if first == last else f"分析运行从未执行到这 {n} 行"
        return diagnostic(file, first, 0, last, max(1, len(lines[last].rstrip())), "not-executed",
                          pick(self.locale, en, zh), (), (UNNECESSARY,))  # fmt: skip


_CLOCK_NUMBERS = sorted({
    str(n) for name in DIALECTS for row in get_dialect(name).system_variables()
    if row.source in ("timer", "date", "time") for n in range(row.first, row.last + 1)
})  # fmt: skip
_CLOCK_NAMES = sorted({
    v.name for name in DIALECTS for v in get_dialect(name).system_variable_names()
    if any(str(n) in _CLOCK_NUMBERS for n in range(v.first, v.last + 1))
})  # fmt: skip
# a read of the clock: ``#[``, a clock variable (by number or 30i name), or a GSK ``#9xxx``
# (indirection through a common)
_CLOCK_READ = re.compile(
    r"#[ \t]*(?:\[|0*(?:" + "|".join(_CLOCK_NUMBERS) + r"|9\d{3})(?!\d)|_(?:" + "|".join(_CLOCK_NAMES) + r")(?!\w))",
    re.I,
)


class _CalledElsewhere(Generic[_T]):
    """The program numbers (or names) that open files other than one call."""

    __slots__ = ("counts", "own")

    def __init__(self, counts: Counter[_T], own: set[_T]) -> None:
        # looked up with any object, as a Container is: one of another type is simply absent
        self.counts: Mapping[Any, int] = counts
        self.own = own

    def __contains__(self, item: object) -> bool:
        return self.counts.get(item, 0) > (1 if item in self.own else 0)


def _clock_reads(lines: list[str]) -> int:
    return len(_CLOCK_READ.findall("\n".join(lines)))


def _changes_structure(old: list[Block], new: list[Block]) -> bool:
    """Whether replacing ``old`` by ``new`` adds, removes or changes a structural block (the
    lines both keep unchanged at their ends, as when Enter splits nothing, do not count; a
    block replaced by one with the same ``structure_key`` changes nothing)."""
    a, b = 0, 0
    while a < len(old) and b < len(new) and old[a] is new[b]:
        a += 1
        b += 1
    x, y = len(old), len(new)
    while x > a and y > b and old[x - 1] is new[y - 1]:
        x -= 1
        y -= 1
    if x - a == y - b and all(o.structure_key() == n.structure_key() for o, n in zip(old[a:x], new[b:y], strict=True)):
        return False  # the same labels, headers and loop markers in the same places (a label line's X typed)
    return any(blk.structural for blk in old[a:x]) or any(blk.structural for blk in new[b:y])
