"""Running the machine until the debugger should stop: continue, step in, over and out.

One step is one block. Step in runs one block (into a call). A lathe roughing cycle (G71–G73
P Q) is one step with its shape: while the planner reads the shape no step or breakpoint stops
in it; a G70 runs its shape as a level that step in enters (docs/semantics.md §10.2). Step over runs blocks until the
program level is back where it started (a G65, M98 or G66 call runs to completion). Step out
runs until the level is above where it started (past the M99). Any of them stops at a
breakpoint, an alarm, an ``M00``/``#3006`` pause, the block budget, the end of the program
(``stop_at_end``: the final state stays to be looked at and stepped back from; the next run
from there ends the session), or a pause request from another thread. Every block a run
arrives at is shown to the breakpoints, so their hit counts are the run's. Step back and
reverse continue walk the history backwards and set the hit counts back with it. A continue
with no breakpoints and no motion echo runs the interpreter at full speed in chunks and is
paused by ``Machine.request_pause``; otherwise it runs block by block. Output (DPRNT,
messages, the echoed motion) goes to ``output`` as it happens; a move is echoed with the axes
the program has commanded so far (``machine.commanded_axes``), never an axis it does not mention.
"""

from __future__ import annotations

import gc
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from ..bilingual import in_language, is_chinese, pick
from ..machine import Machine
from ..machine.alarms import budget_spent
from ..machine.block_roles import skipped
from ..machine.commanded_axes import CommandedAxes
from ..machine.status import FINISHED, RunStatus
from ..planner.moves import Move
from .breakpoints import Breakpoints, Hit, Visit
from .history import History
from .stop_points import can_stop

CONTINUE, STEP_IN, STEP_OVER, STEP_OUT = "continue", "in", "over", "out"


@dataclass(slots=True)
class Stop:
    """How a run ended: why it stopped (``step``, ``pause``, ``entry``, ``exception``, a ``Hit``'s
    reason) with a text to show, or ``finished`` when the program is over."""

    reason: str
    description: str | None = None
    text: str | None = None
    hit_ids: list[int] = field(default_factory=list)
    finished: bool = False


@dataclass(slots=True)
class Filters:
    """The exception filters: stop on alarms, stop on ``#3006``/``M00`` messages."""

    alarms: bool = True
    messages: bool = True


