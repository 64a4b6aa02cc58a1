"""What the editor shows of the cycle time, from the analysis runs (no run of its own).

Each analysis run (``EntryRun``) keeps the clock at each line's first execution, entry by entry
of its records of first executions (``RunState.clocks`` beside ``RunState.order``), and each
tool change with the clock and the cut and rapid path before it (``RunState.tools``).
``file_timings`` turns them into, per file:

- ``elapsed``: line -> seconds of the run when the block first started (from the program the
  analysis ran from: a main program, or for a subprogram the program that calls it), looked up
  when asked (``FirstClocks``): a hover reads one line, and nothing is copied per line at each
  analysis;
- ``programs``: the O line of each program a run started from -> that run's totals, when it
  completed;
- ``tools``: the line of each tool change -> the tool and its part of the run, up to the next
  change or the end (added up over the times the line ran in one run).

The first run that reaches a line decides what it shows (runs go in a fixed order).
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Container, Iterable, Iterator
from dataclasses import dataclass, field

from ...machine.status import RunStatus
from .cycle_summary import Totals, end_totals, tool_parts
from .run_checks import EntryRun

_Source = tuple[dict[int, int], list[tuple[int, str, int]], list[float]]


class FirstClocks:
    """The clock when each line of one file first ran, read from the records of the runs that
    reached it (each: the file's first steps, the run's ``order`` and ``clocks``). The records
    are the runs' own, which a later analysis may change: a lookup that finds them out of step
    answers None, and the editor asks only for the version this analysis was of."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.sources: list[_Source] = []

    def get(self, line: int) -> float | None:
        for first, order, clocks in self.sources:
            step = first.get(line)
            if step is None:
                continue
            key = (step, self.path, line)
            k = bisect_left(order, (step, "", -1))  # the entries of one step are few, in any order
            n = min(len(order), len(clocks))
            while k < n and order[k][0] == step:
                if order[k] == key:
                    return clocks[k]
                k += 1
            return None
        return None

    def items(self) -> Iterator[tuple[int, float]]:
        """Every line with a clock, in no particular order."""
        seen: set[int] = set()
        for first, _, _ in self.sources:
            for line in first:
                if line not in seen:
                    seen.add(line)
                    t = self.get(line)
                    if t is not None:
                        yield line, t


@dataclass(slots=True)
class FileTiming:
    """The cycle time's facts for one file (module docstring)."""

    elapsed: FirstClocks
    programs: dict[int, Totals] = field(default_factory=dict)
    tools: dict[int, tuple[float | None, Totals]] = field(default_factory=dict)


def file_timings(runs: Iterable[tuple[EntryRun, bool]], shown: Container[str]) -> dict[str, FileTiming]:
    """Per file of ``shown``, the timing facts of ``runs`` (each with whether it starts from a
    program of an open file, whose O line then gets the program's totals)."""
    out: dict[str, FileTiming] = {}

    def timing(path: str) -> FileTiming:
        t = out.get(path)
        if t is None:
            t = out[path] = FileTiming(FirstClocks(path))
        return t

    for run, own in runs:
        st = run.state
        for path, lines in st.first.items():
            if path in shown:
                timing(path).elapsed.sources.append((lines, st.order, st.clocks))
        m = run.machine
        if m.status != RunStatus.COMPLETED:
            continue
        end = end_totals(m.planner)
        entry = run.entry
        if own and entry.file.path in shown:
            timing(entry.file.path).programs.setdefault(entry.unit.start, end)
        changes = [(f, line, tool, Totals(c, cut, r)) for _, f, line, tool, c, cut, r in st.tools]
        mine: dict[tuple[str, int], tuple[float | None, Totals]] = {}
        for part in tool_parts(changes, end):
            if part.file in shown:
                had = mine.get((part.file, part.line))
                mine[part.file, part.line] = (part.tool, part.totals if had is None else had[1] + part.totals)
        for (path, line), value in mine.items():
            timing(path).tools.setdefault(line, value)
    return out
