"""Diagnostics found by running: one bounded, resumable run of the machine from an entry point.

An ``EntryRun`` runs one program on a ``Machine`` whose observer it is (``RunObserver``: it
hears of lines run, vacant argument reads, values written and loop passes; never loading
or saving ``#500–#999``, never recording moves, ``M99`` at level 0 ending the run). It runs in
chunks of ``CHUNK`` blocks (fewer where lathe cycles make each block hundreds of passes:
``EntryRun.checkpoint``) and keeps a ``Snapshot`` at every chunk boundary, the step at which
each line first ran, and what the watched blocks reported (vacant argument reads, values
written), each stamped with the chunk it came from. ``rewind(step)`` restores the last
checkpoint at or before a step and forgets everything found after it, so that after an edit
only the part of the run that can differ is run again (see ``workspace.py`` for which step);
the run as it was is kept, and as soon as the resumed run reaches a state the earlier run had
and the edited lines do not run again, the rest of the earlier run is taken over instead of
being run again (``run_convergence.py``). The machine stamps each line it executes with the
serial of its chunk (``RunObserver.last_run``) so that this can be decided.

``run_diagnostics`` turns the state of a finished run into diagnostics: the alarm it stopped
with (mapped by ``codes.alarm_code``), the block budget running out, clamped repeat counts and
vacant argument reads, each at the block where it happened, in that block's file, naming the
call chain, the block count and, inside a loop, which pass of the innermost loop it was
(counted by ``loop_pass``, which only an observed run calls, kept with each checkpoint) in the message
and the call sites as ``related`` places.

Limits keep a run bounded in time and memory whatever the program does: the block budget
(``max_blocks``; lowered by ``workspace.py`` when the other runs from the same file have used up
most of the file's share, ``FILE_BUDGETS`` budgets, so that a file of many programs that each
loop for ever is analysed in bounded time too), a wall-clock limit (``max_seconds``, counted from the start or the last
rewind, across cancelled and resumed advances) and a cap on what the machine records
(``max_records`` notes: messages, DPRNT output, call remarks). A run that reaches one stops
with a ``run-limit`` diagnostic saying which. A run that comes back to the same place with an
equal state can never end, and stops there sooner, with a diagnostic that says so (an
``endless-loop`` error where the control surely never leaves it, ``endless_loops.py``, else
``run-limit``):
at a jump back or a change of frame the machine asks ``came_back``, which counts the passes of
each; at the ``LOOK_FROM``-th pass and every power of two after it, the run pauses there and
keeps a ``Snapshot``, and compares it with the state at the next pass (``look``,
``machine.tracking.same_state``, with the clock whenever a program the run entered may read it:
``may_read_clock``, the decision convergence uses). A loop whose state repeats only every few
passes runs on to the budget. Checkpoints are kept at chunk boundaries only
(a ``#3006`` pause in a loop does not add one) and, beyond ``MAX_CHECKPOINTS``, every other
one is dropped and the interval doubled.
"""

from __future__ import annotations

import math
import time
from bisect import bisect_left
from collections.abc import Callable, Container, Iterable
from dataclasses import dataclass, field, replace
from operator import itemgetter
from pathlib import Path

from ...bilingual import Detail, in_language, pick
from ...dialects import Dialect
from ...dialects.alarms import alarm_text
from ...library.machine_file import MachineSettings
from ...library.programs import FoundProgram, ProgramLibrary
from ...machine import CallLevel, Machine, Snapshot
from ...machine.calls import letters_for_local
from ...machine.frames import Note
from ...machine.observer import RunObserver
from ...machine.status import FINISHED, RunStatus
from ...machine.tracking import same_state
from ...planner.alarms import UNKNOWN_VALUE, MacroAlarm
from ...planner.missing_feed import NO_FEED
from ..codes import MACRO_ALARM, alarm_code
from ..diagnostics import Diagnostic, Related, diagnostic
from .endless_loops import SHARED, loop_certainty, waits_for_the_machine
from .run_convergence import Earlier, keep_earlier, try_converge
from .sure_alarms import surely_reached
from .unknown_stops import guard_opening, is_guard_note, named_persistent_values, runs_as_macro, unknown_value_text

CHUNK = 1000  # blocks between checkpoints: an edit runs about twice this again before converging
# the least interval, a share of CHUNK: a program of lathe cycles, each block hundreds of
# passes, checkpoints at about CHUNK blocks' worth of work (``EntryRun.checkpoint``)
LEAST_SHARE = 16
MAX_SECONDS = 30.0  # wall-clock limit of one run
MAX_RECORDS = 100_000  # notes (messages, DPRNT output, remarks) one run may record
MAX_CHECKPOINTS = 400  # beyond this, every other checkpoint is dropped
FILE_BUDGETS = 3  # the runs from the programs of one file together run at most this many block budgets
LOOK_FROM = 256  # the pass of a jump back at which the run first looks whether it comes back unchanged

Value = float | None
ToolRecord = tuple[int, str, int, Value, float, float, float]


