"""The ranges of blocks that no analysis run reached (the ``not-executed`` hints), kept up to
date in proportion to what an edit changed.

A line counts as executed when any run's records of first executions (``RunState.order``: one
``(step, file, line)`` per line first run, by step) name it. ``UnreachedRanges`` keeps a copy of
each run's records as it last saw them and, per file, how many of those records name each
line. A run taken back to a step (``rewound``) has changed only its records from that step on,
so only those are compared again; the lines they name, and the lines an edit replaced, are the
only places where a range can have appeared, grown, shrunk or gone. Around each such line the
unexecuted stretch is walked out to the executed lines on either side, and the ranges in it
are found again. A file whose lines moved (lines added or removed), whose structure changed,
that was loaded again or seen for the first time is scanned whole, as is a program that a run
entered for the first time or no longer enters.

A range runs over unexecuted blocks of one program: it starts and ends at a block that is not
empty, a ``%`` mark, an O header alone or a block skipped by block delete (the interpreter's
``machine.block_roles.passed_over``), and an executed line ends it.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from ...library.programs import LoadedFile
from ...syntax.nodes import Block

Record = tuple[int, str, int]  # (step, file, line)
Range = tuple[int, int]  # first and last line, both unexecuted and not skippable
_NEVER = 1 << 62
_WHOLE_FILE_SHARE = 8  # more changed lines than 1/8 of a file: scan it whole


@dataclass(slots=True)
class _Mirror:
    """A run's records of first executions as they were at the last question."""

    run: Any
    order: list[Record]


@dataclass(slots=True)
class _FileRanges:
    """The ranges of one file and what they were found from."""

    loaded: LoadedFile
    units: int
    counts: list[int]  # executed lines in each program of the file
    ranges: list[Range] = field(default_factory=list)


