"""Running the machine until the debugger should stop: continue, step in, over and out.

One step is one block. Step in runs one block (into a call). Step over runs blocks until the
program level is back where it started (a G65, M98 or G66 call runs to completion). Step out
runs until the level is above where it started (past the M99). Any of them stops at a
breakpoint, an alarm, an ``M00``/``#3006`` pause, the block budget, or a pause request from
another thread. A continue with no breakpoints and no motion echo runs the interpreter at
full speed in chunks and is paused by ``Machine.request_pause``; otherwise it runs block by
block. Output (DPRNT, messages, the echoed motion) goes to ``output`` as it happens.
"""

from __future__ import annotations

import gc
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from ..machine import Machine
from ..machine.frames import Move
from ..machine.machine import ALARM, COMPLETED, LIMIT, PAUSED, STOPPED
from .breakpoints import Breakpoints
from .history import History

CONTINUE, STEP_IN, STEP_OVER, STEP_OUT = "continue", "in", "over", "out"


@dataclass(slots=True)
class Stop:
    """How a run ended: a DAP stopped reason (or ``finished`` when the program is over)."""

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
        self.pause_requested = False
        self.notes_sent = len(machine.notes)
        self.moves_sent = len(machine.moves)
        self.fresh = True  # nothing has run yet: a breakpoint on the first block counts

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
        self.moves_sent = len(self.machine.moves)

    # ---------------------------------------------------------------- running
    def run(self, mode: str) -> Stop:
        m = self.machine
        if m.finished:  # its end was shown already
            return Stop("exited", finished=True)
        self.breakpoints.prime()
        if self.fresh:
            self.fresh = False
            hit = self.breakpoints.check(m, True) if mode == CONTINUE and not self.breakpoints.empty else None
            if hit is not None:
                return Stop(hit.reason, hit.description, None, hit.ids)
        was_enabled = gc.isenabled()
        gc.disable()
        try:
            if mode == CONTINUE and self.breakpoints.empty and not self.echo_motion:
                return self._run_fast()
            return self._run_blocks(mode)
        finally:
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
            if self.pause_requested:
                return Stop("pause")

    def _run_blocks(self, mode: str) -> Stop:
        m = self.machine
        depth = len(m.frames)
        max_blocks = m.settings.max_blocks
        while True:
            if self.pause_requested:
                return Stop("pause")
            if m.blocks >= max_blocks:
                m.run(0)
                return self._ended()
            before = len(m.frames)
            m.step()
            self.history.record(m)
            if len(m.notes) != self.notes_sent or len(m.moves) != self.moves_sent:
                self._flush()
            stop = self._status_stop()
            if stop is not None:
                return stop
            now = len(m.frames)
            if mode == STEP_IN:
                return Stop("step")
            hit = self.breakpoints.check(m, now > before)
            if hit is not None:
                return Stop(hit.reason, hit.description, None, hit.ids)
            if (mode == STEP_OVER and now <= depth) or (mode == STEP_OUT and now < depth):
                return Stop("step")

    def _status_stop(self) -> Stop | None:
        m = self.machine
        if m.status == PAUSED and m.message is not None:
            if self.filters.messages:
                return Stop("pause", m.message, m.message)
            return None
        if m.status in (COMPLETED, ALARM, LIMIT, STOPPED):
            return self._ended()
        return None

    def _ended(self) -> Stop:
        m = self.machine
        if m.status == ALARM and m.alarm is not None:
            a = m.alarm
            text = f"ALARM {a.number}: {a.message}"
            if self.filters.alarms:
                return Stop("exception", text, text)
            self.output(text + "\n", "stderr")
        elif m.status == LIMIT:
            text = f"stopped after {m.blocks} blocks: the block budget ran out (an endless loop?)"
            return Stop("exception", text, text)
        return Stop("exited", finished=True)

    def _flush(self) -> None:
        m = self.machine
        if self.echo_motion:
            for mv in m.moves[self.moves_sent :]:
                self.output(move_line(mv, m.dialect.axes), "console")
        self.moves_sent = len(m.moves)
        for note in m.notes[self.notes_sent :]:
            where = f"{Path(note.file).name}:{note.line + 1}"
            if note.kind == "output":
                self.output(note.message + "\n", "stdout")
            elif note.kind == "message":
                self.output(f"stop at {where}: {note.message}\n", "console")
            else:
                self.output(f"note at {where}: {note.message}\n", "console")
        self.notes_sent = len(m.notes)


def move_line(mv: Move, axes: tuple[str, ...]) -> str:
    return f"{Path(mv.file).name}:{mv.line + 1} {mv.text(axes)}\n"
