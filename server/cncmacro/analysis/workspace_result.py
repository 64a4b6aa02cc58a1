"""What a workspace analysis hands back: each file's findings and the values its runs left.

``AnalysisResult`` holds ``version`` (of the file asked about when it was analysed),
``diagnostics`` (file -> list, severities applied: syntax, static checks, and what the runs
found), ``values`` (file -> 0-based line -> ``[(variable number, value)]``, the value each
assignment on that line left the last time a run executed it; None is vacant) and ``timing``
(the open files' cycle time, ``cycle_lenses.py``). ``gather`` makes it: each open file's own
findings, then the faults of failed runs and the programs left unrun, then what each run
found (a finding the static checks made on the same line is said once; a caller on disk
reports in open files only), then the ranges no run reached (``unreached.py``).
"""

from __future__ import annotations

import logging
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from ..bilingual import pick
from ..library.programs import FoundProgram, LoadedFile, ProgramLibrary
from .diagnostics import UNNECESSARY, Diagnostic, diagnostic
from .faults import RUN, internal_error
from .indexes.open_programs import RunKey
from .runs.cycle_lenses import FileTiming, file_timings
from .runs.entry_runs import EntryRuns
from .runs.run_checks import FILE_BUDGETS, MAX_SECONDS, EntryRun, not_run_diagnostic, run_diagnostics
from .runs.unknown_stops import after_a_stop, holds_one, passed_guards, unknown_stop
from .runs.unreached import UnreachedRanges
from .severity import apply_severities
from .workspace_documents import WorkspaceDocument

log = logging.getLogger(__name__)

Value = float | None


@dataclass(slots=True)
class AnalysisResult:
    """See the module docstring."""

    version: int | None
    diagnostics: dict[str, list[Diagnostic]]
    values: dict[str, dict[int, list[tuple[int, Value]]]]
    timing: dict[str, FileTiming] = field(default_factory=dict)  # the open files' (cycle_lenses.py)
    # the files that runs cut short by their time slice started in or reached: their findings
    # are not complete yet (``WorkspaceAnalysis.analyze``'s ``slice_seconds``)
    unfinished: frozenset[str] = frozenset()


@dataclass(slots=True)
class _Files:
    """The files as the analysis sees them: the open documents over the library's files on disk."""

    docs: Mapping[str, WorkspaceDocument]
    library: ProgramLibrary

    def loaded(self, file: str) -> LoadedFile | None:
        return self.docs[file].loaded if file in self.docs else self.library.load(file)

    def line_text(self, file: str, line: int) -> str:
        d = self.docs.get(file)
        lines = d.doc.lines if d is not None else None
        if lines is None:
            loaded = self.library.load(file)
            lines = loaded.lines if loaded is not None else []
        return lines[line] if 0 <= line < len(lines) else ""


