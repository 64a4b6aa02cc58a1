"""Where a stopped run stands on its toolpath, and running to a move of it.

The toolpath view draws, while a debug session is paused, the moves run so far and the move
the block the run stands on is about to make (``next_moves``: that block is run on the machine
and the machine put back as it was, ``Machine.snapshot``/``restore``, so nothing is shown, counted
or kept). A block that makes no move (a macro statement, a call, an M code) has none. A lathe
cycle that names its finishing shape (``G71 P Q``, ``G70 P Q``) runs that shape as a level of its
own: its moves are the passes (or the finishing cut) made once the shape's last block is done,
so the block is followed until that level ends, and every pass is the block's.

"Run to here" on a move: ``run_to_move`` puts the run at the block that makes the move with
that number (0 for the first move of the run), before it runs. A move still to come is reached
by running forward, block by block, stopping at breakpoints, alarms and pauses on the way as a
continue does; once the block that makes it has run, the run goes back one block (the
history's replay). A move already made is reached by going back through the history: the
latest block before which fewer moves had been made than its number plus one. Both are
decided here, on the run itself, not by the view.
"""

from __future__ import annotations

from ..bilingual import pick
from ..machine import Machine
from ..planner.moves import Move
from .stepping import CONTINUE, Stepper, Stop
from .stop_points import can_stop

SHAPE_BLOCKS = 10_000  # a shape's blocks followed for its cycle's moves, at most


def next_moves(m: Machine) -> list[Move]:
    """The moves the block at the machine's pc makes (none when the run is over)."""
    if m.finished:
        return []
    snap = m.snapshot()
    made = len(m.planner.moves)
    depth = len(m.frames)
    try:
        m.step()
        if len(m.frames) > depth and m.frames[-1].end_line >= 0 and not m.finished:  # a shape cycle's level
            m.run_until(lambda machine: len(machine.frames) <= depth, max_blocks=SHAPE_BLOCKS)
        return list(m.planner.moves[made:])
    finally:
        m.restore(snap)


def run_to_move(stepper: Stepper, index: int) -> Stop:
    """Put the run at the block that makes move ``index``, forward or back (see above)."""
    m = stepper.machine
    if index < len(m.planner.moves):
        return _back_to_move(stepper, index)
    stop = stepper.run(CONTINUE, until=lambda machine: len(machine.planner.moves) > index)
    if stop.reason != "goto":
        return stop  # a breakpoint, an alarm, a pause or the end came first
    if not stepper.back_to(m.blocks - 1):
        return Stop("entry", pick(stepper.locale, "the start of the kept history", "保留的历史的起点"))
    return Stop("goto", _arrived(stepper, index))


def _back_to_move(stepper: Stepper, index: int) -> Stop:
    m = stepper.machine
    target = stepper.history.earliest  # when the history does not reach back that far
    for block, made in stepper.history.past(m, _moves_made):
        if made is not None and made <= index:
            target = block
            break
    if not stepper.back_to(target) or len(m.planner.moves) > index:
        return Stop("entry", pick(stepper.locale, "the start of the kept history", "保留的历史的起点"))
    return Stop("goto", _arrived(stepper, index))


def _moves_made(m: Machine, *_: bool) -> int | None:
    """The moves made before this earlier point, when a run may stop there."""
    return len(m.planner.moves) if can_stop(m) else None


def _arrived(stepper: Stepper, index: int) -> str:
    n = index + 1
    return pick(stepper.locale, f"at the block of move {n}", f"已到第 {n} 段运动的程序段")