@dataclass(slots=True)
class VacantRead:
    """A macro read local ``#number`` on ``line`` of ``file`` without its caller passing it."""

    stamp: int
    number: int
    file: str
    line: int
    chain: tuple[CallLevel, ...]


@dataclass(slots=True)
class RunState:
    """What a run found so far, each entry stamped with the step of its chunk's start."""

    first: dict[str, dict[int, int]] = field(default_factory=dict)  # file -> line -> first step
    order: list[tuple[int, str, int]] = field(default_factory=list)  # (step, file, line), by step
    file_first: dict[str, int] = field(default_factory=dict)  # file -> the step it first ran at
    # file -> (lines, steps): each line that first ran further into the file than any before it,
    # and when; both increase, so the first step at or after a line is one bisection away
    reach: dict[str, tuple[list[int], list[int]]] = field(default_factory=dict)
    vacant: dict[tuple[str, int, int], VacantRead] = field(default_factory=dict)
    # file -> line -> [(stamp, #n, value)]: the value the line left last in each chunk it assigned
    # in, oldest first, so that going back to a checkpoint finds the value the line left before it
    written: dict[str, dict[int, list[tuple[int, int, Value]]]] = field(default_factory=dict)
    # the cycle time (cycle_lenses.py): the clock (seconds) at each entry of ``order``, entry by
    # entry (a list of floats: shifting it when a run converges is one pass), and each tool change
    # (stamp, file, line, T, seconds, mm cut, mm rapid before it)
    clocks: list[float] = field(default_factory=list)
    tools: list[ToolRecord] = field(default_factory=list)


SMALL_MACHINE = 20_000  # lines of compiled files under which a dropped machine is freed at once


def drop_machine(m: Machine) -> None:
    """A machine no run will use again. A small one has its cycles broken (``Machine.discard``)
    and is freed at once: many small runs started again (typing at the top of a short program)
    would otherwise pile up until the cycle collector's next clean-up. A large one is left to
    that clean-up: freeing a 100k-line file's compiled blocks there and then would add some 30
    ms to the edit that started its run again."""
    if sum(len(cf.code) for cf in m.compiled.values()) < SMALL_MACHINE:
        m.discard()