def gather(version: int | None, own: dict[str, list[Diagnostic]], docs: Mapping[str, WorkspaceDocument],
           library: ProgramLibrary, runs: EntryRuns, entries: Mapping[RunKey, FoundProgram],
           unreached: UnreachedRanges, max_blocks: int, locale: str,
           severities: dict[str, str], max_seconds: float = MAX_SECONDS) -> AnalysisResult:  # fmt: skip
    """The result of the analysis: ``own`` is each open file's own findings (a list of its
    own, which this extends), ``entries`` the callers on disk that ran."""
    files = _Files(docs, library)
    by_file = own
    seen: set[tuple[str, int, str]] = set()
    errors: set[tuple[str, int]] = set()
    milder: dict[tuple[str, int, str], Diagnostic] = {}  # a file's own finding below an error
    for path, diags in by_file.items():
        for x in diags:
            seen.add((path, x.line, x.code))
            if x.severity == "error":
                errors.add((path, x.line))
            else:
                milder.setdefault((path, x.line, x.code), x)
    for k, x in runs.failed.items():
        if k not in entries or x.file in docs:
            by_file.setdefault(x.file, []).append(x)
    for found_entry, spent in runs.not_run.values():
        if found_entry.file.path in docs:
            by_file.setdefault(found_entry.file.path, []).append(
                not_run_diagnostic(found_entry, FILE_BUDGETS * max_blocks, locale, spent, max_seconds)
            )
    for k, run in runs.runs.items():
        shown = docs if k in entries else None  # a caller on disk: findings in open files only
        try:
            found = run_diagnostics(run, files.line_text, locale, errors)
        except Exception as e:  # a bug: say so where the run started
            found = [internal_error(run.entry.file.path, run.entry.unit.start, RUN, e, locale)]
        for x in found:
            if shown is not None and x.file not in shown:
                continue
            key = (x.file, x.line, x.code)
            if key in seen:
                kept = milder.pop(key, None)  # a run that meets the alarm the check called possible: the error
                if kept is not None and x.severity == "error":
                    diags = by_file[x.file]
                    diags[diags.index(kept)] = x
                continue
            seen.add(key)
            by_file.setdefault(x.file, []).append(x)
    try:
        not_reached = _not_executed(files, runs, entries, unreached, locale)
    except Exception:  # only hints are lost
        log.exception("finding the blocks no run reached failed")
        not_reached = []
    for x in not_reached:
        by_file.setdefault(x.file, []).append(x)
    values: dict[str, dict[int, list[tuple[int, Value]]]] = {}
    for k, run in runs.runs.items():
        for file, lines in run.state.written.items():
            if k in entries and file not in docs:
                continue
            per = values.setdefault(file, {})
            for line, h in lines.items():
                _, n, v = h[-1]
                per[line] = [(n, v)]
    out = {}
    for path, diags in by_file.items():
        diags.sort(key=Diagnostic.sort_key)
        out[path] = apply_severities(diags, severities)
    timing = file_timings(((run, k not in entries) for k, run in runs.runs.items()), docs)
    unfinished = {path for k in runs.pending if k in runs.runs for path in _touched(runs.runs[k])}
    return AnalysisResult(version, out, values, timing, frozenset(unfinished))


def _touched(run: EntryRun) -> Iterable[str]:
    """The files a run started in or reached so far."""
    yield run.entry.file.path
    yield from run.last_run


def _not_executed(files: _Files, runs: EntryRuns, entries: Mapping[RunKey, FoundProgram],
                  unreached: UnreachedRanges, locale: str) -> list[Diagnostic]:  # fmt: skip
    """Ranges of blocks that no run reached, in the programs that some run entered, in the
    open files and the files that runs from open files enter (``unreached.py`` keeps them
    up to date across edits)."""
    shown = set(files.docs)
    for k, run in runs.runs.items():
        if k not in entries:
            shown.update(run.state.first)
    out: list[Diagnostic] = []
    found = unreached.ranges(runs.runs, files.loaded, sorted(shown))
    stops = [stop for run in runs.runs.values() for stop in unknown_stop(run.machine)]
    guarded = [at for run in runs.runs.values() for at in passed_guards(run.machine)]
    for file, ranges in found.items():
        loaded = files.loaded(file)
        if loaded is None:  # ``ranges`` found it loaded: only a file gone since then
            continue
        out += [_not_executed_diagnostic(file, loaded.lines, first, last, locale) for first, last in ranges
                if not after_a_stop(stops, file, first) and not holds_one(guarded, file, first, last)]  # fmt: skip
    return out


def _not_executed_diagnostic(file: str, lines: list[str], first: int, last: int, locale: str) -> Diagnostic:
    n = last - first + 1
    en = "no analysis run reaches this block" if first == last else f"no analysis run reaches these {n} lines"
    zh = "分析运行从未执行到此程序段" if first == last else f"分析运行从未执行到这 {n} 行"
    return diagnostic(file, first, 0, last, max(1, len(lines[last].rstrip())), "not-executed",
                      pick(locale, en, zh), (), (UNNECESSARY,))  # fmt: skip