class UnreachedRanges:
    """See the module docstring. ``skippable(block)`` tells the blocks that neither start nor
    end a range."""

    def __init__(self, skippable: Callable[[Block], bool]) -> None:
        self.skippable = skippable
        self._mirrors: dict[Any, _Mirror] = {}
        self._low: dict[int, int] = {}  # id(run) -> the earliest step it went back to since
        self._refs: dict[str, dict[int, int]] = {}  # file -> line -> records naming it
        self._files: dict[str, _FileRanges] = {}
        self._whole: set[str] = set()  # files to scan whole at the next question
        self._edited: dict[str, set[int]] = {}  # file -> lines replaced by edits since

    # ---------------------------------------------------------------- what happened
    def rewound(self, run: Any) -> None:
        """``run`` was just taken back (or started again): its records from the step it is at
        on may have changed."""
        self._low[id(run)] = min(self._low.get(id(run), _NEVER), run.machine.blocks)

    def edited(self, path: str, start: int, count: int, moved: bool) -> None:
        """Lines ``start``.. ``start + count`` of ``path`` were replaced (``moved``: lines were
        added or removed, or the file's structure changed)."""
        if moved:
            self._whole.add(path)
        else:
            self._edited.setdefault(path, set()).update(range(start, start + count))

    def forget(self) -> None:
        """Start again (settings changed): every file is scanned whole at the next question."""
        self._files.clear()

    # ---------------------------------------------------------------- the question
    def ranges(self, runs: Mapping[Any, Any], load: Callable[[str], LoadedFile | None],
               files: Iterable[str]) -> dict[str, list[Range]]:  # fmt: skip
        """The unexecuted ranges of ``files`` (those that some run executed a line of) after
        the runs in ``runs`` (key -> ``EntryRun``); ``load`` gives a file's lines and program."""
        changed = self._follow(runs)
        out: dict[str, list[Range]] = {}
        for file in files:
            if file in out:
                continue
            ran = self._refs.get(file)
            if not ran:
                continue
            loaded = load(file)
            if loaded is None:
                continue
            fr = self._files.get(file)
            was = changed.get(file, {})
            flipped = {x for x, before in was.items() if (x in ran) != before}
            edited = self._edited.get(file, set()) - flipped
            n = len(loaded.program.blocks)
            if (fr is None or fr.loaded is not loaded or file in self._whole or fr.units != len(loaded.program.units)
                    or (len(flipped) + len(edited)) * _WHOLE_FILE_SHARE > n):  # fmt: skip
                fr = self._files[file] = self._scan_file(loaded, ran)
            else:
                self._update(fr, ran, flipped, edited)
            out[file] = fr.ranges
        for file in (self._whole | self._edited.keys() | changed.keys()) - out.keys():
            self._files.pop(file, None)  # its ranges were not kept up to date
        self._whole.clear()
        self._edited.clear()
        for file in [f for f in self._files if f not in self._refs]:
            del self._files[file]
        return out

    def _follow(self, runs: Mapping[Any, Any]) -> dict[str, dict[int, bool]]:
        """Bring the copies of the runs' records up to date; the lines whose records changed,
        each with whether it was executed before."""
        changed: dict[str, dict[int, bool]] = {}
        refs = self._refs

        def drop(records: list[Record]) -> None:
            for _, file, line in records:
                counts = refs[file]
                changed.setdefault(file, {}).setdefault(line, True)
                c = counts[line] - 1
                if c:
                    counts[line] = c
                else:
                    del counts[line]

        def add(records: list[Record]) -> None:
            for _, file, line in records:
                counts = refs.get(file)
                if counts is None:
                    counts = refs[file] = {}
                c = counts.get(line, 0)
                changed.setdefault(file, {}).setdefault(line, c > 0)
                counts[line] = c + 1

        for key in [k for k, m in self._mirrors.items() if runs.get(k) is not m.run]:
            drop(self._mirrors.pop(key).order)
        for key, run in runs.items():
            order = run.state.order
            m = self._mirrors.get(key)
            if m is None:
                m = self._mirrors[key] = _Mirror(run, [])
            cut = bisect_left(m.order, (self._low.get(id(run), _NEVER), "", -1))
            if cut > len(order) or (cut and order[cut - 1] is not m.order[cut - 1]):
                cut = 0  # not taken back as ``rewound`` said: compare everything
            old_end = len(m.order) - _same_tail(m.order, order, cut)
            new_end = len(order) - (len(m.order) - old_end)
            drop(m.order[cut:old_end])
            added = order[cut:new_end]
            add(added)
            m.order[cut:old_end] = added
        self._low.clear()
        for file in [f for f, counts in refs.items() if not counts]:
            del refs[file]
        return changed

    # ---------------------------------------------------------------- finding ranges
    def _scan_file(self, loaded: LoadedFile, ran: Mapping[int, int]) -> _FileRanges:
        units = loaded.program.units
        starts = [u.start for u in units]
        counts = [0] * len(units)
        for line in ran:
            k = bisect_right(starts, line) - 1
            if k >= 0 and line < units[k].end:
                counts[k] += 1
        fr = _FileRanges(loaded, len(units), counts)
        executed = sorted(ran)
        for k, unit in enumerate(units):
            if counts[k]:
                fr.ranges += self._scan_gaps(loaded.program.blocks, executed, unit.start, self._end(loaded, k) - 1)
        return fr

    def _scan_gaps(self, blocks: list[Block], executed: list[int], lo: int, hi: int) -> list[Range]:
        """``_scan`` from executed lines in order (a whole file's, of which those in ``lo``..``hi``
        count): only the stretches between two executed lines are looked at, and only where a
        range may start or end (a program run from end to end has none, and costs a look per
        stretch, not per line)."""
        out: list[Range] = []
        skippable = self.skippable
        at = bisect_left(executed, lo)
        end = bisect_right(executed, hi)
        start = lo  # the first line of the stretch of unexecuted lines after the last executed one
        for i in range(at, end + 1):
            stop = executed[i] if i < end else hi + 1  # the stretch is start .. stop - 1
            first = start
            while first < stop and skippable(blocks[first]):
                first += 1
            if first < stop:
                last = stop - 1
                while skippable(blocks[last]):
                    last -= 1
                out.append((first, last))
            start = stop + 1
        return out

    @staticmethod
    def _end(loaded: LoadedFile, k: int) -> int:
        return min(loaded.program.units[k].end, len(loaded.program.blocks))

    def _scan(self, blocks: list[Block], ran: Mapping[int, int], lo: int, hi: int) -> list[Range]:
        """The ranges within lines ``lo``..``hi`` (both included) of one program, where the
        lines just outside them are executed or outside the program."""
        return self._scan_gaps(blocks, [i for i in range(lo, hi + 1) if i in ran], lo, hi)

    def _update(self, fr: _FileRanges, ran: Mapping[int, int], flipped: set[int], edited: set[int]) -> None:
        """Find the ranges again around the lines that became executed or unexecuted
        (``flipped``) and the lines whose text changed (``edited``); the file's lines did not
        move."""
        units = fr.loaded.program.units
        blocks = fr.loaded.program.blocks
        starts = [u.start for u in units]
        by_unit: dict[int, tuple[list[int], list[int]]] = {}
        for lines, at in ((flipped, 0), (edited, 1)):
            for line in lines:
                k = bisect_right(starts, line) - 1
                if k >= 0 and line < units[k].end:
                    by_unit.setdefault(k, ([], []))[at].append(line)
        ranges = fr.ranges
        for k, (flips, edits) in sorted(by_unit.items()):
            before = fr.counts[k] > 0
            fr.counts[k] += sum(1 if x in ran else -1 for x in flips)
            now = fr.counts[k] > 0
            us, ue = units[k].start, self._end(fr.loaded, k)
            if now != before:  # a run enters this program for the first time, or no longer
                a = bisect_left(ranges, us, key=_first)
                b = bisect_left(ranges, ue, key=_first)
                ranges[a:b] = self._scan(blocks, ran, us, ue - 1) if now else []
                continue
            if not now:
                continue
            # an edited line whose execution did not change matters only where a range may
            # start or end: not on an executed line, nor strictly inside a range
            near = set(flips)
            for x in edits:
                if x in ran:
                    continue
                a = bisect_left(ranges, x, key=_last)
                if a < len(ranges) and ranges[a][0] < x < ranges[a][1]:
                    continue
                near.add(x)
            done = -1
            for x in sorted(near):
                if done < x < ue:
                    done = self._rescan_around(blocks, ran, ranges, x, us, ue)

    def _rescan_around(self, blocks: list[Block], ran: Mapping[int, int], ranges: list[Range], x: int, us: int,
                       ue: int) -> int:  # fmt: skip
        """Find the ranges again in the stretch around line ``x`` of the program ``us``..``ue``
        that reaches the executed lines on either side (and covers every range found before
        that touches it); the last line of the stretch."""
        lo = hi = x
        while True:
            a = bisect_left(ranges, lo, key=_last)
            b = bisect_right(ranges, hi, key=_first)
            if a < b:
                lo = min(lo, ranges[a][0])
                hi = max(hi, ranges[b - 1][1])
            left, right = lo, hi
            while left > us and left - 1 not in ran:
                left -= 1
            while right < ue - 1 and right + 1 not in ran:
                right += 1
            if (left, right) == (lo, hi):
                break
            lo, hi = left, right
        ranges[a:b] = self._scan(blocks, ran, lo, hi)
        return hi


def _same_tail(old: list[Record], new: list[Record], cut: int) -> int:
    """How many records at the end of ``new`` (after ``cut``) are the very records at the end
    of ``old``: those a run resumed after an edit took over from the run before it when it
    converged (``run_convergence.py``) without a shift of steps. Between ``cut`` and them the
    records are new objects, so the count is found by bisection."""
    lo, hi = 0, min(len(old), len(new)) - cut
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if new[len(new) - mid] is old[len(old) - mid]:
            lo = mid
        else:
            hi = mid - 1
    return lo


def _first(r: Range) -> int:
    return r[0]


def _last(r: Range) -> int:
    return r[1]
