"""What the editor shows of the cycle time, from the analysis runs (no run of its own).

Each analysis run (``EntryRun``) keeps, for every line when it first ran, the clock and the cut
and rapid path so far, and each tool change with those three before it (``RunState.times``,
``RunState.tools``). ``file_timings`` turns them into, per file:

- ``elapsed``: line -> seconds of the run when the block first started (from the program the
  analysis ran from: a main program, or for a subprogram the program that calls it);
- ``programs``: the O line of each program a run started from -> that run's totals, when it
  completed;
- ``tools``: the line of each tool change -> the tool and its part of the run, up to the next
  change or the end (added up over the times the line ran in one run).

The first run that reaches a line decides what it shows (runs go in a fixed order).
"""

from __future__ import annotations

from collections.abc import Container, Iterable
from dataclasses import dataclass, field

from ..machine.status import RunStatus
from .cycle_summary import Totals, tool_parts
from .run_checks import EntryRun


@dataclass(slots=True)
class FileTiming:
    """The cycle time's facts for one file (module docstring)."""

    elapsed: dict[int, float] = field(default_factory=dict)
    programs: dict[int, Totals] = field(default_factory=dict)
    tools: dict[int, tuple[float | None, Totals]] = field(default_factory=dict)


def file_timings(runs: Iterable[tuple[EntryRun, bool]], shown: Container[str]) -> dict[str, FileTiming]:
    """Per file of ``shown``, the timing facts of ``runs`` (each with whether it starts from a
    program of an open file, whose O line then gets the program's totals)."""
    out: dict[str, FileTiming] = {}
    for run, own in runs:
        st = run.state
        for path, lines in st.times.items():
            if path not in shown:
                continue
            timing = out.setdefault(path, FileTiming())
            # the run's own record, not a copy (a 100k-line file's would cost each analysis); a
            # second run through the file adds what the first did not reach
            timing.elapsed = {**lines, **timing.elapsed} if timing.elapsed else lines
        m = run.machine
        if m.status != RunStatus.COMPLETED:
            continue
        end = Totals(m.clock, m.cut_length, m.rapid_length)
        entry = run.entry
        if own and entry.file.path in shown:
            out.setdefault(entry.file.path, FileTiming()).programs.setdefault(entry.unit.start, end)
        changes = [(f, line, tool, Totals(c, cut, r)) for _, f, line, tool, c, cut, r in st.tools]
        mine: dict[tuple[str, int], tuple[float | None, Totals]] = {}
        for part in tool_parts(changes, end):
            if part.file in shown:
                had = mine.get((part.file, part.line))
                mine[part.file, part.line] = (part.tool, part.totals if had is None else had[1] + part.totals)
        for (path, line), value in mine.items():
            out.setdefault(path, FileTiming()).tools.setdefault(line, value)
    return out
