"""The runs of a workspace analysis, one per program that runs on its own, kept across edits.

``EntryRuns`` holds each ``EntryRun`` by its entry program (``open_programs.RunKey``), takes
the runs back after edits (``run_rewind.py``), drops the ones whose program no longer runs on
its own, and advances the others within their budgets: each run its own ``max_blocks``, and
the runs from the programs of one file together ``FILE_BUDGETS`` times that, in the order of
the files; and, whatever ``max_blocks`` says, the runs of one file together the time of one run
(``max_seconds``): no setting makes a file's analysis outlast what a person waits for. A
program whose file's share is spent is not run (``not_run``, with the share that was spent:
``check`` names it).
With a time slice (``slice_seconds``) each run goes on for at most that long in one call, then
the next run takes its turn; the runs that did not end are ``pending``, and go on from where
they are at the next call: a long run (a program that waits for a signal under a large
``max_blocks``) does not keep the other files' runs waiting for it.
A bug in one run costs that run only: it is dropped and its fault (``failed``) is reported
where it started, the other runs and the static findings go on.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable, Mapping

from ...library.programs import FoundProgram
from ...machine.status import RunStatus
from ..diagnostics import Diagnostic
from ..faults import RUN, internal_error
from ..indexes.open_programs import RunKey
from ..workspace_documents import WorkspaceDocument
from .run_checks import FILE_BUDGETS, MAX_SECONDS, EntryRun
from .run_rewind import rewind
from .unreached import UnreachedRanges

log = logging.getLogger(__name__)


class EntryRuns:
    """See the module docstring. ``start(found, budget)`` makes the run of a program."""

    def __init__(self, unreached: UnreachedRanges, start: Callable[[FoundProgram, int], EntryRun]) -> None:
        self.runs: dict[RunKey, EntryRun] = {}
        self.failed: dict[RunKey, Diagnostic] = {}  # runs that failed by a fault of the checker
        # entries left out, with what their file had spent: its blocks ("blocks") or its time ("time")
        self.not_run: dict[RunKey, tuple[FoundProgram, str]] = {}
        self.pending: set[RunKey] = set()  # runs that their time slice stopped before their end
        self._unreached = unreached  # the not-executed ranges, told of each run taken back
        self._start = start

    def discard(self) -> None:
        """Every run starts again."""
        for run in self.runs.values():
            run.discard()
        self.runs.clear()

    def take_back(self, docs: Mapping[str, WorkspaceDocument], block_delete: bool) -> None:
        """Take each run back to before the first step the edits of ``docs`` can change."""
        for d in docs.values():
            if d.edits:
                for k, run in list(self.runs.items()):
                    try:
                        rewind(run, d, block_delete, self._unreached.rewound)
                    except Exception:  # a bug: run that program again from its start
                        log.exception("taking an analysis run back failed")
                        self.drop(k)

    def keep_only(self, primary: Mapping[RunKey, FoundProgram]) -> None:
        """Drop the runs of the programs that are not in ``primary`` (a called program is
        analysed only through its callers)."""
        for k in [k for k in self.runs if k not in primary]:
            self.drop(k)

    def drop(self, k: RunKey) -> None:
        run = self.runs.pop(k, None)
        if run is not None:
            run.discard()

    def advance(self, primary: Mapping[RunKey, FoundProgram], max_blocks: int, should_cancel: Callable[[], bool] | None,
                running: Callable[[int, FoundProgram], None], locale: str,
                max_seconds: float = MAX_SECONDS, slice_seconds: float | None = None) -> bool:  # fmt: skip
        """Run each program of ``primary`` to its end or its budget; False when ``should_cancel``
        said stop (the runs go on from where they are the next time). ``running(n, found)`` is
        told before the ``n``-th. ``max_seconds`` is one run's time limit, and one file's;
        ``slice_seconds`` what each run may take in this call (the others: ``pending``)."""
        self.failed = {}
        self.not_run = {}
        self.pending = set()
        file_budget = FILE_BUDGETS * max_blocks
        spent: dict[str, int] = {}  # blocks run by the runs from each file so far
        took: dict[str, float] = {}  # and the seconds they took
        for n, (k, found) in enumerate(primary.items()):
            running(n, found)
            file = found.file.path
            left = file_budget - spent.get(file, 0)
            seconds = max_seconds - took.get(file, 0.0)
            if left <= 0 or seconds <= 0:  # the runs before it used up the file's share: it is not run
                self.drop(k)
                self.not_run[k] = (found, "blocks" if left <= 0 else "time")
                continue
            try:
                if slice_seconds is None:
                    stop = should_cancel
                else:
                    turn_ends = time.monotonic() + slice_seconds
                    stop = _or_after(should_cancel, turn_ends)
                if not self._advance(k, found, stop, min(max_blocks, left), max_blocks, file_budget, seconds):
                    if should_cancel is not None and should_cancel():
                        return False
                    self.pending.add(k)  # its turn ended: it goes on at the next call
                run = self.runs[k]
                spent[file] = spent.get(file, 0) + run.machine.blocks
                took[file] = took.get(file, 0.0) + run.elapsed
            except Exception as e:  # a bug in one run must not cost the others and the static findings
                self.drop(k)
                self.failed[k] = internal_error(found.file.path, found.unit.start, RUN, e, locale)
        return True

    def _advance(self, k: RunKey, found: FoundProgram, should_cancel: Callable[[], bool] | None, budget: int,
                 max_blocks: int, file_budget: int, seconds: float) -> bool:  # fmt: skip
        run = self.runs.get(k)
        if run is None:
            run = self.runs[k] = self._start(found, budget)
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
        run.file_budget = file_budget if budget < max_blocks else None
        if run.elapsed <= seconds:  # a run that ended within the share it had keeps its end
            run.max_seconds = min(run.own_seconds, seconds)
        return run.advance(should_cancel)


def _or_after(should_cancel: Callable[[], bool] | None, deadline: float) -> Callable[[], bool]:
    """Stop when ``should_cancel`` says so or once ``deadline`` (``time.monotonic``) has passed."""

    def stop() -> bool:
        return time.monotonic() > deadline or (should_cancel is not None and should_cancel())

    return stop