class Stepper:
    def __init__(
        self,
        machine: Machine,
        breakpoints: Breakpoints,
        history: History,
        output: Callable[[str, str], None],
        echo_motion: bool = False,
        filters: Filters | None = None,
    ) -> None:
        self.machine = machine
        self.breakpoints = breakpoints
        self.history = history
        self.output = output
        self.echo_motion = echo_motion
        self.filters = filters or Filters()
        self.locale: str | None = None  # the client's (set by the session): alarm details and notes in it
        self.pause_requested = False
        self.notes_sent = len(machine.notes)
        self.moves_sent = len(machine.planner.moves)
        self.commanded = CommandedAxes(machine)  # the axes the echo shows
        self.fresh = True  # nothing has run yet: a breakpoint on the first block counts
        self.stop_at_end = False  # stop where the program ends (set by the session)
        self.never_stop = False  # "Run Without Debugging": the block budget ends the run too

    def arm(self) -> None:
        """Before a run starts (on the requesting thread): forget pause requests of earlier runs,
        so that one made from now on, even before the run's thread gets going, is honoured."""
        self.pause_requested = False
        self.machine.pause_requested = False

    def request_pause(self) -> None:
        """From another thread: stop the run soon (also inside an endless loop)."""
        self.pause_requested = True
        self.machine.request_pause()

    def resync(self) -> None:
        """After the history moved the machine: output already shown is not shown again."""
        self.notes_sent = len(self.machine.notes)
        self.moves_sent = len(self.machine.planner.moves)

    # ---------------------------------------------------------------- running
    def run(self, mode: str, until: Callable[[Machine], bool] | None = None) -> Stop:
        """Run in ``mode``; ``until``, when given, also ends a continue after the first block
        after which it holds (``Stop("goto")``), before any breakpoint there is asked."""
        m = self.machine
        if m.finished:  # its end was shown already
            return Stop("exited", finished=True)
        self.breakpoints.prime()
        if self.fresh:
            self.fresh = False
            hit = self.breakpoints.check(m, True) if not self.breakpoints.empty else None
            if hit is not None and mode == CONTINUE:
                return Stop(hit.reason, hit.description, None, hit.ids)
        was_enabled = gc.isenabled()
        gc.disable()
        try:
            if mode == CONTINUE and self.breakpoints.empty and not self.echo_motion and until is None:
                stop = self._run_fast()
                self.breakpoints.counted_to = m.blocks  # no breakpoint to count for, so far
                return stop
            return self._run_blocks(mode, until)
        finally:
            if m.finished:  # no visit is left to count
                self.breakpoints.counted_to = m.blocks
            if was_enabled:
                gc.enable()

    def _run_fast(self) -> Stop:
        m = self.machine
        interval = self.history.interval
        while True:
            left = m.settings.max_blocks - m.blocks
            if left <= 0:
                m.run(0)
                return self._ended()
            m.run(min(interval - m.blocks % interval, left), is_limit=False)
            self.history.record(m)
            self._flush()
            stop = self._status_stop()
            if stop is not None:
                return stop
            if self.pause_requested:  # inside a shape being read: on to where a stop may be made
                return Stop("pause") if can_stop(m) else self._run_blocks(CONTINUE)

    def _run_blocks(self, mode: str, until: Callable[[Machine], bool] | None = None) -> Stop:
        m = self.machine
        depth = len(m.frames)
        max_blocks = m.settings.max_blocks
        while True:
            if self.pause_requested and can_stop(m):
                return Stop("pause")
            if m.blocks >= max_blocks:
                m.run(0)
                return self._ended()
            before = len(m.frames)
            m.step()
            self.history.record(m)
            if len(m.notes) != self.notes_sent or len(m.planner.moves) != self.moves_sent:
                self._flush()
            if m.finished:
                return self._ended()
            now = len(m.frames)
            if not can_stop(m):  # a roughing cycle reads its shape: one step, no stop inside
                stop = self._status_stop()
                if stop is not None:
                    return stop
                continue
            if until is not None and until(m):
                return Stop("goto")
            hit = self.breakpoints.check(m, now > before)  # counts the visit, also when a step lands here
            stop = self._status_stop()
            if stop is not None:
                return stop
            if mode == STEP_IN and not m.frames[-1].found.file.on_control:  # no source to step through
                return Stop("step")
            if hit is not None:
                return Stop(hit.reason, hit.description, None, hit.ids)
            if (mode == STEP_OVER and now <= depth) or (mode == STEP_OUT and now < depth):
                return Stop("step")

    def _status_stop(self) -> Stop | None:
        m = self.machine
        if m.status == RunStatus.PAUSED and m.message is not None:
            if self.filters.messages:
                text = in_language(m.message, is_chinese(self.locale))
                return Stop("pause", text, text)
            return None
        if m.status in FINISHED:
            return self._ended()
        return None

    def _ended(self) -> Stop:
        m = self.machine
        if m.status == RunStatus.ALARM and m.alarm is not None:
            text = m.alarm.headline(self.locale)
            if self.filters.alarms:
                return Stop("exception", text, text)
            places = m.alarm.places(self.locale, lambda file: Path(file).name)  # where, as a note's line says it
            self.output("\n".join([text, *places]) + "\n", "stderr")
        elif m.status == RunStatus.LIMIT:
            text = budget_spent(m.blocks, self.locale)
            if not self.never_stop:
                return Stop("exception", text, text)
            self.output(text + "\n", "stderr")
        elif m.status == RunStatus.COMPLETED and self.stop_at_end:
            return Stop("step", end_text(m, self.locale))
        return Stop("exited", finished=True)

    # ---------------------------------------------------------------- going back
    def step_back(self) -> Stop:
        """Back one block (to the start of the kept history at most). From an alarm, back over
        the alarm's block, which never ran to its end, to the block before it: one block back
        would stand on the alarm's line with the same values, only the alarm cleared."""
        m = self.machine
        back = 1
        if m.status == RunStatus.COMPLETED and _end_code(m) is None:
            back = 2  # running off the file's end (or into the next O header) counted as a block
        elif m.status == RunStatus.ALARM:
            back = 2  # the alarm's block counted as a block
        if self.back_to(m.blocks - back):
            return Stop("step")
        return Stop("entry", pick(self.locale, "the start of the kept history", "保留的历史的起点"))

    def back_to(self, target: int) -> bool:
        """Back to block count ``target``, or further to the latest point before it where a run
        may stop (``can_stop``: a roughing cycle was one step forward, so back to its block).
        False when the kept history ended first."""
        m = self.machine
        if self._back(target) is not None:
            return False
        while not can_stop(m):
            if self._back(m.blocks - 1) is not None:
                return False
        return True

    def reverse(self) -> Stop:
        """Back to the latest earlier point where a forward run stopped or would have stopped
        at a breakpoint (``Breakpoints.stop_back``), or to the start of the kept history."""
        hit = self._back(None)
        if isinstance(hit, Hit):
            return Stop(hit.reason, hit.description, None, hit.ids)
        return Stop("entry", pick(self.locale, "the start of the kept history", "保留的历史的起点"))

    def _back(self, target: int | None) -> Hit | bool | None:
        """Walk the past to block count ``target`` (None: to a breakpoint's stop). Returns the
        stop's Hit, None when ``target`` was reached, True when the history ended first."""
        m, bps = self.machine, self.breakpoints
        now = m.blocks
        floor = self.history.earliest
        goal = floor if target is None else max(target, floor)
        counted_now = bps.counted_to >= now
        after: dict[int, int] = {}
        found: Hit | None = None
        at = min(goal, now)

        def look(machine: Machine, first: bool, arrival: bool, change: bool, entered: bool) -> Visit | None:
            if can_stop(machine):  # the forward run never stopped nor counted a visit elsewhere
                return bps.look(machine, first, arrival, change, entered)
            if first:
                bps.prime()
            return None

        for block, visit in self.history.past(m, look):
            if visit is not None and target is None and block < now:
                found = bps.stop_back(visit, after)
                if found is not None:
                    at = block
                    break
            if block <= goal:
                break
            if visit is not None and (block < now or counted_now):
                bps.count(visit, after)
        self.history.go_to(m, at)
        bps.rewind(at, after)
        if at != now:
            self.fresh = False
        self.resync()
        if found is not None:
            return found
        return None if target is not None and at == target else True

    def _flush(self) -> None:
        m = self.machine
        if self.echo_motion:
            for mv in m.planner.moves[self.moves_sent :]:
                self.output(move_line(mv, m.dialect.axes, self.commanded.shown(mv)), "console")
        self.moves_sent = len(m.planner.moves)
        for note in m.notes[self.notes_sent :]:
            where = f"{Path(note.file).name}:{note.line + 1}"
            if note.kind == "output":  # a DPRNT line, a BPRNT record (its words in the locale's language)
                self.output(in_language(note.message, is_chinese(self.locale)) + "\n", "stdout")
            elif note.kind == "message":
                text = in_language(note.message, is_chinese(self.locale))
                self.output(pick(self.locale, f"stop at {where}: {text}\n", f"停止（{where}）：{text}\n"), "console")
            else:
                text = in_language(note.message, is_chinese(self.locale))
                self.output(pick(self.locale, f"note at {where}: {text}\n", f"提示（{where}）：{text}\n"), "console")
        self.notes_sent = len(m.notes)
        if self.never_stop:  # Run Without Debugging never goes back: what was shown need not stay
            del m.notes[:], m.output[:], m.planner.moves[:]
            self.notes_sent = self.moves_sent = 0


