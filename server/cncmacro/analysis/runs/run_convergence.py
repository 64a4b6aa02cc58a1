"""Convergence: an analysis run resumed after an edit takes over the rest of the run before it.

When ``EntryRun.rewind`` takes a finished run back to a checkpoint, the run as it was is kept
as an ``Earlier``. While the resumed run re-executes, each of its checkpoints is compared with
the earlier run's checkpoints at the same place (same frames, lines, loops and passes): when
the machine states are equal (``machine.tracking.same_state``; the simulated clock only when
a program the run entered may read it: ``#3001``, ``#3002``, ``#3011``, ``#3012`` or any
indirection) and none of the edited lines runs in the earlier run after that checkpoint (the
per-line chunk stamps ``RunObserver.last_run`` tell), the rest of the earlier run is what the
resumed run would do: its checkpoints, first executions, findings, values, notes and final
state are adopted instead of running again. Step numbers after that point shift by the
difference in executed blocks. A line that the earlier run first executed between the resume
point and the convergence point and the resumed run did not execute is kept as executed when
the earlier run executed it again later, and dropped otherwise; a vacant-argument read found
there must have been found again, because a later one would be hidden behind it. When the
earlier run stopped at its block budget and the blocks shifted, or the shifted end passes the
budget, the run goes back to its last checkpoint within the budget and runs on from there.
An earlier run that stopped in an endless loop (``EntryRun.look``) is taken over the same way:
the rest of it is that loop, found again (unless the shifted end passes the budget).

A chunk stamp (a serial) is either known, ``(first step of its chunk, True)``, or, once a
rewind forgot the chunk, ``(the last step it may stand for, False)``: the line ran then or
earlier, or never. A question that a vaguer stamp cannot answer gives up converging there.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
from dataclasses import dataclass, field
from operator import itemgetter
from typing import TYPE_CHECKING, Any

from ...machine import Snapshot
from ...machine.frames import Note
from ...machine.status import RunStatus
from ...machine.tracking import position_key, same_state

if TYPE_CHECKING:
    from .run_checks import EntryRun, RunState

Serials = dict[int, tuple[int, bool]]


@dataclass(slots=True)
class Earlier:
    """A finished run as it was before the edits (see the module docstring)."""

    checkpoints: list[Snapshot]
    pass_marks: list[dict[tuple[int, int], int]]
    final: Snapshot
    passes: dict[tuple[int, int], int]
    notes: list[Note]
    output: list[str]
    state: RunState
    # the run's live per-line stamps (``RunObserver.last_run``), the files it held then, and
    # the stamp each line had before the resumed run first overwrote it: the earlier run's
    # stamps are read through ``stamp`` without copying a slot per line of every file
    live: dict[str, list[int]]
    files: frozenset[str]
    serials: Serials
    resume: int  # the step the resumed run went back to (the earliest, over several rewinds)
    endless_at: tuple[str, int, int] | None  # where the run found an endless loop (file, line, to), when it stopped so
    changed: dict[str, set[int]] = field(default_factory=dict)  # file -> edited lines
    reads_clock: bool | None = None  # decided at the first comparison
    by_key: dict[tuple[Any, ...], list[int]] = field(default_factory=dict)
    overwritten: dict[str, dict[int, int]] = field(default_factory=dict)  # file -> line -> stamp before

    def stamp(self, path: str, line: int) -> int:
        """The serial the earlier run left on ``line`` of ``path`` (-1: it never ran it)."""
        if path not in self.files:
            return -1
        before = self.overwritten.get(path)
        if before is not None:
            s = before.get(line)
            if s is not None:
                return s
        arr = self.live.get(path)
        return arr[line] if arr is not None and 0 <= line < len(arr) else -1

    def overwriting(self, path: str, line: int) -> None:
        """The resumed run is about to stamp ``line`` of ``path`` for the first time since it
        went back (``EntryRun.first_run``): keep the earlier stamp."""
        if path in self.files:
            before = self.overwritten.get(path)
            if before is None:
                before = self.overwritten[path] = {}
            if line not in before:
                before[line] = self.live[path][line]


def keep_earlier(run: EntryRun) -> Earlier:
    """Keep what ``run`` found so far; the run is about to be rewound (which leaves the records
    it shares with the earlier run alone, see ``EntryRun._forget``)."""
    m = run.machine
    earlier = Earlier(list(run.checkpoints), list(run.pass_marks), m.snapshot(), dict(run.passes), list(m.notes),
                      list(m.output), run.state, run.last_run, frozenset(run.last_run), dict(run.serials),
                      m.blocks, run.endless_at)  # fmt: skip
    for j, snap in enumerate(earlier.checkpoints):
        earlier.by_key.setdefault(position_key(snap.frames), []).append(j)
    return earlier


def try_converge(run: EntryRun) -> bool:
    """Compare the run's newest checkpoint with the earlier run; take its rest over when they
    agree (module docstring). True when it did."""
    e = run.earlier
    assert e is not None
    snap = run.checkpoints[-1]
    candidates = e.by_key.get(position_key(snap.frames))
    if not candidates:
        return False
    if e.reads_clock is None:
        e.reads_clock = run.may_read_clock(e.files)
    m = run.machine
    running = {(k, d) for k, f in enumerate(m.frames) for d in f.loops}
    mine = {key: v for key, v in run.passes.items() if key in running}
    for j in candidates:
        old = e.checkpoints[j]
        if old.blocks <= e.resume or not same_state(snap, old, clock=e.reads_clock):
            continue
        if mine != {key: v for key, v in e.pass_marks[j].items() if key in running}:
            continue
        plan = _plan(run, e, old.blocks)
        if plan is not None:
            _adopt(run, e, j, plan)
            return True
    return False


def _ran_from(e: Earlier, path: str, line: int, step: int) -> bool | None:
    """Whether the earlier run executed ``line`` of ``path`` at or after ``step`` (None: cannot tell)."""
    s = e.stamp(path, line)
    if s < 0:
        return False
    at, known = e.serials[s]
    if known:
        return at >= step
    return None if at >= step else False


def _plan(run: EntryRun, e: Earlier, bj: int) -> tuple[list[tuple[str, int]], list[tuple[str, int]]] | None:
    """The lines to keep as executed and to drop when converging at step ``bj`` of the earlier
    run, or None when converging there is not sound."""
    for path, lines in e.changed.items():
        for line in lines:
            if _ran_from(e, path, line, bj) is not False:
                return None
    st = run.state
    old = e.state
    revive: list[tuple[str, int]] = []
    drop: list[tuple[str, int]] = []
    lo = bisect_left(old.order, (e.resume, "", -1))
    hi = bisect_left(old.order, (bj, "", -1))
    for _, path, line in old.order[lo:hi]:
        if line in st.first.get(path, ()):
            continue
        again = _ran_from(e, path, line, bj)
        if again is None:
            return None
        (revive if again else drop).append((path, line))
    for key, read in old.vacant.items():
        if e.resume <= read.stamp < bj and key not in st.vacant:
            return None
    return revive, drop


def _shift(snap: Snapshot, delta: int, clock: float, outputs: int, notes: int, lengths: tuple[float, float]) -> None:
    snap.blocks += delta
    motion = snap.motion
    if clock:
        motion.clock += clock
        snap.timer_marks = {n: v + clock for n, v in snap.timer_marks.items()}
    if lengths != (0.0, 0.0):
        motion.lengths = (motion.lengths[0] + lengths[0], motion.lengths[1] + lengths[1])
    output, count = snap.counts
    snap.counts = (output + outputs, count + notes)


def _adopt(run: EntryRun, e: Earlier, j: int, plan: tuple[list[tuple[str, int]], list[tuple[str, int]]]) -> None:
    m = run.machine
    old_j = e.checkpoints[j]
    bj = old_j.blocks
    conv = m.blocks
    delta = conv - bj
    p, old_p = m.planner, old_j.motion
    clock = p.clock - old_p.clock
    lengths = (p.cut_length - old_p.lengths[0], p.rapid_length - old_p.lengths[1])
    out_j, notes_j = old_j.counts
    outputs = len(m.output) - out_j
    notes = len(m.notes) - notes_j
    _merge_times(run, e, bj, delta, (clock, *lengths), plan)
    _merge_records(run, e, bj, conv, delta, plan)
    _merge_stamps(run, e, bj, delta)
    for snap in e.checkpoints[j + 1 :]:
        _shift(snap, delta, clock, outputs, notes, lengths)
        run.checkpoints.append(snap)
    run.pass_marks.extend(e.pass_marks[j + 1 :])
    run.passes = dict(e.passes)
    merged_notes = m.notes + e.notes[notes_j:]
    merged_output = m.output + e.output[out_j:]
    _shift(e.final, delta, clock, outputs, notes, lengths)
    m.restore(e.final)
    m.notes = merged_notes
    m.output = merged_output
    run.earlier = None
    if e.endless_at is not None:  # the rest of the run is the same endless loop
        run.stopped_by, run.endless_at = "endless", e.endless_at
    if m.blocks > run.max_blocks or (m.status == RunStatus.LIMIT and e.endless_at is None and delta != 0):
        run.back_to(min(m.blocks, run.max_blocks) - 1)


def _merge_times(run: EntryRun, e: Earlier, bj: int, delta: int, shift: tuple[float, float, float],
                 plan: tuple[list[tuple[str, int]], list[tuple[str, int]]]) -> None:  # fmt: skip
    """The cycle time's records (``RunState.clocks`` and ``tools``) as ``_merge_records`` merges
    the first executions, entry for entry of ``order`` (the lines revived, then the earlier run's
    from step ``bj`` on): later by the time and path the resumed run is ahead (``shift``: seconds,
    mm cut, mm rapid) and ``delta`` blocks on."""
    st = run.state
    old = e.state
    dt, dc, dr = shift
    st.clocks.extend([run.machine.planner.clock] * len(plan[0]))
    tail = old.clocks[bisect_left(old.order, (bj, "", -1)) :]
    st.clocks.extend([c + dt for c in tail] if dt else tail)
    tools = old.tools[bisect_left(old.tools, bj, key=itemgetter(0)) :]
    st.tools.extend((s + delta, f, line, t, c + dt, cut + dc, r + dr) for s, f, line, t, c, cut, r in tools)


def _merge_records(run: EntryRun, e: Earlier, bj: int, conv: int, delta: int,
                   plan: tuple[list[tuple[str, int]], list[tuple[str, int]]]) -> None:  # fmt: skip
    st = run.state
    old = e.state
    revive, drop = plan
    for path, od in old.first.items():  # the earlier run's records are not needed after this
        cd = st.first.get(path)
        merged = od if delta == 0 else {line: s + delta if s >= bj else s for line, s in od.items()}
        if cd:
            merged.update(cd)
        st.first[path] = merged
    highest: dict[str, int] = {}
    for path, line in drop:
        del st.first[path][line]
        highest[path] = max(highest.get(path, -1), line)
    for path, line in revive:
        st.first[path][line] = conv
        highest[path] = max(highest.get(path, -1), line)
    cut = bisect_left(old.order, (bj, "", -1))
    tail = old.order[cut:]
    st.order.extend((conv, path, line) for path, line in sorted(revive))
    st.order.extend(tail if delta == 0 else [(s + delta, path, line) for s, path, line in tail])
    for path, s in old.file_first.items():
        if path not in st.file_first and st.first.get(path):
            st.file_first[path] = s + delta if s >= bj else conv
    for path, (ol, os_) in old.reach.items():
        reach = st.reach.get(path)
        if reach is None:
            reach = st.reach[path] = ([], [])
        top = reach[0][-1] if reach[0] else -1
        z = highest.get(path, -1)
        if z > top:
            reach[0].append(z)
            reach[1].append(conv)
            top = z
        k = bisect_left(os_, bj)
        lines, steps = ol[k:], os_[k:]
        i = bisect_right(lines, top)
        reach[0].extend(lines[i:])
        reach[1].extend(steps[i:] if delta == 0 else [s + delta for s in steps[i:]])
        if not reach[0]:
            del st.reach[path]
    for key, read in old.vacant.items():
        if read.stamp >= bj and key not in st.vacant:
            read.stamp += delta
            st.vacant[key] = read
    for path, ow in old.written.items():
        cw = st.written.setdefault(path, {})
        for line, h in ow.items():
            if h[-1][0] >= bj:
                later = [(w[0] + delta, w[1], w[2]) for w in h[bisect_left(h, bj, key=itemgetter(0)) :]]
                mine = cw.get(line)
                cw[line] = later if mine is None else mine + later


def _merge_stamps(run: EntryRun, e: Earlier, bj: int, delta: int) -> None:
    """Per line, the later of the resumed run's stamp and the earlier run's stamp after the
    convergence point (which is the one after it, when there is one)."""
    m = run.machine
    later: set[int] = set()  # the earlier run's serials after the convergence point
    vague = m.blocks + (e.final.blocks - bj)  # ran by the end of the merged run, or never
    for s, (at, known) in e.serials.items():
        if at >= bj:
            later.add(s)
            run.serials[s] = (at + delta, True) if known else (vague, False)
    if not later:
        return
    # A line the resumed run did not reach still holds the earlier stamp, whose serial now
    # means what it means after the convergence point; a line it reached holds the later of
    # the two stamps.
    for path, before in e.overwritten.items():
        cur = run.last_run.get(path)
        if cur is None:
            continue
        for line, s in before.items():
            if s in later and line < len(cur):
                cur[line] = s
