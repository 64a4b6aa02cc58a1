"""Running the macro machine: block after block until the program ends, alarms, pauses or spends
its budget (docs/design.md, "the interpreter").

``RunLoop`` is the part of ``Machine`` (machine.py) that runs it: ``run`` (the plain loop, or
``tracking.run_tracked`` for a machine with an observer), ``step``, ``run_until``, and the
requests another thread makes (``cancel``, ``request_pause``), seen every ``CANCEL_CHECK``
blocks. Plain motion lines not compiled yet go through ``straight_runs.run_straight``.
"""

from __future__ import annotations

import gc
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, cast

from ..planner.alarms import AlarmBeforeMove
from .alarms import Alarm, CallLevel, MacroAlarm
from .frames import Frame, ModalCall, Note
from .status import CANCEL_CHECK, FINISHED, RunStatus
from .straight_runs import run_straight
from .tracking import run_tracked
from .variables import StopRequest

if TYPE_CHECKING:
    from ..dialects import Dialect
    from ..library.machine_file import MachineSettings
    from .machine import Machine
    from .observer import RunObserver


class RunLoop:
    """The run loop of ``Machine`` (module docstring)."""

    settings: MachineSettings
    dialect: Dialect
    observer: RunObserver | None
    frames: list[Frame]
    modal_calls: list[ModalCall]
    notes: list[Note]
    status: RunStatus
    alarm: Alarm | None
    message: str | None
    blocks: int
    cancel_requested: bool
    pause_requested: bool

    if TYPE_CHECKING:

        def chain(self, at: int | None = None) -> tuple[CallLevel, ...]: ...

    def run(self, max_blocks: int | None = None, *, is_limit: bool = True) -> RunStatus:
        """Run until the program ends, alarms, pauses or has run ``max_blocks`` more blocks
        (status ``limit``, or ``paused`` when ``is_limit`` is False). Returns the status.

        Python's cycle collector is paused meanwhile: a run creates no garbage cycles, yet
        the collector would walk every compiled block again and again (a 100k-block
        program ran 3x slower with it). A machine with an observer runs
        ``tracking.run_tracked``, which the property tests hold to this plain loop."""
        if self.status in FINISHED or not self.frames:
            return self.status
        was_enabled = gc.isenabled()
        gc.disable()
        try:
            if self.observer is not None:
                return run_tracked(cast("Machine", self), self.observer, max_blocks, is_limit)
            return self._run(max_blocks, is_limit)
        finally:
            if was_enabled:
                gc.enable()

    def _run(self, max_blocks: int | None, is_limit: bool) -> RunStatus:
        m = cast("Machine", self)  # this loop runs the blocks of the machine it is a part of
        budget = self.settings.max_blocks if max_blocks is None else max_blocks
        limit = self.blocks + budget
        self.status = RunStatus.RUNNING
        self.message = None
        frame = self.frames[-1]
        cf = frame.code
        code = cf.code
        pc = frame.pc
        n = self.blocks
        try:
            while True:
                if n >= limit:
                    self.status = RunStatus.LIMIT if is_limit else RunStatus.PAUSED
                    break
                c = code[pc]
                if c is None:
                    if not self.modal_calls:
                        done, pc = run_straight(m, cf, pc, min(limit - n, CANCEL_CHECK - n % CANCEL_CHECK))
                        if done:
                            n += done
                            if not n % CANCEL_CHECK and (self.cancel_requested or self.pause_requested):
                                self.take_request()
                                break
                            continue
                    c = cf.runner(pc)
                n += 1
                pc = c(m, pc)
                if pc < 0:
                    if self.status != RunStatus.RUNNING:
                        break
                    frame = self.frames[-1]
                    cf = frame.code
                    code = cf.code
                    pc = frame.pc
                if not n % CANCEL_CHECK and (self.cancel_requested or self.pause_requested):
                    self.take_request()
                    break
        except (MacroAlarm, StopRequest) as e:
            return self.interrupted(e, n, pc)
        return self.stopped_at(n, pc)

    # The run loops (``_run`` and the analysis's ``tracking.run_tracked``) end through these.
    def take_request(self) -> None:
        """Honour a cancel or pause request from another thread (seen every ``CANCEL_CHECK`` blocks)."""
        if self.cancel_requested:
            self.status = RunStatus.STOPPED
        else:
            self.pause_requested = False
            self.status = RunStatus.PAUSED

    def interrupted(self, e: MacroAlarm | StopRequest, n: int, pc: int) -> RunStatus:
        """A run stopped inside block ``pc``, the ``n``-th: by an alarm, or by ``M00``/``#3006``
        (paused, to go on with the next block)."""
        self.blocks = n
        f = self.frames[-1]
        if isinstance(e, MacroAlarm):
            f.pc = pc
            line = pc
            if isinstance(e, AlarmBeforeMove):  # the control stopped before an earlier block moved
                e.take_back()
                if e.at is not None and e.at[0] == f.file:  # on that block (a block of another file: this one)
                    line = e.at[1]
            shown = self.dialect.shown_alarm(e.number)
            self.alarm = Alarm(e.number, e.message, f.file, line, self.chain(line), e.subject, shown)
            self.status = RunStatus.ALARM
        else:
            f.pc = f.code.next_line(pc)
            self.status = RunStatus.PAUSED
            self.message = e.message
            self.notes.append(Note("message", e.message, f.file, pc))
        return self.status

    def stopped_at(self, n: int, pc: int) -> RunStatus:
        """A run loop left after ``n`` blocks with ``pc`` next (negative: the frames say)."""
        self.blocks = n
        if pc >= 0:
            self.frames[-1].pc = pc
        return self.status

    def step(self) -> RunStatus:
        """Execute one block; the status is ``paused`` unless the run ended."""
        return self.run(1, is_limit=False)

    def run_until(self, stop: Callable[[Any], bool], max_blocks: int | None = None) -> RunStatus:
        """Execute blocks until ``stop(machine)`` holds after one, or the run ends."""
        budget = self.settings.max_blocks if max_blocks is None else max_blocks
        limit = self.blocks + budget
        while True:
            status = self.step()
            if status != RunStatus.PAUSED or self.message is not None:
                return status
            if stop(self):
                return status
            if self.blocks >= limit:
                self.status = RunStatus.LIMIT
                return RunStatus.LIMIT

    def resume(self) -> None:
        """Continue after a pause (``M00``, ``#3006``)."""
        if self.status == RunStatus.PAUSED:
            self.status = RunStatus.READY
            self.message = None

    def cancel(self) -> None:
        """Ask a running ``run`` (in another thread) to stop soon."""
        self.cancel_requested = True

    def request_pause(self) -> None:
        """Ask a running ``run`` (in another thread) to pause soon, within ``CANCEL_CHECK``
        blocks (an endless loop too); it returns ``paused`` and may be run on afterwards."""
        self.pause_requested = True
