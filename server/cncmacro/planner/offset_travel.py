"""Where the machine is when an offset changes between two moves (docs/semantics.md §8).

The moves are the programmed path, in the coordinates of the work offset in force; the tool
vector (a lathe's T offset, a mill's G43 H) is not in them.

- **A work offset changes** (`G55`, `G54.1 P2`, a `G10 L2` of the offset in force): the machine
  stays where it is, and so its program position changes (``keep_machine_position``), as the
  control's absolute position display does: `G54 G00 X0 Y0` then `G55 X0 Y0` goes from one vise
  to the other, and an axis the block does not name stays where it is. The run kept the program
  position instead: the move from one vise to the other took no time and drew nothing, and an
  axis left out went to the other vise's value.
- **A mill's tool length offset changes** (`G43 H1`, `G44`, `G49`): the control moves the
  machine by the change, with the next move (`G43 H1 Z50.` lowers the spindle to Z50 plus the
  tool's length). The program position stays; the next move is timed (``travel_start``) from
  where the machine was, seen with the new vector (``vector_changing`` keeps the vector before
  the change until then). A lathe's T offset is left as it was (the offset in force from the T
  on, the tool where the next move sends it, docs/semantics.md §10.1): whether its geometry part
  shifts the coordinates or moves the tool is a parameter of the control (FANUC 5002#4 LGT).

A macro that writes an offset's variable itself (`#5221=…`) is not seen here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .positions import work_offset

if TYPE_CHECKING:
    from .planner import Planner

_NONE = 1e-9  # a change smaller than this is no change (the sums' last bits)


def work_offsets(p: Planner) -> list[float]:
    """Per axis, the work offset in force (the coordinate system's plus the external one)."""
    return [work_offset(p, i) for i in range(len(p.pos))]


def keep_machine_position(p: Planner, before: list[float]) -> dict[int, float]:
    """The work offsets were ``before`` and are now those in force: the tool stays where it is on
    the machine, so its program position takes the difference, which is returned per axis moved
    (for cutter_stage.py's ``frame_moved``)."""
    change: dict[int, float] = {}
    for i, was in enumerate(before):
        d = work_offset(p, i) - was
        if abs(d) >= _NONE:
            p.pos[i] -= d
            change[i] = -d
    return change


def vector_changing(p: Planner) -> None:
    """The tool vector is about to change: keep it as it is for the next move (once until then)."""
    if p.vector_before is None:
        p.vector_before = list(p.tool_vector)


def travel_start(p: Planner, start: tuple[float, ...]) -> tuple[float, ...]:
    """Where a move from ``start`` starts for the machine, with the tool vector now in force:
    ``start`` unless the vector changed since the last move (then where the machine was, seen
    with the new vector)."""
    before = p.vector_before
    if before is None:
        return start
    p.vector_before = None
    moved = [now - then for now, then in zip(p.tool_vector, before, strict=True)]
    if all(abs(d) < _NONE for d in moved):
        return start
    return tuple(s - d for s, d in zip(start, moved, strict=True))