def _end_code(m: Machine) -> str | None:
    """``M30``, ``M02`` or ``M99`` when a code ended the completed run (``Machine.ended_with``,
    as the run evaluated it: ``M#3`` with ``#3=30`` is M30), None when it ran off its end."""
    if m.status != RunStatus.COMPLETED or m.ended_with is None:
        return None
    return f"M{int(m.ended_with):02d}"


def end_text(m: Machine, locale: str | None) -> str:
    """Why the run is over: ``program end (M30)`` (``M02``, ``M99`` in a main program) or
    ``program end`` after its last block."""
    code = _end_code(m)
    if code is None:
        return pick(locale, "program end", "程序结束")
    return pick(locale, f"program end ({code})", f"程序结束 ({code})")


def last_line_run(m: Machine) -> int:
    """The 0-based line of the block that ended a completed run: the M30/M02 itself, or the
    last block before the end of the file (or the next program's O header) it ran off."""
    frame = m.frames[-1]
    if _end_code(m) is not None:
        return frame.pc
    blocks = frame.found.file.program.blocks
    skip_deleted = bool(m.settings.block_delete)
    k = min(frame.pc, len(blocks)) - 1
    while k > 0 and skipped(blocks[k], skip_deleted):
        k -= 1
    return max(k, 0)


def move_line(mv: Move, axes: tuple[str, ...], shown: list[int]) -> str:
    """An echoed move with the axes in ``shown`` (those the program has commanded so far)."""
    return f"{Path(mv.file).name}:{mv.line + 1} {mv.text(axes, shown)}\n"