class EntryRun(RunObserver):
    """One analysis run from one entry program, resumable after edits; the observer of its
    machine (see ``machine/observer.py``)."""

    def __init__(
        self,
        entry: FoundProgram,
        dialect: Dialect,
        settings: MachineSettings,
        library: ProgramLibrary,
        max_blocks: int,
        max_seconds: float = MAX_SECONDS,
        max_records: int = MAX_RECORDS,
    ) -> None:
        super().__init__()
        self.entry = entry
        self.dialect = dialect
        self.settings = settings
        self.library = library
        self.max_blocks = max(1, max_blocks)
        self.file_budget: int | None = None  # set when the file's share, not the run's own budget, is the limit
        self.max_seconds = max_seconds  # this run's time limit: its own, or what its file has left of it
        self.own_seconds = max_seconds
        self.max_records = max_records
        self.interval = CHUNK  # blocks between checkpoints
        self.work = 0  # the lathe cycles' passes since the last checkpoint (``Planner.cycle_passes``)
        self.thinned = False  # the checkpoints were thinned out: the interval no longer shrinks
        self.elapsed = 0.0  # seconds spent running since the start or the last rewind
        self.stopped_by: str | None = None  # "time" or "records" when a limit other than the budget ended it
        self.machine: Machine
        self.checkpoints: list[Snapshot] = []
        self.passes: dict[tuple[int, int], int] = {}  # (level, DO line) -> the pass of the loop running there
        self.pass_marks: list[dict[tuple[int, int], int]] = []  # ``passes`` at each checkpoint
        self.stamp = 0
        self.serial = 0
        # chunk serial -> (first step of the chunk, True), or (last step it may stand for, False)
        self.serials: dict[int, tuple[int, bool]] = {}
        self.earlier: Earlier | None = None  # the run before the edits, until this one converges
        self.rerun_blocks = 0  # blocks run since the last edit
        self.reads_clock: Callable[[str], bool] = lambda path: True  # may a program of this file read the clock?
        # endless loops (``came_back``): passes of each jump back (keyed by ``_jump_key``), the
        # state kept at a pass to compare with the next, the pass to look at now, and where an
        # endless loop was found (file, line)
        self.back_passes: dict[int, int] = {}
        self.watches: dict[int, tuple[int, Snapshot]] = {}
        self.looking: tuple[int, int, int, int] | None = None  # (key, pass, line, to)
        self.endless_at: tuple[str, int, int] | None = None  # (file, jump line or -1, line jumped to)
        self.restart()

    # ---------------------------------------------------------------- running
    def restart(self) -> None:
        """Start again from the first block with a fresh machine."""
        if hasattr(self, "machine"):
            drop_machine(self.machine)
        self.last_run = {}  # the new machine's lines have not run (``RunObserver``)
        self.track_serial = self.track_floor = 0
        m = Machine(self.dialect, self.settings, self.library, m99_ends_main=True, observer=self, kept_unknown=True)
        m.load_persistent(named_persistent_values(self.settings))
        m.planner.record_moves = False
        m.start(self.entry)
        self.as_macro = runs_as_macro(self.entry)  # read once a run: the notes ask again
        if self.as_macro:  # checked without its caller: its arguments and #100-#199 are unknown
            m.unknown_from_caller()
        self.machine = m
        self.state = RunState()
        self.checkpoints = [m.snapshot()]
        self.passes = {}
        self.pass_marks = [{}]
        self.stamp = 0
        self.interval = CHUNK
        self.work = 0
        self.thinned = False
        self.elapsed = 0.0
        self.stopped_by = None
        self.serials = {}
        self.earlier = None
        self.endless_at = None
        self.forget_looks()

    def discard(self) -> None:
        """This run is dropped: free its machine (``drop_machine``)."""
        drop_machine(self.machine)
        self.checkpoints = []
        self.earlier = None

    @property
    def finished(self) -> bool:
        return self.machine.status in FINISHED and self.machine.status != RunStatus.STOPPED

    def advance(self, should_cancel: Callable[[], bool] | None = None) -> bool:
        """Run to the end (or the budget); False when ``should_cancel`` said stop first (the
        run can be advanced again later)."""
        m = self.machine
        while not self.finished:
            if m.status == RunStatus.STOPPED:  # ``Machine.cancel`` from another thread
                m.cancel_requested = False
                m.status = RunStatus.READY
                return False
            if should_cancel is not None and should_cancel():
                return False
            left = self.max_blocks - m.blocks
            chunk = min(max(1, self.interval - (m.blocks - self.checkpoints[-1].blocks)), left)
            self.stamp = before = m.blocks
            self.track_serial = self.new_serial(m.blocks)
            began = time.perf_counter()
            passes = m.planner.cycle_passes
            status = m.run(chunk, is_limit=chunk >= left)
            self.elapsed += time.perf_counter() - began
            self.work += m.planner.cycle_passes - passes
            self.rerun_blocks += m.blocks - before
            if self.looking is not None:
                status = self.look()
            if status == RunStatus.PAUSED:
                m.resume()  # M00, #3006 and the end of a chunk: a simulation goes on
                if m.blocks - self.checkpoints[-1].blocks >= self.interval:
                    self.checkpoint()
                    if self.earlier is not None and self.checkpoints[-1].blocks == m.blocks:
                        try_converge(self)
            if not self.finished and (self.elapsed > self.max_seconds or len(m.notes) > self.max_records):
                self.stopped_by = "time" if self.elapsed > self.max_seconds else "records"
                m.status = RunStatus.LIMIT
        self.earlier = None
        return True

    def may_read_clock(self, files: Iterable[str]) -> bool:
        """Whether a program of any of ``files`` may read the simulated clock: then two states
        are equal only with equal clocks (``same_state``'s ``clock``)."""
        return any(self.reads_clock(path) for path in files)

    # ---------------------------------------------------------------- endless loops
    def look(self) -> RunStatus:
        """The machine paused where ``came_back`` asked: keep its state, or compare it with the
        state kept at the previous pass of the same jump back. Equal, the run can never end (it
        is deterministic, and ``same_state`` compares the clock whenever a program it entered
        may read it): it stops with ``stopped_by`` "endless"."""
        assert self.looking is not None
        key, k, line, to = self.looking
        self.looking = None
        m = self.machine
        snap = m.snapshot()
        kept = self.watches.pop(key, None)
        if kept is None or kept[0] + 1 != k:
            self.watches[key] = (k, snap)
        elif same_state(kept[1], snap, clock=self.may_read_clock(self.last_run)):
            self.stopped_by = "endless"
            self.endless_at = (m.frames[-1].file, line, to)
            m.status = RunStatus.LIMIT
        return m.status

    def forget_looks(self) -> None:
        """The run went back or its program changed: count the passes of jumps back afresh."""
        self.back_passes = {}
        self.watches = {}
        self.looking = None

    def new_serial(self, step: int, known: bool = True) -> int:
        """A serial for the chunk starting at ``step`` (or a vague one: ran by ``step`` or never)."""
        self.serial += 1
        self.serials[self.serial] = (step, known)
        return self.serial

    def checkpoint(self) -> None:
        """Keep the machine's state here; thin the checkpoints out when there are too many.

        A chunk whose blocks made more lathe cycle passes than blocks, and more work than
        ``CHUNK`` blocks (a program of G71, G75 and G76 cycles: hundreds of passes a block),
        halves the interval until its work would not, down to
        ``CHUNK // LEAST_SHARE``, so that an edit runs about as much work again as in a program of
        plain moves. The interval only shrinks by halves, and no more once the checkpoints were
        thinned (which doubles it), so the
        checkpoints stay at multiples of it: a run resumed after an edit makes the same
        decisions on the same blocks and meets the earlier run's checkpoints to converge."""
        blocks = self.machine.blocks - self.checkpoints[-1].blocks
        self.checkpoints.append(self.machine.snapshot())
        self.pass_marks.append(dict(self.passes))
        passes, self.work = self.work, 0
        least = max(1, CHUNK // LEAST_SHARE)
        while (passes > blocks and blocks + passes > CHUNK and not self.thinned and self.interval >= 2 * least
               and not self.machine.blocks % (self.interval // 2)):  # fmt: skip
            self.interval //= 2
            blocks //= 2
            passes //= 2
        if len(self.checkpoints) > MAX_CHECKPOINTS:
            self.checkpoints[:] = self.checkpoints[::2]
            self.pass_marks[:] = self.pass_marks[::2]
            self.interval *= 2
            self.thinned = True

    def edited(self, path: str, lines: list[int] | None) -> None:
        """An edit changed ``lines`` of ``path`` (None: its structure or line count) and the
        run is about to be taken back: keep the run as it was to converge with (see
        ``run_convergence.py``), unless lines moved."""
        self.rerun_blocks = 0
        if lines is None:
            self.earlier = None
            return
        if self.earlier is None and self.finished and self.stopped_by in (None, "endless"):
            self.earlier = keep_earlier(self)
        if self.earlier is not None:
            self.earlier.changed.setdefault(path, set()).update(lines)

    def rewind(self, step: int, avoid_file: str | None = None) -> None:
        """Go back to the last checkpoint at or before ``step`` (before it, and before any
        G66 that names ``avoid_file``, when that file's structure changed) and forget what
        was found after it."""
        if avoid_file is not None:
            self.earlier = None
        self.back_to(step, avoid_file)

    def back_to(self, step: int, avoid_file: str | None = None) -> None:
        """``rewind`` without touching the earlier run kept for converging."""
        strict = avoid_file is not None
        keep = 0
        for k, snap in enumerate(self.checkpoints):
            if snap.blocks > step or (strict and snap.blocks >= step):
                break
            if avoid_file is not None and any(mc.found.file.path == avoid_file for mc in snap.modal_calls):
                break
            keep = k
        snap = self.checkpoints[keep]
        if (strict and snap.blocks >= step) or (avoid_file is not None and snap.blocks == 0):
            self.restart()
            return
        del self.checkpoints[keep + 1 :]
        del self.pass_marks[keep + 1 :]
        self.passes = dict(self.pass_marks[keep])
        self.work = 0
        self.elapsed = 0.0
        self.stopped_by = None
        self.endless_at = None
        self.forget_looks()
        m = self.machine
        m.restore(snap)
        at = snap.blocks
        self._forget(at)
        if self.earlier is not None:
            self.earlier.resume = min(self.earlier.resume, at)
        if m.status == RunStatus.PAUSED:
            m.resume()

    def _forget(self, at: int) -> None:
        """Forget what was found at or after step ``at``; the lines it ran are reported again
        (``first_run``) when they next run, the floor being raised. When the
        earlier run kept for converging holds the records, they stay as they are for it."""
        serials = self.serials
        for s, (step, _) in serials.items():
            if step >= at:
                serials[s] = (at - 1, False)  # the line ran before ``at``, or never
        self.track_floor = self.serial + 1
        st = self.state
        cut = bisect_left(st.order, (at, "", -1))
        if self.earlier is not None and self.earlier.state is st:
            if cut < len(st.order) // 2:
                self.state = _records_before(st, at, cut)
                return
            self.state = st = RunState(
                {f: dict(d) for f, d in st.first.items()}, list(st.order), dict(st.file_first),
                {f: (list(a), list(b)) for f, (a, b) in st.reach.items()}, dict(st.vacant),
                {f: {line: list(h) for line, h in d.items()} for f, d in st.written.items()},
                list(st.clocks), list(st.tools),
            )  # fmt: skip
        for _, path, line in st.order[cut:]:
            lines = st.first[path]
            if lines.get(line, -1) >= at:  # else recorded twice (converging keeps both records)
                del lines[line]
        del st.order[cut:]
        del st.clocks[cut:]
        del st.tools[bisect_left(st.tools, at, key=itemgetter(0)) :]
        for path in [p for p, s in st.file_first.items() if s >= at]:
            del st.file_first[path]
        for path, (reached, steps) in list(st.reach.items()):
            k = bisect_left(steps, at)
            if k == 0:
                del st.reach[path]
            else:
                del reached[k:]
                del steps[k:]
        vacant = self.state.vacant
        for key in [k for k, v in vacant.items() if v.stamp >= at]:
            del vacant[key]
        for written in self.state.written.values():
            for line in [line for line, h in written.items() if h[-1][0] >= at]:
                h = written[line]
                del h[bisect_left(h, at, key=itemgetter(0)) :]
                if not h:
                    del written[line]

    def reset_file(self, path: str) -> None:
        """The file's text changed in structure or length: compile it afresh when it runs."""
        m = self.machine
        cf = m.compiled.get(path)
        if self.earlier is not None and path in self.earlier.files:
            self.earlier = None
        self.forget_looks()
        if cf is not None:
            cf.reset()
            if path in self.last_run:
                self.last_run[path] = [self.new_serial(m.blocks - 1, known=False)] * len(cf.code)
                self.track_floor = self.serial + 1

    def forget_lines(self, path: str, lines: list[int]) -> None:
        """These lines of ``path`` changed: compile them afresh when they run."""
        cf = self.machine.compiled.get(path)
        self.forget_looks()
        if cf is not None:
            for line in lines:
                if 0 <= line < len(cf.code) - 1:
                    cf.code[line] = None

    # ---------------------------------------------------------------- what the machine tells (RunObserver)
    def first_run(self, file: str, line: int, step: int) -> None:
        if self.earlier is not None:
            self.earlier.overwriting(file, line)
        st = self.state
        lines = st.first.get(file)
        if lines is None:
            lines = st.first[file] = {}
        if file not in st.file_first:
            st.file_first[file] = step
        if line not in lines:
            lines[line] = step
            st.order.append((step, file, line))
            st.clocks.append(self.machine.planner.clock)
            reach = st.reach.get(file)
            if reach is None:
                st.reach[file] = ([line], [step])
            elif line > reach[0][-1]:
                reach[0].append(line)
                reach[1].append(step)

    def tool_changed(self, file: str, line: int) -> None:
        m = self.machine
        self.state.tools.append(
            (
                self.stamp,
                file,
                line,
                m.planner.codes.get("T"),
                m.planner.clock,
                m.planner.cut_length,
                m.planner.rapid_length,
            )
        )

    def vacant_argument(self, number: int, file: str, line: int, chain: tuple[CallLevel, ...]) -> None:
        key = (file, line, number)
        if key not in self.state.vacant:
            self.state.vacant[key] = VacantRead(self.stamp, number, file, line, chain)

    def came_back(self, line: int, to: int) -> bool:
        key = (line << 32) | to
        k = self.back_passes.get(key, 0) + 1
        self.back_passes[key] = k
        if (k >= LOOK_FROM and not k & (k - 1)) or (self.watches and key in self.watches):
            self.looking = (key, k, line, to)
            return True
        return False

    def loop_pass(self, level: int, do_line: int, again: bool) -> None:
        key = (level, do_line)
        self.passes[key] = self.passes.get(key, 0) + 1 if again else 1

    def wrote(self, file: str, line: int, number: int, value: Value) -> None:
        lines = self.state.written.get(file)
        if lines is None:
            lines = self.state.written[file] = {}
        h = lines.get(line)
        if h is None:
            lines[line] = [(self.stamp, number, value)]
        elif h[-1][0] == self.stamp:
            h[-1] = (self.stamp, number, value)
        else:
            h.append((self.stamp, number, value))

    def first_reaching(self, path: str, line: int) -> int | None:
        """The first step at which ``line`` or any later line of ``path`` ran."""
        reach = self.state.reach.get(path)
        if reach is None:
            return None
        k = bisect_left(reach[0], line)
        return reach[1][k] if k < len(reach[1]) else None

    def first_step(self, path: str, lines: list[int] | None = None) -> int | None:
        """The first step at which any of ``lines`` (or any line) of ``path`` ran."""
        recorded = self.state.first.get(path)
        if not recorded:
            return None
        if lines is None:
            return self.state.file_first.get(path)
        steps = [s for line in lines if (s := recorded.get(line)) is not None]
        return min(steps) if steps else None


def _records_before(st: RunState, at: int, cut: int) -> RunState:
    """A new ``RunState`` with what ``st`` found before step ``at`` (``cut`` entries of its order)."""
    out = RunState(order=st.order[:cut])
    for step, path, line in out.order:
        out.first.setdefault(path, {}).setdefault(line, step)
    out.clocks = st.clocks[:cut]
    out.tools = st.tools[: bisect_left(st.tools, at, key=itemgetter(0))]
    out.file_first = {f: s for f, s in st.file_first.items() if s < at}
    for path, (lines, steps) in st.reach.items():
        k = bisect_left(steps, at)
        if k:
            out.reach[path] = (lines[:k], steps[:k])
    out.vacant = {key: v for key, v in st.vacant.items() if v.stamp < at}
    for f, d in st.written.items():
        kept = out.written[f] = {}
        for line, h in d.items():
            if h[0][0] < at:
                kept[line] = h[:] if h[-1][0] < at else h[: bisect_left(h, (at,))]
    return out


# ---------------------------------------------------------------- diagnostics of a run


def _in_a_macro_call(chain: tuple[CallLevel, ...]) -> bool:
    """Whether the level a finding's ``chain`` ends at is a macro a G65/G66 called (its locals are arguments)."""
    return len(chain) > 1 and chain[-1].how in ("G65", "G66")


def _still_unknown(m: Machine, n: int) -> bool:
    """Whether ``#n`` reads unknown where the run stopped (what cannot be read counts as unknown)."""
    try:
        value = m.read(float(n))
    except MacroAlarm:  # a number the control refuses to read: nothing to tell from it
        return True
    return isinstance(value, float) and math.isnan(value)


def _alarm_diagnostic(run: EntryRun, code: str, line_text: Callable[[str, int], str], locale: str) -> Diagnostic:
    """The alarm the run stopped with, as a diagnostic of ``code``."""
    m = run.machine
    a = m.alarm
    assert a is not None
    if a.subject == UNKNOWN_VALUE:
        ran = sorted((line for line in run.state.first.get(a.file, {}) if line < a.line), reverse=True)
        en, zh = unknown_value_text(line_text(a.file, a.line), ((n, line_text(a.file, n)) for n in ran), m.kinds,
                                    m.dialect, run.as_macro, lambda n: _still_unknown(m, n),
                                    called=_in_a_macro_call(a.chain))  # fmt: skip
    elif code == MACRO_ALARM:
        en = f"the run reaches macro {a.words()}: {a.message}"
        zh = f"运行到宏程序{a.words('zh')}：{in_language(a.message, True)}"
    else:
        en = f"{a.message} ({a.words()})"
        if isinstance(a.message, Detail):  # its Chinese says what the alarm is: no title before it
            zh = f"{a.message.zh}（{a.words('zh')}）"
        else:  # a text without Chinese: the alarm's title in Chinese says what it is
            zh = f"{alarm_text(a.number, 'zh')}（{a.words('zh')}）：{a.message}"
    in_loop = bool(m.frames and m.frames[-1].loops)
    if in_loop:
        do_line = m.frames[-1].loops[-1]
        k = run.passes.get((len(m.frames) - 1, do_line))
        if k is not None:
            kind = "WHILE" if "WHILE" in line_text(a.file, do_line).upper() else "DO"
            en += f", in iteration {k} of the {kind} loop at line {do_line + 1}"
            zh += f"，第 {do_line + 1} 行 {kind} 循环的第 {k} 次迭代"
    milder = callers_to_decide = False
    if code == MACRO_ALARM:  # an error where every run of the main program stops there (sure_alarms.py)
        path = [(f, line) for _, f, line in run.state.order]
        path.append((a.file, a.line))
        sure = surely_reached(path, line_text, m.kinds, arguments_of=run.entry.file.path if run.as_macro else None)
        milder = run.as_macro or not sure
        callers_to_decide = run.as_macro and not sure  # a macro alone on arguments it was not passed
    found = _diagnostic(a.file, a.line, code, en, zh, a.chain, m.blocks, in_loop, line_text, locale, milder=milder)
    return replace(found, severity="information") if callers_to_decide else found


def _guard_diagnostic(run: EntryRun, note: Note, line_text: Callable[[str, int], str], locale: str) -> Diagnostic:
    """The ``unknown-value`` hint of a guard on an unknown value the run went past on the side
    that does not raise the program's own alarm (machine/guards.py): what the condition depends
    on, named as where a run stops on one."""
    m = run.machine
    ran = sorted((line for line in run.state.first.get(note.file, {}) if line < note.line), reverse=True)
    en, zh = unknown_value_text(line_text(note.file, note.line), ((n, line_text(note.file, n)) for n in ran),
                                m.kinds, m.dialect, run.as_macro, lambda n: _still_unknown(m, n),
                                guard_opening(note.subject), _in_a_macro_call(note.chain))  # fmt: skip
    return _diagnostic(note.file, note.line, "unknown-value", en, zh, note.chain, None, False, line_text, locale)


def _endless_diagnostic(
    run: EntryRun, at: tuple[str, int, int], line_text: Callable[[str, int], str], locale: str
) -> Diagnostic:
    """The endless loop the run found at ``at`` (file, jump line or -1, line jumped to): an
    ``endless-loop`` error, or warning, where the control surely never leaves it
    (``endless_loops.loop_certainty``), else the run's ``run-limit`` note."""
    m = run.machine
    path, jump, to = at
    line = jump if jump >= 0 else to
    certainty = loop_certainty(lambda k: line_text(path, k), jump, to, m.kinds)
    if certainty is None and waits_for_the_machine(lambda k: line_text(path, k), jump, to, m.kinds):
        en = (
            f"the run comes back to line {line + 1} with every variable and position unchanged and cannot leave this "
            "loop; the control leaves it when what the machine changes (a timer, an input signal) ends it"
        )
        zh = (
            f"运行再次到达第 {line + 1} 行时所有变量和位置都没有变化，模拟无法离开此循环；"
            "控制器在机床改变的值（计时器、输入信号）满足条件时离开"
        )
    else:
        en = (
            f"an endless loop: line {line + 1} comes back with every variable and position unchanged; "
            "the control would never leave it"
        )
        zh = f"死循环：第 {line + 1} 行再次执行时所有变量和位置都没有变化，控制器永远不会离开这里"
    if certainty == SHARED:
        en += " unless another path of the control or the operator changes the common variables it reads"
        zh += "，除非其他通道或操作者修改了它读取的公共变量"
    code = "run-limit" if certainty is None else "endless-loop"
    return _diagnostic(path, line, code, en, zh, m.chain(), None, False, line_text, locale,
                       milder=certainty == SHARED)  # fmt: skip


# the run's notes of a finding that is an alarm on another profile: shown at the code's milder severity
_MILDER_NOTES = frozenset(("arc-radius", "cutter-arc", "cutter-interference", "cutter-plane", "cutter-skip"))


def run_diagnostics(
    run: EntryRun,
    line_text: Callable[[str, int], str],
    locale: str,
    invalid: Container[tuple[str, int]] = frozenset(),
) -> list[Diagnostic]:
    """The findings of a finished run (see the module docstring). ``invalid`` holds the (file,
    line) of the blocks the static checks found in error: the alarm a run stops with on one of
    them is that error again, met when the block runs, and is left out (a macro alarm, which the
    program raises itself, never is)."""
    m = run.machine
    out: list[Diagnostic] = []
    base = run.dialect.macro_alarm_base
    if m.status == RunStatus.ALARM and m.alarm is not None:
        a = m.alarm
        code = alarm_code(a.number, a.subject, base)
        if code == MACRO_ALARM or (a.file, a.line) not in invalid:
            out.append(_alarm_diagnostic(run, code, line_text, locale))
    elif m.status == RunStatus.LIMIT and run.stopped_by in (None, "endless") and m.in_main_loop():
        pass  # the main program's loop back (Haas M99 Pn): a production loop, which never ends
    elif m.status == RunStatus.LIMIT and m.frames and run.endless_at is not None:
        out.append(_endless_diagnostic(run, run.endless_at, line_text, locale))
    elif m.status == RunStatus.LIMIT and m.frames:
        f = m.frames[-1]
        if run.stopped_by == "time" and run.max_seconds < run.own_seconds:
            en = (
                f"the analysis run stopped here after {m.blocks} blocks and {run.max_seconds:.3g} s: the programs "
                f"of one file share {run.own_seconds:g} s of analysis, and those before it used the rest"
            )
            zh = (
                f"分析运行在 {m.blocks} 个程序段、{run.max_seconds:.3g} 秒后于此处停止："
                f"一个文件中的程序共用 {run.own_seconds:g} 秒分析时间，其余已被它之前的程序用完"
            )
        elif run.stopped_by == "time":
            en = f"the analysis run stopped here after {m.blocks} blocks and {run.max_seconds:g} s, its time limit"
            zh = f"分析运行在 {m.blocks} 个程序段、{run.max_seconds:g} 秒后于此处停止（达到时间上限）"
        elif run.stopped_by == "records":
            en = (
                f"the analysis run stopped here after {m.blocks} blocks: it recorded more than "
                f"{run.max_records} messages and outputs, its memory limit"
            )
            zh = (
                f"分析运行在 {m.blocks} 个程序段后于此处停止：记录的消息和输出超过 {run.max_records} 条（达到内存上限）"
            )
        elif run.file_budget is not None:
            en = (
                f"the analysis run stopped here after {m.blocks} blocks: the programs of this file together "
                f"ran {run.file_budget} blocks, the budget of one file's analysis (an endless loop?)"
            )
            zh = (
                f"分析运行在 {m.blocks} 个程序段后于此处停止：本文件各程序共运行了 {run.file_budget} 个程序段，"
                f"达到一个文件的分析上限（可能是死循环）"
            )
        else:
            en = f"the analysis run stopped here after {m.blocks} blocks, its budget (an endless loop?)"
            zh = f"分析运行在 {m.blocks} 个程序段后于此处停止（达到上限，可能是死循环）"
        line = f.pc
        cf = m.compiled.get(f.file)
        if cf is not None and line >= len(cf.code) - 1:  # stopped as it ran off the program's end
            line = max(0, len(cf.code) - 2)
        out.append(_diagnostic(f.file, line, "run-limit", en, zh, m.chain(), None, False, line_text, locale))
    out += _note_diagnostics(run, line_text, locale)
    for read in run.state.vacant.values():
        spec1, spec2 = letters_for_local(read.number)
        letter = spec1 or spec2 or "?"
        caller = read.chain[-2] if len(read.chain) >= 2 else None
        how = read.chain[-1].how
        who = f"{caller.program} line {caller.line + 1} ({how})" if caller else "its caller"
        who_zh = f" {caller.program} 第 {caller.line + 1} 行（{how}）" if caller else "调用者"
        en = f"#{read.number} ({letter}) is read, but {who} does not pass {letter}"
        zh = f"读取了 #{read.number}（{letter}），但{who_zh}没有传递 {letter}"
        out.append(_diagnostic(read.file, read.line, "vacant-argument", en, zh, read.chain, None, False, line_text,
                               locale))  # fmt: skip
    return out


def _note_diagnostics(run: EntryRun, line_text: Callable[[str, int], str], locale: str) -> list[Diagnostic]:
    """The findings of the notes a run made (a clamped L, a lathe cycle's warning, a planner's note,
    a guard it went past, ...)."""
    m = run.machine
    base = run.dialect.macro_alarm_base
    out: list[Diagnostic] = []
    for note in m.notes:
        if is_guard_note(note.kind, note.subject):  # went past the program's own guard (machine/guards.py)
            out.append(_guard_diagnostic(run, note, line_text, locale))
        elif note.kind == "call" and note.subject == "repeat-count":
            en = in_language(note.message, False)
            zh = in_language(note.message, True)
            d = _diagnostic(note.file, note.line, "repeat-count-range", en, zh, note.chain, None, False, line_text,
                            locale, milder=True)  # fmt: skip
            out.append(d)
        elif note.kind == "cycle" and note.subject is not None:  # a lathe cycle's warning (planner/cycle_rules.py)
            code = alarm_code(0, note.subject, base)
            en = in_language(note.message, False)
            zh = in_language(note.message, True)
            out.append(_diagnostic(note.file, note.line, code, en, zh, note.chain, None, False, line_text, locale,
                                   milder=True))  # fmt: skip
        elif note.kind in ("arc", "units", "limits", "cutter", "simulation") and note.subject is not None:
            # planner/arc_checks.py, planner/units.py, planner/machine_limits.py, planner/cutter_stage.py,
            # planner/one_shot.py (a cycle not simulated): the subject is the code
            en, zh = in_language(note.message, False), in_language(note.message, True)
            out.append(_diagnostic(note.file, note.line, note.subject, en, zh, note.chain, None, False, line_text,
                                   locale, milder=note.subject in _MILDER_NOTES))  # fmt: skip
        elif note.kind == "feed" or (note.kind == NO_FEED and not run.as_macro):
            # a per-minute feed that looks per revolution (planner.py); a cut with no feed, or per
            # revolution with no S (planner/missing_feed.py), but in a subprogram checked without
            # its caller, which cuts at the feed and speed its caller gives
            en, zh = in_language(note.message, False), in_language(note.message, True)
            out.append(_diagnostic(note.file, note.line, "feed-per-minute" if note.kind == "feed" else NO_FEED, en,
                                   zh, note.chain, None, False, line_text, locale))  # fmt: skip
    return out


def not_run_diagnostic(entry: FoundProgram, file_budget: int, locale: str, spent: str = "blocks",
                       seconds: float = MAX_SECONDS) -> Diagnostic:  # fmt: skip
    """The program ``entry`` was not run: the runs before it in its file used up the file's
    budget of blocks (``spent`` "blocks") or its time (``seconds``, "time"). Marked on its first
    line, where a run would have started."""
    number = entry.unit.number
    name = f"O{number:04d}" if number is not None else display_name(entry.file.path)
    if spent == "time":
        en = (
            f"{name} was not run: the programs before it in this file took {seconds:g} s, the time of one "
            "file's analysis (do they wait for a signal, or loop for ever?)"
        )
        zh = (
            f"{name} 未运行：本文件中它之前的程序共用了 {seconds:g} 秒，"
            "达到一个文件的分析时间上限（是否在等待信号或死循环？）"
        )
    else:
        en = (
            f"{name} was not run: the programs before it in this file together ran {file_budget} blocks, "
            "the budget of one file's analysis (are they endless loops?)"
        )
        zh = (
            f"{name} 未运行：本文件中它之前的程序共运行了 {file_budget} 个程序段，"
            "达到一个文件的分析上限（是否有死循环？）"
        )
    line = entry.unit.start
    text = entry.file.lines[line] if line < len(entry.file.lines) else ""
    start = len(text) - len(text.lstrip())
    end = max(start + 1, len(text.rstrip()))
    return diagnostic(entry.file.path, line, start, line, end, "run-limit", pick(locale, en, zh))


def _diagnostic(
    file: str,
    line: int,
    code: str,
    en: str,
    zh: str,
    chain: tuple[CallLevel, ...],
    blocks: int | None,
    in_loop: bool,
    line_text: Callable[[str, int], str],
    locale: str,
    milder: bool = False,
) -> Diagnostic:
    """A run-found diagnostic spanning the block's text, with how it was reached; ``milder``
    where the control is lenient (``codes.default_severity``)."""
    callers = chain[:-1]
    hows = [c.how for c in chain[1:]]  # how each caller called the next level
    if callers:
        steps = list(zip(callers, hows, strict=True))
        en += "; reached from " + " → ".join(f"{c.program}:{c.line + 1} ({how})" for c, how in steps)
        zh += "；调用路径 " + "→".join(f"{c.program}:{c.line + 1}（{how}）" for c, how in steps)
    if blocks is not None and (in_loop or callers):
        en += f", at block {blocks} of the run" + (" (inside a loop)" if in_loop else "")
        zh += f"，运行的第 {blocks} 个程序段" + ("（循环中）" if in_loop else "")
    text = line_text(file, line)
    start = len(text) - len(text.lstrip())
    end = max(start + 1, len(text.rstrip()))
    related = tuple(
        Related(c.file, c.line, 0, max(1, len(line_text(c.file, c.line).rstrip())),
                pick(locale, f"called from {c.program} ({how})", f"由 {c.program} 调用（{how}）"))
        for c, how in reversed(list(zip(callers, hows, strict=True)))
    )  # fmt: skip
    return diagnostic(file, line, start, line, end, code, pick(locale, en, zh), related, milder=milder)


def display_name(path: str) -> str:
    return Path(path).name
